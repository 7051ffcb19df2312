// Solids: exact shapes combined by booleans, as a part script builds them
// (docs/script.md). A Solid is an immutable value, cheap to copy: its
// operations return new solids and share what they do not change, so one
// part may be reused in many places. Lengths are model units, angles
// degrees. Invalid parameters throw csgray::Error with code
// InvalidArgument and the message the script function of the same name
// gives.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "csgray/material.h"
#include "csgray/types.h"

namespace csgray {

namespace detail {
class Solid;
struct Access;
}  // namespace detail

struct Mesh;
class Region;

// How Solid::linearExtrude sweeps a region up z.
struct ExtrudeOptions {
  bool center = false;   // from −height/2 to height/2 rather than from 0 up
  double twist = 0.0;    // degrees the top is turned clockwise from the bottom, as OpenSCAD's
  Vec2 scale{1.0, 1.0};  // the top's size against the bottom's, along x and y
};

// A 4 × 4 affine map as four rows; the last is 0 0 0 1.
using Matrix4 = std::array<std::array<double, 4>, 4>;

// The closed half-space normal · p <= offset; the normal need not be unit.
struct Plane {
  Vec3 normal;
  double offset = 0.0;
};

// A ball of a blob: within `radius` of `center` it adds
// strength · (1 − d²/radius²)² to the field (d the distance from the
// centre); a negative strength takes away.
struct BlobBall {
  Vec3 center;
  double radius = 1.0;
  double strength = 1.0;
};

class CSGRAY_API Solid {
 public:
  // ---- Primitives ------------------------------------------------------------
  // A ball of radius r about the origin.
  static Solid sphere(double r);
  // A sphere scaled by the three radii.
  static Solid ellipsoid(const Vec3& radii);
  // From the origin to size, or centred on the origin.
  static Solid box(const Vec3& size, bool center = false);
  // A cube of the given edge.
  static Solid box(double size, bool center = false);
  // Along +z from 0 to h (centred on the origin with center).
  static Solid cylinder(double h, double r, bool center = false);
  // A cone frustum along +z: radius r1 at the bottom, r2 at the top.
  static Solid cone(double h, double r1, double r2 = 0.0, bool center = false);
  // normal · p <= offset: unbounded, to cut other solids with.
  static Solid halfSpace(const Vec3& normal, double offset = 0.0);
  // About the z axis: R from the axis to the centre of the tube of radius r.
  static Solid torus(double R, double r);
  // About the origin, radii along x, y and z: e shapes the sections
  // across z, n the profile along z (1 round, towards 0 square, 2 a
  // diamond; from 0.001 to 2).
  static Solid superellipsoid(const Vec3& radii, double e, double n);
  // The balls' fields added up; the solid where the sum reaches threshold
  // (POV-Ray's blob): balls near each other melt into one smooth shape.
  static Solid blob(const std::vector<BlobBall>& balls, double threshold = 0.5);
  // {p : pᵀ M p <= 0} for homogeneous p = (x, y, z, 1); M symmetric.
  static Solid quadric(const Matrix4& m);
  // The named quadrics by their semi-axes (docs/script.md, Named quadrics).
  static Solid hyperboloid1(double a, double b, double c);
  static Solid hyperboloid2(double a, double b, double c);
  static Solid ellipticCone(double a, double b, double c);
  static Solid ellipticParaboloid(double a, double b);
  static Solid hyperbolicParaboloid(double a, double b);
  static Solid ellipticCylinder(double a, double b);
  static Solid hyperbolicCylinder(double a, double b);
  static Solid parabolicCylinder(double p);
  // The Platonic solids about the origin, by circumradius r.
  static Solid tetrahedron(double r);
  static Solid hexahedron(double r);
  static Solid octahedron(double r);
  static Solid dodecahedron(double r);
  static Solid icosahedron(double r);
  // The points inside every plane: normal · p <= offset.
  static Solid convex(const std::vector<Plane>& planes);
  // OpenSCAD's polyhedron: a closed mesh of faces that list point indices
  // (from 0) clockwise seen from outside (all counter-clockwise is turned).
  static Solid polyhedron(const std::vector<Vec3>& points,
                          const std::vector<std::vector<std::int64_t>>& faces);
  // A closed mesh whose triangles run counter-clockwise seen from outside,
  // as exportMesh and readMesh give them. Error (InvalidArgument) naming
  // the fault when it is not such a mesh: open, not a 2-manifold, inside
  // out, or with faces that cross (as fromMeshFile and mesh{} refuse it).
  static Solid fromMesh(const Mesh& mesh);
  // A mesh file (STL, OBJ, OFF, PLY or 3MF) as a solid; with repair, what can
  // be mended is, and repairReport (if given) says what was done.
  static Solid fromMeshFile(const std::string& path, bool repair = false,
                            std::string* repairReport = nullptr);

  // OpenSCAD's surface(): a grid of heights as a solid (docs/script.md,
  // "Height maps"), rows[r][c] the height at x = c, y = r, one unit apart;
  // rows shorter than the longest are filled up with 0. center: centred on
  // the origin in x and y.
  static Solid heightMap(const std::vector<std::vector<double>>& rows, bool center = false);
  // The same from a text file of numbers or a PNG image's grey levels, as
  // the script's height_map{file=} reads it (invert: heights 100/255 · (1 −
  // luminance), from 0.39 down to −99.6, as OpenSCAD computes them). A
  // file that cannot be read, or that holds no grid of numbers or PNG
  // image, is IoError.
  static Solid heightMapFile(const std::string& path, bool center = false, bool invert = false);

  // ---- Hull and Minkowski (docs/script.md, "Hull and Minkowski") -------------
  // The convex hull of shapes and unions of them.
  static Solid hull(const std::vector<Solid>& solids);
  // The Minkowski sum, pair by pair from the first.
  static Solid minkowski(const std::vector<Solid>& solids);
  // A box of outer size whose edges and corners are rounded with radius r.
  static Solid roundedBox(const Vec3& size, double r, bool center = false);
  // ---- Sweeps of 2D regions ---------------------------------------------------
  // The region swept up z by height (OpenSCAD's linear_extrude); twisted
  // and scaled, its faces stay exact (docs/script.md, "Sweeps").
  static Solid linearExtrude(const Region& region, double height,
                             const ExtrudeOptions& options = {});
  // The region, in the half-plane x >= 0 taken as the xz plane, turned
  // about z by angle degrees from the x axis (OpenSCAD's rotate_extrude):
  // counter-clockwise seen from +z, or clockwise for a negative angle;
  // 0 < |angle| <= 360.
  static Solid rotateExtrude(const Region& region, double angle = 360.0);

  // A cylinder along +z whose rims are rounded with radius fillet: height
  // and radius in cylinder()'s order.
  static Solid roundedCylinder(double h, double r, double fillet, bool center = false);

  // ---- Booleans --------------------------------------------------------------
  // Of at least one solid; a difference is the first minus all others.
  static Solid unionOf(const std::vector<Solid>& solids);
  static Solid intersectionOf(const std::vector<Solid>& solids);
  static Solid differenceOf(const std::vector<Solid>& solids);
  Solid operator+(const Solid& other) const;  // union
  Solid operator-(const Solid& other) const;  // difference
  Solid operator*(const Solid& other) const;  // intersection
  // This solid within the box, or within the cutters; cutters without a
  // material take this solid's when all of it has one.
  Solid clip(const Bounds& box) const;
  Solid clip(const std::vector<Solid>& cutters) const;

  // ---- Transforms and material ------------------------------------------------
  Solid translate(const Vec3& offset) const;
  // Degrees about x, then y, then z (OpenSCAD's rotate([x, y, z])).
  Solid rotate(const Vec3& degrees) const;
  // Degrees about the axis through the origin.
  Solid rotate(double degrees, const Vec3& axis) const;
  Solid scale(const Vec3& factors) const;
  Solid scale(double factor) const;
  // Reflection in the plane through the origin with this normal.
  Solid mirror(const Vec3& normal) const;
  Solid transform(const Matrix4& m) const;
  // OpenSCAD's resize(): scaled about the origin so that the solid's own
  // box (ownBounds) gets these sizes; a size of 0 keeps its axis, or with
  // autoAxes set for it scales it by the largest factor of the axes given.
  Solid resize(const Vec3& size, const std::array<bool, 3>& autoAxes = {}) const;
  // On a primitive, its material; on a boolean, the material of every
  // primitive below that has none of its own.
  Solid material(const Material& material) const;

  // ---- Questions ---------------------------------------------------------------
  // A box that holds the whole solid (infinite where it is unbounded).
  Bounds bounds() const;
  // Is the point in the solid (its surface included, up to rounding)?
  bool contains(const Vec3& point) const;
  // The volume, from the exact lengths inside the solid along three
  // jittered grids of grid × grid rays, as `csgray check` measures it: for
  // a smooth part, the error falls faster than 1/grid². grid: 1 to 4096.
  // Error for an unbounded solid, and for one whose volume is past the
  // largest double.
  double volume(int grid = 256) const;
  // The box of the solid's own points, found by rays through it, as
  // `csgray info` prints it: tighter than bounds() where a boolean's
  // operands reach past it. A feature narrower than a 64th of the box
  // along the axis may be missed. Where the rays meet nothing (an
  // unbounded or an empty solid) it is bounds().
  Bounds ownBounds() const;
  // "sphere", "union", ...
  std::string kind() const;
  // Primitives in the tree, a shared part counted once for each use.
  std::size_t primitiveCount() const;

 private:
  explicit Solid(std::shared_ptr<const detail::Solid> impl);
  detail::Shared<detail::Solid> impl_;
  friend struct detail::Access;
};

}  // namespace csgray
