#include "halfeti/app/fluid_section.hpp"

#include "halfeti/core/error.hpp"
#include "halfeti/core/registry.hpp"

namespace halfeti::app {

using scene::Key;
using scene::Schema;

namespace {

// Named choices of the fluid: each resolves through its own registry (the entry's "factory" is the value).
const Registry<sph::KernelKind>& kernel_registry() {
  static const auto r = named_values<sph::KernelKind>({
      {"cubic_spline", "Monaghan's cubic spline, support 2h (the paper)", sph::KernelKind::kCubicSpline},
      {"wendland_c2", "Wendland C2, support 2h", sph::KernelKind::kWendlandC2},
  });
  return r;
}

const Registry<sph::Scheme>& scheme_registry() {
  static const auto r = named_values<sph::Scheme>({
      {"delta", "delta-SPH: density diffusion on (eqs. 3, 5-7)", sph::Scheme::kDeltaSph},
      {"standard", "standard SPH: no density diffusion (the paper's Figs. 13-15 comparison)",
       sph::Scheme::kStandard},
  });
  return r;
}

const Registry<sph::WallFriction>& wall_friction_registry() {
  static const auto r = named_values<sph::WallFriction>({
      {"none", "free slip: the walls push, they do not drag (the paper's walls)", sph::WallFriction::kNone},
      {"log_law", "smooth-wall law of the wall on the first particle layer (docs/sph.md, \"Wall friction\")",
       sph::WallFriction::kLogLaw},
  });
  return r;
}

const Registry<sph::WallGhostPressure>& wall_ghost_pressure_registry() {
  static const auto r = named_values<sph::WallGhostPressure>({
      {"taylor",
       "the wall condition across the wall, the particle's own pressure gradient along it (docs/sph.md)",
       sph::WallGhostPressure::kTaylor},
      {"body_force", "p_i + rho_i (g - a_wall).r (Adami et al. 2012): holds up films on vertical walls",
       sph::WallGhostPressure::kBodyForce},
  });
  return r;
}

std::shared_ptr<Schema> water_block_schema() {
  auto s = std::make_shared<Schema>("A rectangle of still water, filled on a square lattice of spacing dx.");
  s->add(Key::point("from", "lower left corner", "m").required());
  s->add(Key::point("to", "upper right corner; its y is the still free surface", "m").required());
  s->add(Key::real("surface_amplitude",
                   "first-mode surface A cos(pi x / L) added to the top (sloshing tests)", "m")
             .def(0.0));
  return s;
}

std::shared_ptr<Schema> wall_schema() {
  auto s = std::make_shared<Schema>(
      "A rigid internal wall: a line of repulsive particles; no pair interacts across it.");
  s->add(Key::point("from", "one end", "m").required());
  s->add(Key::point("to", "the other end", "m").required());
  return s;
}

}  // namespace

std::shared_ptr<const Schema> fluid_schema() {
  static const std::shared_ptr<const Schema> schema = [] {
    auto s = std::make_shared<Schema>(
        "Weakly compressible delta-SPH water (section 2.1 of the paper). Needs `tank:`.");
    s->add(Key::real("spacing", "initial particle spacing dx", "m").required().positive().at_most(1.0));
    s->add(Key::list("water", "rectangles of still water", water_block_schema()).min_items(1).required());
    s->add(Key::list("walls", "rigid internal walls", wall_schema()));
    s->add(Key::boolean("lid", "close the tank with a wall at its top").def(false));
    s->add(Key::real("density", "rest density rho0 (a liquid: at most 2e4)", "kg/m^3")
               .def(1000.0)
               .positive()
               .at_most(2e4));
    s->add(Key::real("sound_speed",
                     "c0 of eq. 9; 0 chooses it by eq. 10 from the depth and the peak excitation "
                     "(at most 1e4: water's own is 1480)",
                     "m/s")
               .def(0.0)
               .non_negative()
               .at_most(1e4));
    s->add(Key::real("max_density_variation", "allowed |rho - rho0| / rho0 (eq. 10 and the health monitor)")
               .def(0.01)
               .positive()
               .at_most(0.1));
    s->add(Key::boolean("density_variation_fatal", "stop the run when the density variation passes its limit")
               .def(false));
    s->add(Key::choice("kernel", "smoothing kernel", kernel_registry().names()).def("cubic_spline"));
    s->add(Key::real("smoothing_ratio", "h / dx (support 2h)").def(1.33).in(1.0, 2.0));
    s->add(Key::choice("scheme", "delta-SPH or standard SPH", scheme_registry().names()).def("delta"));
    s->add(Key::real("delta", "density diffusion coefficient delta (eq. 3)").def(0.1).in(0.0, 1.0));
    s->add(Key::real("alpha", "artificial viscosity coefficient alpha (eqs. 4, 8)").def(0.02).in(0.0, 1.0));
    s->add(Key::real("laminar_viscosity",
                     "kinematic viscosity nu of a laminar viscous term (Morris et al. 1997, beside eq. 8's "
                     "artificial one), the same at every dx; it dissipates too little beside a free surface "
                     "(docs/sph.md); 0 = off",
                     "m^2/s")
               .def(0.0)
               .at_least(0.0)
               .at_most(1.0));
    s->add(Key::real("xsph", "XSPH coefficient (eq. 11); 0 turns it off").def(0.05).in(0.0, 1.0));
    s->add(Key::boolean("tensile_correction", "Monaghan's (2000) tensile-instability correction").def(true));
    s->add(Key::boolean(
               "free_surface_floor",
               "raise every particle the water has left (its moment matrix's smallest eigenvalue over the "
               "water at most 0.2, Marrone et al. 2010) to rho0 when below it: the atmosphere's pressure")
               .def(false));
    s->add(Key::real("wall_repulsion", "Monaghan & Kos wall strength A = this * c0^2 / h")
               .def(0.01)
               .positive()
               .at_most(10.0));
    s->add(Key::boolean("wall_pressure", "add the kernel-truncated pressure of the wall (see docs/sph.md)")
               .def(true));
    s->add(Key::choice("wall_ghost_pressure", "how the wall ghosts' pressure is continued from the fluid",
                       wall_ghost_pressure_registry().names())
               .def("taylor"));
    s->add(Key::choice("wall_friction", "shear of the tank's walls on the water beside them",
                       wall_friction_registry().names())
               .def("none"));
    s->add(Key::real("kinematic_viscosity", "nu of the law of the wall (wall_friction: log_law)", "m^2/s")
               .def(1.0e-6)
               .positive()
               .at_most(1.0));
    s->add(Key::real("cfl", "Courant number of the time step (above 1: past the usual limit, warned)")
               .def(0.2)
               .positive()
               .at_most(3.0));
    s->add(Key::real("max_dt", "largest time step", "s").def(1e-3).positive());
    s->add(Key::real("min_dt", "time-step floor; the run stops below it", "s").def(1e-9).positive());
    s->add(Key::real("rebalance_threshold", "rebalance when max / target particles per rank exceeds this")
               .def(1.15)
               .at_least(1.0));
    s->add(Key::integer("rebalance_interval", "steps between balance checks").def(50).at_least(1));
    s->add(Key::real("first_rank_share",
                     "rank 0's share of the particles relative to each other rank's (rank 0 also solves the "
                     "structure while the others wait); 1 = equal")
               .def(1.0)
               .positive()
               .at_most(1.0));
    return std::shared_ptr<const Schema>(s);
  }();
  return schema;
}

sph::FluidParams fluid_params(const scene::Node& root, double peak_ground_acceleration) {
  const scene::Node f = root.section("fluid");
  if (!root.has("tank")) HALFETI_USER_ERROR("fluid: needs a `tank:` section (length and height of the tank)");
  const scene::Node tank = root.section("tank");
  sph::FluidParams p;
  p.tank_length = tank.real("length");
  p.tank_height = tank.real("height");
  p.lid = f.boolean("lid");
  p.spacing = f.real("spacing");
  const double min_side = std::min(p.tank_length, p.tank_height);
  if (p.spacing > 0.25 * min_side)
    HALFETI_USER_ERROR(f.key_path("spacing")
                       << ": dx = " << p.spacing << " m leaves fewer than 4 particles across the " << min_side
                       << " m tank; expected dx <= " << 0.25 * min_side);
  for (const auto& w : f.list("water")) {
    const auto a = w.point("from"), b = w.point("to");
    sph::WaterBlock block{a[0], a[1], b[0], b[1], w.real("surface_amplitude")};
    if (!(b[0] > a[0] && b[1] > a[1]))
      HALFETI_USER_ERROR(w.path() << ": 'to' must lie above and right of 'from', found from [" << a[0] << ", "
                                  << a[1] << "] to [" << b[0] << ", " << b[1] << "]");
    if (a[0] < 0 || a[1] < 0 || b[0] > p.tank_length ||
        b[1] + std::abs(block.surface_amplitude) > p.tank_height)
      HALFETI_USER_ERROR(w.path() << ": water from [" << a[0] << ", " << a[1] << "] to [" << b[0] << ", "
                                  << b[1] << "] does not fit in the tank [0, " << p.tank_length << "] x [0, "
                                  << p.tank_height << "]");
    // The lattice shows the surface to within a spacing: a smaller wave would live in the initial pressure only.
    if (block.surface_amplitude != 0.0 && std::abs(block.surface_amplitude) < 0.5 * p.spacing)
      HALFETI_USER_ERROR(w.key_path("surface_amplitude")
                         << ": " << block.surface_amplitude << " m is below half the spacing ("
                         << 0.5 * p.spacing
                         << " m), which the particle lattice cannot show; use 0 or "
                            "at least dx / 2");
    // Two blocks over the same place would put two particles there.
    for (std::size_t k = 0; k < p.water.size(); ++k) {
      const auto& o = p.water[k];
      const double top = block.y1 + std::abs(block.surface_amplitude),
                   other_top = o.y1 + std::abs(o.surface_amplitude);
      if (std::min(block.x1, o.x1) > std::max(block.x0, o.x0) &&
          std::min(top, other_top) > std::max(block.y0, o.y0))
        HALFETI_USER_ERROR(w.path() << ": water from [" << a[0] << ", " << a[1] << "] to [" << b[0] << ", "
                                    << b[1] << "] overlaps fluid.water[" << k << "]");
    }
    p.water.push_back(block);
  }
  for (const auto& w : f.list("walls")) {
    const auto a = w.point("from"), b = w.point("to");
    for (const auto& q : {a, b})
      if (q[0] < 0 || q[0] > p.tank_length || q[1] < 0 || q[1] > p.tank_height)
        HALFETI_USER_ERROR(w.path() << ": wall end [" << q[0] << ", " << q[1] << "] lies outside the tank");
    if (a == b) HALFETI_USER_ERROR(w.path() << ": the wall's two ends coincide");
    p.internal_walls.push_back({a[0], a[1], b[0], b[1]});
  }
  p.h_over_dx = f.real("smoothing_ratio");
  p.kernel = kernel_registry().get(f.string("kernel")).make;
  p.density = f.real("density");
  p.sound_speed = f.real("sound_speed");
  p.max_density_variation = f.real("max_density_variation");
  p.density_variation_fatal = f.boolean("density_variation_fatal");
  p.gravity = root.real("gravity");
  p.peak_ground_acceleration = peak_ground_acceleration;
  p.scheme = scheme_registry().get(f.string("scheme")).make;
  p.delta = f.real("delta");
  p.alpha = f.real("alpha");
  p.laminar_viscosity = f.real("laminar_viscosity");
  p.xsph = f.real("xsph");
  p.tensile_correction = f.boolean("tensile_correction");
  p.free_surface_floor = f.boolean("free_surface_floor");
  p.wall_repulsion = f.real("wall_repulsion");
  p.wall_pressure = f.boolean("wall_pressure");
  p.wall_ghost_pressure = wall_ghost_pressure_registry().get(f.string("wall_ghost_pressure")).make;
  p.wall_friction = wall_friction_registry().get(f.string("wall_friction")).make;
  p.kinematic_viscosity = f.real("kinematic_viscosity");
  p.cfl = f.real("cfl");
  p.max_dt = f.real("max_dt");
  p.min_dt = f.real("min_dt");
  if (p.min_dt >= p.max_dt)
    HALFETI_USER_ERROR(f.key_path("min_dt")
                       << ": the floor " << p.min_dt << " s must be below max_dt " << p.max_dt << " s");
  p.rebalance_threshold = f.real("rebalance_threshold");
  p.rebalance_interval = static_cast<int>(f.integer("rebalance_interval"));
  p.first_rank_share = f.real("first_rank_share");
  return p;
}

}  // namespace halfeti::app
