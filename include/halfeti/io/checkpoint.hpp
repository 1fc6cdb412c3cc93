// Restart files: one HDF5 file per checkpoint with a run's whole state at a step boundary (DESIGN.md,
// "Contracts"): the water's particles (each rank writes its slab; a reader gets them all, in any rank count's
// order), the replicated state of the other parts as named blocks of doubles (rank 0's copy), named texts (the
// resolved scene, the health log) and the clock. Written under a temporary name and renamed when complete, so a
// checkpoint is whole or absent, even when a rank dies while writing it.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "halfeti/core/particle_arrays.hpp"

namespace halfeti::io {

using halfeti::ParticleArrays;

struct Checkpoint {
  double time = 0.0;
  long long steps = 0;
  int ranks = 0;             // the rank count of the run that wrote it
  ParticleArrays particles;  // write: this rank's owned; read: every particle
  std::map<std::string, std::vector<double>>
      blocks;                                // write: the same names on every rank, rank 0's values kept
  std::map<std::string, std::string> texts;  // likewise
};

// Collective over comm. Raises IoError naming the file and the system's reason when a write fails.
void write_checkpoint(MPI_Comm comm, const std::string& path, const Checkpoint& c);

// Serial (any rank). UserError when the file is missing or not a halfeti checkpoint.
Checkpoint read_checkpoint(const std::string& path);

// The checkpoint a --restart PATH names: PATH itself when it is a file, else the latest checkpoint of the run
// folder PATH (its checkpoints/) or of the checkpoints folder PATH. UserError when there is none.
std::string resolve_checkpoint(const std::string& path);

// The checkpoint files of a folder, oldest first (by the step in their names).
std::vector<std::string> list_checkpoints(const std::string& dir);

// The file name of the checkpoint at `steps` steps.
std::string checkpoint_file_name(long long steps);

}  // namespace halfeti::io
