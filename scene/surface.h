// Surfaces that are not solids (docs/theory.md, "Planar surfaces"): an infinite
// plane, a disc, a triangle and a parallelogram (a rectangle and a square
// are parallelograms with right angles), and an open triangle mesh
// (scene/surface_mesh.h). They enclose nothing, so they are scene objects
// with a material and never operands of a boolean.
//
// Each shape is the unit shape in the plane z = 0 of its own frame, placed
// by an affine frame: the frame's x and y columns span the supporting plane,
// so the object-space (x, y) of a hit are the linear factors (ϑ, φ) of the
// intersection test. A mesh's frame places it; its triangles tell their
// own normals.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "engine/affine.h"
#include "engine/bounds.h"
#include "profile/region.h"
#include "scene/material.h"

namespace csgray::detail {

class Surface;
class SurfaceMesh;
using SurfacePtr = std::shared_ptr<const Surface>;

class Surface : public std::enable_shared_from_this<Surface> {
 public:
  enum class Shape {
    Plane,          // all (ϑ, φ)
    Disc,           // ϑ² + φ² ≤ 1
    Triangle,       // ϑ, φ ≥ 0 and ϑ + φ ≤ 1
    Parallelogram,  // ϑ, φ ∈ [0, 1]
    Region,         // (ϑ, φ) in a 2D region (scene/region_surface.h)
    Mesh,           // an open triangle mesh, not planar (scene/surface_mesh.h)
  };

  // worldFromObject maps the unit shape into place; it must be invertible.
  Surface(Shape shape, const Affine& worldFromObject, std::string kind);
  // A 2D region in the plane z = 0 of its frame (scene/region_surface.h).
  Surface(RegionPtr region, const Affine& worldFromObject, std::string kind);
  // An open triangle mesh, placed by its frame.
  Surface(std::shared_ptr<const SurfaceMesh> mesh, const Affine& worldFromObject, std::string kind);

  // A plane through point with the given normal.
  static SurfacePtr plane(const dvec3& point, const dvec3& normal);
  // A disc about center with the given normal and radius.
  static SurfacePtr disc(const dvec3& center, const dvec3& normal, double radius);
  // The triangle a, b, c. Throws std::invalid_argument if it has no area.
  static SurfacePtr triangle(const dvec3& a, const dvec3& b, const dvec3& c);
  // origin + ϑ·u + φ·v for ϑ, φ ∈ [0, 1]; kind names it ("parallelogram",
  // "rectangle", "square"). Throws if u and v are parallel or zero.
  static SurfacePtr parallelogram(const dvec3& origin, const dvec3& u, const dvec3& v,
                                  const std::string& kind = "parallelogram");

  // The ray parameter λ of the hit with tMin < λ < tMax, if any
  // (λ = −n·w / n·r; a ray parallel to the plane misses). face, if given,
  // is set to the face hit: a mesh's triangle, 0 on a planar shape.
  std::optional<double> hit(const Ray& ray, int* face = nullptr) const {
    if (shape_ == Shape::Mesh) return meshHit(ray, face);
    if (face) *face = 0;
    const double t = planeHit(ray);
    if (t == kInfinity) return std::nullopt;
    return t;
  }
  // A planar shape's unit normal in world space (the frame's z axis
  // through the normal matrix).
  const dvec3& normal() const { return normal_; }
  // The unit normal that shades a point on face `face` (hit's): a planar
  // shape's normal(); on a mesh, interpolated from its points' normals
  // when smooth. It lies on the side of faceNormal(face), which tells
  // which side of the surface a ray is on; the renderer turns both towards
  // the viewer.
  dvec3 normalAt(const dvec3& worldPoint, int face) const {
    return shape_ == Shape::Mesh ? meshNormalAt(worldPoint, face) : normal_;
  }
  dvec3 faceNormal(int face) const;
  const Bounds& bounds() const { return bounds_; }
  Shape shape() const { return shape_; }
  const std::string& kind() const { return kind_; }
  const Affine& frame() const { return frame_; }
  const RegionPtr& region() const { return region_; }                       // a Region's, else null
  const std::shared_ptr<const SurfaceMesh>& mesh() const { return mesh_; }  // a Mesh's, else null

  const MaterialPtr& material() const { return material_; }
  // Texture space: the world as it was when the material was given.
  dvec3 texturePoint(const dvec3& worldPoint) const;
  // texturePoint's (constant) derivative by the world point.
  glm::dmat3 textureFromWorld() const;
  dvec3 textureNormal() const;
  // At a point on face `face` (hit's), which a mesh needs.
  dvec3 textureNormal(const dvec3& worldPoint, int face) const;

  SurfacePtr transformed(const Affine& worldFromObject) const;
  SurfacePtr withMaterial(const MaterialPtr& material) const;

 private:
  void update();
  // The hit's λ, or +inf where there is none.
  double planeHit(const Ray& ray) const;
  std::optional<double> meshHit(const Ray& ray, int* face) const;
  dvec3 meshNormalAt(const dvec3& worldPoint, int face) const;

  Shape shape_;
  RegionPtr region_;
  std::shared_ptr<const SurfaceMesh> mesh_;
  Affine frame_;
  std::string kind_;
  MaterialPtr material_;
  Affine textureFromObject_;
  dvec3 normal_;
  Bounds bounds_;
};

// ---- Open surfaces as users give them --------------------------------------

// The script's plane{}, disc{}, rectangle{} and square{} with their checks
// and messages ("disc: the radius must be > 0"); triangle{} and
// parallelogram{} are Surface::triangle and Surface::parallelogram.
// The plane normal·p = offset; the normal need not be unit.
SurfacePtr planeOf(const dvec3& normal, double offset);
// A disc of radius r or diameter d (one of them) about center.
SurfacePtr discOf(std::optional<double> r, std::optional<double> d, const dvec3& center,
                  const dvec3& normal);
// A width × height rectangle in the xy plane from the origin (centred on it
// with center), facing +z, like OpenSCAD's square; kind is "rectangle" or
// "square".
SurfacePtr rectangleOf(const char* kind, double width, double height, bool center);

}  // namespace csgray::detail
