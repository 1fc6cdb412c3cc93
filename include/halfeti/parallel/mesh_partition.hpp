// Partition of a finite-element mesh over ranks (METIS_PartMeshDual): the structure's elements, as the SPH cells
// are partitioned in decomposition.hpp. METIS is called from parallel/ only (DESIGN); the caller says which nodes
// of each element define its neighbours.
#pragma once

#include <vector>

namespace halfeti::parallel {

// element_start has one entry per element plus one: element e's nodes are element_nodes[element_start[e] ..
// element_start[e + 1]). Two elements are neighbours when they share `common` nodes (2 for an edge in 2D).
// Returns each element's part in [0, parts); the partition is reproducible (fixed seed). Not collective: call it
// on one rank and broadcast.
std::vector<int> partition_mesh_dual(const std::vector<int>& element_start,
                                     const std::vector<int>& element_nodes, int node_count, int common,
                                     int parts);

}  // namespace halfeti::parallel
