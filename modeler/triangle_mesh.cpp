#include "modeler/triangle_mesh.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace csgray {

void TriangleMesh::append(const TriangleMesh& other) {
  const auto offset = static_cast<std::uint32_t>(points.size());
  points.insert(points.end(), other.points.begin(), other.points.end());
  triangles.reserve(triangles.size() + other.triangles.size());
  for (const Triangle& t : other.triangles)
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
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

}  // namespace csgray
