#include "tessellation/mesh_shells.h"

#include <algorithm>
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
  return shells;
}

ShellApproach nearestShells(const TriangleMesh& mesh, const MeshShells& shells) {
  // A sweep along x: sorted by x, each point is held against the points
  // after it until they are further along x than the best distance yet.
  std::vector<std::uint32_t> order(mesh.points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return mesh.points[a].x < mesh.points[b].x; });
  ShellApproach best{std::numeric_limits<double>::infinity()};
  // Shells far apart beside each other along x make this quadratic: past
  // a budget of pairs the best so far is given (an upper bound).
  std::size_t budget = 20'000'000;
  for (std::size_t i = 0; i < order.size() && budget > 0; ++i) {
    const dvec3& p = mesh.points[order[i]];
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const dvec3& q = mesh.points[order[j]];
      if (q.x - p.x >= best.distance || budget-- == 0) break;
      if (shells.shellOfPoint[order[i]] == shells.shellOfPoint[order[j]]) continue;
      const double d = glm::length(q - p);
      if (d < best.distance) best = {d, p, q};
    }
  }
  // Shells that touch where one has a vertex and the other a face (a
  // cone's tip on a box) come closer than any two of their vertices: each
  // vertex is held against the faces of other shells within the best
  // distance yet along x, sweeping both along x.
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
    while (nextFace < faces.size() && lowX(faces[nextFace]) <= p.x + best.distance)
      active.push_back(faces[nextFace++]);
    std::erase_if(active, [&](std::uint32_t f) { return highX(f) < p.x - best.distance; });
    for (std::uint32_t f : active) {
      if (budget-- == 0) break;
      const TriangleMesh::Triangle& t = mesh.triangles[f];
      if (shells.shellOfPoint[t[0]] == shells.shellOfPoint[order[i]]) continue;
      const double d =
          pointTriangleDistance(p, mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
      if (d < best.distance) best = {d, p, p};
    }
  }
  return best;
}

}  // namespace csgray::detail
