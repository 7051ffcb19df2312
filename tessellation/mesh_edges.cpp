#include "tessellation/mesh_edges.h"

#include <tbb/parallel_sort.h>

namespace csgray::detail {

void sortEdgeUses(std::vector<EdgeUse>& uses) {
  // On all threads: the order is total (each side once), so the same
  // whatever the threads.
  tbb::parallel_sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.side < y.side;
  });
}

std::span<const EdgeUse> usesOfEdge(const std::vector<EdgeUse>& uses, std::size_t first) {
  std::size_t end = first;
  while (end < uses.size() && uses[end].edge == uses[first].edge) ++end;
  return std::span<const EdgeUse>(uses).subspan(first, end - first);
}

EdgeFault edgeFault(std::span<const EdgeUse> uses) {
  if (uses.size() == 1) return EdgeFault::Open;
  if (uses.size() > 2) return EdgeFault::NonManifold;
  if (uses[0].forward == uses[1].forward) return EdgeFault::SameWay;
  return EdgeFault::None;
}

}  // namespace csgray::detail
