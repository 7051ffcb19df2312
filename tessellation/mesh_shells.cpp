#include "tessellation/mesh_shells.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>

namespace csgray::detail {

MeshShells meshShells(const TriangleMesh& mesh) {
  // Union-find over the points, joined along every triangle's edges.
  std::vector<std::uint32_t> parent(mesh.points.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const TriangleMesh::Triangle& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) {
      const std::uint32_t a = root(t[0]), b = root(t[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  MeshShells shells;
  shells.shellOfPoint.resize(mesh.points.size());
  std::vector<std::uint32_t> number(mesh.points.size(), std::numeric_limits<std::uint32_t>::max());
  std::vector<bool> used(mesh.points.size(), false);
  for (const TriangleMesh::Triangle& t : mesh.triangles)
    for (std::uint32_t v : t) used[v] = true;
  std::uint32_t next = 0;
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v) {
    const std::uint32_t r = root(v);
    if (number[r] == std::numeric_limits<std::uint32_t>::max()) {
      number[r] = next++;
      if (used[v]) ++shells.count;
    }
    shells.shellOfPoint[v] = number[r];
  }
  // Signed volumes by the divergence theorem: a tetrahedron from the origin
  // on each triangle, a·(b × c)/6.
  std::vector<double> volume(next, 0.0);
  for (const TriangleMesh::Triangle& t : mesh.triangles)
    volume[shells.shellOfPoint[t[0]]] +=
        glm::dot(mesh.points[t[0]], glm::cross(mesh.points[t[1]], mesh.points[t[2]])) / 6.0;
  for (double v : volume) shells.cavities += v < 0.0;
  return shells;
}

namespace {

// Holds points of the mesh against the points and faces near them along
// x, sweeping along x: nearPoints(i, j) for each pair of points less than
// `reach` apart along x, nearFace(i, f) for a point and each face whose
// extent along x comes within `reach` of it. `reach` may shrink as they
// are called. Shells far apart beside each other along x make this
// quadratic: false where the pairs ran past a budget, before all were
// seen.
template <class NearPoints, class NearFace>
bool sweepNearPairs(const TriangleMesh& mesh, const double& reach, NearPoints&& nearPoints,
                    NearFace&& nearFace) {
  std::vector<std::uint32_t> order(mesh.points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return mesh.points[a].x < mesh.points[b].x; });
  bool complete = true;
  std::size_t budget = 20'000'000;
  auto spend = [&] {
    if (budget == 0) return complete = false;
    --budget;
    return true;
  };
  for (std::size_t i = 0; i < order.size() && budget > 0; ++i) {
    const dvec3& p = mesh.points[order[i]];
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      if (mesh.points[order[j]].x - p.x >= reach) break;
      if (!spend()) break;
      nearPoints(order[i], order[j]);
    }
  }
  // Where one shell has a vertex and the other a face (a cone's tip on a
  // box), they come closer than any two of their vertices.
  std::vector<std::uint32_t> faces(mesh.triangles.size());
  std::iota(faces.begin(), faces.end(), 0u);
  auto lowX = [&](std::uint32_t f) {
    const TriangleMesh::Triangle& t = mesh.triangles[f];
    return std::min({mesh.points[t[0]].x, mesh.points[t[1]].x, mesh.points[t[2]].x});
  };
  auto highX = [&](std::uint32_t f) {
    const TriangleMesh::Triangle& t = mesh.triangles[f];
    return std::max({mesh.points[t[0]].x, mesh.points[t[1]].x, mesh.points[t[2]].x});
  };
  std::sort(faces.begin(), faces.end(),
            [&](std::uint32_t a, std::uint32_t b) { return lowX(a) < lowX(b); });
  std::vector<std::uint32_t> active;  // faces begun along x, not yet left behind
  std::size_t nextFace = 0;
  budget = 20'000'000;
  for (std::size_t i = 0; i < order.size() && budget > 0; ++i) {
    const dvec3& p = mesh.points[order[i]];
    while (nextFace < faces.size() && lowX(faces[nextFace]) <= p.x + reach)
      active.push_back(faces[nextFace++]);
    std::erase_if(active, [&](std::uint32_t f) { return highX(f) < p.x - reach; });
    for (std::uint32_t f : active) {
      if (!spend()) break;
      nearFace(order[i], f);
    }
  }
  return complete;
}

double distanceToFace(const TriangleMesh& mesh, std::uint32_t point, std::uint32_t face) {
  const TriangleMesh::Triangle& t = mesh.triangles[face];
  return pointTriangleDistance(mesh.points[point], mesh.points[t[0]], mesh.points[t[1]],
                               mesh.points[t[2]]);
}

}  // namespace

ShellApproach nearestShells(const TriangleMesh& mesh, const MeshShells& shells) {
  // Each pair within the best distance yet along x; past the budget, the
  // best so far (an upper bound).
  ShellApproach best{std::numeric_limits<double>::infinity()};
  const auto& shellOf = shells.shellOfPoint;
  sweepNearPairs(
      mesh, best.distance,
      [&](std::uint32_t i, std::uint32_t j) {
        if (shellOf[i] == shellOf[j]) return;
        const double d = glm::length(mesh.points[j] - mesh.points[i]);
        if (d < best.distance) best = {d, mesh.points[i], mesh.points[j]};
      },
      [&](std::uint32_t i, std::uint32_t f) {
        if (shellOf[mesh.triangles[f][0]] == shellOf[i]) return;
        const double d = distanceToFace(mesh, i, f);
        if (d < best.distance) best = {d, mesh.points[i], mesh.points[i]};
      });
  return best;
}

std::optional<std::vector<std::uint32_t>> shellGroupsWithin(const TriangleMesh& mesh,
                                                            const MeshShells& shells,
                                                            double distance) {
  std::uint32_t numbers = 0;
  for (std::uint32_t s : shells.shellOfPoint) numbers = std::max(numbers, s + 1);
  std::vector<std::uint32_t> group(numbers);
  std::iota(group.begin(), group.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (group[x] != x) x = group[x] = group[group[x]];
    return x;
  };
  auto join = [&](std::uint32_t point, std::uint32_t other, double d) {
    const std::uint32_t a = root(shells.shellOfPoint[point]), b = root(shells.shellOfPoint[other]);
    if (a != b && d <= distance) group[std::max(a, b)] = std::min(a, b);
  };
  // The reach a hair past the distance: pairs exactly that far apart too.
  const double reach = std::nextafter(distance, INFINITY);
  const bool complete = sweepNearPairs(
      mesh, reach,
      [&](std::uint32_t i, std::uint32_t j) {
        if (root(shells.shellOfPoint[i]) != root(shells.shellOfPoint[j]))
          join(i, j, glm::length(mesh.points[j] - mesh.points[i]));
      },
      [&](std::uint32_t i, std::uint32_t f) {
        const std::uint32_t corner = mesh.triangles[f][0];
        if (root(shells.shellOfPoint[i]) != root(shells.shellOfPoint[corner]))
          join(i, corner, distanceToFace(mesh, i, f));
      });
  if (!complete) return std::nullopt;
  for (std::uint32_t& g : group) g = root(g);
  return group;
}

}  // namespace csgray::detail
