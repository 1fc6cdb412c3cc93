// The fluid's time step (DESIGN.md "One time step", fluid part) and its distribution over ranks.
#include "halfeti/sph/fluid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "halfeti/core/error.hpp"
#include "halfeti/parallel/decomposition.hpp"
#include "halfeti/parallel/halo_plan.hpp"
#include "halfeti/parallel/migration.hpp"
#include "halfeti/sph/equation_of_state.hpp"
#include "halfeti/sph/wall_friction.hpp"

namespace halfeti::sph {

namespace {
Kernel make_kernel(const FluidParams& p) {
  Kernel k{p.kernel, p.h_over_dx * p.spacing};
  k.gradient_scale = lattice_gradient_moment(k, p.spacing);
  return k;
}

parallel::CellGrid make_grid(const FluidParams& p) {
  // The tank plus a margin of one support radius on every side (wall extensions live there); cell = support.
  const double s = 2.0 * p.h_over_dx * p.spacing;
  return parallel::CellGrid::covering(-s, -s, p.tank_length + s, p.tank_height + s, s);
}

template <class T>
void permute(std::vector<T>& v, const std::vector<int>& perm) {
  std::vector<T> out(perm.size());
  for (std::size_t k = 0; k < perm.size(); ++k) out[k] = v[perm[k]];
  v.swap(out);
}
}  // namespace

double resolved_sound_speed(const FluidParams& p) {
  if (p.sound_speed > 0.0) return p.sound_speed;
  double depth = 0.0;
  for (const auto& b : p.water) depth = std::max(depth, b.y1 + std::abs(b.surface_amplitude) - b.y0);
  HALFETI_CHECK(depth > 0.0, "no water to size the sound speed on");
  // eq. 10 with u_b = sqrt(g d) (long-wave speed), F = g + peak ground acceleration, l = d, aiming at half the
  // allowed density variation so that the hydrostatic state alone stays clear of the 1% monitor.
  return sound_speed_eq10(std::sqrt(p.gravity * depth), p.gravity + std::abs(p.peak_ground_acceleration),
                          depth, 0.5 * p.max_density_variation);
}

Fluid::Fluid(MPI_Comm comm, const FluidParams& params, const excitation::GroundMotion* motion)
    : comm_(comm),
      params_(params),
      motion_(motion),
      kernel_(make_kernel(params)),
      grid_(make_grid(params)),
      search_(grid_, kernel_) {
  if (params.spacing <= 0.0) HALFETI_USER_ERROR("fluid spacing must be positive, got " << params.spacing);
  if (params.water.empty()) HALFETI_USER_ERROR("the fluid needs at least one water block");
  rank_ = comm_.rank();
  size_ = comm_.size();
  dx_ = params.spacing;
  c0_ = resolved_sound_speed(params);
  walls_ = build_walls(params, kernel_.support());
  ghosts_ = build_wall_ghosts(params, kernel_.support());
  search_.set_fixed_points(0, walls_.x, walls_.y);
  search_.set_fixed_points(1, ghosts_.x, ghosts_.y, ghosts_.internal);
  set_barriers({});
  initialise_particles();
}

void Fluid::set_barriers(const std::vector<Barrier>& extra) {
  std::vector<Barrier> all;
  for (const auto& w : params_.internal_walls) all.push_back({w.xa, w.ya, w.xb, w.yb});
  all.insert(all.end(), extra.begin(), extra.end());
  search_.set_barriers(std::move(all));
}

void Fluid::set_plate_outline(const PlateOutline& outline) {
  plate_wall_.set_outline(outline, dx_, kernel_.support());
  set_barriers(plate_wall_.midline());
}

bool Fluid::near_internal_wall(double px, double py) const {
  for (const auto& w : params_.internal_walls) {
    const double tx = w.xb - w.xa, ty = w.yb - w.ya, len2 = tx * tx + ty * ty;
    const double s = len2 > 0.0 ? std::clamp(((px - w.xa) * tx + (py - w.ya) * ty) / len2, 0.0, 1.0) : 0.0;
    if (std::hypot(px - (w.xa + s * tx), py - (w.ya + s * ty)) < 0.5 * dx_) return true;
  }
  return false;
}

bool Fluid::excluded(double px, double py) const {
  for (const auto& e : params_.exclusions)
    if (px > e.x0 && px < e.x1 && py > e.y0 && py < e.y1) return true;
  return false;
}

void Fluid::initialise_particles() {
  // Every rank lays out the same lattice with the same global ids, then keeps the particles of its cells.
  ParticleArrays all;
  std::int64_t next = 0;
  const double g = params_.gravity, rho0 = params_.density;
  for (const auto& b : params_.water) {
    const int nx = static_cast<int>(std::lround((b.x1 - b.x0) / dx_));
    const int ny = static_cast<int>(std::lround((b.y1 + std::abs(b.surface_amplitude) - b.y0) / dx_));
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double px = b.x0 + (i + 0.5) * dx_, py = b.y0 + (j + 0.5) * dx_;
        const double surface = b.y1 + b.surface_amplitude * std::cos(M_PI * px / params_.tank_length);
        if (py >= surface || near_internal_wall(px, py) || excluded(px, py)) continue;
        // Hydrostatic initial state: p = rho0 g (surface - y), density from eq. 9; each particle stands for a dx^2
        // cell of water at its density.
        const double rho = density_from_pressure(rho0 * g * (surface - py), rho0, c0_);
        all.gid.push_back(next++);
        all.x.push_back(px);
        all.y.push_back(py);
        all.vx.push_back(0.0);
        all.vy.push_back(0.0);
        all.rho.push_back(rho);
        all.mass.push_back(rho * dx_ * dx_);
      }
  }
  distribute(std::move(all));
}

void Fluid::set_owner(std::vector<int> owner) {
  owner_ = std::move(owner);
  peers_ = parallel::neighbour_ranks(grid_, owner_, rank_);
}

void Fluid::distribute(ParticleArrays all) {
  const std::size_t n = all.gid.size();
  std::vector<long> counts(grid_.cell_count(), 0);
  for (std::size_t k = 0; k < n; ++k) ++counts[grid_.cell_of(all.x[k], all.y[k])];
  set_owner(parallel::partition_cells_collective(comm_.get(), grid_, counts, params_.first_rank_share));
  gid_.clear();
  for (auto* v : {&x_, &y_, &vx_, &vy_, &rho_, &mass_}) v->clear();
  for (std::size_t k = 0; k < n; ++k) {
    if (owner_[grid_.cell_of(all.x[k], all.y[k])] != rank_) continue;
    gid_.push_back(all.gid[k]);
    x_.push_back(all.x[k]);
    y_.push_back(all.y[k]);
    vx_.push_back(all.vx[k]);
    vy_.push_back(all.vy[k]);
    rho_.push_back(all.rho[k]);
    mass_.push_back(all.mass[k]);
  }
  n_owned_ = n_local_ = static_cast<int>(gid_.size());
  n_global_ = static_cast<long>(n);
  sort_owned_by_cell();
}

void Fluid::sort_owned_by_cell(bool cells_current) {
  if (!cells_current) {
    cell_.resize(n_owned_);
    for (int i = 0; i < n_owned_; ++i) cell_[i] = grid_.cell_of(x_[i], y_[i]);
  }
  const auto before = [&](int a, int b) {
    return cell_[a] != cell_[b] ? cell_[a] < cell_[b] : gid_[a] < gid_[b];
  };
  bool sorted = true;  // most steps: nobody changed cell
  for (int i = 1; i < n_owned_ && sorted; ++i) sorted = !before(i, i - 1);
  if (sorted) return;
  std::vector<int> perm(n_owned_);
  std::iota(perm.begin(), perm.end(), 0);
  std::sort(perm.begin(), perm.end(), before);
  permute(gid_, perm);
  permute(x_, perm);
  permute(y_, perm);
  permute(vx_, perm);
  permute(vy_, perm);
  permute(rho_, perm);
  permute(mass_, perm);
  permute(cell_, perm);
}

void Fluid::exchange_halo() {
  // The plan is rebuilt every step (particles move every step; building it costs less than one field update).
  const parallel::HaloPlan plan(comm_.get(), grid_, owner_, cell_, peers_, &traffic_);
  plan.update({&x_, &y_, &vx_, &vy_, &rho_, &mass_}, n_owned_);
  plan.update(gid_, n_owned_);
  n_local_ = n_owned_ + static_cast<int>(plan.ghost_count());
  halo_plan_ = plan;
}

void Fluid::refresh_pressure_and_volume(int i) {
  p_[i] = pressure_from_density(rho_[i], params_.density, c0_);  // eq. 9
  volume_[i] = mass_[i] / rho_[i];
}

void Fluid::compute_forces() {
  {
    ScopedTimer t(timers_, "halo");
    exchange_halo();
    p_.resize(n_local_);
    volume_.resize(n_local_);
    for (int i = 0; i < n_local_; ++i) refresh_pressure_and_volume(i);
  }
  {
    ScopedTimer t(timers_, "neighbours");
    search_.fluid_pairs(x_.data(), y_.data(), gid_.data(), n_owned_, n_local_, pairs_);
    search_.fixed_pairs(0, x_.data(), y_.data(), n_owned_, wall_pairs_);
    search_.fixed_pairs(1, x_.data(), y_.data(), n_owned_, ghost_pairs_);
  }
  const ParticleView pv{x_.data(),    y_.data(), vx_.data(),     vy_.data(), rho_.data(),
                        mass_.data(), p_.data(), volume_.data(), n_owned_,   n_local_};
  if (params_.free_surface_floor) floor_separated_density(pv);
  if (!plate_wall_.empty()) {  // the plate's surface as a moving wall (plate_wall.hpp)
    {
      ScopedTimer t(timers_, "neighbours");  // its ghost pairs
      plate_wall_.find_pairs(x_.data(), y_.data(), n_owned_, kernel_);
      if (plate_free_surface_) {  // Marrone et al. (2010): the water around the particle is gone
        std::vector<unsigned char> marks;
        marks.reserve(plate_wall_.particles().size());
        for (const int i : plate_wall_.particles()) {
          const bool free =
              moment_min_eigenvalue(pv, pairs_, ghost_pairs_, ghosts_, i) <= kFreeSurfaceEigenvalue;
          marks.push_back(free ? 1 : 0);
          if (free) p_[i] = std::max(p_[i], 0.0);  // at the atmosphere's pressure or above
        }
        plate_wall_.set_free_surface(std::move(marks));
      }
    }
    if (plate_free_surface_) {  // the marked particles' neighbours on other ranks see the floored pressure
      ScopedTimer t(timers_, "halo");
      halo_plan_.update(p_, n_owned_, 1);
    }
  }
  const bool use_delta = params_.scheme == Scheme::kDeltaSph && params_.delta > 0.0;
  // The wall ghosts' pressure is continued along the walls with the owned particles' gradient (eqs. 6, 9), so
  // the standard scheme needs the gradient pass too (without its halo update: only owned particles read it).
  const bool wall_taylor = params_.wall_pressure && params_.wall_ghost_pressure == WallGhostPressure::kTaylor;
  {
    ScopedTimer t(timers_, "density_gradient");
    if (use_delta || wall_taylor)
      density_gradient(pv, pairs_, grad_rho_);
    else
      grad_rho_.clear();
    if (use_delta) halo_plan_.update(grad_rho_, n_owned_, 2);
  }
  {
    ScopedTimer t(timers_, "forces");
    const double ag = motion_ ? motion_->acceleration(time_) : 0.0;
    RateConstants& k = constants_;
    k.rho0 = params_.density;
    k.c0 = c0_;
    k.h = kernel_.h;
    k.dx = dx_;
    k.delta = use_delta ? params_.delta : 0.0;
    k.alpha = params_.alpha;
    k.laminar_nu = params_.laminar_viscosity;
    k.xsph = params_.xsph;
    k.tensile = params_.tensile_correction;
    k.eps_neg = params_.tensile_epsilon_negative;
    k.eps_pos = params_.tensile_epsilon_positive;
    k.w_dx = kernel_.value(dx_);
    k.wall_amplitude = params_.wall_repulsion * c0_ * c0_ / kernel_.h;
    k.wall_range = 0.5 * dx_;
    k.wall_pressure = params_.wall_pressure;
    k.wall_no_slip = params_.wall_no_slip;
    k.body_x = -ag;  // the tank frame: every mass feels -a_g(t)
    k.body_y = -params_.gravity;
    static const std::vector<double> kNoGradient;
    momentum_rates(pv, pairs_, wall_pairs_, walls_, ghost_pairs_, ghosts_,
                   wall_taylor ? grad_rho_ : kNoGradient, k, rates_);
    if (params_.wall_friction ==
        WallFriction::kLogLaw)  // the walls' shear on the first layer (wall_friction.hpp)
      add_wall_friction(x_.data(), y_.data(), vx_.data(), vy_.data(), n_owned_,
                        {params_.tank_length, params_.tank_height, params_.lid}, dx_,
                        params_.kinematic_viscosity, rates_.ax.data(), rates_.ay.data());
    if (!plate_wall_.empty()) {  // the plate's surface as a moving wall (plate_wall.hpp)
      PlateWallConstants pk{dx_, kernel_.h, k.rho0, c0_, k.alpha, k.laminar_nu, k.body_x, k.body_y};
      pk.wall_amplitude = k.wall_amplitude;  // the tank walls' repulsion on the faces too
      pk.wall_range = k.wall_range;
      pk.tank_length = params_.tank_length;
      pk.tank_height = params_.tank_height;
      pk.lid = params_.lid;
      plate_wall_.momentum(vx_.data(), vy_.data(), rho_.data(), p_.data(), mass_.data(), gid_.data(), pk,
                           rates_.ax.data(), rates_.ay.data());
    }
    if (!plate_wall_.empty() || params_.wall_friction != WallFriction::kNone) {
      double a2 = rates_.max_accel * rates_.max_accel;
      for (int i = 0; i < n_owned_; ++i)
        a2 = std::max(a2, rates_.ax[i] * rates_.ax[i] + rates_.ay[i] * rates_.ay[i]);
      rates_.max_accel = std::sqrt(a2);
    }
    // Time step: CFL on sound and viscous signal speed and the force limit (Monaghan 1989 style); max is exact.
    double m[2] = {rates_.max_mu, rates_.max_accel};
    MPI_Allreduce(MPI_IN_PLACE, m, 2, MPI_DOUBLE, MPI_MAX, comm_.get());
    double dt = params_.cfl * kernel_.h / (c0_ + m[0]);
    if (m[1] > 0.0) dt = std::min(dt, params_.cfl * std::sqrt(kernel_.h / m[1]));
    // the laminar term's diffusion limit (Morris et al. 1997): dt <= 0.125 h^2 / nu
    if (params_.laminar_viscosity > 0.0)
      dt = std::min(dt, 0.125 * kernel_.h * kernel_.h / params_.laminar_viscosity);
    dt_ = std::min(dt, params_.max_dt);
  }
  extra_ax_.assign(n_owned_, 0.0);
  extra_ay_.assign(n_owned_, 0.0);
  forces_ready_ = true;
}

void Fluid::floor_separated_density(const ParticleView& pv) {
  // Marrone et al. (2010): a particle whose moment matrix over the water (the inverse of eq. 7's L_i without the
  // walls) has its smallest eigenvalue at most kFreeSurfaceEigenvalue has the water around it gone. Its pressure is
  // the atmosphere's: a density below rho0 (tension carried out of the water, or an expansion by the walls'
  // ghosts) is raised to rho0 (eq. 9: p = 0). Its mass is kept; only its volume m / rho shrinks.
  static const PairList kNoGhosts;
  const double rho0 = params_.density;
  {
    ScopedTimer t(timers_, "density_gradient");
    // marked first, raised after: every particle's measure sees its neighbours' volumes as they came
    floored_.clear();
    for (int i = 0; i < n_owned_; ++i)
      if (rho_[i] < rho0 &&
          moment_min_eigenvalue(pv, pairs_, kNoGhosts, ghosts_, i) <= kFreeSurfaceEigenvalue)
        floored_.push_back(i);
    for (const int i : floored_) {
      rho_[i] = rho0;
      refresh_pressure_and_volume(i);
    }
  }
  // every rank's copies of the raised particles, and their pressure and volume, as the owners'
  ScopedTimer t(timers_, "halo");
  halo_plan_.update(rho_, n_owned_, 1);
  for (int i = n_owned_; i < n_local_; ++i) refresh_pressure_and_volume(i);
}

void Fluid::predict(PlateDensity plate) {
  HALFETI_CHECK(forces_ready_, "Fluid::predict() needs compute_forces() first");
  forces_ready_ = false;
  density_pending_ = plate == PlateDensity::kDeferred;
  {
    ScopedTimer t(timers_, "integrate");
    // Leap-frog in symplectic-Euler form (velocities staggered half a step): kick v += dt (a + Delta C) ...
    for (int i = 0; i < n_owned_; ++i) {
      vx_[i] += dt_ * (rates_.ax[i] + extra_ax_[i]);  // eq. 4 with Delta C
      vy_[i] += dt_ * (rates_.ay[i] + extra_ay_[i]);
    }
  }
  {
    // ... then the density rate and XSPH with the kicked velocities (the same halo plan carries them) ...
    ScopedTimer t(timers_, "halo");
    halo_plan_.update({&vx_, &vy_}, n_owned_);
  }
  {
    ScopedTimer t(timers_, "forces");
    const ParticleView pv{x_.data(),    y_.data(), vx_.data(),     vy_.data(), rho_.data(),
                          mass_.data(), p_.data(), volume_.data(), n_owned_,   n_local_};
    continuity_rates(pv, pairs_, ghost_pairs_, ghosts_, grad_rho_, constants_, rates_);
    if (!plate_wall_.empty() && !density_pending_)
      plate_wall_.continuity(vx_.data(), vy_.data(), rho_.data(), rates_.drho.data());
  }
  {
    // ... and drift r += dt (v + XSPH), rho += dt Drho.
    ScopedTimer t(timers_, "integrate");
    for (int i = 0; i < n_owned_; ++i) {
      x_[i] += dt_ * (vx_[i] + rates_.xsph_x[i]);  // eq. 11
      y_[i] += dt_ * (vy_[i] + rates_.xsph_y[i]);
      if (!density_pending_) rho_[i] += dt_ * rates_.drho[i];  // eq. 3
    }
    for (auto* v : {&x_, &y_, &vx_, &vy_, &rho_, &mass_}) v->resize(n_owned_);
    gid_.resize(n_owned_);
    n_local_ = n_owned_;
    time_ += dt_;
    ++step_;
  }
  predicted_ = true;
}

void Fluid::update_density(const PlateOutline& motion) {
  HALFETI_CHECK(predicted_ && density_pending_,
                "Fluid::update_density() follows predict(PlateDensity::kDeferred)");
  density_pending_ = false;
  ScopedTimer t(timers_, "integrate");
  if (!plate_wall_.empty()) {
    plate_wall_.set_wall_velocity(motion);
    plate_wall_.continuity(vx_.data(), vy_.data(), rho_.data(), rates_.drho.data());
  }
  for (int i = 0; i < n_owned_; ++i) rho_[i] += dt_ * rates_.drho[i];  // eq. 3
}

void Fluid::snapshot(Snapshot& into) const {
#define HALFETI_FLUID_SAVE(m)                       \
  if (into.m)                                       \
    *into.m = m; /* the buffer's capacity reused */ \
  else                                              \
    into.m.emplace(m);
  HALFETI_FLUID_STEP_STATE(HALFETI_FLUID_SAVE)
#undef HALFETI_FLUID_SAVE
}

void Fluid::rollback(const Snapshot& from) {
  HALFETI_CHECK(from.x_.has_value(), "Fluid::rollback() needs a snapshot() first");
#define HALFETI_FLUID_LOAD(m) m = *from.m;
  HALFETI_FLUID_STEP_STATE(HALFETI_FLUID_LOAD)
#undef HALFETI_FLUID_LOAD
}

void Fluid::apply_corrections(const std::vector<int>& touched, const double* dx, const double* dy,
                              const double* dvx, const double* dvy, const double* drho) {
  HALFETI_CHECK(predicted_ && !density_pending_,
                "Fluid::apply_corrections() belongs between predict() (and update_density()) and finish()");
  ScopedTimer t(timers_, "integrate");
  // The tank's walls bound a correction. The contact solve knows only the plate, and at the plate's foot the face's
  // normal tilts towards the floor as the plate bends (and under a hanging gate's free end it points at the floor):
  // a particle pushed out of the plate there would be pushed into the floor. So a correction may not bring a
  // particle closer to a wall than the nearer of its predicted distance and the wall repulsion's range (dx/2), and
  // a particle that ends within one spacing of a wall keeps no velocity correction into it: the rigid wall takes
  // that part of the contact's impulse. (With `velocity_update: acceleration` the particle would otherwise carry
  // the relocation's speed, up to dx/dt, into the floor within a step or two: the Antoci gate at dx 2 mm lost a
  // particle through the floor under its free end at 0.037 s so; holding only those within dx/2 did not help.)
  const double keep = 0.5 * dx_, L = params_.tank_length;
  for (int i : touched) {
    HALFETI_DEBUG_CHECK(i >= 0 && i < n_owned_, "correction for particle " << i << " of " << n_owned_);
    double nx = x_[i] + dx[i], ny = y_[i] + dy[i], ux = dvx[i], uy = dvy[i];
    ny = std::max(ny, std::min(y_[i], keep));
    nx = std::max(nx, std::min(x_[i], keep));
    nx = std::min(nx, L - std::min(L - x_[i], keep));
    // one spacing: the band where the wall's repulsion and the contact meet
    drop_part_into_walls(nx, ny, 2.0 * keep, L, params_.tank_height, params_.lid, ux, uy);
    x_[i] = nx;
    y_[i] = ny;
    vx_[i] += ux;
    vy_[i] += uy;
    rho_[i] += drho[i];  // eq. 24 for the density; the pressure follows from eq. 9
  }
}

void Fluid::finish() {
  HALFETI_CHECK(predicted_ && !density_pending_,
                "Fluid::finish() needs predict() (and update_density()) first");
  predicted_ = false;
  {
    ScopedTimer t(timers_, "health");
    check_health();
  }
  {
    ScopedTimer t(timers_, "rebalance");
    maybe_rebalance();
  }
  {
    ScopedTimer t(timers_, "migrate");
    migrate();
  }
}

void Fluid::advance() {
  predict();
  finish();
}

void Fluid::step() {
  compute_forces();
  advance();
}

std::vector<long> Fluid::global_cell_counts() const {
  std::vector<long> counts(grid_.cell_count(), 0);
  for (int i = 0; i < n_owned_; ++i) ++counts[grid_.cell_of(x_[i], y_[i])];
  MPI_Allreduce(MPI_IN_PLACE, counts.data(), grid_.cell_count(), MPI_LONG, MPI_SUM, comm_.get());
  return counts;
}

void Fluid::maybe_rebalance() {
  if (size_ == 1 || params_.rebalance_interval <= 0 || step_ % params_.rebalance_interval != 0) return;
  const auto counts = global_cell_counts();
  if (parallel::imbalance(owner_, counts, size_, params_.first_rank_share) <= params_.rebalance_threshold)
    return;
  set_owner(parallel::partition_cells_collective(comm_.get(), grid_, counts, params_.first_rank_share));
  far_move_ = true;  // particles now move between ranks that may not be neighbours
}

void Fluid::migrate() {
  // cell_ holds the cells the health scan found (it follows the last move); fewer rows after a spill: only the
  // particles left may migrate.
  cell_.resize(n_owned_);
  bool cells_current = true;
  if (size_ > 1) {
    const auto to = parallel::destinations(cell_, owner_);
    const parallel::ParticleMigration move =
        far_move_ ? parallel::ParticleMigration(comm_.get(), to, &traffic_)
                  : parallel::ParticleMigration(comm_.get(), to, peers_, &traffic_);
    far_move_ = false;
    if (move.anything_moves()) {
      for (auto* v : {&x_, &y_, &vx_, &vy_, &rho_, &mass_}) move.apply(*v);
      move.apply(gid_);
      n_owned_ = n_local_ = static_cast<int>(move.new_count());
      cells_current = false;  // the arrivals' cells are not in cell_
    }
  }
  sort_owned_by_cell(cells_current);
}

Fluid::State Fluid::state() const {
  State s;
  const auto owned = [&](const auto& v) { return std::vector(v.begin(), v.begin() + n_owned_); };
  s.particles = {owned(gid_), owned(x_), owned(y_), owned(vx_), owned(vy_), owned(rho_), owned(mass_)};
  s.time = time_;
  s.spilled_mass = spilled_mass_;
  s.step = step_;
  s.events = events_;
  s.active_warnings = active_warnings_;
  return s;
}

void Fluid::restore(State all) {
  const ParticleArrays& p = all.particles;
  const std::size_t n = p.gid.size();
  HALFETI_CHECK(p.x.size() == n && p.y.size() == n && p.vx.size() == n && p.vy.size() == n &&
                    p.rho.size() == n && p.mass.size() == n,
                "Fluid::restore: particle arrays of unequal length");
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(p.x[k]) || !std::isfinite(p.y[k]))
      HALFETI_USER_ERROR("restart: particle " << p.gid[k] << " has a position that is not finite");
  // As at the start: the cells partitioned afresh over this run's ranks (results do not depend on it).
  distribute(std::move(all.particles));
  time_ = all.time;
  step_ = all.step;
  spilled_mass_ = all.spilled_mass;
  events_ = std::move(all.events);
  active_warnings_ = std::move(all.active_warnings);
  forces_ready_ = predicted_ = density_pending_ = false;
}

std::vector<double> Fluid::pressure() const {
  std::vector<double> p(n_owned_);
  for (int i = 0; i < n_owned_; ++i) p[i] = pressure_from_density(rho_[i], params_.density, c0_);
  return p;
}

}  // namespace halfeti::sph
