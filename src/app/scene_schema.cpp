#include "halfeti/app/scene_schema.hpp"

#include "halfeti/app/coupling_section.hpp"
#include "halfeti/app/fluid_section.hpp"
#include "halfeti/app/probes.hpp"
#include "halfeti/app/structure_section.hpp"
#include "halfeti/excitation/excitation_scene.hpp"

namespace halfeti::app {

using scene::Key;
using scene::Schema;

namespace {

std::shared_ptr<Schema> run_schema() {
  auto s = std::make_shared<Schema>("What the run is and how long it lasts.");
  s->add(Key::string("name", "scene name; names the default output folder out/<name>").required());
  s->add(Key::string("description", "free text, copied to summary.json"));
  s->add(Key::real("end_time", "simulated time to reach", "s").required().positive().at_most(1e4));
  return s;
}

std::shared_ptr<Schema> output_schema() {
  auto s = std::make_shared<Schema>("When outputs are written (simulated time).");
  s->add(Key::real("probe_interval", "time between rows of probes.csv", "s").def(0.005).positive());
  s->add(Key::real("field_interval", "time between field files (0: none)", "s").def(0.05).non_negative());
  s->add(
      Key::real(
          "checkpoint_interval",
          "time between checkpoints (0: only at the end, at a stop and on failure); a run continues from one "
          "with --restart",
          "s")
          .def(0.0)
          .non_negative());
  s->add(Key::integer("checkpoint_keep", "how many of the newest checkpoints stay in checkpoints/ (0: all)")
             .def(2)
             .at_least(0));
  s->add(Key::real("progress_interval", "time between progress lines (0: 50 lines per run)", "s")
             .def(0.0)
             .non_negative());
  return s;
}

std::shared_ptr<Schema> tank_schema() {
  auto s = std::make_shared<Schema>(
      "The tank, lower left corner at the origin; fields are per unit depth of the out-of-plane width.");
  s->add(Key::real("length", "inner length (x)", "m").required().positive().at_most(100.0));
  s->add(Key::real("height", "inner height (y)", "m").required().positive().at_most(100.0));
  s->add(Key::real("width", "out-of-plane width; cable sets are divided by it", "m").def(0.15).positive());
  return s;
}

}  // namespace

std::shared_ptr<const Schema> scene_schema() {
  static const std::shared_ptr<const Schema> schema = [] {
    auto s = std::make_shared<Schema>("A halfeti scene (YAML). Sections not named are not built.");
    s->add(Key::section("scene", "what the run is", run_schema()).required());
    s->add(Key::section("output", "output schedule", output_schema()).always());
    s->add(Key::real("gravity", "gravitational acceleration, acting towards -y", "m/s^2")
               .def(9.81)
               .non_negative()
               .at_most(100.0));
    s->add(Key::section("tank", "the tank", tank_schema()));
    s->add(Key::section("excitation", "ground motion", excitation::excitation_schema()).always());
    s->add(Key::section("fluid", "the water (delta-SPH)", fluid_schema()));
    s->add(Key::section("structure", "the rubber plate (finite elements)", structure_schema()));
    s->add(Key::list("cables", "cable sets holding the plate", cable_schema()));
    s->add(Key::section("coupling", "contact of water and plate", coupling_schema())
               .implied_by({"fluid", "structure"}));
    s->add(Key::list("probes", "columns of probes.csv", probe_schema()));
    return std::shared_ptr<const Schema>(s);
  }();
  return schema;
}

}  // namespace halfeti::app
