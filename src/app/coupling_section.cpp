#include "halfeti/app/coupling_section.hpp"

#include "halfeti/core/registry.hpp"

namespace halfeti::app {

using scene::Key;
using scene::Schema;

namespace {

const Registry<coupling::ContactConstraint>& constraint_registry() {
  static const auto r = named_values<coupling::ContactConstraint>({
      {"tied", "eq. 19 as a vector: the particle is held normally and tangentially (no slip)",
       coupling::ContactConstraint::kTied},
      {"normal", "frictionless: only the normal overlap is constrained",
       coupling::ContactConstraint::kNormal},
  });
  return r;
}

const Registry<coupling::ContactSolver>& solver_registry() {
  static const auto r = named_values<coupling::ContactSolver>({
      {"condensed", "the invaders' unknowns eliminated exactly onto the plate's system (fastest)",
       coupling::ContactSolver::kCondensed},
      {"saddle_point", "the full saddle-point matrix of eq. 21 (MUMPS, or fieldsplit by PETSc options)",
       coupling::ContactSolver::kSaddlePoint},
  });
  return r;
}

const Registry<coupling::VelocityUpdate>& velocity_registry() {
  static const auto r = named_values<coupling::VelocityUpdate>({
      {"acceleration", "dv = C dt / m: the contact acceleration of eq. 4 held over the step",
       coupling::VelocityUpdate::kAcceleration},
      {"displacement", "dv = dx / dt: the velocity of the relocation itself",
       coupling::VelocityUpdate::kDisplacement},
      {"normal_stop",
       "dv = -min(0, (v - v_surface).n) n: the approach is stopped, the relocation adds no velocity",
       coupling::VelocityUpdate::kNormalStop},
  });
  return r;
}

std::shared_ptr<Schema> ssosd_schema() {
  auto s = std::make_shared<Schema>(
      "Shifting the surface of the structural domain (eqs. 22-23): particles in a layer of thickness "
      "L = layer_ratio * max(u_max, velocity_floor) * dt outside the plate are relocated by an exponential "
      "law.");
  s->add(Key::boolean(
             "enabled",
             "true: the paper's relocation (use it with plate_wall: false); false: invaders are particles "
             "past the surface, pushed exactly onto it (docs/coupling.md, section 15)")
             .def(false));
  s->add(Key::real("layer_ratio", "L / (u_max dt), eq. 23's range").def(10.0).in(5.0, 50.0));
  s->add(Key::real("velocity_floor", "smallest u_max used for L (still water keeps a layer)", "m/s")
             .def(0.5)
             .positive());
  return s;
}

std::shared_ptr<Schema> implicit_schema() {
  auto s = std::make_shared<Schema>(
      "Each step repeats the plate's solve and the water's force computation until the water's load on the "
      "plate "
      "at the step's end agrees with the load the plate was solved under.");
  s->add(Key::integer(
             "max_iterations",
             "evaluations of the water's load per step at most (each costs a step's force computation). An "
             "iteration that reaches it, or stalls (3 evaluations without a new best), ends with its best "
             "iterate (one evaluation more if that was not the last), counted and warned")
             .def(20)
             .in(1, 1000));
  s->add(Key::real("tolerance",
                   "||F_out - F_in|| / ||F_out|| over the plate's surface points at which a step is "
                   "converged")
             .def(1e-3)
             .in(1e-12, 0.5));
  s->add(
      Key::choice("acceleration",
                  "iqn_ils (interface quasi-Newton, least-squares inverse Jacobian: Degroote et al. 2009) or "
                  "relaxation (constant under-relaxation)",
                  {"iqn_ils", "relaxation"})
          .def("iqn_ils"));
  s->add(Key::real("relaxation", "under-relaxation of the first (iqn_ils) or every (relaxation) update")
             .def(1.0)
             .in(1e-3, 1.0));
  return s;
}

}  // namespace

std::shared_ptr<const Schema> coupling_schema() {
  static const std::shared_ptr<const Schema> schema = [] {
    auto s = std::make_shared<Schema>(
        "Contact coupling of water and plate (section 2.3); used when the scene has both fluid and "
        "structure.");
    s->add(Key::choice("constraint", "contact constraint per invader", constraint_registry().names())
               .def("tied"));
    s->add(Key::choice("solver", "how eq. 21 is solved", solver_registry().names()).def("condensed"));
    s->add(Key::choice("velocity_update", "how the contact changes an invader's velocity",
                       velocity_registry().names())
               .def("acceleration"));
    s->add(Key::choice(
               "mass_participation",
               "invader mass participation in eq. 21: kick_drift (m/dt^2, consistent with the fluid's step, "
               "inelastic) or constant_acceleration (the paper's 2m/dt^2)",
               {"kick_drift", "constant_acceleration"})
               .def("kick_drift"));
    s->add(Key::boolean("unilateral", "release invaders the solve would pull towards the plate").def(true));
    s->add(Key::boolean(
               "plate_wall",
               "the plate's faces enter the SPH sums as a moving wall (pressure ghosts, their force on the "
               "plate); false: the paper's form, contact only")
               .def(true));
    s->add(Key::boolean(
               "plate_wall_velocity",
               "the plate-wall ghosts move with the plate's faces in the continuity and viscous terms "
               "(false: at rest, the still-water validation's setting; the paper scenes use true, stable "
               "with the interface added mass)")
               .def(false));
    s->add(Key::boolean(
               "plate_wall_free_surface",
               "a particle beside a face with the water around it gone (Marrone et al. 2010's "
               "free-surface mark) is held at the atmosphere's pressure or above, pushes the face but does "
               "not pull it, and does not expand as it leaves it: water separating from a face as a free "
               "surface; docs/coupling.md section 21 (false: the ghosts continue every particle's pressure, "
               "tension included)")
               .def(true));
    s->add(Key::choice(
               "plate_wall_exchange",
               "the plate-water exchange: extrapolated (explicit, the water's load and the face's velocity "
               "extrapolated to mid-step, second order), lagged (explicit, as computed at the step's start) "
               "or implicit (converged within the step by interface quasi-Newton: the plate under the "
               "water's load at the step's end; needs added_mass: none; docs/coupling.md, section 16)",
               {"extrapolated", "lagged", "implicit"})
               .def("extrapolated"));
    s->add(Key::section("implicit", "the converged exchange's iterations (plate_wall_exchange: implicit)",
                        implicit_schema())
               .always());
    s->add(Key::choice(
               "added_mass",
               "the water's mass the plate's faces carry implicitly in the plate's step against a change of "
               "velocity: acoustic (rho0 c0 dt per face area, the water's impedance), layer "
               "(added_mass_layer spacings of water) or none (the exchange fully explicit)",
               {"acoustic", "layer", "none"})
               .def("acoustic"));
    s->add(Key::real(
               "added_mass_layer",
               "with added_mass: layer, the depth of the water layer, in particle spacings, whose mass the "
               "plate's faces carry; 0: none",
               "dx")
               .def(0.25)
               .in(0.0, 4.0));
    s->add(Key::section("ssosd", "the intermediate layer", ssosd_schema()).always());
    s->add(
        Key::real(
            "inside_tolerance",
            "depth past the surface at which a particle left inside stops the run (a shallower one is the "
            "next step's invader; pushed exactly onto a concave face, a particle can sit nanometres behind "
            "the neighbouring segment)",
            "m")
            .def(1e-6)
            .positive());
    return std::shared_ptr<const Schema>(s);
  }();
  return schema;
}

coupling::CouplingParameters coupling_params(const scene::Node& root) {
  const scene::Node c = root.section("coupling");
  coupling::CouplingParameters p;
  p.constraint = constraint_registry().get(c.string("constraint")).make;
  p.solver = solver_registry().get(c.string("solver")).make;
  p.velocity_update = velocity_registry().get(c.string("velocity_update")).make;
  p.unilateral = c.boolean("unilateral");
  p.plate_wall = c.boolean("plate_wall");
  p.plate_wall_velocity = c.boolean("plate_wall_velocity");
  p.plate_wall_free_surface = c.boolean("plate_wall_free_surface");
  const std::string exchange = c.string("plate_wall_exchange");
  using Exchange = coupling::CouplingParameters::PlateWallExchange;
  p.plate_wall_exchange = exchange == "extrapolated" ? Exchange::kExtrapolated
                          : exchange == "lagged"     ? Exchange::kLagged
                                                     : Exchange::kImplicit;
  const scene::Node implicit = c.section("implicit");
  p.implicit.max_iterations = static_cast<int>(implicit.integer("max_iterations"));
  p.implicit.tolerance = implicit.real("tolerance");
  p.implicit.accelerator.method = implicit.string("acceleration") == "iqn_ils"
                                      ? coupling::InterfaceAcceleration::kIqnIls
                                      : coupling::InterfaceAcceleration::kRelaxation;
  p.implicit.accelerator.relaxation = implicit.real("relaxation");
  p.added_mass_layer = c.real("added_mass_layer");
  const std::string added_mass = c.string("added_mass");
  p.added_mass_kind = added_mass == "acoustic" ? coupling::CouplingParameters::AddedMass::kAcoustic
                      : added_mass == "layer"  ? coupling::CouplingParameters::AddedMass::kLayer
                                               : coupling::CouplingParameters::AddedMass::kNone;
  p.mass_participation = c.string("mass_participation") == "kick_drift" ? 1.0 : 2.0;
  const scene::Node s = c.section("ssosd");
  p.ssosd.enabled = s.boolean("enabled");
  p.ssosd.layer_ratio = s.real("layer_ratio");
  p.ssosd.velocity_floor = s.real("velocity_floor");
  p.inside_tolerance = c.real("inside_tolerance");
  coupling::validate(p);
  return p;
}

}  // namespace halfeti::app
