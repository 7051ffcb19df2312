// An open triangle mesh as the shape of a surface (scene/surface.h): a
// graph's sheet, a parametric patch that does not close, a landscape. It
// encloses nothing, so it is no solid; rays meet its flat triangles
// exactly (triangle_crossing.h: no ray slips through a seam) from either
// side. It is shaded smooth by default: the normal at a hit is
// interpolated from normals at the points, given (a function's
// derivatives) or averaged from the triangles around each point.
//
// Normals are lines, not arrows: a surface need not have two sides (a
// Möbius strip), so the triangles' normals are turned to agree before they
// are averaged, and each point's normal is turned to the triangle's side
// before it is interpolated.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/bvh.h"
#include "primitives/triangle_crossing.h"
#include "scene/surface.h"

namespace csgray::detail {

class SurfaceMesh {
 public:
  // Points, faces of three indices into them (from 0, in either order),
  // and either no normals or one per point (a zero one is averaged from
  // the triangles, as all are without normals); smooth=false shades each
  // triangle flat. Triangles with no area are left out (they show
  // nothing). Throws std::invalid_argument ("<function>: ...") naming the
  // first bad point, face or normal.
  SurfaceMesh(std::vector<dvec3> points, const std::vector<std::vector<std::int64_t>>& faces,
              std::vector<dvec3> normals, bool smooth, const std::string& function);

  // The first triangle the ray meets with tMin < t < tMax, from either
  // side: its t, and the triangle in `triangle`.
  std::optional<double> hit(const Ray& ray, std::uint32_t& triangle) const;
  // The unit normal of a triangle, (b − a) × (c − a).
  const dvec3& faceNormal(std::uint32_t triangle) const { return faceNormals_[triangle]; }
  // The unit shading normal at point p of the triangle, on the side of its
  // faceNormal: the points' normals weighted by p's barycentric
  // coordinates (Phong, "Illumination for Computer Generated Pictures",
  // CACM 18(6), 1975), or the face's own when flat.
  dvec3 normalAt(const dvec3& p, std::uint32_t triangle) const;

  const std::vector<dvec3>& points() const { return points_; }
  const std::vector<MeshTriangle>& triangles() const { return triangles_; }
  // One unit normal per point; empty when flat.
  const std::vector<dvec3>& pointNormals() const { return pointNormals_; }
  const Bounds& bounds() const { return bounds_; }
  // Bytes the mesh holds (points, triangles, normals, BVH).
  std::size_t memoryBytes() const;

 private:
  std::vector<dvec3> points_;
  std::vector<MeshTriangle> triangles_;
  std::vector<dvec3> faceNormals_;
  std::vector<dvec3> pointNormals_;
  Bounds bounds_;
  Bvh bvh_;
};

// The script's mesh_surface{} and the library's Surface::mesh: a surface
// of the mesh above, kind "mesh surface".
SurfacePtr meshSurfaceOf(std::vector<dvec3> points,
                         const std::vector<std::vector<std::int64_t>>& faces,
                         std::vector<dvec3> normals, bool smooth);

}  // namespace csgray::detail
