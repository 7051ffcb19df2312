#include "tessellation/triangle_mesh.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace csgray::detail {

void TriangleMesh::append(const TriangleMesh& other) {
  const auto offset = static_cast<std::uint32_t>(points.size());
  points.insert(points.end(), other.points.begin(), other.points.end());
  // Grown geometrically, as push_back grows it: a reserve of exactly the
  // sum copied the whole mesh at every append, and 10 000 pegs joined one
  // by one copied gigabytes.
  const std::size_t needed = triangles.size() + other.triangles.size();
  if (needed > triangles.capacity()) triangles.reserve(std::max(needed, 2 * triangles.capacity()));
  for (const Triangle& t : other.triangles)
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  pinched = pinched || other.pinched;
}

void TriangleMesh::flip() {
  for (Triangle& t : triangles) std::swap(t[1], t[2]);
}

Bounds TriangleMesh::bounds() const {
  Bounds b;
  for (const dvec3& p : points) b.include(p);
  return b;
}

double TriangleMesh::volume() const {
  // Sum of the signed tetrahedra (o, a, b, c), each (a−o)·((b−o) × (c−o))/6,
  // with o a point of the mesh rather than the origin, so that a part far
  // from the origin does not lose its volume to cancellation.
  if (points.empty()) return 0.0;
  const dvec3 o = points[0];
  double sum = 0.0;
  for (const Triangle& t : triangles)
    sum += glm::dot(points[t[0]] - o, glm::cross(points[t[1]] - o, points[t[2]] - o));
  return sum / 6.0;
}

double TriangleMesh::area() const {
  double sum = 0.0;
  for (const Triangle& t : triangles)
    sum += glm::length(glm::cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]));
  return sum / 2.0;
}

// Ericson, Real-Time Collision Detection (2005), §5.1.5: the Voronoi
// region of p among the corners, edges and face decides the nearest point.
double pointTriangleDistance(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return glm::length(ap);
  const dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return glm::length(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::length(ap - d1 / (d1 - d3) * ab);
  const dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return glm::length(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::length(ap - d2 / (d2 - d6) * ac);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return glm::length(bp - (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b));
  const double denominator = va + vb + vc;
  if (denominator <= 0.0) return std::min({glm::length(ap), glm::length(bp), glm::length(cp)});
  const double v = vb / denominator, w = vc / denominator;
  return glm::length(ap - v * ab - w * ac);
}

}  // namespace csgray::detail
