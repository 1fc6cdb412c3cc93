// Distribution of the plate over the structure's ranks: elements split by METIS (dual graph, elements sharing
// an edge), each node owned by the lowest rank among its elements, and PETSc's numbering of the nodes: by
// owner rank, then by node id, so that each rank owns one contiguous block range. On one rank the numbering
// is the identity.
#pragma once

#include <mpi.h>

#include <vector>

#include "halfeti/structure/plate_mesh.hpp"

namespace halfeti::structure {

struct PlatePartition {
  std::vector<int> element_rank;    // per element
  std::vector<int> node_rank;       // per node
  std::vector<int> petsc_node;      // node id -> PETSc block row
  std::vector<int> owned_elements;  // of this rank, ascending
  int first_block = 0;              // this rank's PETSc block rows: [first_block, first_block + owned_blocks)
  int owned_blocks = 0;
};

// Collective over comm: METIS runs on rank 0 and the element ranks are broadcast, so every rank agrees.
PlatePartition partition_plate(const PlateMesh& mesh, MPI_Comm comm);

}  // namespace halfeti::structure
