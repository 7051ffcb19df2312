#include "tessellation/mesh_edges.h"

#include <tbb/parallel_sort.h>

namespace csgray::detail {

void sortEdgeUses(std::vector<EdgeUse>& uses) {
  auto order = [](const EdgeUse& x, const EdgeUse& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.side < y.side;
  };
  // A large mesh's on all threads: the order is total (each side once), so
  // the same whatever the threads. A small one's stays on this thread,
  // where starting TBB's scheduler would cost more (two frustums glued:
  // 1.1 times the export's CPU time).
  if (uses.size() < 30000)
    std::sort(uses.begin(), uses.end(), order);
  else
    tbb::parallel_sort(uses.begin(), uses.end(), order);
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
