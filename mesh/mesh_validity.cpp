#include "mesh/mesh_validity.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <optional>
#include <vector>

namespace csgray {

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

// The faces across each side: across[3f + k] is the face on the other side
// of the edge from corner k to corner k+1 of face f. Empty string when
// every edge has two faces that run along it in opposite directions.
std::string checkEdges(const TriangleMesh& mesh, std::vector<std::uint32_t>& across) {
  const auto& triangles = mesh.triangles;
  // Each side as (undirected edge lo·2³² + hi, corner 3f + k), sorted so
  // that the sides of one edge are neighbours.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sides;
  sides.reserve(3 * triangles.size());
  for (std::uint32_t f = 0; f < triangles.size(); ++f)
    for (std::uint32_t k = 0; k < 3; ++k) {
      std::uint64_t a = triangles[f][k], b = triangles[f][(k + 1) % 3];
      sides.emplace_back(std::min(a, b) << 32 | std::max(a, b), 3 * f + k);
    }
  std::sort(sides.begin(), sides.end());
  auto faceOf = [](std::uint32_t corner) { return corner / 3; };
  auto forward = [&](std::uint32_t corner) {
    const auto& t = triangles[corner / 3];
    return t[corner % 3] < t[(corner % 3 + 1) % 3];
  };
  across.assign(3 * triangles.size(), 0);
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].first == sides[i].first) ++j;
    const auto lo = std::uint32_t(sides[i].first >> 32), hi = std::uint32_t(sides[i].first);
    const std::uint32_t first = sides[i].second;
    // Only an edge that is reported is put in words.
    auto edge = [&] {
      return "the edge from " + vertexText(mesh, lo) + " to " + vertexText(mesh, hi);
    };
    if (j - i == 1)
      return "open: " + edge() + " has one face (face " + std::to_string(faceOf(first)) +
             "); the mesh has a hole there";
    if (j - i > 2) {
      std::string faces;
      for (std::size_t k = i; k < j && k < i + 4; ++k)
        faces += (k > i ? ", " : "") + std::to_string(faceOf(sides[k].second));
      return "non-manifold: " + edge() + " has " + std::to_string(j - i) + " faces (" + faces +
             (j - i > 4 ? ", ...)" : ")");
    }
    const std::uint32_t second = sides[i + 1].second;
    if (forward(first) == forward(second))
      return "inconsistent orientation: faces " + std::to_string(faceOf(first)) + " and " +
             std::to_string(faceOf(second)) + " both run the same way along " + edge() +
             "; one of them is flipped";
    across[first] = faceOf(second);
    across[second] = faceOf(first);
    i = j;
  }
  return "";
}

// With every edge between two faces, the faces around a vertex must form
// one fan; two fans meeting at a vertex (cones tip to tip) do not bound a
// volume there.
std::string checkVertices(const TriangleMesh& mesh, const std::vector<std::uint32_t>& across) {
  const auto& triangles = mesh.triangles;
  std::vector<std::uint32_t> fansAt(mesh.points.size(), 0);
  std::vector<bool> visited(3 * triangles.size(), false);
  for (std::size_t corner = 0; corner < visited.size(); ++corner) {
    if (visited[corner]) continue;
    const std::uint32_t v = triangles[corner / 3][corner % 3];
    if (++fansAt[v] > 1)
      return "non-manifold: " + vertexText(mesh, v) + " joins " +
             "separate fans of faces (the surface touches itself at a point)";
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
  return "";
}

// Where two crossing faces are, for the message: the midpoint of their
// centroids. (Not their intersection: constructing that overflows on the
// huge coordinates a broken file may hold, and the message needs no more.)
std::string meetingPoint(const Surface& surface, FaceIndex f, FaceIndex g) {
  // Two faces with a corner at one place (parts that touch at a point or
  // along an edge) meet there.
  for (auto v : CGAL::vertices_around_face(surface.halfedge(f), surface))
    for (auto w : CGAL::vertices_around_face(surface.halfedge(g), surface))
      if (surface.point(v) == surface.point(w)) {
        const Point& p = surface.point(v);
        return " at " + coordinates(dvec3(p.x(), p.y(), p.z())) +
               ", where two parts touch at a point or an edge";
      }
  dvec3 sum(0.0);
  for (FaceIndex face : {f, g})
    for (auto v : CGAL::vertices_around_face(surface.halfedge(face), surface)) {
      const Point& p = surface.point(v);
      sum += dvec3(p.x(), p.y(), p.z()) / 6.0;
    }
  return " near " + coordinates(sum);
}

}  // namespace

std::string meshDefect(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return "empty: the mesh has no triangles";
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v) {
    const dvec3& p = mesh.points[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return "vertex " + std::to_string(v) + " " + coordinates(p) + " is not finite";
  }
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    for (std::uint32_t v : t)
      if (v >= mesh.points.size())
        return "face " + std::to_string(f) + " names vertex " + std::to_string(v) + " of " +
               std::to_string(mesh.points.size());
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return "degenerate: face " + std::to_string(f) + " uses a vertex twice (vertices " +
             std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
    // Exact: a sliver is fine, only a face without area is degenerate.
    if (CGAL::collinear(point(mesh.points[t[0]]), point(mesh.points[t[1]]),
                        point(mesh.points[t[2]])))
      return "degenerate: face " + std::to_string(f) + " has no area: " + vertexText(mesh, t[0]) +
             ", " + vertexText(mesh, t[1]) + " and " + vertexText(mesh, t[2]) + " are on one line";
  }
  std::vector<std::uint32_t> across;
  if (std::string defect = checkEdges(mesh, across); !defect.empty()) return defect;
  if (std::string defect = checkVertices(mesh, across); !defect.empty()) return defect;

  // A valid polygon mesh now: CGAL's surface, its faces in the same order.
  std::vector<Point> points;
  points.reserve(mesh.points.size());
  for (const dvec3& p : mesh.points) points.push_back(point(p));
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  Surface surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);

  // Stopped at the first pair found (in parallel mode, a few).
  std::vector<std::pair<FaceIndex, FaceIndex>> crossing;
  PMP::self_intersections<CGAL::Parallel_if_available_tag>(surface, std::back_inserter(crossing),
                                                           CGAL::parameters::maximum_number(1));
  if (!crossing.empty()) {
    // The lowest pair, so the message does not depend on the threads.
    std::pair<std::size_t, std::size_t> first{SIZE_MAX, SIZE_MAX};
    FaceIndex a, b;
    for (auto [f, g] : crossing) {
      std::pair<std::size_t, std::size_t> pair{std::min(std::size_t(f), std::size_t(g)),
                                               std::max(std::size_t(f), std::size_t(g))};
      if (pair < first) first = pair, a = f, b = g;
    }
    return "self-intersecting: faces " + std::to_string(first.first) + " and " +
           std::to_string(first.second) + " cross" + meetingPoint(surface, a, b);
  }

  // Every shell closed and apart: outer shells must face out and the
  // shells inside them (cavities) in. does_bound_a_volume also accepts a
  // mesh turned wholly inside out (bounding all of space but the part),
  // which the sign of the volume tells.
  if (mesh.volume() < 0.0)
    return "inside out: the faces point inward (the mesh encloses a negative volume); faces "
           "must run counter-clockwise seen from outside";
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
      return "inside out: the shell of face " + std::to_string(std::size_t(f)) + " (" +
             vertexText(mesh, corners[0]) +
             ") faces the wrong way; outer shells must face out, cavities in";
    }
    return "inside out: the shells do not bound a volume";
  }
  return "";
}

}  // namespace csgray
