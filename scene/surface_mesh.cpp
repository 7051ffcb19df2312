#include "scene/surface_mesh.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace csgray::detail {

namespace {

bool finite(const dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The angle at corner a of the triangle a, b, c.
double cornerAngle(const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 u = b - a, v = c - a;
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

}  // namespace

SurfaceMesh::SurfaceMesh(std::vector<dvec3> points,
                         const std::vector<std::vector<std::int64_t>>& faces,
                         std::vector<dvec3> normals, bool smooth, const std::string& function) {
  auto refuse = [&](const std::string& message) {
    throw std::invalid_argument(function + ": " + message);
  };
  if (points.size() < 3)
    refuse("needs at least 3 points (got " + std::to_string(points.size()) + ")");
  if (points.size() >= std::numeric_limits<std::uint32_t>::max() ||
      faces.size() >= std::numeric_limits<std::uint32_t>::max())
    refuse("too many points or faces");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!finite(points[i])) {
      std::ostringstream msg;
      msg << "point " << i << " has a coordinate that is not finite (" << points[i].x << ", "
          << points[i].y << ", " << points[i].z << ")";
      refuse(msg.str());
    }
  if (!normals.empty() && normals.size() != points.size())
    refuse("normals must give one normal per point (" + std::to_string(points.size()) +
           " points, " + std::to_string(normals.size()) + " normals)");
  for (std::size_t i = 0; i < normals.size(); ++i)
    if (!finite(normals[i])) refuse("normal " + std::to_string(i) + " is not finite");
  if (faces.empty()) refuse("needs at least one face");

  points_ = std::move(points);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::vector<std::int64_t>& face = faces[f];
    if (face.size() != 3)
      refuse("face " + std::to_string(f) + " has " + std::to_string(face.size()) +
             " points; the faces of a surface are triangles of 3");
    MeshTriangle tri;
    for (int k = 0; k < 3; ++k) {
      if (face[k] < 0 || face[k] >= std::int64_t(points_.size()))
        refuse("face " + std::to_string(f) + ": point index " + std::to_string(face[k]) +
               " is out of range (there are " + std::to_string(points_.size()) +
               " points, numbered from 0)");
      tri[k] = std::uint32_t(face[k]);
    }
    const dvec3 &a = points_[tri[0]], &b = points_[tri[1]], &c = points_[tri[2]];
    if (collinear(a, b, c)) continue;  // no area: nothing to see or hit
    triangles_.push_back(tri);
    faceNormals_.push_back(triangleNormal(a, b, c));
  }
  if (triangles_.empty()) refuse("no face has an area (every face's points lie on one line)");
  for (const MeshTriangle& tri : triangles_)
    for (std::uint32_t v : tri) bounds_.include(points_[v]);
  bvh_ = triangleBvh(points_, triangles_, bounds_);
  if (!smooth) return;

  // Each point's normal: the one given, else the mean of its triangles'
  // normals weighted by their angles at the point (Thürmer and Wüthrich,
  // "Computing vertex normals from polygonal facets", Journal of Graphics
  // Tools 3(1), 1998), each turned to agree with the sum so far.
  pointNormals_.assign(points_.size(), dvec3(0.0));
  std::vector<bool> given(points_.size(), false);
  for (std::size_t i = 0; i < normals.size(); ++i)
    if (normals[i] != dvec3(0.0)) pointNormals_[i] = glm::normalize(normals[i]), given[i] = true;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const MeshTriangle& tri = triangles_[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = tri[k];
      if (given[v]) continue;
      const dvec3 n =
          cornerAngle(points_[v], points_[tri[(k + 1) % 3]], points_[tri[(k + 2) % 3]]) *
          faceNormals_[t];
      pointNormals_[v] += glm::dot(pointNormals_[v], n) < 0.0 ? -n : n;
    }
  }
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const double length = glm::length(pointNormals_[i]);
    // (A point of no triangle, or whose triangles cancel: its triangles'
    // own normals stand in, see normalAt.)
    pointNormals_[i] = length > 0.0 ? pointNormals_[i] / length : dvec3(0.0);
  }
}

std::optional<double> SurfaceMesh::hit(const Ray& ray, std::uint32_t& triangle) const {
  if (!usableRay(ray)) return std::nullopt;
  // A ray of its own, with the 1/dir that the BVH's slab tests need (an
  // object-space ray comes without it).
  const Ray within(ray.origin, ray.dir, ray.tMin, ray.tMax);
  std::optional<double> best;
  double tMax = ray.tMax;
  forEachTriangleCrossing(bvh_, points_, triangles_, within, tMax,
                          [&](std::uint32_t tri, double t, int) {
                            if (t > ray.tMin && t < tMax) best = t, tMax = t, triangle = tri;
                          });
  return best;
}

dvec3 SurfaceMesh::normalAt(const dvec3& p, std::uint32_t triangle) const {
  const dvec3& face = faceNormals_[triangle];
  if (pointNormals_.empty()) return face;
  const MeshTriangle& tri = triangles_[triangle];
  // p's barycentric coordinates (Ericson, "Real-Time Collision Detection",
  // 2005, 3.4), kept within the triangle: a hit may round a little off it.
  const dvec3 &a = points_[tri[0]], &b = points_[tri[1]], &c = points_[tri[2]];
  const dvec3 v0 = b - a, v1 = c - a, v2 = p - a;
  const double d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
  const double d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
  const double det = d00 * d11 - d01 * d01;
  double v = det > 0.0 ? (d11 * d20 - d01 * d21) / det : 1.0 / 3.0;
  double w = det > 0.0 ? (d00 * d21 - d01 * d20) / det : 1.0 / 3.0;
  v = std::clamp(v, 0.0, 1.0), w = std::clamp(w, 0.0, 1.0 - v);
  const double weights[3] = {1.0 - v - w, v, w};
  dvec3 n(0.0);
  for (int k = 0; k < 3; ++k) {
    const dvec3& m = pointNormals_[tri[k]];
    n += weights[k] * (glm::dot(m, face) < 0.0 ? -m : m);
  }
  const double length = glm::length(n);
  return length > 1e-12 ? n / length : face;
}

std::size_t SurfaceMesh::memoryBytes() const {
  return sizeof(SurfaceMesh) + points_.capacity() * sizeof(dvec3) +
         triangles_.capacity() * sizeof(MeshTriangle) +
         (faceNormals_.capacity() + pointNormals_.capacity()) * sizeof(dvec3) + bvh_.memoryBytes();
}

SurfacePtr meshSurfaceOf(std::vector<dvec3> points,
                         const std::vector<std::vector<std::int64_t>>& faces,
                         std::vector<dvec3> normals, bool smooth) {
  auto mesh = std::make_shared<const SurfaceMesh>(std::move(points), faces, std::move(normals),
                                                  smooth, "mesh_surface");
  return std::make_shared<Surface>(std::move(mesh), Affine(), "mesh surface");
}

}  // namespace csgray::detail
