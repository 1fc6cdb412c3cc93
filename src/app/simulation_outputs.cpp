// The run's files besides the field data (README "Outputs"): the field series' handles, probes.csv (carrying a
// restarted run's rows up to its checkpoint), probes.json, log.txt and scene.resolved.yaml.
#include "halfeti/app/restart.hpp"
#include "halfeti/app/simulation.hpp"
#include "halfeti/core/collective.hpp"
#include "halfeti/core/version.hpp"
#include "halfeti/io/json.hpp"

namespace halfeti::app {

void Simulation::open_field_series() {
  const std::string fields = out_dir_ + "/fields";
  if (parts_.fluid) {
    fluid_fields_ = std::make_unique<io::FieldSeries>(comm_, fields, "fluid");
    tank_fields_ = std::make_unique<io::FieldSeries>(comm_, fields, "tank");
  }
  if (parts_.structure_setup) plate_fields_ = std::make_unique<io::FieldSeries>(comm_, fields, "plate");
  if (!parts_.cable_setups.empty())
    cable_fields_ = std::make_unique<io::FieldSeries>(comm_, fields, "cables");
}

// After a restore (t_ is the checkpoint's): a continued run carries the probe rows up to the checkpoint (from its
// own folder or the one it came from), continues the field series in its own folder, and appends to its log.
void Simulation::open_outputs(bool restored) {
  std::vector<std::string> names;
  for (const auto& p : probes_) names.push_back(p.name);
  std::vector<std::string> carried;
  collective_outcome(comm_, 0, rank_ == 0, [&] {
    if (restored)
      carried =
          probe_rows_until(run_folder_of(restart_path_) + "/probes.csv", io::ProbeWriter::header(names), t_);
  });
  collective_outcome(comm_, 0, true, [&] {  // rank 0 opens the file: its failure is every rank's
    probe_out_ = std::make_unique<io::ProbeWriter>(out_dir_ + "/probes.csv", names, rank_ == 0, carried);
  });
  if (continuing_) {
    for (auto* series : {fluid_fields_.get(), plate_fields_.get(), cable_fields_.get(), tank_fields_.get()})
      if (series) series->resume(t_);
  }
  collective_outcome(comm_, 0, true, [&] {
    log_ = std::make_unique<io::RunLog>(out_dir_ + "/log.txt", rank_ == 0, options_.echo, continuing_);
  });
  collective_outcome(comm_, 0, rank_ == 0, [&] {
    std::vector<std::string> units, kinds;
    for (const auto& p : probes_) {
      units.push_back(p.unit);
      kinds.push_back(p.kind);
    }
    io::write_file_atomically(out_dir_ + "/probes.json", io::probe_columns_json(names, units, kinds));
    io::write_file_atomically(out_dir_ + "/scene.resolved.yaml", std::string("# resolved by halfeti ") +
                                                                     kVersion + " from " + scene_.file +
                                                                     "\n" + scene_.resolved_text());
  });
}

}  // namespace halfeti::app
