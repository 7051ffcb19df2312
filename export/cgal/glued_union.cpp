#include "export/cgal/glued_union.h"

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <unordered_map>
#include <vector>

namespace csgray::detail {

namespace {

using Vertex = ExactMesh::Vertex_index;
using Face = ExactMesh::Face_index;
using Key = std::array<double, 3>;

// The plane the boxes meet in: the axis and the coordinate, and whether a
// lies below it. Nothing when the boxes overlap with volume, or meet only
// along an edge or at a corner.
struct ContactPlane {
  int axis = 0;
  double at = 0.0;
  bool aBelow = true;
};

std::optional<ContactPlane> contactPlane(const Bounds& boxA, const Bounds& boxB) {
  if (boxA.empty() || boxB.empty()) return std::nullopt;
  const Bounds meet = boxA.intersected(boxB);
  std::optional<ContactPlane> plane;
  for (int k = 0; k < 3; ++k) {
    if (meet.lo[k] < meet.hi[k]) continue;
    if (meet.lo[k] > meet.hi[k] || plane) return std::nullopt;  // apart, or an edge
    if (boxA.hi[k] == boxB.lo[k] && boxA.lo[k] < boxA.hi[k] && boxB.lo[k] < boxB.hi[k])
      plane = ContactPlane{k, boxA.hi[k], true};
    else if (boxB.hi[k] == boxA.lo[k] && boxA.lo[k] < boxA.hi[k] && boxB.lo[k] < boxB.hi[k])
      plane = ContactPlane{k, boxA.lo[k], false};
    else
      return std::nullopt;
  }
  return plane;
}

// A point's coordinates when each is a double (its interval is one
// number), as a primitive's tessellation makes them.
std::optional<Key> doublesOf(const ExactMesh::Point& p) {
  const auto& q = p.approx();
  Key key{};
  for (int k = 0; k < 3; ++k) {
    const auto& c = q[k];
    if (c.inf() != c.sup()) return std::nullopt;
    key[k] = c.inf();
  }
  return key;
}

// A mesh's faces in the contact plane, each as its corners' points in
// order, starting at the least, so that the same triangle gives the same
// key however its corners were numbered.
struct PlaneFaces {
  std::vector<Face> faces;
  std::map<std::array<Key, 3>, Face> byCorners;
  std::map<Key, Vertex> vertices;  // every vertex in the plane
};

std::array<Key, 3> rotatedToLeast(std::array<Key, 3> t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// The faces of `mesh` in the plane, or nothing when a vertex in the plane
// is not a double or not a corner of such a face, or an edge in the plane
// is not a side of one: then the mesh may touch the other elsewhere.
std::optional<PlaneFaces> facesInPlane(const ExactMesh& mesh, const ContactPlane& plane) {
  PlaneFaces out;
  std::unordered_map<std::uint32_t, bool> onPlane;
  for (Vertex v : mesh.vertices()) {
    const auto& c = mesh.point(v).approx()[plane.axis];
    if (c.sup() < plane.at || c.inf() > plane.at) continue;
    const std::optional<Key> key = doublesOf(mesh.point(v));
    if (!key) return std::nullopt;
    if (!out.vertices.emplace(*key, v).second) return std::nullopt;  // two vertices at one point
    onPlane[std::uint32_t(v)] = false;
  }
  auto inPlane = [&](Vertex v) { return onPlane.contains(std::uint32_t(v)); };
  for (Face f : mesh.faces()) {
    std::array<Key, 3> corners;
    int k = 0;
    bool flat = true;
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      flat = flat && inPlane(v);
      if (flat && k < 3) corners[k] = *doublesOf(mesh.point(v));
      ++k;
    }
    if (!flat || k != 3) continue;
    out.faces.push_back(f);
    out.byCorners.emplace(rotatedToLeast(corners), f);
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      onPlane[std::uint32_t(v)] = true;
  }
  for (const auto& [v, corner] : onPlane)
    if (!corner) return std::nullopt;
  std::sort(out.faces.begin(), out.faces.end());
  auto flatFace = [&](Face x) {
    return x != ExactMesh::null_face() && std::binary_search(out.faces.begin(), out.faces.end(), x);
  };
  for (auto e : mesh.edges()) {
    const auto h = mesh.halfedge(e);
    if (!inPlane(mesh.source(h)) || !inPlane(mesh.target(h))) continue;
    if (!flatFace(mesh.face(h)) && !flatFace(mesh.face(mesh.opposite(h)))) return std::nullopt;
  }
  return out;
}

}  // namespace

bool meetInPlane(const Bounds& boxA, const Bounds& boxB) {
  return contactPlane(boxA, boxB).has_value();
}

bool glueAcrossPlane(ExactMesh& a, const ExactMesh& b, const Bounds& boxA, const Bounds& boxB) {
  const std::optional<ContactPlane> plane = contactPlane(boxA, boxB);
  if (!plane) return false;
  const std::optional<PlaneFaces> capsA = facesInPlane(a, *plane);
  if (!capsA || capsA->faces.empty()) return false;
  const std::optional<PlaneFaces> capsB = facesInPlane(b, *plane);
  if (!capsB || capsB->faces.size() != capsA->faces.size()) return false;
  // Each of b's faces must be one of a's turned over.
  for (const auto& [corners, f] : capsB->byCorners) {
    const std::array<Key, 3> turned = rotatedToLeast({corners[0], corners[2], corners[1]});
    if (!capsA->byCorners.contains(turned)) return false;
  }

  // The joined mesh, built anew so that a stays as it was if it fails;
  // b's vertices in the plane become a's at the same point, and vertices
  // that only the dropped faces used are left out.
  ExactMesh joined;
  joined.reserve(a.number_of_vertices() + b.number_of_vertices(),
                 a.number_of_edges() + b.number_of_edges(),
                 a.number_of_faces() + b.number_of_faces());
  auto tags = tagsOf(joined);
  std::vector<Vertex> fromA(a.number_of_vertices() + a.number_of_removed_vertices(),
                            ExactMesh::null_vertex());
  std::vector<Vertex> fromB(b.number_of_vertices() + b.number_of_removed_vertices(),
                            ExactMesh::null_vertex());
  auto vertexOfA = [&](Vertex v) {
    Vertex& w = fromA[v];
    if (w == ExactMesh::null_vertex()) w = joined.add_vertex(a.point(v));
    return w;
  };
  auto vertexOfB = [&](Vertex v) {
    Vertex& w = fromB[v];
    if (w != ExactMesh::null_vertex()) return w;
    const auto& c = b.point(v).approx()[plane->axis];
    if (c.inf() == plane->at && c.sup() == plane->at)
      return w = vertexOfA(capsA->vertices.at(*doublesOf(b.point(v))));
    return w = joined.add_vertex(b.point(v));
  };
  auto copy = [&](const ExactMesh& from, const PlaneFaces& caps, auto&& vertexOf) {
    auto fromTags = tagsOf(from);
    for (Face f : from.faces()) {
      if (std::binary_search(caps.faces.begin(), caps.faces.end(), f)) continue;
      std::array<Vertex, 3> t;
      int k = 0;
      for (Vertex v : CGAL::vertices_around_face(from.halfedge(f), from)) {
        if (k == 3) return false;
        t[k++] = vertexOf(v);
      }
      const Face g = joined.add_face(t[0], t[1], t[2]);
      if (g == ExactMesh::null_face()) return false;
      tags[g] = fromTags[f];
    }
    return true;
  };
  if (!copy(a, *capsA, vertexOfA) || !copy(b, *capsB, vertexOfB) || !CGAL::is_closed(joined))
    return false;
  a = std::move(joined);
  return true;
}

}  // namespace csgray::detail
