#include "halfeti/excitation/excitation_scene.hpp"

namespace halfeti::excitation {

using scene::Key;
using scene::Schema;

namespace {

std::shared_ptr<Schema> pulse_keys() {
  auto s = std::make_shared<Schema>();
  s->add(
      Key::real("amplitude", "peak ground acceleration of the cycle", "m/s^2").required().in(-100.0, 100.0));
  s->add(Key::real("period", "duration of the one cycle", "s").required().positive().at_most(100.0));
  s->add(Key::real("start", "time the cycle begins", "s").def(0.0).non_negative());
  return s;
}

std::string resolve_path(const std::string& file, const std::string& scene_dir) {
  if (file.empty() || file[0] == '/' || scene_dir.empty()) return file;
  return scene_dir + "/" + file;
}

Registry<GroundMotionFactory> build_registry() {
  Registry<GroundMotionFactory> r;
  r.add("none", "the tank stands still", std::make_shared<Schema>(),
        [](const scene::Node&, const std::string&) { return make_still(); });
  r.add("sine_pulse", "one cycle of a sine (the paper's Fig. 4b)", pulse_keys(),
        [](const scene::Node& s, const std::string&) {
          return make_sine_pulse(s.real("amplitude"), s.real("period"), s.real("start"));
        });
  r.add("cosine_pulse", "one cycle of a cosine (the paper's Fig. 4a)", pulse_keys(),
        [](const scene::Node& s, const std::string&) {
          return make_cosine_pulse(s.real("amplitude"), s.real("period"), s.real("start"));
        });
  auto record = std::make_shared<Schema>();
  record->add(
      Key::string("file", "CSV accelerogram: '#' lines, a header row, then t, a rows (relative to the scene)")
          .required());
  record->add(Key::choice("units", "units of the acceleration column", {"g", "m/s2"}).def("g"));
  record->add(Key::real("scale", "factor applied to every sample").def(1.0).in(-100.0, 100.0));
  record->add(Key::real("start", "record applied from this time", "s").def(0.0).non_negative());
  record->add(Key::real("end", "record applied until this time (default: its last sample)", "s").positive());
  record->add(Key::real("time_shift", "added to the record's time column", "s").def(0.0));
  r.add("record", "a sampled accelerogram, linearly interpolated", record,
        [](const scene::Node& s, const std::string& dir) {
          const double end = s.has("end") ? s.real("end") : 1e300;
          return read_record_csv(resolve_path(s.string("file"), dir), s.string("units"), s.real("scale"),
                                 s.real("start"), end, s.real("time_shift"));
        });
  return r;
}

}  // namespace

const Registry<GroundMotionFactory>& ground_motion_registry() {
  static const Registry<GroundMotionFactory> registry = build_registry();
  return registry;
}

std::shared_ptr<const Schema> excitation_schema() {
  return ground_motion_registry().section_schema(
      "kind", "Horizontal ground motion of the tank; in the tank's frame every mass feels -a_g(t).", {},
      "none");
}

std::unique_ptr<GroundMotion> make_ground_motion(const scene::Node& section, const std::string& scene_dir) {
  return ground_motion_registry().get(section.string("kind")).make(section, scene_dir);
}

}  // namespace halfeti::excitation
