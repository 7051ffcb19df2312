#include "export/cgal/glued_caps.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace csgray::detail {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

using Edge = std::pair<std::uint32_t, std::uint32_t>;

// The directed edges of the faces that no other face of them runs the
// other way: the border of the region they cover, each edge in the sense
// its face gives it. corner maps a face's corner to the index compared.
template <class Corner>
std::vector<Edge> borderOf(const std::vector<TriangleMesh::Triangle>& faces, Corner corner) {
  std::map<Edge, int> count;
  for (const auto& t : faces)
    for (int k = 0; k < 3; ++k) ++count[{corner(t[k]), corner(t[(k + 1) % 3])}];
  std::vector<Edge> border;
  for (const auto& [edge, n] : count)
    if (!count.contains({edge.second, edge.first})) border.push_back(edge);
  return border;
}

}  // namespace

bool glueAtSharedCap(DoubleMesh& a, const DoubleMesh& b, const Bounds& boxA, const Bounds& boxB,
                     double reach) {
  const std::vector<dvec3>& pa = a.mesh.points;
  const std::vector<dvec3>& pb = b.mesh.points;
  const Bounds nearB{boxB.lo - dvec3(reach), boxB.hi + dvec3(reach)};
  const Bounds nearA{boxA.lo - dvec3(reach), boxA.hi + dvec3(reach)};

  // Each point of b with the one point of a within reach of it (on every
  // axis), looked up among a's points near b sorted along x.
  std::vector<std::uint32_t> nearPoints;
  for (std::uint32_t i = 0; i < pa.size(); ++i)
    if (nearB.contains(pa[i])) nearPoints.push_back(i);
  std::sort(nearPoints.begin(), nearPoints.end(),
            [&](std::uint32_t i, std::uint32_t j) { return pa[i].x < pa[j].x; });
  std::vector<std::uint32_t> partner(pb.size(), kNone);
  std::vector<bool> taken(pa.size(), false);
  for (std::uint32_t j = 0; j < pb.size(); ++j) {
    if (!nearA.contains(pb[j])) continue;
    auto it = std::lower_bound(nearPoints.begin(), nearPoints.end(), pb[j].x - reach,
                               [&](std::uint32_t i, double x) { return pa[i].x < x; });
    for (; it != nearPoints.end() && pa[*it].x <= pb[j].x + reach; ++it) {
      const dvec3 d = glm::abs(pa[*it] - pb[j]);
      if (std::max({d.x, d.y, d.z}) > reach) continue;
      if (partner[j] != kNone || taken[*it]) return false;  // not one point for one point
      partner[j] = *it;
      taken[*it] = true;
    }
  }

  // The faces of each on those points: b's face and a's.
  std::vector<TriangleMesh::Triangle> capB, capA;
  std::vector<bool> inCapB(b.mesh.size(), false), inCapA(a.mesh.size(), false);
  for (std::size_t f = 0; f < b.mesh.size(); ++f) {
    const auto& t = b.mesh.triangles[f];
    if (partner[t[0]] != kNone && partner[t[1]] != kNone && partner[t[2]] != kNone) {
      capB.push_back(t);
      inCapB[f] = true;
    }
  }
  if (capB.empty()) return false;
  for (std::size_t f = 0; f < a.mesh.size(); ++f) {
    const auto& t = a.mesh.triangles[f];
    if (taken[t[0]] && taken[t[1]] && taken[t[2]]) {
      capA.push_back(t);
      inCapA[f] = true;
    }
  }
  // Every matched point a corner of both faces, so that the solids meet
  // there only, and the two faces' borders the same, run the other way.
  std::vector<bool> cornerB(pb.size(), false), cornerA(pa.size(), false);
  for (const auto& t : capB)
    for (std::uint32_t v : t) cornerB[v] = true;
  for (const auto& t : capA)
    for (std::uint32_t v : t) cornerA[v] = true;
  for (std::uint32_t j = 0; j < pb.size(); ++j)
    if (partner[j] != kNone && (!cornerB[j] || !cornerA[partner[j]])) return false;
  std::vector<Edge> borderB = borderOf(capB, [&](std::uint32_t v) { return partner[v]; });
  const std::vector<Edge> borderA = borderOf(capA, [](std::uint32_t v) { return v; });
  if (borderB.size() != borderA.size()) return false;
  for (Edge& e : borderB) std::swap(e.first, e.second);
  std::sort(borderB.begin(), borderB.end());
  if (borderB != borderA) return false;  // (borderOf gives them sorted)

  // The face's plane, its normal out of b; the face flat to within reach,
  // and each solid on its own side of it near the other.
  dvec3 normal(0.0);
  for (const auto& t : capB) normal += glm::cross(pb[t[1]] - pb[t[0]], pb[t[2]] - pb[t[0]]);
  if (!(glm::length(normal) > 0.0)) return false;
  normal = glm::normalize(normal);
  const dvec3 origin = pb[capB[0][0]];
  auto height = [&](const dvec3& p) { return glm::dot(p - origin, normal); };
  for (std::uint32_t j = 0; j < pb.size(); ++j) {
    const double h = height(pb[j]);
    if (partner[j] != kNone ? std::abs(h) > reach : nearA.contains(pb[j]) && !(h < -reach))
      return false;
  }
  for (std::uint32_t i = 0; i < pa.size(); ++i)
    if (!taken[i] && nearB.contains(pa[i]) && !(height(pa[i]) > reach)) return false;

  // The joined mesh: a's points, then b's that have no partner; the two
  // faces left out of it.
  DoubleMesh joined;
  joined.mesh.points = pa;
  std::vector<std::uint32_t> index(pb.size());
  for (std::uint32_t j = 0; j < pb.size(); ++j) {
    if (partner[j] != kNone) {
      index[j] = partner[j];
    } else {
      index[j] = std::uint32_t(joined.mesh.points.size());
      joined.mesh.points.push_back(pb[j]);
    }
  }
  for (std::size_t f = 0; f < a.mesh.size(); ++f) {
    if (inCapA[f]) continue;
    joined.mesh.triangles.push_back(a.mesh.triangles[f]);
    joined.tags.push_back(a.tags[f]);
  }
  for (std::size_t f = 0; f < b.mesh.size(); ++f) {
    if (inCapB[f]) continue;
    const auto& t = b.mesh.triangles[f];
    joined.mesh.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    joined.tags.push_back(b.tags[f]);
  }
  // The points only the dropped faces used (a fan's centre) are left out.
  std::vector<std::uint32_t> renumbered(joined.mesh.points.size(), kNone);
  std::vector<dvec3> used;
  for (auto& t : joined.mesh.triangles)
    for (std::uint32_t& v : t) {
      if (renumbered[v] == kNone) {
        renumbered[v] = std::uint32_t(used.size());
        used.push_back(joined.mesh.points[v]);
      }
      v = renumbered[v];
    }
  joined.mesh.points = std::move(used);
  if (!closedManifold(joined.mesh)) return false;
  a = std::move(joined);
  return true;
}

}  // namespace csgray::detail
