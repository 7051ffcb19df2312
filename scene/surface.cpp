#include "scene/surface.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "primitives/check.h"
#include "profile/shapes.h"
#include "scene/surface_mesh.h"
#include "scene/value_checks.h"

namespace csgray::detail {

namespace {

void requireFinite(const char* shape, const char* name, const dvec3& v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
    std::ostringstream msg;
    msg << shape << ": " << name << " must be finite (got " << v.x << ", " << v.y << ", " << v.z
        << ")";
    throw std::invalid_argument(msg.str());
  }
}

// The unit normal, refusing a zero (or overflowing) vector.
dvec3 unitNormal(const char* shape, const dvec3& normal) {
  requireFinite(shape, "normal", normal);
  double len = glm::length(normal);
  if (!(len > 0.0) || !std::isfinite(len))
    throw std::invalid_argument(std::string(shape) + ": the normal must not be zero");
  return normal / len;
}

// Two unit vectors a, b with a × b = n for the unit vector n, so that the
// frame (a, b, n) is right-handed and its z axis is the given normal. The
// helper axis is the one least aligned with n, which keeps the cross product
// well away from zero.
void basisAround(const dvec3& n, dvec3& a, dvec3& b) {
  dvec3 helper = std::abs(n.x) < 0.6 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
  a = glm::normalize(glm::cross(helper, n));
  b = glm::cross(n, a);
}

// Coordinate `axis` of a world point (w = 1) or direction (w = 0) in the
// frame's object space, bit for bit as Affine::rayToObject maps it: as
// given for the identity, moved for a translation, else summed in the
// order of glm's matrix product, (m₀x + m₁y) + (m₂z + m₃w) (the build
// contracts no products into fused multiply-adds).
double objectCoordinate(const Affine& frame, int axis, const dvec3& v, double w) {
  const glm::dmat4& m = frame.objectFromWorld();
  if (frame.isIdentity()) return v[axis];
  if (frame.isTranslation()) return w == 0.0 ? v[axis] : v[axis] + m[3][axis];
  return (m[0][axis] * v.x + m[1][axis] * v.y) + (m[2][axis] * v.z + m[3][axis] * w);
}

// The frame with the given columns; a singular or non-finite one (which the
// shape's own checks should already have refused) is reported under the
// shape's name.
Affine frameOf(const char* shape, const dvec3& x, const dvec3& y, const dvec3& z,
               const dvec3& origin) {
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(x, 0.0);
  m[1] = glm::dvec4(y, 0.0);
  m[2] = glm::dvec4(z, 0.0);
  m[3] = glm::dvec4(origin, 1.0);
  try {
    return Affine::fromMatrix(m);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(shape) + ": " + e.what());
  }
}

// The spanning vectors u = b − a and v = c − a of a triangle or parallelogram
// and the unit normal of their plane (n = u × v; docs/theory.md, "Planar surfaces"). Refuses
// zero edges and parallel edges: the area |u × v| must not be tiny against
// |u|·|v|, the same test Affine::fromMatrix applies to the frame.
dvec3 spannedNormal(const char* shape, const dvec3& u, const dvec3& v,
                    const char* parallelMessage) {
  double lu = glm::length(u), lv = glm::length(v);
  if (!(lu > 0.0) || !(lv > 0.0))
    throw std::invalid_argument(std::string(shape) + ": an edge has zero length");
  dvec3 n = glm::cross(u, v);
  double area = glm::length(n);
  if (!std::isfinite(area) || !std::isfinite(lu) || !std::isfinite(lv))
    throw std::invalid_argument(std::string(shape) + ": the coordinates are too large");
  if (!(area > 1e-12 * lu * lv)) throw std::invalid_argument(std::string(shape) + parallelMessage);
  return n / area;
}

}  // namespace

Surface::Surface(Shape shape, const Affine& worldFromObject, std::string kind)
    : shape_(shape), frame_(worldFromObject), kind_(std::move(kind)) {
  update();
}

Surface::Surface(RegionPtr region, const Affine& worldFromObject, std::string kind)
    : shape_(Shape::Region),
      region_(std::move(region)),
      frame_(worldFromObject),
      kind_(std::move(kind)) {
  update();
}

Surface::Surface(std::shared_ptr<const SurfaceMesh> mesh, const Affine& worldFromObject,
                 std::string kind)
    : shape_(Shape::Mesh), mesh_(std::move(mesh)), frame_(worldFromObject), kind_(std::move(kind)) {
  update();
}

SurfacePtr Surface::plane(const dvec3& point, const dvec3& normal) {
  requireFinite("plane", "point", point);
  dvec3 n = unitNormal("plane", normal);
  dvec3 a, b;
  basisAround(n, a, b);
  return std::make_shared<Surface>(Shape::Plane, frameOf("plane", a, b, n, point), "plane");
}

SurfacePtr Surface::disc(const dvec3& center, const dvec3& normal, double radius) {
  requireFinite("disc", "center", center);
  dvec3 n = unitNormal("disc", normal);
  requirePositive("disc", "radius", radius);
  // The unit disc scaled by the radius within the plane only: the z column
  // stays unit, so the frame is a similarity and the normal is n exactly.
  dvec3 a, b;
  basisAround(n, a, b);
  return std::make_shared<Surface>(Shape::Disc, frameOf("disc", radius * a, radius * b, n, center),
                                   "disc");
}

SurfacePtr Surface::triangle(const dvec3& a, const dvec3& b, const dvec3& c) {
  requireFinite("triangle", "first point", a);
  requireFinite("triangle", "second point", b);
  requireFinite("triangle", "third point", c);
  if (a == b || b == c || a == c)
    throw std::invalid_argument("triangle: two of the points coincide");
  // As in Winkler, "Raytracing", 17.3.2: the base corner a and the spanning vectors to its
  // neighbours, so that object (x, y) are the linear factors (ϑ, φ).
  dvec3 u = b - a, v = c - a;
  dvec3 n = spannedNormal("triangle", u, v, ": the points are collinear");
  return std::make_shared<Surface>(Shape::Triangle, frameOf("triangle", u, v, n, a), "triangle");
}

SurfacePtr Surface::parallelogram(const dvec3& origin, const dvec3& u, const dvec3& v,
                                  const std::string& kind) {
  const char* name = kind.empty() ? "parallelogram" : kind.c_str();
  requireFinite(name, "origin", origin);
  requireFinite(name, "first edge", u);
  requireFinite(name, "second edge", v);
  dvec3 n = spannedNormal(name, u, v, ": the edges are parallel");
  return std::make_shared<Surface>(Shape::Parallelogram, frameOf(name, u, v, n, origin),
                                   kind.empty() ? std::string("parallelogram") : kind);
}

double Surface::planeHit(const Ray& ray) const {
  // In the object frame the supporting plane is z = 0 with n = (0, 0, 1) and
  // t = 0, so λ = −n·w / n·r (docs/theory.md) is −o.z / d.z. The mapped
  // ray keeps its parameter, so λ is the world ray's parameter too. Only
  // the object z decides whether the ray meets the plane within its
  // window: x and y are mapped only for a ray that does (most shadow rays
  // from the ground do not), not the whole ray through the 4 × 4 matrix.
  auto object = [&](int axis, const dvec3& origin, const dvec3& dir) {
    return dvec2(objectCoordinate(frame_, axis, origin, 1.0),
                 objectCoordinate(frame_, axis, dir, 0.0));
  };
  const dvec2 z = object(2, ray.origin, ray.dir);
  // Parallel to the plane, or lying in it: no hit.
  if (z.y == 0.0) return kInfinity;
  // Where the window starts at or beyond the ray's origin, a hit needs
  // t = −z.x / z.y > 0: z.x and z.y of opposite signs. Most shadow rays
  // leave the ground so, and are refused without the division, which
  // waits for the ray's own set-up (its direction's inverse).
  if (ray.tMin >= 0.0 && !((z.x < 0.0 && z.y > 0.0) || (z.x > 0.0 && z.y < 0.0))) return kInfinity;
  double t = -z.x / z.y;
  // Also refuses NaN and an overflow to infinity.
  if (!(t > ray.tMin && t < ray.tMax)) return kInfinity;
  // The linear factors (ϑ, φ) of the hit are its object (x, y) (Winkler, 17.3.2.3).
  const dvec2 ox = object(0, ray.origin, ray.dir), oy = object(1, ray.origin, ray.dir);
  double x = ox.x + t * ox.y, y = oy.x + t * oy.y;
  bool inside = false;
  switch (shape_) {
    case Shape::Plane:
      inside = std::isfinite(x) && std::isfinite(y);
      break;
    case Shape::Disc:
      // ‖s − m‖ ≤ r (Winkler, 17.3.2.2) for the unit disc about the origin.
      inside = x * x + y * y <= 1.0;
      break;
    case Shape::Triangle:
      inside = x >= 0.0 && y >= 0.0 && x + y <= 1.0;
      break;
    case Shape::Parallelogram:
      inside = x >= 0.0 && x <= 1.0 && y >= 0.0 && y <= 1.0;
      break;
    case Shape::Region:
      inside = std::isfinite(x) && std::isfinite(y) && region_->contains(dvec2(x, y));
      break;
    case Shape::Mesh:  // meshHit's
      break;
  }
  if (!inside) return kInfinity;
  return t;
}

std::optional<double> Surface::meshHit(const Ray& ray, int* face) const {
  // The mapped ray keeps its parameter, as for the planar shapes.
  std::uint32_t triangle = 0;
  std::optional<double> t =
      mesh_->hit(frame_.isIdentity() ? ray : frame_.rayToObject(ray), triangle);
  if (face) *face = int(triangle);
  return t;
}

dvec3 Surface::faceNormal(int face) const {
  if (shape_ != Shape::Mesh) return normal_;
  return frame_.normalToWorld(mesh_->faceNormal(std::uint32_t(face)));
}

dvec3 Surface::meshNormalAt(const dvec3& worldPoint, int face) const {
  return frame_.normalToWorld(
      mesh_->normalAt(frame_.pointToObject(worldPoint), std::uint32_t(face)));
}

dvec3 Surface::texturePoint(const dvec3& worldPoint) const {
  return textureFromObject_.pointToWorld(frame_.pointToObject(worldPoint));
}

glm::dmat3 Surface::textureFromWorld() const {
  return glm::dmat3(textureFromObject_.worldFromObject()) * glm::dmat3(frame_.objectFromWorld());
}

dvec3 Surface::textureNormal() const { return textureFromObject_.normalToWorld(dvec3(0, 0, 1)); }

dvec3 Surface::textureNormal(const dvec3& worldPoint, int face) const {
  if (shape_ != Shape::Mesh) return textureNormal();
  return textureFromObject_.normalToWorld(
      mesh_->normalAt(frame_.pointToObject(worldPoint), std::uint32_t(face)));
}

SurfacePtr Surface::transformed(const Affine& worldFromObject) const {
  auto copy = std::make_shared<Surface>(*this);
  copy->frame_ = frame_.then(worldFromObject);
  copy->update();
  return copy;
}

SurfacePtr Surface::withMaterial(const MaterialPtr& material) const {
  auto copy = std::make_shared<Surface>(*this);
  copy->material_ = material;
  // Texture space is the world as it is now, so the texture stays on the
  // surface when it is moved afterwards (as for primitives).
  copy->textureFromObject_ = frame_;
  return copy;
}

void Surface::update() {
  // The frame's z axis through the normal matrix: perpendicular to the
  // mapped x and y axes also under non-uniform scale and shear.
  normal_ = frame_.normalToWorld(dvec3(0, 0, 1));
  if (shape_ == Shape::Plane) {
    // An infinite plane may reach anywhere; the scene leaves it out of what
    // it frames.
    bounds_ = Bounds::everything();
    return;
  }
  const glm::dmat4& m = frame_.worldFromObject();
  bounds_ = Bounds{};
  if (shape_ == Shape::Disc) {
    // The disc is the ellipse c + cos α·X + sin α·Y (X, Y the frame's x and
    // y columns); along axis i it reaches max over α = √(X_i² + Y_i²).
    dvec3 c(m[3]);
    dvec3 half;
    for (int i = 0; i < 3; ++i) half[i] = std::sqrt(m[0][i] * m[0][i] + m[1][i] * m[1][i]);
    bounds_.include(c - half);
    bounds_.include(c + half);
  } else if (shape_ == Shape::Mesh) {
    // The box of the eight corners of the mesh's box, placed.
    const Bounds& box = mesh_->bounds();
    for (int i = 0; i < 8; ++i)
      bounds_.include(frame_.pointToWorld(dvec3(
          i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z)));
  } else if (shape_ == Shape::Region) {
    // The corners of the region's box in its plane bound its image.
    const ProfileBounds& box = region_->bounds();
    if (box.empty()) return;  // an empty region: nothing to hit
    for (double x : {box.lo.x, box.hi.x})
      for (double y : {box.lo.y, box.hi.y}) bounds_.include(frame_.pointToWorld(dvec3(x, y, 0)));
  } else {
    bounds_.include(frame_.pointToWorld(dvec3(0, 0, 0)));
    bounds_.include(frame_.pointToWorld(dvec3(1, 0, 0)));
    bounds_.include(frame_.pointToWorld(dvec3(0, 1, 0)));
    if (shape_ == Shape::Parallelogram) bounds_.include(frame_.pointToWorld(dvec3(1, 1, 0)));
  }
  // A flat shape has a box of (nearly) zero thickness, but a hit point
  // computed from a ray rounds off the plane by a few ulps: pad the box by a
  // tiny share of its coordinates' magnitude so that it holds its own hit
  // points and a slab test does not cull hits by rounding.
  double scale = 0.0;
  for (int i = 0; i < 3; ++i)
    scale = std::max({scale, std::abs(bounds_.lo[i]), std::abs(bounds_.hi[i])});
  dvec3 pad(1e-9 * scale);
  bounds_.lo -= pad;
  bounds_.hi += pad;
}

// ---- Open surfaces as users give them --------------------------------------

SurfacePtr planeOf(const dvec3& normal, double offset) {
  checkNonZero("plane", "normal", normal);
  checkFinite("plane", "offset", offset);
  const dvec3 unit = glm::normalize(normal);
  return Surface::plane(offset / glm::length(normal) * unit, unit);
}

SurfacePtr discOf(std::optional<double> r, std::optional<double> d, const dvec3& center,
                  const dvec3& normal) {
  if (r && d) throw std::invalid_argument("disc: give r or d, not both");
  if (!r && !d) throw std::invalid_argument("disc: needs r (radius) or d (diameter)");
  const double radius = r ? *r : *d / 2.0;
  if (!(radius > 0.0)) throw std::invalid_argument("disc: the radius must be > 0");
  checkNonZero("disc", "normal", normal);
  return Surface::disc(center, normal, radius);
}

SurfacePtr rectangleOf(const char* kind, double width, double height, bool center) {
  // The checks and messages of the script's square{} and rectangle{},
  // which are regions (profile/shapes.h).
  rectangleRegion(kind, width, height, center);
  const dvec3 origin = center ? dvec3(-width / 2, -height / 2, 0) : dvec3(0.0);
  return Surface::parallelogram(origin, dvec3(width, 0, 0), dvec3(0, height, 0), kind);
}

}  // namespace csgray::detail
