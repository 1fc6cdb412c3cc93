// The coupled step: search (all ranks) -> gather (to root) -> eq. 21 with the plate (root) -> hand-back.
#include "halfeti/coupling/contact_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "halfeti/core/collective.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/parallel/gather.hpp"

namespace halfeti::coupling {

namespace {
constexpr int kMaxActiveSetPasses = 5;  // releases settle in one or two passes; a bound keeps a step finite
}  // namespace

void validate(const CouplingParameters& p) {
  validate(p.ssosd);
  if (!(p.inside_tolerance > 0.0))
    HALFETI_USER_ERROR("coupling.inside_tolerance = " << p.inside_tolerance << " m must be > 0");
  if (p.implicit_exchange()) {
    if (!p.plate_wall)
      HALFETI_USER_ERROR(
          "coupling.plate_wall_exchange: implicit converges the plate-wall exchange; it needs "
          "coupling.plate_wall: true");
    if (p.added_mass_kind != CouplingParameters::AddedMass::kNone)
      HALFETI_USER_ERROR(
          "coupling.added_mass: with plate_wall_exchange: implicit the water's response is converged "
          "within the step, not modelled; set coupling.added_mass: none");
    if (p.implicit.max_iterations < 1)
      HALFETI_USER_ERROR("coupling.implicit.max_iterations = " << p.implicit.max_iterations
                                                               << " must be >= 1");
    if (!(p.implicit.tolerance > 0.0 && p.implicit.tolerance < 1.0))
      HALFETI_USER_ERROR("coupling.implicit.tolerance = " << p.implicit.tolerance << " must be in (0, 1)");
    if (!(p.implicit.accelerator.relaxation > 0.0 && p.implicit.accelerator.relaxation <= 1.0))
      HALFETI_USER_ERROR("coupling.implicit.relaxation = " << p.implicit.accelerator.relaxation
                                                           << " must be in (0, 1]");
  }
}

void SurfacePointLoad::start_step(const Eigen::Vector2d& load, const Eigen::Vector2d& place,
                                  const Eigen::Matrix2d& added_mass, Guess guess) {
  added_mass_ = added_mass;
  rest_ = has_previous_ ? Eigen::Vector2d(2.0 * place - place_) : place;
  // The explicit exchange's trapezoidal step wants the load at mid-step; the water's is from the step's start. The
  // converged exchange's starts from the load extrapolated to the step's end.
  force_ = load;
  if (has_previous_ && guess == Guess::kMidStep) force_ = 1.5 * load - 0.5 * previous_;
  if (has_previous_ && guess == Guess::kStepEnd) force_ = 2.0 * load - previous_;
  previous_ = load;
  place_ = place;
  has_previous_ = true;
}

void SurfacePointLoad::save_state(std::vector<double>& state) const {
  state.insert(state.end(),
               {previous_.x(), previous_.y(), place_.x(), place_.y(), has_previous_ ? 1.0 : 0.0});
}

const double* SurfacePointLoad::restore_state(const double* state) {
  previous_ = Eigen::Vector2d(state[0], state[1]);
  place_ = Eigen::Vector2d(state[2], state[3]);
  has_previous_ = state[4] != 0.0;
  return state + 5;
}

ContactCoupling::ContactCoupling(MPI_Comm world, structure::PlateSolver* solver,
                                 const CouplingParameters& params, int root)
    : comm_(world), root_(root), solver_(solver), params_(params) {
  accelerator_ = InterfaceQuasiNewton(params_.implicit.accelerator);
  validate(params_);
  rank_ = comm_.rank();
  HALFETI_CHECK((rank_ == root_) == (solver_ != nullptr),
                "the plate solver must be given on the root rank only");
  if (solver_ != nullptr)
    system_ = std::make_unique<ContactSystem>(*solver_, params_.constraint, params_.options_prefix,
                                              params_.solver, params_.mass_participation);
  broadcast_surface();
  // The plate's thickness (its base corners are the surface's ends): how deep inside the plate the search looks.
  if (surface_.points.size() >= 2) thickness_ = (surface_.points.front() - surface_.points.back()).norm();
  if (solver_ != nullptr) {
    for (int node : surface_.nodes) {
      loads_.push_back(std::make_unique<SurfacePointLoad>(node));
      solver_->add_nodal_element(loads_.back().get());
    }
    const auto corners = sph::outline_corners(plate_outline());
    if (corners.first > 0 && corners.second > corners.first) {  // else everything counts as the top
      corners_[0] = corners.first;
      corners_[1] = corners.second;
      const Eigen::Vector2d d = surface_.points[1] - surface_.points[0];
      first_face_ =
          d.y() > 0.0 ? PlateLoadBreakdown::kRight : PlateLoadBreakdown::kLeft;  // outward (t_y, -t_x)
      second_face_ = d.y() > 0.0 ? PlateLoadBreakdown::kLeft : PlateLoadBreakdown::kRight;
    }
  }
}

sph::PlateOutline ContactCoupling::plate_outline() const {
  sph::PlateOutline o;
  for (std::size_t k = 0; k < surface_.points.size(); ++k) {
    o.x.push_back(surface_.points[k].x());
    o.y.push_back(surface_.points[k].y());
    o.vx.push_back(params_.plate_wall_velocity ? surface_motion_[4 * k] : 0.0);
    o.vy.push_back(params_.plate_wall_velocity ? surface_motion_[4 * k + 1] : 0.0);
    o.ax.push_back(surface_motion_[4 * k + 2]);
    o.ay.push_back(surface_motion_[4 * k + 3]);
  }
  return o;
}

std::vector<Eigen::Vector2d> ContactCoupling::gather_point_loads(const std::vector<sph::PlateWallLoad>& local,
                                                                 bool breakdown) {
  std::vector<sph::PlateWallLoad> all = parallel::gather_to_root(comm_.get(), root_, local);
  std::vector<Eigen::Vector2d> load;
  if (rank_ != root_) return load;
  // (gid, point) order: a fixed summation order on any number of ranks (stable: one particle's loads on one
  // point keep its own rank's order, which does not depend on the split).
  std::stable_sort(all.begin(), all.end(), [](const sph::PlateWallLoad& a, const sph::PlateWallLoad& b) {
    return a.gid != b.gid ? a.gid < b.gid : a.point < b.point;
  });
  load.assign(loads_.size(), Eigen::Vector2d::Zero());
  const auto normal = breakdown ? surface_normals() : std::vector<Eigen::Vector2d>{};
  if (breakdown) {
    for (auto& face : breakdown_.wall_push) face[0] = face[1] = 0.0;
    for (auto& face : breakdown_.wall_suction) face[0] = face[1] = 0.0;
  }
  for (const sph::PlateWallLoad& l : all) {
    HALFETI_CHECK(
        l.point >= 0 && static_cast<std::size_t>(l.point) < load.size(),
        "plate-wall load of particle " << l.gid << " on outline point " << l.point << " of " << load.size());
    const auto p = static_cast<std::size_t>(l.point);
    const Eigen::Vector2d f(l.fx, l.fy);
    load[p] += f;
    if (!breakdown) continue;
    // Push: the force on the plate points into it (against the outward normal); suction: out of it.
    const int face = point_face(static_cast<int>(p));
    double* part = f.dot(normal[p]) <= 0.0 ? breakdown_.wall_push[face] : breakdown_.wall_suction[face];
    part[0] += f.x();
    part[1] += f.y();
  }
  return load;
}

std::vector<Eigen::Vector2d> ContactCoupling::surface_normals() const {
  // The outward normal at each surface point: from its neighbours (radial at a corner; one segment at the
  // polyline's ends, the clamped base corners).
  const auto& pts = surface_.points;
  std::vector<Eigen::Vector2d> normal(pts.size());
  if (pts.empty()) return normal;
  const std::size_t last = pts.size() - 1;
  for (std::size_t k = 0; k <= last; ++k) {
    const Eigen::Vector2d t = pts[std::min(k + 1, last)] - pts[k == 0 ? 0 : k - 1];
    normal[k] = turned_clockwise(t).normalized();
  }
  return normal;
}

void ContactCoupling::set_fluid_loads(const std::vector<sph::PlateWallLoad>& local, double dt) {
  ScopedTimer timer(timers_, "fluid_load");
  const std::vector<Eigen::Vector2d> load = gather_point_loads(local, true);
  double sum[2] = {0.0, 0.0};
  if (rank_ == root_) {
    const auto& pts = surface_.points;
    const std::size_t last = pts.size() - 1;
    const auto normal = surface_normals();
    const double mass_per_area = params_.added_mass_per_area(dt);
    using Guess = SurfacePointLoad::Guess;
    const Guess guess = params_.plate_wall_exchange == CouplingParameters::PlateWallExchange::kExtrapolated
                            ? Guess::kMidStep
                        : params_.implicit_exchange() ? Guess::kStepEnd
                                                      : Guess::kStart;
    for (std::size_t k = 0; k < loads_.size(); ++k) {
      auto& l = *loads_[k];
      // The interface added mass on this point (sections 13, 15): along its normal, on half of each neighbouring
      // segment's length; none on the clamped base corners.
      Eigen::Matrix2d added_mass = Eigen::Matrix2d::Zero();
      if (k > 0 && k < last && mass_per_area > 0.0) {
        const double length = 0.5 * ((pts[k] - pts[k - 1]).norm() + (pts[k + 1] - pts[k]).norm());
        added_mass = mass_per_area * length * normal[k] * normal[k].transpose();
      }
      l.start_step(load[k], pts[k], added_mass, guess);
      sum[0] += load[k].x();
      sum[1] += load[k].y();
    }
    accelerator_.start();
  }
  exchange_iteration_ = 0;
  MPI_Bcast(sum, 2, MPI_DOUBLE, root_, comm_.get());
  fluid_load_[0] = sum[0];
  fluid_load_[1] = sum[1];
}

void ContactCoupling::broadcast_surface() {
  int count = 0;
  std::vector<double> flat;
  if (rank_ == root_) {
    surface_ = ContactSystem::surface(*solver_);
    count = static_cast<int>(surface_.points.size());
    for (const auto& p : surface_.points) flat.insert(flat.end(), {p.x(), p.y()});
    for (int node : surface_.nodes)
      for (int c = 0; c < 2; ++c) flat.push_back(solver_->velocity()(2 * node + c));
    for (int node : surface_.nodes)
      for (int c = 0; c < 2; ++c) flat.push_back(solver_->acceleration()(2 * node + c));
  }
  MPI_Bcast(&count, 1, MPI_INT, root_, comm_.get());
  flat.resize(6 * static_cast<std::size_t>(count));
  MPI_Bcast(flat.data(), 6 * count, MPI_DOUBLE, root_, comm_.get());
  surface_motion_.resize(4 * static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    surface_motion_[4 * k] = flat[2 * count + 2 * k];
    surface_motion_[4 * k + 1] = flat[2 * count + 2 * k + 1];
    surface_motion_[4 * k + 2] = flat[4 * count + 2 * k];
    surface_motion_[4 * k + 3] = flat[4 * count + 2 * k + 1];
  }
  if (rank_ != root_) {
    surface_.points.resize(count);
    surface_.nodes.assign(count, -1);  // node ids are the structure's business
    for (int k = 0; k < count; ++k) surface_.points[k] = Eigen::Vector2d(flat[2 * k], flat[2 * k + 1]);
  }
}

std::vector<sph::Barrier> ContactCoupling::outline() const {
  std::vector<sph::Barrier> out;
  for (int k = 0; k < surface_.segment_count(); ++k)
    out.push_back({surface_.points[k].x(), surface_.points[k].y(), surface_.points[k + 1].x(),
                   surface_.points[k + 1].y()});
  return out;
}

PhaseTimers ContactCoupling::timers() const {
  PhaseTimers all = timers_;
  if (system_) all.merge(system_->timers());
  return all;
}

std::vector<InvaderCorrection> ContactCoupling::solve_on_root(double t, double dt, double layer,
                                                              const std::vector<Invader>& gathered) {
  const double when = t + dt;
  std::vector<InvaderCorrection> corrections(gathered.size());
  last_solve_ = ContactSolveReport{};
  for (auto& l : loads_) l->set_time_step(dt);  // section 13
  for (auto& face : breakdown_.contact) face[0] = face[1] = 0.0;
  const Eigen::VectorXd u_before = solver_->displacement();
  // The water's work on the plate over the step, part by part: the trapezoid of each part's nodal force at the
  // step's start and end times the node's displacement over it, the discrete work of the trapezoidal rule (with
  // gamma = 1/2 the plate's energy then changes by exactly this; with gamma > 1/2 the difference is the Newmark
  // dissipation).
  auto add_work = [&] {
    double* work[3] = {&breakdown_.work_wall, &breakdown_.work_added_mass, &breakdown_.work_contact};
    for (int part = 0; part < 3; ++part) {
      auto& now = nodal_force_[part];
      auto& before = previous_force_[part];
      if (before.size() != now.size()) before.assign(now.size(), Eigen::Vector2d::Zero());
      for (std::size_t node = 0; node < now.size(); ++node) {
        const Eigen::Vector2d step =
            solver_->displacement().segment<2>(2 * node) - u_before.segment<2>(2 * node);
        *work[part] += 0.5 * (before[node] + now[node]).dot(step);
      }
      before.swap(now);
    }
  };
  // Each part's force on the plate's nodes at the step's end (reused buffers).
  for (auto& v : nodal_force_)
    v.assign(static_cast<std::size_t>(solver_->node_count()), Eigen::Vector2d::Zero());
  auto add_surface_forces = [&] {
    for (auto& l : loads_) {
      const int node = l->nodes()[0];
      nodal_force_[0][node] += l->force();
      nodal_force_[1][node] += l->spring_force(solver_->position(node));
    }
  };
  if (gathered.empty()) {
    solver_->step(t, dt);  // nothing touches the plate: its own Newton loop
    last_.newton_iterations = solver_->last_step().newton_iterations;
    add_surface_forces();
    add_work();
    return corrections;
  }
  // Frozen data of the step from the surface at the start of the step (the plate's predictor is u_n):
  // the contact segment, eta (eq. 20) and the target gap (eq. 22, or 0 without SSOSD).
  std::vector<ContactInvader> invaders;
  invaders.reserve(gathered.size());
  const double reach = std::max(layer, thickness_);
  const SurfaceSearch before(surface_, reach);
  std::vector<double> predicted_gap;
  predicted_gap.reserve(gathered.size());
  for (const Invader& g : gathered) {
    const Eigen::Vector2d x(g.x, g.y);
    const ContactPoint c = before.closest_within_reach(x);  // found by the same search on the owner: in reach
    HALFETI_CHECK(c.segment >= 0, "invader " << g.gid << " out of the search's reach");
    invaders.push_back({x, g.mass, c.segment, c.projection.eta, relocated_gap(c.projection.gap, layer)});
    if (params_.trace)  // one line per invader
      std::fprintf(stderr, "invader t=%.6f gid=%lld x=(%.7f, %.7f) seg=%d eta=%.4f gap=%.3e m=%.3e\n", t,
                   static_cast<long long>(g.gid), g.x, g.y, c.segment, c.projection.eta, c.projection.gap,
                   g.mass);
    predicted_gap.push_back(c.projection.gap);
  }
  // Unilateral contact by an active set: an invader the converged solve pulls towards the plate (normal force
  // C . n < 0, the plate moving away faster than the target allows) is released and Newton continues from the
  // current iterate with the others. A released particle keeps its predicted state, so only particles predicted
  // outside the surface (in the layer) may be released: one predicted past it stays in the solve.
  std::vector<int> active(gathered.size());
  for (std::size_t k = 0; k < active.size(); ++k) active[k] = static_cast<int>(k);
  const auto& segments = solver_->mesh().surface;
  solver_->begin_step(t, dt);
  int iterations = 0;
  for (int pass = 0;; ++pass) {
    std::vector<ContactInvader> subset;
    for (int k : active) subset.push_back(invaders[k]);
    last_solve_ = system_->solve(subset, dt, when);
    iterations += last_solve_.iterations;
    if (!params_.unilateral || pass >= kMaxActiveSetPasses) break;
    std::vector<int> kept;
    for (std::size_t j = 0; j < active.size(); ++j) {
      const auto& seg = segments[static_cast<std::size_t>(subset[j].segment)];
      const Eigen::Vector2d n =
          turned_clockwise(solver_->position(seg.second) - solver_->position(seg.first)).normalized();
      if (system_->forces()[j].dot(n) >= 0.0 || predicted_gap[active[j]] < 0.0) kept.push_back(active[j]);
    }
    if (kept.size() == active.size()) break;
    last_.released += static_cast<int>(active.size() - kept.size());
    active.swap(kept);
  }
  solver_->end_step();
  last_.newton_iterations = iterations;
  add_surface_forces();
  // The contact's share of the load breakdown: each active invader's force, its opposite on the plate shared by
  // its segment's points ((1 - eta), eta as in eq. 19), and its work over the step.
  for (std::size_t j = 0; j < active.size(); ++j) {
    const ContactInvader& c = invaders[static_cast<std::size_t>(active[j])];
    const Eigen::Vector2d on_plate = -system_->forces()[j];
    const int face = segment_face(c.segment);
    breakdown_.contact[face][0] += on_plate.x();
    breakdown_.contact[face][1] += on_plate.y();
    const auto& seg = segments[static_cast<std::size_t>(c.segment)];
    const double eta = std::clamp(c.eta, 0.0, 1.0);
    nodal_force_[2][seg.first] += (1.0 - eta) * on_plate;
    nodal_force_[2][seg.second] += eta * on_plate;
  }
  add_work();

  // Health: no invader may stay past the (new) surface.
  const SurfacePolyline after = ContactSystem::surface(*solver_);
  const SurfaceSearch search_after(after,
                                   reach);  // a particle past the surface is within the thickness of it
  std::vector<int> slot(gathered.size(), -1);
  for (std::size_t j = 0; j < active.size(); ++j) slot[active[j]] = static_cast<int>(j);
  for (std::size_t k = 0; k < gathered.size(); ++k) {
    const int j = slot[k];
    const Eigen::Vector2d y = j >= 0 ? system_->positions()[j] : invaders[k].predicted;
    const ContactPoint c = search_after.closest_within_reach(y);
    if (c.segment >= 0 && c.projection.gap < -params_.inside_tolerance)
      HALFETI_NUMERICAL_ERROR("particle "
                              << gathered[k].gid << " left inside the plate after the contact solve ("
                              << c.projection.gap << " m past segment " << c.segment << ") at (" << y.x()
                              << ", " << y.y() << ") m");
    if (j < 0) continue;  // released: no correction
    const Eigen::Vector2d& f = system_->forces()[j];
    InvaderCorrection& out = corrections[k];
    out.dx = y.x() - gathered[k].x;
    out.dy = y.y() - gathered[k].y;
    if (params_.velocity_update == VelocityUpdate::kAcceleration) {
      // Delta C = C / m held over the step (eq. 4): the velocity changes by C dt / m.
      out.dvx = f.x() * dt / gathered[k].mass;
      out.dvy = f.y() * dt / gathered[k].mass;
    } else if (params_.velocity_update == VelocityUpdate::kDisplacement) {
      out.dvx = out.dx / dt;
      out.dvy = out.dy / dt;
    } else {
      // Inelastic contact without the relocation's velocity: remove the normal approach relative to the surface.
      const auto& seg = segments[static_cast<std::size_t>(invaders[k].segment)];
      const SegmentProjection at =  // eq. 20 at the final surface
          project_on_segment(y, solver_->position(seg.first), solver_->position(seg.second));
      const double eta = std::clamp(at.eta, 0.0, 1.0);
      const Eigen::Vector2d vs = (1.0 - eta) * solver_->velocity().segment<2>(2 * seg.first) +
                                 eta * solver_->velocity().segment<2>(2 * seg.second);
      const Eigen::Vector2d& n = at.normal;
      const double vn = (Eigen::Vector2d(gathered[k].vx, gathered[k].vy) - vs).dot(n);
      out.dvx = vn < 0.0 ? -vn * n.x() : 0.0;
      out.dvy = vn < 0.0 ? -vn * n.y() : 0.0;
    }
    out.fx = f.x();
    out.fy = f.y();
  }
  return corrections;
}

const CouplingStepReport& ContactCoupling::step(double t, double dt, const InterfaceParticles& particles,
                                                Corrections& out) {
  last_ = CouplingStepReport{};
  std::vector<Invader> local, gathered;
  {
    ScopedTimer timer(timers_, "search");
    double u2_max = 0.0;
    for (std::size_t i = 0; i < particles.count; ++i)
      u2_max = std::max(u2_max, particles.vx[i] * particles.vx[i] + particles.vy[i] * particles.vy[i]);
    double u_max = std::sqrt(u2_max);
    MPI_Allreduce(MPI_IN_PLACE, &u_max, 1, MPI_DOUBLE, MPI_MAX,
                  comm_.get());  // max is exact: rank-independent
    last_.u_max = u_max;
    last_.layer = layer_thickness(params_.ssosd, u_max, dt);
    local = find_local_invaders(particles, surface_, last_.layer, thickness_, rank_);
  }
  {
    ScopedTimer timer(timers_, "gather");
    gathered = gather_invaders(comm_.get(), root_, local);
  }

  // The structure's part runs on root; its outcome is broadcast so that every rank throws together.
  std::vector<InvaderCorrection> corrections;
  // The root solves; its failure, named with the step, is raised on every rank together.
  collective_outcome(comm_.get(), root_, rank_ == root_, [&] {
    try {
      corrections = solve_on_root(t, dt, last_.layer, gathered);
    } catch (const NumericalError& e) {
      std::ostringstream s;
      s << "coupling step t = " << t << " -> " << t + dt << " s (" << gathered.size()
        << " invaders): " << e.what();
      throw NumericalError(s.str());
    }
  });

  {
    ScopedTimer timer(timers_, "handback");
    scatter_corrections(comm_.get(), root_, gathered, corrections, particles, out);
    double summary[6] = {
        static_cast<double>(gathered.size()), static_cast<double>(last_.newton_iterations), 0.0, 0.0, 0.0,
        static_cast<double>(last_.released)};
    for (const auto& c : corrections) {  // root only; gid order: a fixed summation order
      summary[2] += c.fx;
      summary[3] += c.fy;
      summary[4] = std::max(summary[4], std::hypot(c.fx, c.fy));
    }
    MPI_Bcast(summary, 6, MPI_DOUBLE, root_, comm_.get());
    last_.released = static_cast<int>(summary[5]);
    last_.invaders = static_cast<int>(summary[0]);
    last_.newton_iterations = static_cast<int>(summary[1]);
    last_.force_x = summary[2];
    last_.force_y = summary[3];
    last_.max_force = summary[4];
    static_assert(sizeof(PlateLoadBreakdown) == 21 * sizeof(double),
                  "the breakdown is broadcast as 21 doubles");
    MPI_Bcast(&breakdown_, 21, MPI_DOUBLE, root_, comm_.get());
    const std::vector<Eigen::Vector2d> before = surface_.points;
    broadcast_surface();
    // The surface's velocity for the water is its mean velocity over the step, (x_n+1 - x_n) / dt: the Newmark
    // (trapezoidal) nodal velocity carries the plate's undamped high-frequency content, v_n+1 = 2 (u_n+1 - u_n) /
    // dt - v_n, and fed back through the plate-wall ghosts it grew into a plate-water oscillation (docs/coupling.md).
    // Explicit exchange: extrapolated to the coming step's middle, 2 v_n+1/2 - v_n-1/2; the converged exchange uses
    // this step's own motion (Fluid::update_density) and has the faces' velocity in the next force computation lag
    // half a step (the viscous term only).
    if (before.size() == surface_.points.size()) {
      const bool first = mean_velocity_.size() != 2 * before.size();
      mean_velocity_.resize(2 * before.size());
      for (std::size_t k = 0; k < before.size(); ++k)
        for (int c = 0; c < 2; ++c) {
          const double v = (surface_.points[k][c] - before[k][c]) / dt;
          const double old = first ? v : mean_velocity_[2 * k + c];
          const bool extrapolate =
              params_.plate_wall_exchange == CouplingParameters::PlateWallExchange::kExtrapolated;
          surface_motion_[4 * k + c] = extrapolate ? 2.0 * v - old : v;
          mean_velocity_[2 * k + c] = v;
        }
    }
  }
  return last_;
}

// Layout: [surface_motion_ size, values][mean_velocity_ size, values][fluid_load_ 2][breakdown_ 21]
//         [loads_ count, 5 each][for each part: previous_force_ count, 2 each] (the last two root's only).
std::vector<double> ContactCoupling::save_state() const {
  std::vector<double> s;
  for (const auto* v : {&surface_motion_, &mean_velocity_}) {
    s.push_back(static_cast<double>(v->size()));
    s.insert(s.end(), v->begin(), v->end());
  }
  s.insert(s.end(), fluid_load_, fluid_load_ + 2);
  const auto* b = reinterpret_cast<const double*>(&breakdown_);
  s.insert(s.end(), b, b + 21);
  s.push_back(static_cast<double>(loads_.size()));
  for (const auto& l : loads_) l->save_state(s);
  for (const auto& part : previous_force_) {
    s.push_back(static_cast<double>(part.size()));
    for (const auto& f : part) s.insert(s.end(), {f.x(), f.y()});
  }
  return s;
}

void ContactCoupling::restore_state(const std::vector<double>& state) {
  broadcast_surface();  // the surface of the restored plate (and, overwritten below, its nodal motion)
  const double* p = state.data();
  const double* end = p + state.size();
  auto take_count = [&](std::size_t each) {
    if (p >= end)
      HALFETI_USER_ERROR("restart: the coupling's state is shorter than this scene's coupling needs");
    const auto n = static_cast<std::size_t>(*p++);
    if (static_cast<std::size_t>(end - p) < n * each)
      HALFETI_USER_ERROR("restart: the coupling's state is shorter than this scene's coupling needs");
    return n;
  };
  for (auto* v : {&surface_motion_, &mean_velocity_}) {
    const std::size_t n = take_count(1);
    v->assign(p, p + n);
    p += n;
  }
  if (surface_motion_.size() != 4 * surface_.points.size())
    HALFETI_USER_ERROR("restart: the coupling's state is for a plate surface of "
                       << surface_motion_.size() / 4 << " points, this scene's has "
                       << surface_.points.size());
  if (end - p < 23)
    HALFETI_USER_ERROR("restart: the coupling's state is shorter than this scene's coupling needs");
  std::copy(p, p + 2, fluid_load_);
  p += 2;
  std::copy(p, p + 21, reinterpret_cast<double*>(&breakdown_));
  p += 21;
  const std::size_t loads = take_count(5);
  // One load per surface point: the root's count (a checkpoint holds the root's copy on every rank), or, for a step
  // taken back within a run, this rank's own (none off the root).
  if (loads != surface_.points.size() && loads != loads_.size())
    HALFETI_USER_ERROR("restart: the coupling's state has " << loads << " surface loads, this scene's plate "
                                                            << surface_.points.size());
  if (rank_ == root_) {
    for (auto& l : loads_) p = l->restore_state(p);
  } else {
    p += 5 * loads;
  }
  for (auto& part : previous_force_) {
    const std::size_t n = take_count(2);
    part.resize(rank_ == root_ ? n : 0);
    for (std::size_t k = 0; k < part.size(); ++k) part[k] = Eigen::Vector2d(p[2 * k], p[2 * k + 1]);
    p += 2 * n;
  }
}

}  // namespace halfeti::coupling
