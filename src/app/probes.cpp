#include "halfeti/app/probes.hpp"

#include <set>

namespace halfeti::app {

using scene::Key;
using scene::Schema;

namespace {

Registry<ProbeFactory> build_registry() {
  Registry<ProbeFactory> r;
  r.add("ground_acceleration", "the tank's horizontal ground acceleration a_g(t) [m/s^2]", std::make_shared<Schema>(),
        [](const scene::Node& p, Parts& parts) {
          const excitation::GroundMotion* m = parts.motion.get();
          return ProbeColumn{p.string("name"), [m](double t) { return m ? m->acceleration(t) : 0.0; }};
        });
  return r;
}

}  // namespace

const Registry<ProbeFactory>& probe_registry() {
  static const Registry<ProbeFactory> registry = build_registry();
  return registry;
}

std::shared_ptr<const Schema> probe_schema() {
  const std::vector<Key> common = {
      Key::string("name", "column name in probes.csv (letters, digits, _ and -)").required()};
  return probe_registry().section_schema("kind", "One column of probes.csv.", common);
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
