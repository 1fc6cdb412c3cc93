#include "halfeti/app/structure_section.hpp"

#include <mpi.h>

#include <set>

#include "halfeti/cable/catenary.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/core/registry.hpp"
#include "halfeti/structure/plate_mesh.hpp"

namespace halfeti::app {

using scene::Key;
using scene::Schema;

namespace {

const Registry<structure::MaterialModel>& material_registry() {
  static const auto r = named_values<structure::MaterialModel>({
      {"neo_hookean", "compressible Neo-Hookean (large strains)", structure::MaterialModel::kNeoHookean},
      {"saint_venant_kirchhoff", "St. Venant-Kirchhoff (moderate strains)",
       structure::MaterialModel::kStVenantKirchhoff},
  });
  return r;
}

const Registry<structure::PlaneHypothesis>& hypothesis_registry() {
  static const auto r = named_values<structure::PlaneHypothesis>({
      {"plane_strain", "the plate spans the tank's width (default)",
       structure::PlaneHypothesis::kPlaneStrain},
      {"plane_stress", "a thin free-edged strip", structure::PlaneHypothesis::kPlaneStress},
  });
  return r;
}

const Registry<structure::ElementType>& element_registry() {
  static const auto r = named_values<structure::ElementType>({
      {"q9", "nine-node quadrilateral, selective reduced integration (default)", structure::ElementType::kQ9},
      {"q4_eas",
       "four-node quadrilateral with 4 enhanced strain modes (Simo & Armero 1992), condensed per element; "
       "needs an even cells_across",
       structure::ElementType::kQ4Eas},
  });
  return r;
}

const Registry<structure::Orientation>& orientation_registry() {
  static const auto r = named_values<structure::Orientation>({
      {"standing", "clamped at its base, free end up (default; the paper's plate)",
       structure::Orientation::kStanding},
      {"hanging",
       "clamped at its top, free end down (a gate): the standing plate turned by 180 degrees about `base`, "
       "the "
       "clamp's centre; free-end nodes bottom_left, bottom_centre, bottom_right, clamp nodes clamp_left, "
       "clamp_centre, clamp_right",
       structure::Orientation::kHanging},
  });
  return r;
}

// The plate's named nodes, for error messages.
std::string node_names(const structure::PlateMesh& mesh) {
  std::string out;
  for (const auto& [name, id] : mesh.named_nodes) out += (out.empty() ? "" : ", ") + name;
  return out;
}

std::shared_ptr<Schema> load_schema() {
  auto s = std::make_shared<Schema>("A dead point load on a named node (tests and static cases).");
  s->add(Key::string("node",
                     "named node: top_left, top_centre, top_right, base_left, ... (hanging: bottom_centre, "
                     "clamp_left, ...)")
             .required());
  s->add(Key::point("force", "force per unit depth", "N/m").required());
  return s;
}

}  // namespace

std::shared_ptr<const Schema> structure_schema() {
  static const std::shared_ptr<const Schema> schema = [] {
    auto s = std::make_shared<Schema>(
        "The rubber plate: a 2D large-deformation solid of Q9 (or Q4 enhanced-strain) elements, clamped at "
        "its "
        "base (or, hanging, at its top), per unit depth.");
    s->add(Key::point("base", "centre of the clamped base (hanging: of the clamped top)", "m").required());
    s->add(
        Key::choice("orientation", "which end is clamped", orientation_registry().names()).def("standing"));
    s->add(Key::real("height", "plate height (length from the clamp to the free end)", "m")
               .def(0.08)
               .positive()
               .at_most(100.0));
    s->add(Key::real("thickness", "plate thickness", "m").def(0.003).positive().at_most(100.0));
    s->add(Key::integer("cells_across", "cells (elements) through the thickness").def(2).in(1, 64));
    s->add(Key::integer("cells_along", "cells (elements) along the height (2 x 60 is the paper's 120)")
               .def(60)
               .in(1, 4096));
    s->add(Key::choice("element", "finite element of the plate", element_registry().names()).def("q9"));
    s->add(Key::choice("material", "hyperelastic law", material_registry().names()).def("neo_hookean"));
    s->add(Key::real("youngs_modulus", "E (at most 1e12 Pa, stiffer than steel)", "Pa")
               .def(10e6)
               .positive()
               .at_most(1e12));
    s->add(Key::real("poisson_ratio",
                     "nu (rubber 0.45-0.49; at most 0.499: the bulk modulus grows as 1 / (1 - 2 nu))")
               .def(0.45)
               .above(-1.0)
               .at_most(0.499));
    s->add(Key::real("density", "rubber density (not stated by the paper)", "kg/m^3")
               .def(1150.0)
               .positive()
               .at_most(1e5));
    s->add(Key::choice("hypothesis", "out-of-plane hypothesis", hypothesis_registry().names())
               .def("plane_strain"));
    s->add(
        Key::real("newmark_beta", "Newmark beta (1/4: trapezoidal rule)").def(0.25).above(0.0).at_most(0.5));
    s->add(Key::real("newmark_gamma", "Newmark gamma (1/2: no numerical damping)").def(0.5).in(0.5, 1.0));
    s->add(Key::integer("newton_max_iterations", "Newton iterations per step before the run stops")
               .def(25)
               .in(1, 1000));
    s->add(Key::real("newton_rtol", "Newton: residual over the step's force scale that counts as converged")
               .def(1e-6)
               .above(0.0)
               .below(1.0));
    s->add(Key::real("time_step", "step of a scene without water (with water the fluid sets it)", "s")
               .positive());
    s->add(Key::boolean(
               "start_static",
               "solve the static equilibrium (gravity, cables, loads) before t = 0; the water's load is not "
               "in it: it meets the plate at t = 0")
               .def(false));
    s->add(Key::integer(
               "ranks",
               "MPI ranks of the structure's own communicator (the first N ranks of the run; METIS splits "
               "the mesh, MUMPS solves); at most the run's rank count, and 1 in scenes with water")
               .def(1)
               .in(1, 65536));
    s->add(Key::list("loads", "dead point loads", load_schema()));
    return std::shared_ptr<const Schema>(s);
  }();
  return schema;
}

std::shared_ptr<const Schema> cable_schema() {
  static const std::shared_ptr<const Schema> schema = [] {
    auto s = std::make_shared<Schema>(
        "A set of real cables side by side across the tank's width, from a wall anchor to a named plate "
        "node, "
        "modelled per unit depth as one two-node catenary element (section 2.2). Give exactly one of "
        "unstretched_length and initial_stress. The water does not act on cables (as in the paper).");
    s->add(Key::string("name", "name used by probes").required());
    s->add(Key::point("anchor", "fixed end on a tank wall", "m").required());
    s->add(
        Key::string("node",
                    "plate node it holds: top_left, top_centre, top_right, ... (hanging: bottom_left, ...)")
            .required());
    s->add(Key::integer("count", "real cables across the tank's width").def(1).in(1, 100000));
    s->add(Key::real("area", "cross-section of one cable (at most 0.01: a cable 11 cm across)", "m^2")
               .required()
               .positive()
               .at_most(1e-2));
    s->add(Key::real("modulus", "Young's modulus of the cable (at most 1e12)", "Pa")
               .required()
               .positive()
               .at_most(1e12));
    s->add(Key::real("density", "cable density", "kg/m^3").required().positive().at_most(1e5));
    s->add(Key::boolean("submerged", "buoyant in the water (weight uses density - water density)").def(true));
    s->add(Key::real("unstretched_length", "unstretched length L0", "m").positive().at_most(1e3));
    s->add(
        Key::real("initial_stress", "tension stress at the plate end in the initial state", "Pa").positive());
    return std::shared_ptr<const Schema>(s);
  }();
  return schema;
}

StructureSetup structure_setup(const scene::Node& root) {
  const scene::Node s = root.section("structure");
  StructureSetup out;
  auto& p = out.params;
  const auto base = s.point("base");
  p.geometry.base_centre = {base[0], base[1]};
  p.geometry.height = s.real("height");
  p.geometry.thickness = s.real("thickness");
  p.geometry.cells_across = static_cast<int>(s.integer("cells_across"));
  p.geometry.cells_along = static_cast<int>(s.integer("cells_along"));
  p.geometry.element = element_registry().get(s.string("element")).make;
  p.geometry.orientation = orientation_registry().get(s.string("orientation")).make;
  p.material.model = material_registry().get(s.string("material")).make;
  p.material.youngs_modulus = s.real("youngs_modulus");
  p.material.poisson_ratio = s.real("poisson_ratio");
  p.material.density = s.real("density");
  p.material.hypothesis = hypothesis_registry().get(s.string("hypothesis")).make;
  p.newmark.beta = s.real("newmark_beta");
  p.newmark.gamma = s.real("newmark_gamma");
  p.newton.max_iterations = static_cast<int>(s.integer("newton_max_iterations"));
  p.newton.residual_rtol = s.real("newton_rtol");
  p.gravity = {0.0, -root.real("gravity")};
  if (root.has("tank")) {
    const scene::Node tank = root.section("tank");
    const double half = 0.5 * p.geometry.thickness;
    const bool hanging = p.geometry.orientation == structure::Orientation::kHanging;
    const double lowest = hanging ? base[1] - p.geometry.height : base[1];
    if (base[0] - half < 0 || base[0] + half > tank.real("length") || lowest < 0 ||
        lowest + p.geometry.height > tank.real("height"))
      HALFETI_USER_ERROR(s.path() << ": the plate (base [" << base[0] << ", " << base[1] << "], "
                                  << p.geometry.thickness << " x " << p.geometry.height
                                  << " m) does not fit in the tank");
  }
  if (p.geometry.element == structure::ElementType::kQ4Eas && p.geometry.cells_across % 2 != 0)
    HALFETI_USER_ERROR(s.key_path("cells_across")
                       << ": " << p.geometry.cells_across
                       << " must be even with element: q4_eas (the top and base centres "
                       << "must be nodes)");
  if (s.has("time_step")) out.time_step = s.real("time_step");
  if (!root.has("fluid") && !s.has("time_step"))
    HALFETI_USER_ERROR(s.key_path("time_step")
                       << ": required when the scene has no `fluid:` (the water sets the "
                       << "step otherwise)");
  out.start_static = s.boolean("start_static");
  out.ranks = static_cast<int>(s.integer("ranks"));
  if (out.ranks > 1 && root.has("fluid"))
    HALFETI_USER_ERROR(s.key_path("ranks")
                       << ": " << out.ranks << ": scenes with water (coupled) need "
                       << "structure.ranks: 1 (the contact coupling solves the plate on one rank)");
  int world = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  if (out.ranks > world)
    HALFETI_USER_ERROR(s.key_path("ranks")
                       << ": " << out.ranks << " ranks for the structure, but the run has " << world
                       << " MPI rank(s) (structure.ranks must lie in [1, " << world << "])");
  const structure::PlateMesh names_only = structure::make_plate_mesh(p.geometry);
  for (const auto& l : s.list("loads")) {
    const std::string node = l.string("node");
    if (!names_only.named_nodes.count(node))
      HALFETI_USER_ERROR(l.key_path("node") << ": no node named '" << node << "' (the plate has "
                                            << node_names(names_only) << ")");
    const auto f = l.point("force");
    out.point_loads.push_back({node, {f[0], f[1]}});
  }
  structure::validate(p);
  return out;
}

std::vector<CableSetup> cable_setups(const scene::Node& root, const StructureSetup& plate,
                                     double fluid_density) {
  std::vector<CableSetup> out;
  const auto cables = root.list("cables");
  if (cables.empty()) return out;
  if (!root.has("structure"))
    HALFETI_USER_ERROR("cables: need a `structure:` to hold (the plate they attach to)");
  const structure::PlateMesh mesh = structure::make_plate_mesh(plate.params.geometry);
  const double width = root.has("tank") ? root.section("tank").real("width") : 1.0;
  std::set<std::string> names;
  for (const auto& c : cables) {
    CableSetup cs;
    cs.name = c.string("name");
    if (!names.insert(cs.name).second)
      HALFETI_USER_ERROR(c.key_path("name") << ": cable name '" << cs.name << "' used twice");
    const auto a = c.point("anchor");
    cs.anchor = {a[0], a[1]};
    // A cable is anchored on the tank: on its floor or a side wall (within 1 % of the tank's size), not in mid-water
    // or outside it.
    if (root.has("tank")) {
      const double L = root.section("tank").real("length"), H = root.section("tank").real("height");
      const double tol = 0.01 * std::max(L, H);
      const bool inside = a[0] >= -tol && a[0] <= L + tol && a[1] >= -tol && a[1] <= H + tol;
      const bool on_wall = std::abs(a[0]) <= tol || std::abs(a[0] - L) <= tol || std::abs(a[1]) <= tol;
      if (!inside || !on_wall)
        HALFETI_USER_ERROR(c.key_path("anchor")
                           << ": [" << a[0] << ", " << a[1]
                           << "] m is not on the tank's floor or a "
                              "side wall (the tank is "
                           << L << " x " << H << " m; within " << tol << " m of a wall)");
    }
    cs.node = c.string("node");
    const auto it = mesh.named_nodes.find(cs.node);
    if (it == mesh.named_nodes.end())
      HALFETI_USER_ERROR(c.key_path("node")
                         << ": no plate node named '" << cs.node << "' (" << node_names(mesh) << ")");
    cs.set.count = static_cast<int>(c.integer("count"));
    cs.set.area = c.real("area");
    cs.set.modulus = c.real("modulus");
    cs.set.density = c.real("density");
    cs.set.depth = width;
    cs.set.fluid_density = c.boolean("submerged") ? fluid_density : 0.0;
    cs.set.gravity = root.real("gravity");
    const bool has_length = c.has("unstretched_length"), has_stress = c.has("initial_stress");
    if (has_length == has_stress)
      HALFETI_USER_ERROR(c.path() << ": give exactly one of unstretched_length and initial_stress");
    const Eigen::Vector2d node_position = mesh.nodes[it->second];
    if ((node_position - cs.anchor).norm() < 1e-9)
      HALFETI_USER_ERROR(c.key_path("anchor")
                         << ": the anchor coincides with plate node '" << cs.node << "'");
    if (has_length) {
      cs.unstretched_length = c.real("unstretched_length");
    } else {
      cs.initial_stress = c.real("initial_stress");
      if (cs.initial_stress >= cs.set.modulus)
        HALFETI_USER_ERROR(c.key_path("initial_stress")
                           << ": " << cs.initial_stress << " Pa is at or past the cable's "
                           << "modulus " << cs.set.modulus << " Pa (a strain of 100 %)");
      const auto per_depth = cable::per_unit_depth(cs.set);
      try {
        cs.unstretched_length = cable::unstretched_length_for_end_tension(
            cs.anchor, node_position, per_depth.axial_stiffness, per_depth.weight_per_length,
            cs.initial_stress * per_depth.area);
      } catch (const NumericalError& e) {  // the scene asks for what no cable gives: bad input
        HALFETI_USER_ERROR(c.key_path("initial_stress") << ": no unstretched length gives "
                                                        << cs.initial_stress << " Pa (" << e.what() << ")");
      }
    }
    out.push_back(cs);
  }
  return out;
}

}  // namespace halfeti::app
