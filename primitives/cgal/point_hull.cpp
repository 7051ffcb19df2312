#include "primitives/cgal/point_hull.h"

#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace csgray::detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Point2 = Kernel::Point_2;
using HullMesh = CGAL::Surface_mesh<Point3>;

// Relative to the set's size: what counts as on a line or a plane.
constexpr double kFlat = 1e-9;

dvec3 vec(const Point3& p) { return {p.x(), p.y(), p.z()}; }

// The plane of a loop by Newell's method (Sutherland, Sproull and
// Schumacker, "A Characterization of Ten Hidden-Surface Algorithms", 1974),
// which averages over every corner rather than trusting three.
Polytope::Face faceOf(const std::vector<dvec3>& vertices, std::vector<std::uint32_t> loop) {
  dvec3 n(0.0), centre(0.0);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const dvec3& a = vertices[loop[i]];
    const dvec3& b = vertices[loop[(i + 1) % loop.size()]];
    n += dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    centre += a;
  }
  n = glm::normalize(n);
  centre /= double(loop.size());
  return {n, glm::dot(n, centre), std::move(loop)};
}

// Union-find over the hull's triangles: one set per plane.
class PlaneGroups {
 public:
  explicit PlaneGroups(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::size_t> parent_;
};

Polytope solidHull(std::span<const dvec3> points) {
  std::vector<Point3> given;
  given.reserve(points.size());
  for (const dvec3& p : points) given.emplace_back(p.x, p.y, p.z);
  HullMesh mesh;
  CGAL::convex_hull_3(given.begin(), given.end(), mesh);

  PlaneGroups groups(mesh.number_of_faces());
  for (auto e : mesh.edges()) {
    auto h = mesh.halfedge(e), o = mesh.opposite(h);
    const Point3& a = mesh.point(mesh.source(h));
    const Point3& b = mesh.point(mesh.target(h));
    const Point3& c = mesh.point(mesh.target(mesh.next(h)));
    const Point3& d = mesh.point(mesh.target(mesh.next(o)));
    if (CGAL::coplanar(a, b, c, d)) groups.join(mesh.face(h).idx(), mesh.face(o).idx());
  }
  auto groupOf = [&](HullMesh::Halfedge_index h) { return groups.find(mesh.face(h).idx()); };

  // A corner lies in three planes or more; a point where only two meet is
  // on an edge, and one inside a face is in one.
  Polytope result;
  result.dimension = 3;
  std::vector<std::uint32_t> index(mesh.number_of_vertices(), UINT32_MAX);
  for (auto v : mesh.vertices()) {
    std::vector<std::size_t> around;
    for (auto h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
      std::size_t g = groupOf(h);
      if (std::find(around.begin(), around.end(), g) == around.end()) around.push_back(g);
    }
    if (around.size() < 3) continue;
    index[v.idx()] = static_cast<std::uint32_t>(result.vertices.size());
    result.vertices.push_back(vec(mesh.point(v)));
  }

  // Each plane's boundary: its halfedges whose other side is another
  // plane's, walked in the triangles' order (counter-clockwise from
  // outside), turning about each corner past the edges inside the plane.
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<bool> walked(mesh.number_of_halfedges(), false);
  for (auto start : mesh.halfedges()) {
    std::size_t g = groupOf(start);
    if (walked[start.idx()] || groupOf(mesh.opposite(start)) == g) continue;
    std::vector<std::uint32_t> loop;
    auto h = start;
    do {
      walked[h.idx()] = true;
      std::uint32_t corner = index[mesh.source(h).idx()];
      if (corner != UINT32_MAX) loop.push_back(corner);
      auto next = mesh.next(h);
      while (groupOf(mesh.opposite(next)) == g) next = mesh.next(mesh.opposite(next));
      h = next;
    } while (h != start);
    loops.push_back(std::move(loop));
  }
  // CGAL lists the hull's vertices and faces in an order that follows
  // where its working data lay in memory (a longer name of the output
  // file changed it, and so the export's triangles). The polytope is put
  // in an order of its own: the corners by their coordinates, each loop
  // from its least corner, the faces by their loops.
  std::vector<std::uint32_t> byPlace(result.vertices.size()), rank(result.vertices.size());
  std::iota(byPlace.begin(), byPlace.end(), 0u);
  std::sort(byPlace.begin(), byPlace.end(), [&](std::uint32_t a, std::uint32_t b) {
    const dvec3 &p = result.vertices[a], &q = result.vertices[b];
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  });
  std::vector<dvec3> sorted(result.vertices.size());
  for (std::uint32_t i = 0; i < byPlace.size(); ++i) {
    rank[byPlace[i]] = i;
    sorted[i] = result.vertices[byPlace[i]];
  }
  result.vertices = std::move(sorted);
  for (std::vector<std::uint32_t>& loop : loops) {
    for (std::uint32_t& corner : loop) corner = rank[corner];
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  }
  std::sort(loops.begin(), loops.end());
  for (std::vector<std::uint32_t>& loop : loops)
    result.faces.push_back(faceOf(result.vertices, std::move(loop)));
  return result;
}

// Points that lie in the plane through p0 with normal n: their hull in
// that plane, by CGAL's convex_hull_2 on coordinates along u (in the
// plane) and n × u, as the polygon's two sides.
Polytope flatHull(std::span<const dvec3> points, const dvec3& p0, const dvec3& n, const dvec3& u) {
  dvec3 w = glm::cross(n, u);
  std::vector<Point2> plane;
  plane.reserve(points.size());
  for (const dvec3& p : points) plane.emplace_back(glm::dot(p - p0, u), glm::dot(p - p0, w));
  std::vector<std::size_t> all(points.size()), corners;
  std::iota(all.begin(), all.end(), 0);
  using Traits =
      CGAL::Convex_hull_traits_adapter_2<Kernel, CGAL::Pointer_property_map<Point2>::type>;
  CGAL::convex_hull_2(all.begin(), all.end(), std::back_inserter(corners),
                      Traits(CGAL::make_property_map(plane)));
  Polytope result;
  result.dimension = 2;
  std::vector<std::uint32_t> up, down;
  for (std::size_t i : corners) {
    up.push_back(static_cast<std::uint32_t>(result.vertices.size()));
    result.vertices.push_back(points[i]);
  }
  down.assign(up.rbegin(), up.rend());
  // Counter-clockwise in (u, w), w = n × u: counter-clockwise seen from +n.
  Polytope::Face top = faceOf(result.vertices, up), bottom = faceOf(result.vertices, down);
  result.faces = {top, bottom};
  return result;
}

}  // namespace

Polytope pointHull(std::span<const dvec3> points) {
  if (points.empty()) throw std::invalid_argument("hull: no points");
  Bounds box;
  for (const dvec3& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::invalid_argument("hull: a point is not finite");
    box.include(p);
  }
  const double flat = kFlat * glm::length(box.size());
  // The point farthest from the first, then the one farthest from their
  // line: the best conditioned line and plane for the dimension tests.
  const dvec3 p0 = points[0];
  auto farthest = [&](auto&& distance) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < points.size(); ++i)
      if (distance(points[i]) > distance(points[best])) best = i;
    return points[best];
  };
  const dvec3 p1 = farthest([&](const dvec3& p) { return glm::length(p - p0); });
  Polytope result;
  if (glm::length(p1 - p0) <= flat) {
    result.vertices = {p0};
    return result;
  }
  const dvec3 e = glm::normalize(p1 - p0);
  auto offLine = [&](const dvec3& p) { return glm::length(glm::cross(p - p0, e)); };
  const dvec3 p2 = farthest(offLine);
  if (offLine(p2) <= flat) {
    auto along = [&](const dvec3& p) { return glm::dot(p - p0, e); };
    result.dimension = 1;
    result.vertices = {farthest([&](const dvec3& p) { return -along(p); }), farthest(along)};
    return result;
  }
  const dvec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  auto offPlane = [&](const dvec3& p) { return std::abs(glm::dot(p - p0, n)); };
  if (offPlane(farthest(offPlane)) <= flat) return flatHull(points, p0, n, e);
  return solidHull(points);
}

}  // namespace csgray::detail
