#include "halfeti/app/probes.hpp"

#include <cctype>
#include <set>

#include "halfeti/structure/plate_mesh.hpp"

namespace halfeti::app {

using scene::Key;
using scene::Schema;

namespace {

// Structure and cable values live on the structure's rank; every rank returns the same number.
double from_structure_rank(const Parts& parts, double value_on_structure_rank) {
  double v = parts.structure_rank ? value_on_structure_rank : 0.0;
  MPI_Bcast(&v, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return v;
}

template <class Read>
ProbeFactory structure_probe(Read read, std::string unit) {
  return [read, unit](const scene::Node& p, Parts& parts) {
    parts.require_structure(p.path());
    const Parts* owner = &parts;
    return ProbeColumn{p.string("name"),
                       [owner, read](double) {
                         return from_structure_rank(*owner, owner->plate ? read(*owner->plate) : 0.0);
                       },
                       unit};
  };
}

// A water probe read along the vertical line at `x` (inside the tank).
template <class Read>
ProbeFactory at_x(Read read, std::string unit) {
  return [read, unit](const scene::Node& p, Parts& parts) {
    const auto& f = parts.require_fluid(p.path());
    const double x = p.real("x");
    if (x > f.tank_length)
      HALFETI_USER_ERROR(p.key_path("x")
                         << ": " << x << " lies outside the tank [0, " << f.tank_length << "]");
    const Parts* owner = &parts;
    return ProbeColumn{p.string("name"), [owner, read, x](double) { return read(*owner->fluid, x); }, unit};
  };
}

// The plate-water coupling's probes need both a plate and water.
void require_coupling(const scene::Node& p, const Parts& parts) {
  parts.require_structure(p.path());
  if (!parts.coupling_params)
    HALFETI_USER_ERROR(p.path() << ": this probe reads the plate-water coupling, but the scene has no water");
}

std::shared_ptr<Schema> keys(std::vector<Key> list) {
  auto s = std::make_shared<Schema>();
  for (auto& k : list) s->add(std::move(k));
  return s;
}

// A point probe must stand inside the tank.
std::array<double, 2> point_in_tank(const scene::Node& p, const Parts& parts) {
  const auto& f = parts.require_fluid(p.path());
  const auto at = p.point("at");
  if (at[0] < 0 || at[0] > f.tank_length || at[1] < 0 || at[1] > f.tank_height)
    HALFETI_USER_ERROR(p.key_path("at") << ": [" << at[0] << ", " << at[1] << "] lies outside the tank [0, "
                                        << f.tank_length << "] x [0, " << f.tank_height << "]");
  return at;
}

template <class Read>
ProbeFactory fluid_probe(Read read, std::string unit) {
  return [read, unit](const scene::Node& p, Parts& parts) {
    parts.require_fluid(p.path());
    const Parts* owner = &parts;
    return ProbeColumn{p.string("name"), [owner, read](double) { return read(*owner->fluid); }, unit};
  };
}

Registry<ProbeFactory> build_registry() {
  Registry<ProbeFactory> r;
  r.add("ground_acceleration", "the tank's horizontal ground acceleration a_g(t) [m/s^2]", keys({}),
        [](const scene::Node& p, Parts& parts) {
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"), [owner](double t) { return owner->motion->acceleration(t); },
                             "m/s^2"};
        });
  r.add("pressure", "water pressure at a point: Shepard-normalised kernel sum over fluid particles [Pa]",
        keys({Key::point("at", "where", "m").required()}), [](const scene::Node& p, Parts& parts) {
          const auto at = point_in_tank(p, parts);
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"),
                             [owner, at](double) { return owner->fluid->pressure_at(at[0], at[1]); }, "Pa"};
        });
  r.add("velocity", "one component of the water velocity at a point [m/s]",
        keys({Key::point("at", "where", "m").required(),
              Key::choice("component", "which component", {"x", "y"}).required()}),
        [](const scene::Node& p, Parts& parts) {
          const auto at = point_in_tank(p, parts);
          const int c = p.string("component") == "x" ? 0 : 1;
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"),
                             [owner, at, c](double) { return owner->fluid->velocity_at(at[0], at[1])[c]; },
                             "m/s"};
        });
  r.add("elevation",
        "free-surface elevation at x: top fluid particle within dx of x, plus dx/2 (follows run-up jets) [m]",
        keys({Key::real("x", "where", "m").required().non_negative()}),
        at_x([](const sph::Fluid& f, double x) { return f.free_surface_elevation(x); }, "m"));
  r.add("surface_level",
        "the bulk's free surface at x: where the water's kernel-interpolated volume fraction falls below "
        "1/2, upward "
        "from the floor (run-up jets and spray above a gap not counted) [m]",
        keys({Key::real("x", "where", "m").required().non_negative()}),
        at_x([](const sph::Fluid& f, double x) { return f.surface_level(x); }, "m"));
  r.add(
      "surface_mode",
      "amplitude of the free surface's standing mode n, cos(n pi x / L): (2 / M) sum_k level(x_k) "
      "cos(n pi x_k / L) over M midpoints x_k = (k + 1/2) L / M, level as surface_level [m]",
      keys({Key::integer("mode", "n, the mode's number of half waves across the tank").required().at_least(1),
            Key::integer("samples", "M, the points across the tank the surface is sampled at")
                .def(32)
                .at_least(8)}),
      [](const scene::Node& p, Parts& parts) {
        parts.require_fluid(p.path());
        const int n = static_cast<int>(p.integer("mode")), m = static_cast<int>(p.integer("samples"));
        if (2 * n > m)
          HALFETI_USER_ERROR(p.key_path("samples") << ": " << m << " samples cannot resolve mode " << n
                                                   << " (at least 2 per half wave: " << 2 * n << ")");
        const Parts* owner = &parts;
        return ProbeColumn{p.string("name"),
                           [owner, n, m](double) { return owner->fluid->surface_mode(n, m); }, "m"};
      });
  r.add("front", "surge front: largest x of the water below a height, plus dx/2 [m]",
        keys({Key::real("below", "only particles below this height count", "m").required().positive()}),
        [](const scene::Node& p, Parts& parts) {
          parts.require_fluid(p.path());
          const double below = p.real("below");
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"),
                             [owner, below](double) { return owner->fluid->front_position(below); }, "m"};
        });
  r.add("total_mass", "mass of the water per unit depth [kg/m]", keys({}),
        fluid_probe([](const sph::Fluid& f) { return f.total_mass(); }, "kg/m"));
  r.add("kinetic_energy", "kinetic energy of the water per unit depth [J/m]", keys({}),
        fluid_probe([](const sph::Fluid& f) { return f.kinetic_energy(); }, "J/m"));
  r.add("max_density_variation", "max |rho - rho0| / rho0 over the water [-]", keys({}),
        fluid_probe([](const sph::Fluid& f) { return f.max_density_variation(); }, "-"));
  r.add("plate_free_surface",
        "water particles beside the plate marked as at a free surface at the last force evaluation "
        "(coupling.plate_wall_free_surface; 0 when off) [-]",
        keys({}), fluid_probe([](const sph::Fluid& f) { return f.plate_free_surface_count(); }, "-"));
  r.add("free_surface_floor",
        "water particles the water has left raised to rho0, the atmosphere's pressure, at the last force "
        "evaluation (fluid.free_surface_floor; 0 when off) [-]",
        keys({}), fluid_probe([](const sph::Fluid& f) { return f.floored_count(); }, "-"));
  r.add("min_spacing", "closest pair of water particles at the last neighbour search, in dx [-] (clumping)",
        keys({}), fluid_probe([](const sph::Fluid& f) { return f.min_spacing(); }, "dx"));
  r.add("displacement", "displacement of a named plate node [m]",
        keys({Key::string(
                  "node",
                  "top_left, top_centre, top_right, ... (hanging plate: bottom_left, bottom_centre, ...)")
                  .required(),
              Key::choice("component", "which component", {"x", "y"}).required()}),
        [](const scene::Node& p, Parts& parts) {
          const auto& s = parts.require_structure(p.path());
          const std::string node = p.string("node");
          const auto mesh = structure::make_plate_mesh(s.params.geometry);
          if (!mesh.named_nodes.count(node))
            HALFETI_USER_ERROR(p.key_path("node") << ": no plate node named '" << node << "'");
          const int id = mesh.named_nodes.at(node), c = p.string("component") == "x" ? 0 : 1;
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"),
                             [owner, id, c](double) {
                               return from_structure_rank(
                                   *owner, owner->plate ? owner->plate->displacement(id)[c] : 0.0);
                             },
                             "m"};
        });
  r.add("strain_energy", "strain energy of the plate per unit depth [J/m]", keys({}),
        structure_probe([](const structure::PlateSolver& s) { return s.strain_energy(); }, "J/m"));
  r.add("structure_kinetic_energy", "kinetic energy of the plate per unit depth [J/m]", keys({}),
        structure_probe([](const structure::PlateSolver& s) { return s.kinetic_energy(); }, "J/m"));
  r.add("structure_potential_energy",
        "the plate's potential energy in gravity from its reference shape [J/m]", keys({}),
        structure_probe([](const structure::PlateSolver& s) { return s.gravity_potential_energy(); }, "J/m"));
  r.add("max_von_mises", "largest von Mises (Cauchy) stress in the plate [Pa]", keys({}),
        structure_probe([](const structure::PlateSolver& s) { return s.max_von_mises(); }, "Pa"));
  r.add(
      "plate_load",
      "the water's force on the plate over the last step, by part, face and sign (docs/coupling.md, section "
      "15) [N/m]",
      keys({Key::choice("part", "plate-wall ghosts, contact, or both", {"wall", "contact", "all"}).def("all"),
            Key::choice("face", "the plate's face (tank's view; top: the free end)",
                        {"left", "right", "top", "all"})
                .def("all"),
            Key::choice("sign", "the wall part pushing into the face, pulling it (suction), or both",
                        {"push", "suction", "all"})
                .def("all"),
            Key::choice("component", "which component", {"x", "y"}).required()}),
      [](const scene::Node& p, Parts& parts) {
        require_coupling(p, parts);
        const std::string part = p.string("part"), face = p.string("face"), sign = p.string("sign");
        if (part == "contact" && sign != "all")
          HALFETI_USER_ERROR(p.key_path("sign")
                             << ": '" << sign
                             << "' splits the plate-wall part only; the contact only pushes");
        const int c = p.string("component") == "x" ? 0 : 1;
        const int f = face == "right" ? 0 : face == "top" ? 1 : face == "left" ? 2 : -1;
        const bool wall = part != "contact", contact = part != "wall";
        const bool push = sign != "suction", suction = sign != "push";
        const Parts* owner = &parts;
        return ProbeColumn{p.string("name"),
                           [owner, c, f, wall, contact, push, suction](double) {
                             const auto& b = owner->coupling->load_breakdown();
                             double v = 0.0;
                             for (int k = 0; k < 3; ++k) {
                               if (f >= 0 && k != f) continue;
                               if (wall && push) v += b.wall_push[k][c];
                               if (wall && suction) v += b.wall_suction[k][c];
                               if (contact) v += b.contact[k][c];
                             }
                             return v;
                           },
                           "N/m"};
      });
  r.add("plate_load_work",
        "the water's work on the plate since the start (docs/coupling.md, section 15) [J/m]",
        keys({Key::choice("part", "plate-wall load, interface added mass, contact, or all",
                          {"wall", "added_mass", "contact", "all"})
                  .def("all")}),
        [](const scene::Node& p, Parts& parts) {
          require_coupling(p, parts);
          const std::string part = p.string("part");
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"),
                             [owner, part](double) {
                               const auto& b = owner->coupling->load_breakdown();
                               if (part == "wall") return b.work_wall;
                               if (part == "added_mass") return b.work_added_mass;
                               if (part == "contact") return b.work_contact;
                               return b.work_wall + b.work_added_mass + b.work_contact;
                             },
                             "J/m"};
        });
  r.add(
      "cable_tension", "tension of one real cable of a set, at one end: stress [Pa] or force [N]",
      keys({Key::string("cable", "cable name").required(),
            Key::choice("end", "which end", {"anchor", "plate"}).def("plate"),
            Key::choice("quantity", "stress of one cable, or its force", {"stress", "force"}).def("stress")}),
      [](const scene::Node& p, Parts& parts) {
        const int i = parts.cable_index(p.path(), p.string("cable"));
        const bool at_plate = p.string("end") == "plate", stress = p.string("quantity") == "stress";
        const Parts* owner = &parts;
        return ProbeColumn{p.string("name"),
                           [owner, i, at_plate, stress](double) {
                             double v = 0.0;
                             if (owner->structure_rank) {
                               const auto& sol = owner->cables[i]->last_solution();
                               const double t = at_plate ? sol.tension_end : sol.tension_start;
                               const auto& set = owner->cable_setups[i].set;
                               v = stress ? cable::tension_stress(set, t) : cable::tension_per_cable(set, t);
                             }
                             return from_structure_rank(*owner, v);
                           },
                           stress ? "Pa" : "N"};
      });
  r.add("cable_slack", "1 when the cable's chord is shorter than its unstretched length, else 0 [-]",
        keys({Key::string("cable", "cable name").required()}), [](const scene::Node& p, Parts& parts) {
          const int i = parts.cable_index(p.path(), p.string("cable"));
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"),
                             [owner, i](double) {
                               const bool slack =
                                   owner->structure_rank &&
                                   owner->cables[i]->last_solution().state == cable::CableState::kSlack;
                               return from_structure_rank(*owner, slack ? 1.0 : 0.0);
                             },
                             "-"};
        });
  r.add("cable_chord", "distance between the cable's two ends [m]",
        keys({Key::string("cable", "cable name").required()}), [](const scene::Node& p, Parts& parts) {
          const int i = parts.cable_index(p.path(), p.string("cable"));
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"),
                             [owner, i](double) {
                               return from_structure_rank(
                                   *owner,
                                   owner->structure_rank ? owner->cables[i]->last_solution().chord : 0.0);
                             },
                             "m"};
        });
  return r;
}

}  // namespace

const Registry<ProbeFactory>& probe_registry() {
  static const Registry<ProbeFactory> registry = build_registry();
  return registry;
}

std::shared_ptr<const Schema> probe_schema() {
  static const std::shared_ptr<const Schema> schema = [] {
    const std::vector<Key> common = {
        Key::string("name", "column name in probes.csv (letters, digits, _ and -)").required()};
    return std::shared_ptr<const Schema>(
        probe_registry().section_schema("kind", "One column of probes.csv.", common));
  }();
  return schema;
}

std::vector<ProbeColumn> make_probes(const scene::Node& root, Parts& parts) {
  std::vector<ProbeColumn> out;
  std::set<std::string> names;
  for (const auto& p : root.list("probes")) {
    const std::string name = p.string("name");
    for (char ch : name)
      if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-'))
        HALFETI_USER_ERROR(p.key_path("name")
                           << ": probe name '" << name << "' may hold only letters, digits, _ and -");
    if (name == "t")
      HALFETI_USER_ERROR(p.key_path("name") << ": 't' is the time column; choose another name");
    if (!names.insert(name).second)
      HALFETI_USER_ERROR(p.key_path("name") << ": probe name '" << name << "' used twice");
    out.push_back(probe_registry().get(p.string("kind")).make(p, parts));
    out.back().kind = p.string("kind");
    HALFETI_CHECK(!out.back().unit.empty(), "probe kind '" << out.back().kind << "' states no unit");
  }
  return out;
}

}  // namespace halfeti::app
