#include "halfeti/parallel/mesh_partition.hpp"

#include <metis.h>

#include "halfeti/core/error.hpp"

namespace halfeti::parallel {

std::vector<int> partition_mesh_dual(const std::vector<int>& element_start,
                                     const std::vector<int>& element_nodes, int node_count, int common,
                                     int parts) {
  HALFETI_CHECK(!element_start.empty() && element_start.back() == static_cast<int>(element_nodes.size()),
                "partition_mesh_dual: element_start does not end at the node list's size");
  idx_t n_elements = static_cast<idx_t>(element_start.size()) - 1, n_nodes = node_count, n_common = common,
        n_parts = parts, cut = 0;
  std::vector<idx_t> eptr(element_start.begin(), element_start.end());
  std::vector<idx_t> eind(element_nodes.begin(), element_nodes.end());
  std::vector<idx_t> epart(n_elements), npart(n_nodes);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // reproducible partitions
  const int status =
      METIS_PartMeshDual(&n_elements, &n_nodes, eptr.data(), eind.data(), nullptr, nullptr, &n_common,
                         &n_parts, nullptr, options, &cut, epart.data(), npart.data());
  HALFETI_CHECK(status == METIS_OK, "METIS_PartMeshDual failed with status " << status);
  return {epart.begin(), epart.end()};
}

}  // namespace halfeti::parallel
