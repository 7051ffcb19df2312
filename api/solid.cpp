// csgray::Solid: the factories, booleans and transforms of the script's
// solids, made with the same checks (scene/shapes.h, quadric_shapes.h).
#include "csgray/solid.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "api/access.h"
#include "api/convert.h"
#include "api/errors.h"
#include "check/exact_volume.h"
#include "csgray/mesh.h"
#include "engine/tight_bounds.h"
#include "export/cgal/mesh_validity.h"
#include "io/height_map_file.h"
#include "io/image_file.h"
#include "meshio/mesh_import.h"
#include "primitives/convex_polyhedron.h"
#include "primitives/quadric.h"
#include "scene/height_map.h"
#include "scene/hull_shapes.h"
#include "scene/quadric_shapes.h"
#include "scene/resize.h"
#include "scene/rotation.h"
#include "scene/shapes.h"
#include "scene/value_checks.h"

namespace csgray {

using detail::Access;
using detail::guarded;
using detail::toDetail;

namespace {

Solid wrap(detail::SolidPtr p) { return Access::solid(std::move(p)); }

std::vector<detail::SolidPtr> internals(const std::vector<Solid>& solids) {
  std::vector<detail::SolidPtr> out;
  out.reserve(solids.size());
  for (const Solid& s : solids) out.push_back(Access::of(s));
  return out;
}

// A NaN or an infinity refused as the script refuses one, before the shape
// sees it: "cylinder: h must be finite", a vector's component by the
// script's index, "box: size[1] must be finite".
void finite(const char* function, const char* key, double value) {
  detail::checkFinite(function, key, value);
}
void finite(const char* function, const char* key, const Vec3& vector) {
  const double components[3] = {vector.x, vector.y, vector.z};
  for (int i = 0; i < 3; ++i)
    detail::checkFinite(function, (key + ("[" + std::to_string(i + 1) + "]")).c_str(),
                        components[i]);
}

// name: the script's function, for the messages.
Solid namedQuadric(const char* name, detail::NamedQuadric kind, detail::QuadricAxes axes) {
  return guarded([&] {
    const std::pair<const char*, const std::optional<double>*> given[] = {
        {"a", &axes.a}, {"b", &axes.b}, {"c", &axes.c}, {"p", &axes.p}};
    for (const auto& [key, value] : given)
      if (*value) finite(name, key, **value);
    return wrap(detail::namedQuadricShape(kind, axes));
  });
}

Solid platonic(const char* name, detail::Platonic kind, double r) {
  return guarded([&] {
    finite(name, "r", r);
    return wrap(detail::platonicSolid(kind, r));
  });
}

Solid boolean(detail::Boolean::Op op, const std::vector<Solid>& solids) {
  return guarded([&] { return wrap(detail::booleanShape(op, internals(solids))); });
}

}  // namespace

Solid::Solid(std::shared_ptr<const detail::Solid> impl) : impl_(std::move(impl)) {}

Solid Solid::sphere(double r) {
  return guarded([&] {
    finite("sphere", "r", r);
    return wrap(detail::sphereShape(r, std::nullopt));
  });
}

Solid Solid::ellipsoid(const Vec3& radii) {
  return guarded([&] {
    finite("ellipsoid", "radii", radii);
    return wrap(detail::ellipsoidShape(toDetail(radii)));
  });
}

Solid Solid::box(const Vec3& size, bool center) {
  return guarded([&] {
    finite("box", "size", size);
    return wrap(detail::boxShape(toDetail(size), center));
  });
}

Solid Solid::box(double size, bool center) {
  guarded([&] { finite("box", "size", size); });
  return box(Vec3{size, size, size}, center);
}

Solid Solid::cylinder(double h, double r, bool center) {
  detail::CylinderParams p;
  p.h = h;
  p.r = r;
  p.center = center;
  return guarded([&] {
    finite("cylinder", "h", h);
    finite("cylinder", "r", r);
    return wrap(detail::cylinderShape("cylinder", p));
  });
}

Solid Solid::cone(double h, double r1, double r2, bool center) {
  detail::CylinderParams p;
  p.h = h;
  p.r1 = r1;
  p.r2 = r2;
  p.center = center;
  return guarded([&] {
    finite("cone", "h", h);
    finite("cone", "r1", r1);
    finite("cone", "r2", r2);
    return wrap(detail::cylinderShape("cone", p));
  });
}

Solid Solid::halfSpace(const Vec3& normal, double offset) {
  return guarded([&] {
    finite("half_space", "normal", normal);
    finite("half_space", "offset", offset);
    return wrap(detail::halfSpaceShape(toDetail(normal), offset));
  });
}

Solid Solid::blob(const std::vector<BlobBall>& balls, double threshold) {
  return guarded([&] {
    std::vector<detail::BlobBall> made;
    made.reserve(balls.size());
    for (const BlobBall& b : balls) made.push_back({toDetail(b.center), b.radius, b.strength});
    return wrap(detail::blobShape(std::move(made), threshold));
  });
}

Solid Solid::superellipsoid(const Vec3& radii, double e, double n) {
  return guarded([&] {
    finite("superellipsoid", "radii", radii);
    finite("superellipsoid", "e", e);
    finite("superellipsoid", "n", n);
    return wrap(detail::superellipsoidShape(toDetail(radii), e, n));
  });
}

Solid Solid::torus(double R, double r) {
  return guarded([&] {
    finite("torus", "R", R);
    finite("torus", "r", r);
    return wrap(detail::torusShape(R, r));
  });
}

Solid Solid::quadric(const Matrix4& rows) {
  return guarded([&] { return wrap(detail::Primitive::create<detail::Quadric>(toDetail(rows))); });
}

Solid Solid::hyperboloid1(double a, double b, double c) {
  return namedQuadric("hyperboloid1", detail::NamedQuadric::Hyperboloid1, {a, b, c, {}});
}
Solid Solid::hyperboloid2(double a, double b, double c) {
  return namedQuadric("hyperboloid2", detail::NamedQuadric::Hyperboloid2, {a, b, c, {}});
}
Solid Solid::ellipticCone(double a, double b, double c) {
  return namedQuadric("elliptic_cone", detail::NamedQuadric::EllipticCone, {a, b, c, {}});
}
Solid Solid::ellipticParaboloid(double a, double b) {
  return namedQuadric("elliptic_paraboloid", detail::NamedQuadric::EllipticParaboloid,
                      {a, b, {}, {}});
}
Solid Solid::hyperbolicParaboloid(double a, double b) {
  return namedQuadric("hyperbolic_paraboloid", detail::NamedQuadric::HyperbolicParaboloid,
                      {a, b, {}, {}});
}
Solid Solid::ellipticCylinder(double a, double b) {
  return namedQuadric("elliptic_cylinder", detail::NamedQuadric::EllipticCylinder, {a, b, {}, {}});
}
Solid Solid::hyperbolicCylinder(double a, double b) {
  return namedQuadric("hyperbolic_cylinder", detail::NamedQuadric::HyperbolicCylinder,
                      {a, b, {}, {}});
}
Solid Solid::parabolicCylinder(double p) {
  return namedQuadric("parabolic_cylinder", detail::NamedQuadric::ParabolicCylinder,
                      {{}, {}, {}, p});
}

Solid Solid::tetrahedron(double r) {
  return platonic("tetrahedron", detail::Platonic::Tetrahedron, r);
}
Solid Solid::hexahedron(double r) {
  return platonic("hexahedron", detail::Platonic::Hexahedron, r);
}
Solid Solid::octahedron(double r) {
  return platonic("octahedron", detail::Platonic::Octahedron, r);
}
Solid Solid::dodecahedron(double r) {
  return platonic("dodecahedron", detail::Platonic::Dodecahedron, r);
}
Solid Solid::icosahedron(double r) {
  return platonic("icosahedron", detail::Platonic::Icosahedron, r);
}

Solid Solid::convex(const std::vector<Plane>& planes) {
  return guarded([&] {
    std::vector<detail::ConvexPolyhedron::Plane> made;
    made.reserve(planes.size());
    for (const Plane& p : planes) made.push_back({toDetail(p.normal), p.offset});
    return wrap(detail::Primitive::create<detail::ConvexPolyhedron>(made, "convex"));
  });
}

Solid Solid::polyhedron(const std::vector<Vec3>& points,
                        const std::vector<std::vector<std::int64_t>>& faces) {
  return guarded([&] {
    std::vector<detail::dvec3> made;
    made.reserve(points.size());
    for (const Vec3& p : points) made.push_back(toDetail(p));
    return wrap(detail::Primitive::create<detail::MeshSolid>(made, faces));
  });
}

Solid Solid::fromMesh(const Mesh& mesh) {
  return guarded([&] {
    detail::TriangleMesh made;
    made.points.reserve(mesh.vertices.size());
    for (const Vec3& p : mesh.vertices) made.points.push_back(toDetail(p));
    made.triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
    // As a mesh file is held (fromMeshFile, the script's mesh{}): a solid's
    // boundary, closed, outward and without crossing faces.
    if (const detail::MeshDefect defect = detail::meshDefect(made); !defect.valid())
      throw std::invalid_argument("mesh: " + defect.text);
    return wrap(detail::meshShape(made, "mesh"));
  });
}

Solid Solid::fromMeshFile(const std::string& path, bool repair, std::string* repairReport) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw Error(ErrorCode::IoError, "mesh: " + path + ": no such file");
  detail::TriangleMesh read = detail::readMeshFileAsError(path);
  return guarded(ErrorCode::IoError, [&] {
    std::string report;
    try {
      Solid solid = wrap(
          detail::meshShape(detail::importedMesh(std::move(read), path, repair, report), path));
      if (repairReport) *repairReport = report;
      return solid;
    } catch (const std::invalid_argument& e) {
      // As the script's mesh{} says it.
      throw std::invalid_argument("mesh: " + std::string(e.what()));
    }
  });
}

Solid Solid::heightMap(const std::vector<std::vector<double>>& rows, bool center) {
  return guarded([&] {
    detail::HeightMap map;
    map.rows = rows.size();
    for (const std::vector<double>& row : rows) map.columns = std::max(map.columns, row.size());
    if (map.rows * map.columns > detail::kMaxHeightMapPoints)
      throw std::invalid_argument("height_map: more than " +
                                  std::to_string(detail::kMaxHeightMapPoints) + " heights");
    map.heights.assign(map.rows * map.columns, 0.0);
    for (std::size_t r = 0; r < map.rows; ++r)
      std::copy(rows[r].begin(), rows[r].end(), map.heights.begin() + r * map.columns);
    try {
      return wrap(detail::heightMapSolid(map, center));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("height_map: " + std::string(e.what()));
    }
  });
}

Solid Solid::heightMapFile(const std::string& path, bool center, bool invert) {
  const std::string name = std::filesystem::path(path).filename().string();
  detail::HeightMap map;
  try {
    map = detail::readHeightMap(path, name, invert, detail::readTextureImage);
  } catch (const std::bad_alloc&) {
    throw Error(ErrorCode::OutOfMemory, "out of memory");
  } catch (const std::exception& e) {
    throw Error(ErrorCode::IoError, "height_map: " + std::string(e.what()));
  }
  // A file of too few rows or of heights that are not finite holds no grid
  // to build: the file's fault, as one that is not numbers.
  return guarded(ErrorCode::IoError, [&] {
    try {
      return wrap(detail::heightMapSolid(map, center));
    } catch (const std::invalid_argument& e) {
      throw Error(ErrorCode::IoError, "height_map: " + name + ": " + e.what());
    }
  });
}

Solid Solid::hull(const std::vector<Solid>& solids) {
  return guarded([&] { return wrap(detail::hullShape(internals(solids))); });
}

Solid Solid::minkowski(const std::vector<Solid>& solids) {
  return guarded([&] { return wrap(detail::minkowskiShape(internals(solids))); });
}

Solid Solid::roundedBox(const Vec3& size, double r, bool center) {
  return guarded([&] { return wrap(detail::roundedBoxShape(toDetail(size), r, center)); });
}

Solid Solid::roundedCylinder(double h, double r, double fillet, bool center) {
  return guarded([&] { return wrap(detail::roundedCylinderShape(r, h, fillet, center)); });
}

Solid Solid::unionOf(const std::vector<Solid>& solids) {
  return boolean(detail::Boolean::Op::Union, solids);
}
Solid Solid::intersectionOf(const std::vector<Solid>& solids) {
  return boolean(detail::Boolean::Op::Intersection, solids);
}
Solid Solid::differenceOf(const std::vector<Solid>& solids) {
  return boolean(detail::Boolean::Op::Difference, solids);
}
Solid Solid::operator+(const Solid& other) const { return unionOf({*this, other}); }
Solid Solid::operator-(const Solid& other) const { return differenceOf({*this, other}); }
Solid Solid::operator*(const Solid& other) const { return intersectionOf({*this, other}); }

Solid Solid::clip(const Bounds& box) const {
  return guarded([&] {
    detail::SolidPtr cutter = detail::clipBoxShape(toDetail(box.lo), toDetail(box.hi));
    return wrap(detail::clippedShape(impl_.pointer(), {cutter}));
  });
}

Solid Solid::clip(const std::vector<Solid>& cutters) const {
  return guarded([&] { return wrap(detail::clippedShape(impl_.pointer(), internals(cutters))); });
}

Solid Solid::translate(const Vec3& offset) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::Affine::translation(toDetail(offset)))); });
}

Solid Solid::rotate(const Vec3& degrees) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::rotationDegrees(toDetail(degrees)))); });
}

Solid Solid::rotate(double degrees, const Vec3& axis) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::rotationDegrees(degrees, toDetail(axis)))); });
}

Solid Solid::scale(const Vec3& factors) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::Affine::scaling(toDetail(factors)))); });
}

Solid Solid::scale(double factor) const { return scale(Vec3{factor, factor, factor}); }

Solid Solid::mirror(const Vec3& normal) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::Affine::mirror(toDetail(normal)))); });
}

Solid Solid::transform(const Matrix4& rows) const {
  return guarded(
      [&] { return wrap(impl_->transformed(detail::Affine::fromMatrix(toDetail(rows)))); });
}

Solid Solid::resize(const Vec3& size, const std::array<bool, 3>& autoAxes) const {
  return guarded([&] {
    const detail::dvec3 factors =
        detail::resizeFactors(detail::tightBounds(*impl_), toDetail(size), autoAxes);
    return wrap(impl_->transformed(detail::Affine::scaling(factors)));
  });
}

Solid Solid::material(const Material& material) const {
  return guarded(
      [&] { return wrap(detail::solidWithMaterial(impl_.pointer(), toDetail(material))); });
}

Bounds Solid::bounds() const { return detail::toPublic(impl_->bounds()); }

Bounds Solid::ownBounds() const {
  return guarded([&] { return detail::toPublic(detail::tightBounds(*impl_)); });
}

bool Solid::contains(const Vec3& point) const { return impl_->contains(toDetail(point)); }

double Solid::volume(int grid) const {
  return guarded([&] {
    detail::checkWhole("volume", "grid", grid, 1, 4096);
    const detail::Bounds box = impl_->bounds();
    if (!box.empty() && !box.finite())
      throw std::invalid_argument(
          "volume: the solid is unbounded, or bounded only by half-spaces, whose reach csgray "
          "does not work out; clip it with a box (Solid::clip) to measure it");
    const double volume = detail::exactVolume(*impl_, grid);
    // A solid of 10¹⁰³ across has a volume past the largest double.
    if (!std::isfinite(volume))
      throw std::invalid_argument("volume: the solid is too large for its volume to be a number");
    return volume;
  });
}

std::string Solid::kind() const { return impl_->kind(); }

std::size_t Solid::primitiveCount() const { return impl_->primitiveCount(); }

}  // namespace csgray
