// Probes: named columns of probes.csv. Each probe kind resolves through one registry: its keys (the scene schema
// of `probes[]` is built from it) and a factory that binds it to the parts of the run.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "halfeti/app/parts.hpp"
#include "halfeti/core/registry.hpp"
#include "halfeti/core/scene.hpp"

namespace halfeti::app {

struct ProbeColumn {
  ProbeColumn(std::string n, std::function<double(double t)> s, std::string u)
      : name(std::move(n)), sample(std::move(s)), unit(std::move(u)) {}
  std::string name;
  std::function<double(double t)> sample;  // collective over the run's ranks; same value on every rank
  std::string unit;  // SI ("-" for a pure number, "dx" in particle spacings): probes.json
  std::string kind;  // the probe's kind (set by make_probes)
};

// Throws UserError when the probe names a part the scene does not have.
using ProbeFactory = std::function<ProbeColumn(const scene::Node& probe, Parts& parts)>;

const Registry<ProbeFactory>& probe_registry();
std::shared_ptr<const scene::Schema> probe_schema();

// Builds every probe of the scene; checks that names are unique and that each probe's part exists.
std::vector<ProbeColumn> make_probes(const scene::Node& root, Parts& parts);

}  // namespace halfeti::app
