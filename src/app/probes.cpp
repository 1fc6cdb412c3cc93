#include "halfeti/app/probes.hpp"

#include <cctype>
#include <set>

namespace halfeti::app {

using scene::Key;
using scene::Schema;

const sph::FluidParams& Parts::require_fluid(const std::string& who) const {
  if (!fluid_params) HALFETI_USER_ERROR(who << ": this probe reads the water, but the scene has no `fluid:` section");
  return *fluid_params;
}

namespace {

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
ProbeFactory fluid_probe(Read read) {
  return [read](const scene::Node& p, Parts& parts) {
    parts.require_fluid(p.path());
    const Parts* owner = &parts;
    return ProbeColumn{p.string("name"), [owner, read](double) { return read(*owner->fluid); }};
  };
}

Registry<ProbeFactory> build_registry() {
  Registry<ProbeFactory> r;
  r.add("ground_acceleration", "the tank's horizontal ground acceleration a_g(t) [m/s^2]", keys({}),
        [](const scene::Node& p, Parts& parts) {
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"), [owner](double t) { return owner->motion->acceleration(t); }};
        });
  r.add("pressure", "water pressure at a point: Shepard-normalised kernel sum over fluid particles [Pa]",
        keys({Key::point("at", "where", "m").required()}), [](const scene::Node& p, Parts& parts) {
          const auto at = point_in_tank(p, parts);
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"), [owner, at](double) { return owner->fluid->pressure_at(at[0], at[1]); }};
        });
  r.add("velocity", "one component of the water velocity at a point [m/s]",
        keys({Key::point("at", "where", "m").required(),
              Key::choice("component", "which component", {"x", "y"}).required()}),
        [](const scene::Node& p, Parts& parts) {
          const auto at = point_in_tank(p, parts);
          const int c = p.string("component") == "x" ? 0 : 1;
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"),
                             [owner, at, c](double) { return owner->fluid->velocity_at(at[0], at[1])[c]; }};
        });
  r.add("elevation", "free-surface elevation at x: top fluid particle within dx of x, plus dx/2 [m]",
        keys({Key::real("x", "where", "m").required().non_negative()}), [](const scene::Node& p, Parts& parts) {
          const auto& f = parts.require_fluid(p.path());
          const double x = p.real("x");
          if (x > f.tank_length)
            HALFETI_USER_ERROR(p.key_path("x") << ": " << x << " lies outside the tank [0, " << f.tank_length << "]");
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"), [owner, x](double) { return owner->fluid->free_surface_elevation(x); }};
        });
  r.add("front", "surge front: largest x of the water below a height, plus dx/2 [m]",
        keys({Key::real("below", "only particles below this height count", "m").required().positive()}),
        [](const scene::Node& p, Parts& parts) {
          parts.require_fluid(p.path());
          const double below = p.real("below");
          const Parts* owner = &parts;
          return ProbeColumn{p.string("name"), [owner, below](double) { return owner->fluid->front_position(below); }};
        });
  r.add("total_mass", "mass of the water per unit depth [kg/m]", keys({}),
        fluid_probe([](const sph::Fluid& f) { return f.total_mass(); }));
  r.add("kinetic_energy", "kinetic energy of the water per unit depth [J/m]", keys({}),
        fluid_probe([](const sph::Fluid& f) { return f.kinetic_energy(); }));
  r.add("max_density_variation", "max |rho - rho0| / rho0 over the water [-]", keys({}),
        fluid_probe([](const sph::Fluid& f) { return f.max_density_variation(); }));
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
    return std::shared_ptr<const Schema>(probe_registry().section_schema("kind", "One column of probes.csv.", common));
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
        HALFETI_USER_ERROR(p.key_path("name") << ": probe name '" << name
                                              << "' may hold only letters, digits, _ and -");
    if (name == "t") HALFETI_USER_ERROR(p.key_path("name") << ": 't' is the time column; choose another name");
    if (!names.insert(name).second) HALFETI_USER_ERROR(p.key_path("name") << ": probe name '" << name << "' used twice");
    out.push_back(probe_registry().get(p.string("kind")).make(p, parts));
  }
  return out;
}

}  // namespace halfeti::app
