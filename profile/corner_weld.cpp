#include "profile/corner_weld.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "profile/bezier.h"

namespace csgray::detail {

namespace {

// Within this much of the largest coordinate's size, 2⁻⁴⁰ (10⁻¹² at 1,
// 10⁻¹⁰ at 100): far above the rounding of a corner placed by a few
// operations in doubles, far below any edge a part has.
constexpr double kHair = 0x1p-40;

void addCorners(const Region& region, double ellipseTolerance, std::vector<dvec2>& corners) {
  if (region.op() != Region::Op::Leaf) {
    for (const RegionPtr& operand : region.operands())
      addCorners(*operand, ellipseTolerance, corners);
    return;
  }
  const Profile flat = bezierEdgesFlattened(region.profile(), ellipseTolerance);
  for (const ProfileLoop& loop : flat.loops) {
    const std::size_t n = loop.edges.size();
    for (std::size_t i = 0; i < n; ++i) {
      const ProfileEdge &e = loop.edges[i], &next = loop.edges[(i + 1) % n];
      if (e.kind == ProfileEdge::Kind::Segment && next.kind == ProfileEdge::Kind::Segment)
        corners.push_back(e.to);
    }
  }
}

}  // namespace

CornerWeld::CornerWeld(const Region& region, double ellipseTolerance) {
  std::vector<dvec2> corners;
  addCorners(region, ellipseTolerance, corners);
  double largest = 0.0;
  for (const dvec2& p : corners) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  const double hair = largest * kHair;
  std::sort(corners.begin(), corners.end(),
            [](const dvec2& a, const dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  // Each corner goes where the first (in x, then y) of the corners within
  // a hair of it on both axes went; a sweep along x looks back only as
  // far as a hair.
  std::vector<dvec2> to(corners);
  for (std::size_t i = 1; i < corners.size(); ++i)
    for (std::size_t j = i; j-- > 0 && corners[i].x - corners[j].x <= hair;)
      if (std::abs(corners[i].y - corners[j].y) <= hair) to[i] = to[j];
  for (std::size_t i = 0; i < corners.size(); ++i)
    if (to[i] != corners[i]) moved_.emplace(std::pair(corners[i].x, corners[i].y), to[i]);
}

dvec2 CornerWeld::operator()(const dvec2& p) const {
  if (moved_.empty()) return p;
  const auto it = moved_.find(std::pair(p.x, p.y));
  return it == moved_.end() ? p : it->second;
}

}  // namespace csgray::detail
