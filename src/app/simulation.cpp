#include "halfeti/app/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "halfeti/app/coupling_section.hpp"
#include "halfeti/app/fluid_section.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/core/version.hpp"
#include "halfeti/excitation/excitation_scene.hpp"
#include "halfeti/io/json.hpp"

namespace halfeti::app {

namespace {

std::string directory_of(const std::string& file) {
  const auto p = file.find_last_of('/');
  return p == std::string::npos ? std::string(".") : file.substr(0, p);
}

double wall_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The largest |a_g| over the run, sampled finely enough for records (0.02 s) and pulses.
double peak_ground_acceleration(const excitation::GroundMotion& m, double end) {
  double peak = 0.0;
  const int n = std::max(2000, static_cast<int>(end / 1e-3));
  for (int i = 0; i <= n; ++i) peak = std::max(peak, std::abs(m.acceleration(end * i / n)));
  return peak;
}

std::string format(const char* fmt, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, a);
  return buf;
}

// The structure solves on its own ranks (world rank 0 among them, and the plate's failures are raised on all of
// them together); its failure must stop every rank together (no rank may be left waiting in a collective call),
// so the structure's ranks run `work`, then rank 0 shares the outcome.
template <class Work>
void on_structure_rank(MPI_Comm comm, bool structure_rank, Work&& work) {
  std::string failure;
  if (structure_rank) {
    try {
      work();
    } catch (const NumericalError& e) {
      failure = e.what();
    }
  }
  int n = static_cast<int>(failure.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, comm);
  if (n == 0) return;
  failure.resize(static_cast<size_t>(n));
  MPI_Bcast(failure.data(), n, MPI_CHAR, 0, comm);
  throw NumericalError(failure);
}

}  // namespace

namespace {
void read_parameters(const scene::Scene& scene, Parts& parts);
}  // namespace

std::vector<ProbeColumn> build_parameters(const scene::Scene& scene, Parts& parts) {
  // Checks across keys name the key path; the scene file is added here.
  try {
    read_parameters(scene, parts);
    return make_probes(scene.root(), parts);
  } catch (const UserError& e) {
    const std::string what = e.what();
    if (what.rfind(scene.file, 0) == 0) throw;
    throw UserError(scene.file + ": " + what);
  }
}

namespace {
void read_parameters(const scene::Scene& scene, Parts& parts) {
  const scene::Node root = scene.root();
  parts.scene_dir = directory_of(scene.file);
  parts.gravity = root.real("gravity");
  parts.motion = excitation::make_ground_motion(root.section("excitation"), parts.scene_dir);
  const double end = root.section("scene").real("end_time");
  if (root.has("fluid")) parts.fluid_params = fluid_params(root, peak_ground_acceleration(*parts.motion, end));
  if (root.has("structure")) parts.structure_setup = structure_setup(root);
  if (!root.list("cables").empty() && !parts.structure_setup)
    HALFETI_USER_ERROR("cables: need a `structure:` to hold (the plate they attach to)");
  if (parts.structure_setup)
    parts.cable_setups =
        cable_setups(root, *parts.structure_setup, parts.fluid_params ? parts.fluid_params->density : 0.0);
  if (parts.fluid_params && parts.structure_setup) {
    parts.coupling_params = coupling_params(root);
    // The water fills its blocks except where the plate stands, as its lattice resolves it: the plate's faces
    // rounded to the nearest lattice lines (ties outward, at least one column). The plate-wall ghosts stand at
    // those lines, so that the first water row is half a spacing from them (docs/coupling.md, section 12).
    const auto& g = parts.structure_setup->params.geometry;
    const auto& fp = *parts.fluid_params;
    const double dx = fp.spacing, x0 = fp.water.front().x0, y0 = fp.water.front().y0;
    const double left = g.base_centre.x() - 0.5 * g.thickness, right = g.base_centre.x() + 0.5 * g.thickness;
    const double lattice_left = x0 + dx * std::ceil((left - x0) / dx - 0.5);
    const double lattice_right = std::max(x0 + dx * std::floor((right - x0) / dx + 0.5), lattice_left + dx);
    if (g.orientation == structure::Orientation::kStanding) {
      const double top = g.base_centre.y() + g.height;
      const double lattice_top = y0 + dx * std::floor((top - y0) / dx + 0.5);
      parts.plate_offsets = {lattice_right - right, left - lattice_left, lattice_top - top};
      parts.fluid_params->exclusions.push_back({lattice_left, g.base_centre.y() - dx, lattice_right, lattice_top});
    } else {
      // Hanging (the standing plate turned about its clamp): the free end is the bottom, rounded down on a tie;
      // the offsets are in the plate's frame, whose "right" face (the outline's first) is the tank's left face.
      const double bottom = g.base_centre.y() - g.height;
      const double lattice_bottom = y0 + dx * std::ceil((bottom - y0) / dx - 0.5);
      parts.plate_offsets = {left - lattice_left, lattice_right - right, bottom - lattice_bottom};
      parts.fluid_params->exclusions.push_back({lattice_left, lattice_bottom, lattice_right, g.base_centre.y() + dx});
    }
  }
}
}  // namespace

namespace {

// The plate and its cables live on the first structure.ranks world ranks (the structure's own communicator; rank 0
// is always one of them and holds what probes and outputs read).
void build_structure(Parts& parts, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const bool member = rank < parts.structure_setup->ranks;
  MPI_Comm sub = MPI_COMM_NULL;
  MPI_Comm_split(comm, member ? 0 : MPI_UNDEFINED, rank, &sub);
  parts.structure_comm = Communicator::adopt(sub);
  parts.structure_rank = member;
  if (!parts.structure_rank) return;
  const StructureSetup& s = *parts.structure_setup;
  parts.plate = std::make_unique<structure::PlateSolver>(parts.structure_comm.get(), s.params, parts.motion.get());
  for (const auto& l : s.point_loads) parts.plate->add_point_load(parts.plate->mesh().node(l.node), l.force);
  for (const auto& c : parts.cable_setups) {
    const int node = parts.plate->mesh().node(c.node);
    parts.cables.push_back(std::make_unique<cable::CableElement>(c.anchor, node,
                                                                 cable::cable_properties(c.set, c.unstretched_length)));
    parts.plate->add_nodal_element(parts.cables.back().get());
  }
  // One evaluation at the initial geometry, so that t = 0 probes read the initial tension.
  for (auto& c : parts.cables) {
    const int node = c->nodes()[0];
    Eigen::VectorXd f;
    Eigen::MatrixXd k;
    c->evaluate({parts.plate->position(node)}, f, k);
  }
}

// The owned particles' global ids as doubles, for the field and checkpoint files.
std::vector<double> owned_gids(const sph::Fluid& f) {
  return std::vector<double>(f.gid().begin(), f.gid().begin() + static_cast<long>(f.owned_count()));
}

// Mass per unit length of a cable set per unit depth that feels the tank's inertial load (as its weight does).
double cable_line_mass(const CableSetup& c) {
  return c.set.count * (c.set.density - c.set.fluid_density) * c.set.area / c.set.depth;
}

}  // namespace

Simulation::Simulation(MPI_Comm comm, scene::Scene scene, RunOptions options)
    : comm_(comm), scene_(std::move(scene)), options_(std::move(options)) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
  const scene::Node root = scene_.root();
  out_dir_ = options_.out_dir.empty() ? "out/" + root.section("scene").string("name") : options_.out_dir;
  // The folders are made on rank 0 and the outcome shared, so a bad --out is one error on every rank.
  int ok = 1;
  std::string why;
  if (rank_ == 0) {
    try {
      for (const char* sub : {"", "/fields", "/checkpoints"}) io::make_directories(out_dir_ + sub);
    } catch (const UserError& e) {
      ok = 0;
      why = e.what();
    }
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, comm_);
  if (!ok) throw UserError(rank_ == 0 ? why : "cannot create the output folder '" + out_dir_ + "'");

  probes_ = build_parameters(scene_, parts_);
  if (parts_.fluid_params) {
    ScopedTimer timer(timers_, "setup");
    parts_.fluid = std::make_unique<sph::Fluid>(comm_, *parts_.fluid_params, parts_.motion.get());
    fluid_fields_ = std::make_unique<io::FieldSeries>(comm_, out_dir_ + "/fields", "fluid");
    checkpoints_ = std::make_unique<io::FieldSeries>(comm_, out_dir_ + "/checkpoints", "fluid_state");
  }
  if (parts_.structure_setup) {
    ScopedTimer timer(timers_, "setup");
    build_structure(parts_, comm_);
    plate_fields_ = std::make_unique<io::FieldSeries>(comm_, out_dir_ + "/fields", "plate");
    plate_checkpoints_ = std::make_unique<io::FieldSeries>(comm_, out_dir_ + "/checkpoints", "plate_state");
  }
  if (parts_.coupling_params) {
    auto& cp = *parts_.coupling_params;
    const auto& fluid = *parts_.fluid;
    cp.density = fluid.params().density;
    cp.sound_speed = fluid.sound_speed();
    cp.spacing = fluid.params().spacing;
    parts_.coupling = std::make_unique<coupling::ContactCoupling>(comm_, parts_.plate.get(), cp);
    if (parts_.coupling_params->plate_wall) {
      parts_.fluid->set_plate_offsets(parts_.plate_offsets);
      parts_.fluid->set_plate_outline(parts_.coupling->plate_outline());  // and its mid-line as the barrier
    } else {
      parts_.fluid->set_barriers(parts_.coupling->outline());
    }
  }
  std::vector<std::string> names;
  for (const auto& p : probes_) names.push_back(p.name);
  probe_out_ = std::make_unique<io::ProbeWriter>(out_dir_ + "/probes.csv", names, rank_ == 0);
  log_ = std::make_unique<io::RunLog>(out_dir_ + "/log.txt", rank_ == 0, options_.echo);
  if (rank_ == 0) {
    std::ofstream resolved(out_dir_ + "/scene.resolved.yaml");
    resolved << "# resolved by halfeti " << kVersion << " from " << scene_.file << "\n" << scene_.resolved_text();
  }
}

Simulation::~Simulation() = default;

void Simulation::announce() {
  log_->line(std::string("halfeti ") + kVersion + ": scene " + scene_.file + " on " + std::to_string(size_) +
             " rank(s); output in " + out_dir_);
  log_->line("excitation: " + parts_.motion->describe());
  if (const auto* f = parts_.fluid.get()) {
    std::ostringstream os;
    os << "fluid: " << f->global_count() << " particles, dx = " << f->params().spacing
       << " m, h = " << f->smoothing_length() << " m, c0 = " << f->sound_speed() << " m/s, scheme "
       << (f->params().scheme == sph::Scheme::kDeltaSph ? "delta-SPH" : "standard SPH");
    log_->line(os.str());
  }
  if (parts_.plate) log_->line(parts_.plate->summary());
  for (const auto& c : parts_.cable_setups) {
    log_->line(cable::describe_per_depth(c.set, c.name));
    std::ostringstream os;
    os << "cable " << c.name << ": anchor [" << c.anchor.x() << ", " << c.anchor.y() << "] to " << c.node
       << ", unstretched length " << c.unstretched_length << " m";
    if (c.initial_stress > 0) os << " (from the initial stress " << c.initial_stress << " Pa)";
    log_->line(os.str());
  }
  if (!parts_.fluid && !parts_.structure_setup) log_->line("no parts: the clock advances by the probe interval");
}

void Simulation::prepare_structure() {
  if (!parts_.structure_setup) return;
  on_structure_rank(comm_, parts_.structure_rank, [&] {
    if (parts_.structure_setup->start_static) {
      // The equilibrium of the tank at rest: every ground motion is zero before t = 0, so solve at t = -1 s.
      const auto report = parts_.plate->solve_static(-1.0, 10);
      log_->line("structure: static equilibrium in " + std::to_string(report.newton_iterations) +
                 " Newton iterations");
    }
    parts_.plate->initialise_acceleration(0.0);
  });
}

void Simulation::load_cables(double t) {
  // The tank frame's inertial load on the cables (their weight stays in the element), at the end of the step.
  const double ag = parts_.motion->acceleration(t);
  for (size_t i = 0; i < parts_.cables.size(); ++i)
    parts_.cables[i]->set_horizontal_load(-cable_line_mass(parts_.cable_setups[i]) * ag);
}

void Simulation::step_structure(double t, double dt) {
  if (!parts_.structure_setup) return;
  ScopedTimer timer(timers_, "structure");
  on_structure_rank(comm_, parts_.structure_rank, [&] {
    load_cables(t + dt);
    parts_.plate->step(t, dt);
  });
}

// One coupled step (DESIGN.md "One time step"): fluid forces and prediction, the interface gathered to the plate's
// rank, the plate and the invaders solved together (eq. 21), the corrections handed back (eqs. 4, 22-24), then
// the fluid finishes its step (health, migration) and the plate's new outline bars pairs across it.
double Simulation::advance_coupled() {
  sph::Fluid& f = *parts_.fluid;
  f.compute_forces();
  const double t = f.time(), dt = f.dt();
  const bool plate_wall = parts_.coupling->parameters().plate_wall;
  if (plate_wall) parts_.coupling->set_fluid_loads(f.plate_wall_loads(), dt);  // the water's wall force on the plate
  f.predict();
  if (parts_.plate) load_cables(t + dt);
  const coupling::InterfaceParticles view{f.owned_count(), f.gid().data(),  f.x().data(),
                                          f.y().data(),    f.vx().data(),   f.vy().data(),
                                          f.mass().data(),
                                          f.renormalised_density_gradient().empty() ? nullptr : f.renormalised_density_gradient().data()};
  {
    ScopedTimer timer(timers_, "coupling");
    parts_.coupling->step(t, dt, view, parts_.corrections);
  }
  const auto& c = parts_.corrections;
  f.apply_corrections(c.touched, c.dx.data(), c.dy.data(), c.dvx.data(), c.dvy.data(), c.drho.data());
  f.finish();
  // The barrier: the plate's mid-line with the plate-wall ghosts (they stand for what the plate hides), its
  // outline in the paper's contact-only form.
  if (plate_wall)
    f.set_plate_outline(parts_.coupling->plate_outline());  // with its mid-line as the barrier
  else
    f.set_barriers(parts_.coupling->outline());
  // Diagnostic: one line per step on stderr (contact and plate-wall forces on the plate's side), for the noise
  // figures of docs/coupling.md.
  static const bool trace = std::getenv("HALFETI_TRACE_COUPLING") != nullptr;
  if (trace) {
    const auto& r = parts_.coupling->last_step();
    double best = 0, bx = 0, by = 0;  // this rank's fastest particle
    for (std::size_t i = 0; i < f.owned_count(); ++i) {
      const double u = std::hypot(f.vx()[i], f.vy()[i]);
      if (u > best) { best = u; bx = f.x()[i]; by = f.y()[i]; }
    }
    std::fprintf(stderr, "coupling_trace_fastest t=%.6f u=%.3g at (%.5f, %.5f)\n", f.time(), best, bx, by);
    if (rank_ == 0)
      std::fprintf(stderr, "coupling_trace t=%.6f inv=%d rel=%d L=%.3g umax=%.3g Fc=(%.4g,%.4g) maxF=%.3g Fw=(%.4g,%.4g)\n", f.time(),
                   r.invaders, r.released, r.layer, r.u_max, r.force_x, r.force_y, r.max_force,
                   parts_.coupling->fluid_load_x(), parts_.coupling->fluid_load_y());
  }
  return dt;
}

double Simulation::advance(double remaining) {
  if (parts_.coupling) return advance_coupled();
  if (parts_.fluid) {
    parts_.fluid->step();
    return parts_.fluid->dt();
  }
  if (parts_.structure_setup) {
    const double dt = std::min(parts_.structure_setup->time_step, remaining);
    step_structure(t_, dt);
    return dt;
  }
  return std::min(scene_.root().section("output").real("probe_interval"), remaining);
}

void Simulation::sample(double t) {
  ScopedTimer timer(timers_, "probes");
  std::vector<double> row;
  row.reserve(probes_.size());
  for (auto& p : probes_) row.push_back(p.sample(t));
  probe_out_->write(t, row);
  if (parts_.fluid) max_density_variation_ = std::max(max_density_variation_, parts_.fluid->max_density_variation());
}

void Simulation::write_plate_fields(double t) {
  if (!plate_fields_) return;
  ScopedTimer timer(timers_, "fields");
  std::vector<double> x, y, ux, uy;
  std::vector<std::int64_t> cells;
  if (const auto* plate = rank_ == 0 ? parts_.plate.get() : nullptr) {  // the state is replicated: write it once
    const auto& mesh = plate->mesh();
    for (int n = 0; n < plate->node_count(); ++n) {
      const Eigen::Vector2d p = plate->position(n), u = plate->displacement(n);
      x.push_back(p.x());
      y.push_back(p.y());
      ux.push_back(u.x());
      uy.push_back(u.y());
    }
    // Drawn as linear quadrilaterals (a Q9 as its four quarters).
    for (const auto& q : mesh.linear_cells()) cells.insert(cells.end(), q.begin(), q.end());
  }
  io::CellBlock block{"Quadrilateral", 4, cells.data(), cells.size() / 4};
  plate_fields_->write(t, x.size(), x.data(), y.data(), {{"ux", ux.data()}, {"uy", uy.data()}}, &block);
}

void Simulation::write_fields(double t) {
  write_plate_fields(t);
  if (!parts_.fluid) return;
  ScopedTimer timer(timers_, "fields");
  const sph::Fluid& f = *parts_.fluid;
  const std::size_t n = f.owned_count();
  const std::vector<double> p = f.pressure();
  const std::vector<double> gid = owned_gids(f);
  fluid_fields_->write(t, n, f.x().data(), f.y().data(),
                       {{"vx", f.vx().data()}, {"vy", f.vy().data()}, {"rho", f.rho().data()},
                        {"p", p.data()}, {"gid", gid.data()}});
}

void Simulation::write_checkpoint(const std::string& label) {
  ScopedTimer timer(timers_, "checkpoint");
  if (parts_.fluid) {
    const sph::Fluid& f = *parts_.fluid;
    const std::size_t n = f.owned_count();
    const std::vector<double> gid = owned_gids(f);
    const std::string path = checkpoints_->write(t_, n, f.x().data(), f.y().data(),
                                                 {{"vx", f.vx().data()}, {"vy", f.vy().data()},
                                                  {"rho", f.rho().data()}, {"gid", gid.data()}});
    log_->line("checkpoint (" + label + "): " + path);
  }
  if (plate_checkpoints_) {
    // The plate's Newmark state on its reference nodes (rank 0 writes it; the others write nothing).
    std::vector<double> x, y, u[2], v[2], a[2];
    if (const auto* plate = rank_ == 0 ? parts_.plate.get() : nullptr) {
      for (int n = 0; n < plate->node_count(); ++n) {
        x.push_back(plate->mesh().nodes[n].x());
        y.push_back(plate->mesh().nodes[n].y());
        for (int c = 0; c < 2; ++c) {
          u[c].push_back(plate->displacement()(2 * n + c));
          v[c].push_back(plate->velocity()(2 * n + c));
          a[c].push_back(plate->acceleration()(2 * n + c));
        }
      }
    }
    const std::string path = plate_checkpoints_->write(
        t_, x.size(), x.data(), y.data(),
        {{"ux", u[0].data()}, {"uy", u[1].data()}, {"vx", v[0].data()}, {"vy", v[1].data()}, {"ax", a[0].data()},
         {"ay", a[1].data()}});
    log_->line("checkpoint (" + label + "): " + path);
  }
}

std::string Simulation::progress_line(double dt, double wall) const {
  const double end = scene_.root().section("scene").real("end_time");
  const double eta = t_ > 0 ? wall * std::max(0.0, end - t_) / t_ : 0.0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "t = %.4f s (%5.1f%%)  step %lld  dt = %.3e s  wall %.1f s  eta %.1f s", t_,
                std::min(100.0, 100.0 * t_ / end), steps_, dt, wall, eta);
  return buf;
}

void Simulation::run() {
  const scene::Node root = scene_.root();
  const double end = root.section("scene").real("end_time");
  const scene::Node out = root.section("output");
  const double probe_dt = out.real("probe_interval");
  const double field_dt = out.real("field_interval");
  const double checkpoint_dt = out.real("checkpoint_interval");
  const double progress_dt = out.real("progress_interval") > 0 ? out.real("progress_interval") : end / 50.0;
  const double start = wall_now();
  announce();
  if (parts_.fluid) initial_mass_ = parts_.fluid->total_mass();

  double next_probe = probe_dt, next_field = field_dt, next_checkpoint = checkpoint_dt, next_progress = progress_dt;
  const double loop_start = wall_now();
  double dt = 0.0;
  try {
    prepare_structure();
    sample(t_);
    if (field_dt > 0) write_fields(t_);
    // A step ends within round-off of a scheduled time counts as reaching it.
    const double tol = 1e-9 * end;
    while (t_ < end - tol) {
      dt = advance(end - t_);
      t_ = parts_.fluid ? parts_.fluid->time() : t_ + dt;
      ++steps_;
      if (t_ >= next_probe - tol) {
        sample(t_);
        while (next_probe <= t_ + tol) next_probe += probe_dt;
      }
      if (field_dt > 0 && t_ >= next_field - tol) {
        write_fields(t_);
        while (next_field <= t_ + tol) next_field += field_dt;
      }
      if (checkpoint_dt > 0 && t_ >= next_checkpoint - tol) {
        write_checkpoint("scheduled");
        while (next_checkpoint <= t_ + tol) next_checkpoint += checkpoint_dt;
      }
      if (t_ >= next_progress - tol) {
        log_->line(progress_line(dt, wall_now() - start));
        while (next_progress <= t_ + tol) next_progress += progress_dt;
      }
    }
  } catch (const NumericalError& e) {
    // Errors are raised on every rank together (the monitors reduce first), so the checkpoint is collective.
    log_->line(std::string("stopped: ") + e.what());
    write_checkpoint("at the failure");
    write_summary("numerical_failure", wall_now() - start, wall_now() - loop_start);
    throw;
  }
  const double loop_wall = wall_now() - loop_start;
  write_checkpoint("final");
  log_->line(progress_line(dt, wall_now() - start));
  write_summary("ok", wall_now() - start, loop_wall);
  log_->line("done: " + std::to_string(steps_) + " steps, " + format("%.2f", wall_now() - start) + " s wall");
}

HealthLog Simulation::health_events() const {
  HealthLog out;
  if (parts_.fluid)
    for (const auto& e : parts_.fluid->health_events()) out.push_back({e.time, e.step, e.kind, e.message, e.fatal});
  return out;
}

void Simulation::write_summary(const std::string& status, double wall, double loop_wall) {
  // Every rank takes part in the collective reads below; rank 0 writes.
  const long long particles = parts_.fluid ? parts_.fluid->global_count() : 0;
  const double mass = parts_.fluid ? parts_.fluid->total_mass() : 0.0;
  PhaseTimers timers = timers_;
  if (parts_.fluid) timers.merge(parts_.fluid->timers());
  if (parts_.coupling) {
    PhaseTimers contact;
    const PhaseTimers coupling_timers = parts_.coupling->timers();  // returned by value: keep it alive
    for (const auto& [phase, seconds] : coupling_timers.all()) contact.add("contact_" + phase, seconds);
    timers.merge(contact);
  }
  if (parts_.plate) {
    PhaseTimers plate;
    for (const auto& [phase, seconds] : parts_.plate->timers().all()) plate.add(phase, seconds);
    timers.merge(plate);
  }
  const long long dofs = parts_.plate ? parts_.plate->dof_count() : 0;  // written by rank 0, a structure rank
  if (rank_ != 0) return;
  const scene::Node root = scene_.root();
  io::Json j = io::Json::object();
  j.set("halfeti", kVersion);
  j.set("scene", root.section("scene").string("name"));
  j.set("scene_file", scene_.file);
  if (root.section("scene").has("description")) j.set("description", root.section("scene").string("description"));
  j.set("ranks", size_);
  j.set("particles", particles);
  j.set("structure_dofs", dofs);
  j.set("cables", static_cast<int>(parts_.cable_setups.size()));
  j.set("steps", steps_);
  j.set("simulated_time", t_);
  j.set("wall_time", wall);
  j.set("loop_wall_time", loop_wall);
  j.set("ns_per_particle_step",
        particles > 0 && steps_ > 0 ? io::Json(1e9 * loop_wall / (static_cast<double>(particles) * steps_)) : io::Json());
  io::Json tj = io::Json::object();
  for (const auto& [phase, seconds] : timers.all()) tj.set(phase, seconds);
  j.set("timers", tj);
  j.set("max_density_variation", parts_.fluid ? io::Json(max_density_variation_) : io::Json());
  // Water thrown over the tank's open top leaves the run (a "spilled" health event); the error counts it in.
  const double spilled = parts_.fluid ? parts_.fluid->spilled_mass() : 0.0;
  j.set("mass_error",
        parts_.fluid && initial_mass_ > 0 ? io::Json((mass + spilled - initial_mass_) / initial_mass_) : io::Json());
  j.set("spilled_mass", parts_.fluid ? io::Json(spilled) : io::Json());
  io::Json events = io::Json::array();
  for (const auto& e : health_events()) {
    io::Json ev = io::Json::object();
    ev.set("time", e.time).set("step", e.step).set("kind", e.kind).set("fatal", e.fatal).set("message", e.message);
    events.push(ev);
  }
  j.set("health_events", events);
  j.set("exit_status", status);
  std::ofstream f(out_dir_ + "/summary.json");
  f << j.dump() << "\n";
}

}  // namespace halfeti::app
