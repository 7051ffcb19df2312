#include "export/cgal/mesh_validity.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <glm/geometric.hpp>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

#include "engine/cancellation.h"
#include "export/cgal/box_pairs.h"
#include "export/triangle_filters.h"
#include "tessellation/mesh_edges.h"

namespace csgray::detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
using FaceIndex = Surface::Face_index;
namespace PMP = CGAL::Polygon_mesh_processing;

std::string coordinates(const dvec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x, p.y, p.z);
  return text;
}

std::string vertexText(const TriangleMesh& mesh, std::uint32_t v) {
  return "vertex " + std::to_string(v) + " " + coordinates(mesh.points[v]);
}

Point point(const dvec3& p) { return Point(p.x, p.y, p.z); }

MeshDefect defect(MeshDefect::Kind kind, std::string text) { return {kind, std::move(text)}; }

// The faces across each side: across[3f + k] is the face on the other side
// of the edge from corner k to corner k+1 of face f. No defect when every
// edge has two faces that run along it in opposite directions
// (tessellation/mesh_edges.h).
MeshDefect checkEdges(const TriangleMesh& mesh, std::vector<std::uint32_t>& across) {
  const std::vector<EdgeUse> uses = edgeUses(mesh.triangles);
  auto faceOf = [](const EdgeUse& use) { return use.side / 3; };
  across.assign(3 * mesh.triangles.size(), 0);
  for (std::size_t i = 0; i < uses.size();) {
    const std::span<const EdgeUse> edge = usesOfEdge(uses, i);
    i += edge.size();
    const auto lo = std::uint32_t(edge[0].edge >> 32), hi = std::uint32_t(edge[0].edge);
    // Only an edge that is reported is put in words.
    auto where = [&] {
      return "the edge from " + vertexText(mesh, lo) + " to " + vertexText(mesh, hi);
    };
    switch (edgeFault(edge)) {
      case EdgeFault::Open:
        return defect(MeshDefect::Kind::Open, "open: " + where() + " has one face (face " +
                                                  std::to_string(faceOf(edge[0])) +
                                                  "); the mesh has a hole there");
      case EdgeFault::NonManifold: {
        std::string faces;
        for (std::size_t k = 0; k < edge.size() && k < 4; ++k)
          faces += (k > 0 ? ", " : "") + std::to_string(faceOf(edge[k]));
        return defect(MeshDefect::Kind::NonManifold,
                      "non-manifold: " + where() + " has " + std::to_string(edge.size()) +
                          " faces (" + faces + (edge.size() > 4 ? ", ...)" : ")"));
      }
      case EdgeFault::SameWay:
        return defect(MeshDefect::Kind::InconsistentOrientation,
                      "inconsistent orientation: faces " + std::to_string(faceOf(edge[0])) +
                          " and " + std::to_string(faceOf(edge[1])) +
                          " both run the same way along " + where() + "; one of them is flipped");
      case EdgeFault::None:
        across[edge[0].side] = faceOf(edge[1]);
        across[edge[1].side] = faceOf(edge[0]);
        break;
    }
  }
  return {};
}

// With every edge between two faces, the faces around a vertex must form
// one fan; two fans meeting at a vertex (cones tip to tip) do not bound a
// volume there.
MeshDefect checkVertices(const TriangleMesh& mesh, const std::vector<std::uint32_t>& across) {
  const auto& triangles = mesh.triangles;
  std::vector<std::uint32_t> fansAt(mesh.points.size(), 0);
  std::vector<bool> visited(3 * triangles.size(), false);
  for (std::size_t corner = 0; corner < visited.size(); ++corner) {
    if (visited[corner]) continue;
    const std::uint32_t v = triangles[corner / 3][corner % 3];
    if (++fansAt[v] > 1)
      return defect(MeshDefect::Kind::NonManifold,
                    "non-manifold: " + vertexText(mesh, v) + " joins " +
                        "separate fans of faces (the surface touches itself at a point)");
    // Around v: from face f, where v is corner k, the edge v → corner k+1
    // leads to the next face.
    std::size_t c = corner;
    for (std::size_t steps = 0; !visited[c] && steps <= visited.size(); ++steps) {
      visited[c] = true;
      std::uint32_t next = across[c];
      const auto& t = triangles[next];
      c = 3 * std::size_t(next) + std::size_t(t[0] == v ? 0 : t[1] == v ? 1 : 2);
    }
  }
  return {};
}

// The connected pieces of the surface: faces joined across their edges.
std::size_t shellCount(const TriangleMesh& mesh, const std::vector<std::uint32_t>& across) {
  std::vector<bool> reached(mesh.triangles.size(), false);
  std::vector<std::uint32_t> todo;
  std::size_t shells = 0;
  for (std::uint32_t start = 0; start < reached.size(); ++start) {
    if (reached[start]) continue;
    ++shells;
    reached[start] = true;
    todo.push_back(start);
    while (!todo.empty()) {
      const std::uint32_t f = todo.back();
      todo.pop_back();
      for (int k = 0; k < 3; ++k)
        if (std::uint32_t g = across[3 * f + k]; !reached[g]) reached[g] = true, todo.push_back(g);
    }
  }
  return shells;
}

// Where two crossing faces meet, for the message: in plain doubles, and
// only points that come out finite (CGAL's constructions in Epick may
// overflow on the huge coordinates a broken file holds, and its exact
// fallback then stops the process on a NaN), so a place to look.
std::string meetingPoint(const TriangleMesh& mesh, std::uint32_t f, std::uint32_t g) {
  const auto &a = mesh.triangles[f], &b = mesh.triangles[g];
  // Two faces with a corner at one place (parts that touch at a point or
  // along an edge) meet there.
  for (std::uint32_t v : a)
    for (std::uint32_t w : b)
      if (mesh.points[v] == mesh.points[w])
        return " at " + coordinates(mesh.points[v]) +
               ", where two parts touch at a point or an edge";
  // Else the middle of where the edges of each pierce the other (in
  // doubles: a place to look, not a proof), or of their corners if none
  // does (faces folded onto each other in one plane).
  dvec3 sum(0.0);
  int found = 0;
  for (int side = 0; side < 2; ++side) {
    const auto& edges = side == 0 ? a : b;
    const auto& face = side == 0 ? b : a;
    const dvec3 &f0 = mesh.points[face[0]], &f1 = mesh.points[face[1]], &f2 = mesh.points[face[2]];
    const dvec3 normal = glm::cross(f1 - f0, f2 - f0);
    const double area2 = glm::dot(normal, normal);
    if (!(area2 > 0.0)) continue;
    for (int k = 0; k < 3; ++k) {
      const dvec3 &p = mesh.points[edges[k]], &q = mesh.points[edges[(k + 1) % 3]];
      const double dp = glm::dot(normal, p - f0), dq = glm::dot(normal, q - f0);
      if ((dp > 0.0 && dq > 0.0) || (dp < 0.0 && dq < 0.0) || dp == dq) continue;
      const dvec3 x = p + (dp / (dp - dq)) * (q - p);
      // Inside the face: on the inner side of each of its edges.
      const double u = glm::dot(glm::cross(f1 - x, f2 - x), normal);
      const double v = glm::dot(glm::cross(f2 - x, f0 - x), normal);
      const double w = glm::dot(glm::cross(f0 - x, f1 - x), normal);
      const double slack = -1e-9 * area2;
      if (!(u >= slack && v >= slack && w >= slack) || !std::isfinite(x.x + x.y + x.z)) continue;
      sum += x;
      ++found;
    }
  }
  if (found > 0) return " near " + coordinates(sum / double(found));
  sum = dvec3(0.0);
  for (std::uint32_t v : a) sum += mesh.points[v] / 6.0;
  for (std::uint32_t v : b) sum += mesh.points[v] / 6.0;
  return " near " + coordinates(sum);
}

// Do faces f and g of a closed 2-manifold mesh meet anywhere but at the
// corners and the edge they share? Exact predicates throughout.
//  - No shared corner: the triangles must not meet at all.
//  - One shared corner v: the two triangles, both convex and holding v,
//    meet elsewhere exactly when the edge of one opposite v meets the
//    other triangle (the far side of their common part lies on such an
//    edge).
//  - A shared edge: the triangles meet only along it unless they lie in
//    one plane on the same side of it (folded onto each other).
bool facesCross(const TriangleMesh& mesh, std::uint32_t f, std::uint32_t g) {
  const auto &a = mesh.triangles[f], &b = mesh.triangles[g];
  int shared = 0, aOnly = -1, bOnly = -1;
  for (int i = 0; i < 3; ++i) {
    bool inB = a[i] == b[0] || a[i] == b[1] || a[i] == b[2];
    bool inA = b[i] == a[0] || b[i] == a[1] || b[i] == a[2];
    shared += inB;
    if (!inB) aOnly = i;
    if (!inA) bOnly = i;
  }
  // The corners of each, from corner `first` on: the filters in doubles
  // answer most pairs before CGAL's exact predicates are asked.
  auto corners = [&](const TriangleMesh::Triangle& t, int first, dvec3 out[3]) {
    for (int k = 0; k < 3; ++k) out[k] = mesh.points[t[(first + k) % 3]];
  };
  dvec3 ca[3], cb[3];
  auto p = [&](std::uint32_t v) { return point(mesh.points[v]); };
  // (Made only for the few pairs the filters leave to CGAL.)
  auto triangle = [&](const TriangleMesh::Triangle& t) {
    return Kernel::Triangle_3(p(t[0]), p(t[1]), p(t[2]));
  };
  switch (shared) {
    case 0:
      corners(a, 0, ca), corners(b, 0, cb);
      return !certainlyApart(ca, cb) && CGAL::do_intersect(triangle(a), triangle(b));
    case 1: {
      // av, bv: where the shared corner is in each; the edges opposite it.
      int av = 0, bv = 0;
      while (a[av] != b[0] && a[av] != b[1] && a[av] != b[2]) ++av;
      while (b[bv] != a[av]) ++bv;
      corners(a, av, ca), corners(b, bv, cb);
      if (certainlyMeetOnlyAtCorner(ca, cb)) return false;
      const Kernel::Segment_3 aFar(p(a[(av + 1) % 3]), p(a[(av + 2) % 3]));
      const Kernel::Segment_3 bFar(p(b[(bv + 1) % 3]), p(b[(bv + 2) % 3]));
      return CGAL::do_intersect(aFar, triangle(b)) || CGAL::do_intersect(bFar, triangle(a));
    }
    case 2: {
      corners(a, 0, ca), corners(b, 0, cb);
      if (certainlyNotFolded(ca, cb)) return false;
      const Point u = p(a[(aOnly + 1) % 3]), w = p(a[(aOnly + 2) % 3]);
      const Point ra = p(a[aOnly]), rb = p(b[bOnly]);
      return CGAL::coplanar(u, w, ra, rb) &&
             CGAL::coplanar_orientation(u, w, ra, rb) == CGAL::POSITIVE;
    }
    default:
      return true;  // the same face twice
  }
}

// The crossing pair of faces with the lowest indices, if any: faces whose
// boxes meet are found by CGAL's box intersection, split across the
// threads (box_pairs.h), then tested exactly. Several threads may find
// crossings; the lowest pair keeps the message the same whatever the
// threads did. (PMP's self_intersections does the same with a general
// test of each pair; this one knows the mesh is a closed 2-manifold,
// which took plate(8)'s check from 0.23 to 0.16 s. A BVH of the boxes
// took longer to build than CGAL's box intersection took in all.)
std::optional<std::pair<std::uint32_t, std::uint32_t>> firstCrossing(const TriangleMesh& mesh) {
  std::vector<FaceBox> boxes;
  boxes.reserve(mesh.triangles.size());
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    boxes.push_back(faceBox(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], f));
  }
  std::mutex lock;
  std::optional<std::pair<std::uint32_t, std::uint32_t>> first;
  std::atomic<std::size_t> found = 0;
  // The longest step of an export's last test (a second for a million
  // faces): the caller's cancel is read at each pair, on every thread.
  const std::atomic<bool>* cancel = cancelFlag();
  forEachMeetingPair(boxes, [&](std::uint32_t x, std::uint32_t y) {
    stopIfCancelled(cancel);
    // A broken mesh may cross itself millions of times: some are enough.
    if (found.load(std::memory_order_relaxed) > 64) return;
    const std::uint32_t f = std::min(x, y), g = std::max(x, y);
    if (!facesCross(mesh, f, g)) return;
    ++found;
    std::lock_guard guard(lock);
    if (!first || std::pair(f, g) < *first) first = std::pair(f, g);
  });
  return first;
}

}  // namespace

MeshDefect meshDefect(const TriangleMesh& mesh) {
  using Kind = MeshDefect::Kind;
  stopIfCancelled();  // (a large mesh's test takes seconds: engine/cancellation.h)
  if (mesh.triangles.empty()) return defect(Kind::Empty, "empty: the mesh has no triangles");
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v) {
    const dvec3& p = mesh.points[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return defect(Kind::NotFinite,
                    "vertex " + std::to_string(v) + " " + coordinates(p) + " is not finite");
  }
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    for (std::uint32_t v : t)
      if (v >= mesh.points.size())
        return defect(Kind::BadIndex, "face " + std::to_string(f) + " names vertex " +
                                          std::to_string(v) + " of " +
                                          std::to_string(mesh.points.size()));
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return defect(Kind::Degenerate, "degenerate: face " + std::to_string(f) +
                                          " uses a vertex twice (vertices " + std::to_string(t[0]) +
                                          ", " + std::to_string(t[1]) + ", " +
                                          std::to_string(t[2]) + ")");
    // Exact: a sliver is fine, only a face without area is degenerate.
    if (CGAL::collinear(point(mesh.points[t[0]]), point(mesh.points[t[1]]),
                        point(mesh.points[t[2]])))
      return defect(Kind::Degenerate, "degenerate: face " + std::to_string(f) + " has no area: " +
                                          vertexText(mesh, t[0]) + ", " + vertexText(mesh, t[1]) +
                                          " and " + vertexText(mesh, t[2]) + " are on one line");
  }
  std::vector<std::uint32_t> across;
  stopIfCancelled();
  if (MeshDefect found = checkEdges(mesh, across); !found.valid()) return found;
  stopIfCancelled();
  if (MeshDefect found = checkVertices(mesh, across); !found.valid()) return found;

  stopIfCancelled();
  if (auto crossing = firstCrossing(mesh))
    return defect(Kind::SelfIntersecting,
                  "self-intersecting: faces " + std::to_string(crossing->first) + " and " +
                      std::to_string(crossing->second) + " cross" +
                      meetingPoint(mesh, crossing->first, crossing->second));

  // Every shell closed and apart: outer shells must face out and the
  // shells inside them (cavities) in. does_bound_a_volume also accepts a
  // mesh turned wholly inside out (bounding all of space but the part),
  // which the sign of the volume tells.
  if (mesh.volume() < 0.0)
    return defect(Kind::InsideOut,
                  "inside out: the faces point inward (the mesh encloses a negative volume); "
                  "faces must run counter-clockwise seen from outside");
  // One shell with a positive volume faces out: only nested shells need
  // CGAL's test (a plate's export is one shell, and skips its cost).
  if (shellCount(mesh, across) == 1) return {};
  // A valid polygon mesh now: CGAL's surface, its faces in the same order.
  std::vector<Point> points;
  points.reserve(mesh.points.size());
  for (const dvec3& p : mesh.points) points.push_back(point(p));
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  Surface surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
  if (!PMP::does_bound_a_volume(surface)) {
    // Name a shell that orienting the whole would turn.
    Surface oriented = surface;
    PMP::orient_to_bound_a_volume(oriented);
    for (FaceIndex f : oriented.faces()) {
      // Turned when the oriented face runs s → t against the original.
      auto h = oriented.halfedge(f);
      const std::size_t s = oriented.source(h), t = oriented.target(h);
      const auto& corners = mesh.triangles[std::size_t(f)];
      bool kept = false;
      for (int k = 0; k < 3; ++k) kept |= corners[k] == s && corners[(k + 1) % 3] == t;
      if (kept) continue;
      return defect(Kind::InsideOut,
                    "inside out: the shell of face " + std::to_string(std::size_t(f)) + " (" +
                        vertexText(mesh, corners[0]) +
                        ") faces the wrong way; outer shells must face out, cavities in");
    }
    return defect(Kind::InsideOut, "inside out: the shells do not bound a volume");
  }
  return {};
}

}  // namespace csgray::detail
