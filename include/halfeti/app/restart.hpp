// What a restart needs beyond the parts' own state (simulation.cpp saves and restores those): whether the scene
// of the continued run may continue the saved one, lists of lines as text, and a run folder's bookkeeping (which
// outputs it holds, the probe rows a continued run carries over).
#pragma once

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "halfeti/core/scene.hpp"
#include "halfeti/io/checkpoint.hpp"

namespace halfeti::app {

// The first key (path.to.key) whose value differs between two resolved scenes, other than those a continued run
// may change (scene.end_time, scene.description, output.*), with both values; empty when none does.
std::string changed_physics_key(const std::string& saved_scene, const std::string& scene);

// Lines of text as one text and back (the health log's text is core/health.hpp's).
std::string encode_lines(const std::vector<std::string>& lines);
std::vector<std::string> decode_lines(const std::string& text);

// The outputs of a run that `dir` holds (probes.csv, summary.json, ..., fields and checkpoints), as paths.
std::vector<std::string> run_outputs(const std::string& dir);

// The data rows of DIR/probes.csv at or before time t (to within round-off), verbatim, after checking that its
// header is `header`; none when the file does not exist.
std::vector<std::string> probe_rows_until(const std::string& path, const std::string& header, double t);

// The folder a checkpoint belongs to: DIR for DIR/checkpoints/checkpoint_*.h5, else the checkpoint's folder.
std::string run_folder_of(const std::string& checkpoint);

// Whether two paths name the same existing folder.
bool same_folder(const std::string& a, const std::string& b);

// The checkpoint `restart` names (a file, or a run folder's latest), read on every rank, with its path; refused
// (UserError) when the scene changes the physics it was saved with or ends before it.
std::unique_ptr<io::Checkpoint> read_restart(const std::string& restart, const scene::Scene& scene,
                                             std::string& checkpoint_path);

// Collective: makes the run folder `out_dir` (with fields/ and checkpoints/) on rank 0 and returns whether the run
// continues the one it holds (a restart from its own checkpoint: later checkpoints removed). Any other run's outputs
// there are refused, or removed with `overwrite`.
bool prepare_run_folder(MPI_Comm comm, const std::string& out_dir, const io::Checkpoint* checkpoint,
                        const std::string& checkpoint_path, bool overwrite);

}  // namespace halfeti::app
