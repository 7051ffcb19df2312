// csgray::Surface: the script's open surfaces (scene/surface.h and
// scene/surface_mesh.h), with the same checks.

#include "api/access.h"
#include "api/convert.h"
#include "api/errors.h"
#include "csgray/scene.h"
#include "scene/region_surface.h"
#include "scene/rotation.h"
#include "scene/surface_mesh.h"

namespace csgray {

using detail::Access;
using detail::guarded;
using detail::toDetail;

namespace {

Surface wrap(detail::SurfacePtr p) { return Access::surface(std::move(p)); }

}  // namespace

Surface::Surface(std::shared_ptr<const detail::Surface> impl) : impl_(std::move(impl)) {}

Surface Surface::plane(const Vec3& normal, double offset) {
  return guarded([&] { return wrap(detail::planeOf(toDetail(normal), offset)); });
}

Surface Surface::disc(double r, const Vec3& center, const Vec3& normal) {
  return guarded(
      [&] { return wrap(detail::discOf(r, std::nullopt, toDetail(center), toDetail(normal))); });
}

Surface Surface::triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return guarded(
      [&] { return wrap(detail::Surface::triangle(toDetail(a), toDetail(b), toDetail(c))); });
}

Surface Surface::parallelogram(const Vec3& origin, const Vec3& u, const Vec3& v) {
  return guarded([&] {
    return wrap(detail::Surface::parallelogram(toDetail(origin), toDetail(u), toDetail(v)));
  });
}

Surface Surface::rectangle(double width, double height, bool center) {
  return guarded([&] { return wrap(detail::rectangleOf("rectangle", width, height, center)); });
}

Surface Surface::square(double size, bool center) {
  return guarded([&] { return wrap(detail::rectangleOf("square", size, size, center)); });
}

Surface Surface::region(const Region& region) {
  return guarded([&] { return wrap(detail::regionSurface(detail::Access::of(region), "region")); });
}

Surface Surface::mesh(const std::vector<Vec3>& points,
                      const std::vector<std::vector<std::int64_t>>& faces,
                      const std::vector<Vec3>& normals, bool smooth) {
  return guarded([&] {
    std::vector<detail::dvec3> madePoints, madeNormals;
    for (const Vec3& p : points) madePoints.push_back(toDetail(p));
    for (const Vec3& n : normals) madeNormals.push_back(toDetail(n));
    return wrap(
        detail::meshSurfaceOf(std::move(madePoints), faces, std::move(madeNormals), smooth));
  });
}

Surface Surface::translate(const Vec3& offset) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::Affine::translation(toDetail(offset)))); });
}

Surface Surface::rotate(const Vec3& degrees) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::rotationDegrees(toDetail(degrees)))); });
}

Surface Surface::rotate(double degrees, const Vec3& axis) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::rotationDegrees(degrees, toDetail(axis)))); });
}

Surface Surface::scale(const Vec3& factors) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::Affine::scaling(toDetail(factors)))); });
}

Surface Surface::mirror(const Vec3& normal) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::Affine::mirror(toDetail(normal)))); });
}

Surface Surface::transform(const Matrix4& rows) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::Affine::fromMatrix(toDetail(rows)))); });
}

Surface Surface::material(const Material& material) const {
  return guarded([&] { return wrap(impl_->withMaterial(toDetail(material))); });
}

std::string Surface::kind() const { return impl_->kind(); }

Bounds Surface::bounds() const { return detail::toPublic(impl_->bounds()); }

}  // namespace csgray
