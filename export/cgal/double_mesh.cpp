#include "export/cgal/double_mesh.h"

#include <span>
#include <stdexcept>

namespace csgray::detail {

void DoubleMesh::append(const DoubleMesh& other) {
  mesh.append(other.mesh);
  tags.insert(tags.end(), other.tags.begin(), other.tags.end());
}

bool closedManifold(const TriangleMesh& mesh) {
  // Each corner seen from its vertex v: the face (v, next, prev) leaves v
  // towards `next` and comes back from `prev`. The corners of each vertex
  // are gathered in one array (a counting sort by vertex).
  const std::size_t n = mesh.points.size();
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) {
      if (v >= n) return false;
      ++start[v + 1];
    }
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  struct Corner {
    std::uint32_t next, prev;
  };
  std::vector<Corner> corners(start[n]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return false;
    for (int k = 0; k < 3; ++k) corners[fill[t[k]]++] = {t[(k + 1) % 3], t[(k + 2) % 3]};
  }
  // Around v, the face that leaves v towards p follows the one that came
  // back from p: a map of v's corners to themselves when every edge out of
  // v is used once and each edge into v has its reverse, and one cycle
  // through all of them when the faces are one fan.
  for (std::size_t v = 0; v < n; ++v) {
    const std::span<const Corner> around(corners.data() + start[v], start[v + 1] - start[v]);
    if (around.empty()) continue;
    auto leaving = [&](std::uint32_t p) -> std::size_t {
      std::size_t found = around.size();
      for (std::size_t i = 0; i < around.size(); ++i)
        if (around[i].next == p) {
          if (found != around.size()) return around.size() + 1;  // used twice
          found = i;
        }
      return found;
    };
    std::size_t i = 0, steps = 0;
    do {
      i = leaving(around[i].prev);
      if (i >= around.size()) return false;
    } while (++steps < around.size() && i != 0);
    if (i != 0 || steps != around.size()) return false;
  }
  return true;
}

ExactMesh exactOf(const DoubleMesh& doubles) {
  const TriangleMesh& triangles = doubles.mesh;
  ExactMesh mesh;
  mesh.reserve(triangles.points.size(), triangles.size() * 3 / 2, triangles.size());
  for (const dvec3& p : triangles.points) mesh.add_vertex(ExactMesh::Point(p.x, p.y, p.z));
  auto tags = tagsOf(mesh);
  using Vertex = ExactMesh::Vertex_index;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles.triangles[i];
    const auto f = mesh.add_face(Vertex(t[0]), Vertex(t[1]), Vertex(t[2]));
    if (f == ExactMesh::null_face())
      throw std::runtime_error("a mesh made in doubles is not a 2-manifold");
    tags[f] = doubles.tags[i];
  }
  return mesh;
}

std::optional<DoubleMesh> doublesOf(const ExactMesh& exact) {
  DoubleMesh out;
  std::vector<std::uint32_t> index(exact.number_of_vertices() + exact.number_of_removed_vertices());
  out.mesh.points.reserve(exact.number_of_vertices());
  for (auto v : exact.vertices()) {
    const auto& p = exact.point(v);
    dvec3 q;
    for (int k = 0; k < 3; ++k) {
      const auto range = CGAL::to_interval(p[k]);
      if (range.first != range.second) return std::nullopt;
      q[k] = range.first;
    }
    index[v] = std::uint32_t(out.mesh.points.size());
    out.mesh.points.push_back(q);
  }
  out.mesh.triangles.reserve(exact.number_of_faces());
  out.tags.reserve(exact.number_of_faces());
  auto tags = tagsOf(exact);
  for (auto f : exact.faces()) {
    // From the target of the face's halfedge on, as trianglesOf writes
    // it: the order add_face was given.
    TriangleMesh::Triangle t{};
    auto h = exact.halfedge(f);
    for (int k = 0; k < 3; ++k, h = exact.next(h)) t[k] = index[exact.target(h)];
    if (h != exact.halfedge(f)) return std::nullopt;  // not a triangle
    out.mesh.triangles.push_back(t);
    out.tags.push_back(tags ? tags[f] : 0);
  }
  return out;
}

}  // namespace csgray::detail
