// An invertible affine map between an object's frame and the world, kept
// with its inverse and the normal matrix (inverse transpose), so that rays
// go into the object with objectFromWorld and normals come out exactly,
// also under non-uniform scale.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "engine/ray.h"

namespace csgray::detail {

class Affine {
 public:
  Affine() = default;  // identity

  // Throws std::invalid_argument if the matrix is not affine (last row
  // 0 0 0 1), not finite, or singular.
  static Affine fromMatrix(const glm::dmat4& worldFromObject);
  static Affine translation(const dvec3& offset);
  static Affine scaling(const dvec3& factors);
  // Rotation by angle (radians) about a unit axis through the origin.
  static Affine rotation(double radians, const dvec3& axis);
  // The same turn given by its cosine and sine (a point of the unit
  // circle), which the caller may know exactly (engine/degrees.h).
  static Affine rotation(double cosine, double sine, const dvec3& axis);
  // Reflection in the plane through the origin with the given normal.
  static Affine mirror(const dvec3& normal);

  // This map followed by outer: the object is first placed by *this, then
  // the result by outer.
  Affine then(const Affine& outer) const;

  const glm::dmat4& worldFromObject() const { return worldFromObject_; }
  const glm::dmat4& objectFromWorld() const { return objectFromWorld_; }
  bool isIdentity() const { return identity_; }
  // Is the linear part the identity (rayToObject then only moves the origin)?
  bool isTranslation() const { return translation_; }

  dvec3 pointToObject(const dvec3& p) const { return dvec3(objectFromWorld_ * glm::dvec4(p, 1.0)); }
  dvec3 pointToWorld(const dvec3& p) const { return dvec3(worldFromObject_ * glm::dvec4(p, 1.0)); }
  // A ray in the object frame with the same parameter t: dir is not
  // renormalised, and 1/dir is not computed (Ray::withoutInverse).
  Ray rayToObject(const Ray& r) const {
    if (translation_)
      return Ray::withoutInverse(r.origin + dvec3(objectFromWorld_[3]), r.dir, r.tMin, r.tMax);
    return Ray::withoutInverse(pointToObject(r.origin),
                               dvec3(objectFromWorld_ * glm::dvec4(r.dir, 0.0)), r.tMin, r.tMax);
  }
  // Object-frame normal (any length) to a unit world-frame normal.
  dvec3 normalToWorld(const dvec3& n) const;

 private:
  explicit Affine(const glm::dmat4& worldFromObject);

  glm::dmat4 worldFromObject_{1.0};
  glm::dmat4 objectFromWorld_{1.0};
  glm::dmat3 normalFromObject_{1.0};
  bool identity_ = true;
  bool translation_ = true;
};

}  // namespace csgray::detail
