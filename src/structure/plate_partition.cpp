#include "halfeti/structure/plate_partition.hpp"

#include <algorithm>
#include <array>
#include <numeric>

#include "halfeti/core/error.hpp"
#include "halfeti/parallel/mesh_partition.hpp"

namespace halfeti::structure {

PlatePartition partition_plate(const PlateMesh& mesh, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int ne = mesh.element_count(), nn = static_cast<int>(mesh.nodes.size());
  if (size > ne)
    HALFETI_USER_ERROR("structure.ranks = " << size << " exceeds the plate's " << ne << " elements");
  PlatePartition p;
  p.element_rank.assign(ne, 0);
  if (size > 1) {
    if (rank == 0) {
      // Dual graph on the corner nodes: two elements are neighbours when they share an edge (2 corners).
      std::vector<int> start(ne + 1, 0), corners;
      for (int e = 0; e < ne; ++e) {
        const int* nodes = mesh.element_nodes(e);
        const bool q9 = mesh.nodes_per_element() == 9;
        for (int a : q9 ? std::array<int, 4>{0, 2, 8, 6} : std::array<int, 4>{0, 1, 3, 2})
          corners.push_back(nodes[a]);
        start[e + 1] = static_cast<int>(corners.size());
      }
      p.element_rank = parallel::partition_mesh_dual(start, corners, nn, 2, size);
    }
    MPI_Bcast(p.element_rank.data(), ne, MPI_INT, 0, comm);
  }
  p.node_rank.assign(nn, size);
  for (int e = 0; e < ne; ++e)
    for (int k = 0; k < mesh.nodes_per_element(); ++k)
      for (int n : {mesh.element_nodes(e)[k]}) p.node_rank[n] = std::min(p.node_rank[n], p.element_rank[e]);
  std::vector<int> order(nn);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return p.node_rank[a] < p.node_rank[b]; });
  p.petsc_node.assign(nn, -1);
  for (int k = 0; k < nn; ++k) p.petsc_node[order[k]] = k;
  for (int e = 0; e < ne; ++e)
    if (p.element_rank[e] == rank) p.owned_elements.push_back(e);
  p.first_block = static_cast<int>(
      std::count_if(p.node_rank.begin(), p.node_rank.end(), [rank](int r) { return r < rank; }));
  p.owned_blocks = static_cast<int>(std::count(p.node_rank.begin(), p.node_rank.end(), rank));
  HALFETI_CHECK(p.owned_blocks > 0, "rank " << rank << " owns no structure node");
  return p;
}

}  // namespace halfeti::structure
