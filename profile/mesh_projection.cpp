#include "profile/mesh_projection.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "profile/region_evaluation.h"

namespace csgray::detail {

namespace {

using Segment = std::array<dvec2, 2>;

// Which side of z = 0 a point is on, a point on the plane counted as
// `onPlaneAbove` says (a symbolic shift of the plane, so that every edge
// either crosses it once or not at all).
bool above(const dvec3& p, bool onPlaneAbove) { return p.z > 0.0 || (p.z == 0.0 && onPlaneAbove); }

// Where the edge from the point above to the point below meets the plane.
// Both triangles of the edge call this with the same two points in the same
// order, so they get the same double: the segments join exactly.
dvec2 crossing(const dvec3& up, const dvec3& down) {
  if (up.z == 0.0) return dvec2(up);
  if (down.z == 0.0) return dvec2(down);
  const double t = up.z / (up.z - down.z);
  return dvec2(up) + t * (dvec2(down) - dvec2(up));
}

// The segments of the section with the plane shifted as onPlaneAbove says:
// a triangle whose corners are on both sides has one edge that goes down
// through the plane and one that comes back up; with the triangle's corners
// counterclockwise seen from outside, the solid is on the left of the
// segment from the first crossing to the second.
void addSectionSegments(const TriangleMesh& mesh, bool onPlaneAbove,
                        std::vector<Segment>& segments) {
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    const std::array<dvec3, 3> p = {mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]};
    const std::array<bool, 3> side = {above(p[0], onPlaneAbove), above(p[1], onPlaneAbove),
                                      above(p[2], onPlaneAbove)};
    if (side[0] == side[1] && side[1] == side[2]) continue;
    dvec2 goingDown{0.0}, comingUp{0.0};
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (side[i] && !side[j]) goingDown = crossing(p[i], p[j]);
      if (!side[i] && side[j]) comingUp = crossing(p[j], p[i]);
    }
    segments.push_back({goingDown, comingUp});
  }
}

}  // namespace

Profile meshSection(const TriangleMesh& mesh, PlaneShift shift) {
  std::vector<Segment> segments;
  addSectionSegments(mesh, shift == PlaneShift::Down, segments);
  return nonZeroFill(segments);
}

bool touchesPlane(const TriangleMesh& mesh) {
  return std::any_of(mesh.points.begin(), mesh.points.end(),
                     [](const dvec3& p) { return p.z == 0.0; });
}

Profile meshShadow(const TriangleMesh& mesh) {
  // The edges of the upward triangles, each counted +1 from its lower
  // point index to its higher and -1 the other way: an edge between two
  // of them comes to 0. Sorted, so that the result does not depend on
  // the order of a hash table.
  std::vector<std::pair<std::uint64_t, int>> edges;
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    const dvec2 a(mesh.points[t[0]]), b(mesh.points[t[1]]), c(mesh.points[t[2]]);
    const dvec2 u = b - a, v = c - a;
    if (!(u.x * v.y - u.y * v.x > 0.0)) continue;  // facing down or seen edge on
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t from = t[i], to = t[(i + 1) % 3];
      if (from < to)
        edges.emplace_back(std::uint64_t{from} << 32 | to, 1);
      else
        edges.emplace_back(std::uint64_t{to} << 32 | from, -1);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<Segment> segments;
  for (std::size_t i = 0; i < edges.size();) {
    const std::uint64_t key = edges[i].first;
    int count = 0;
    for (; i < edges.size() && edges[i].first == key; ++i) count += edges[i].second;
    const dvec2 low(mesh.points[key >> 32]), high(mesh.points[key & 0xffffffffu]);
    for (int k = 0; k < std::abs(count); ++k)
      segments.push_back(count > 0 ? Segment{low, high} : Segment{high, low});
  }
  return nonZeroFill(segments);
}

}  // namespace csgray::detail
