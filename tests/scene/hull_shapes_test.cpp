// Hulls, Minkowski sums and the rounded shapes: analytic volumes (Steiner's
// formula for a box and a ball, Pappus's for the turned shapes), spans that
// agree with contains() and outward normals, an edge-on render whose every
// pixel is held against the analytic outline, exports that pass the check,
// meshes whose volume is within what the tolerance allows, and the errors.
#include "scene/hull_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "check/exact_volume.h"
#include "check_support.h"
#include "engine/primitive.h"
#include "primitives/cgal/point_hull.h"
#include "primitives/convex_polyhedron.h"
#include "primitives/linear_extrusion.h"
#include "primitives/rounded_polytope.h"
#include "profile/shapes.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "scene/shapes.h"
#include "tessellation/triangle_mesh.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::scriptError;
using test::solidOf;

constexpr double kPi = std::numbers::pi;

SolidPtr ball(double r, const dvec3& at = dvec3(0.0)) {
  return sphereShape(r, std::nullopt)->transformed(Affine::translation(at));
}
SolidPtr cuboid(const dvec3& size, const dvec3& at = dvec3(0.0)) {
  return boxShape(size, false)->transformed(Affine::translation(at));
}

// Steiner's formula for a box a × b × c plus a ball of radius r: the box,
// a slab over each face, a quarter cylinder along each edge, an eighth of
// the ball at each corner.
double roundedBoxVolume(const dvec3& s, double r) {
  return s.x * s.y * s.z + 2.0 * r * (s.x * s.y + s.y * s.z + s.z * s.x) +
         kPi * r * r * (s.x + s.y + s.z) + 4.0 / 3.0 * kPi * r * r * r;
}

// Pappus: the profile's area times the path of its centroid. The profile
// of a rounded cylinder: the rectangle [0, R − f] × [0, H], the strip
// [R − f, R] × [f, H − f], and two quarter discs of radius f whose
// centroids lie 4f/(3π) beyond R − f.
double roundedCylinderVolume(double R, double H, double f) {
  double inner = R - f;
  return kPi * inner * inner * H + kPi * (R * R - inner * inner) * (H - 2.0 * f) +
         2.0 * (kPi * f * f / 4.0) * 2.0 * kPi * (inner + 4.0 * f / (3.0 * kPi));
}

// The hull of two balls: a cap of each beyond the circle where the common
// tangent cone touches it, and the cone frustum between the circles.
double twoBallHullVolume(double r1, double r2, double d) {
  double s = (r1 - r2) / d, c = std::sqrt(1.0 - s * s);
  auto cap = [](double r, double h) { return kPi * h * h * (3.0 * r - h) / 3.0; };
  double rho1 = r1 * c, rho2 = r2 * c, height = d + (r2 - r1) * s;
  return cap(r1, r1 + r1 * s) + cap(r2, r2 - r2 * s) +
         kPi * height * (rho1 * rho1 + rho1 * rho2 + rho2 * rho2) / 3.0;
}

// The check's volume (three jittered grids of 400 × 400 rays) is within a
// few parts in 10⁵ of the truth for these smooth parts.
void expectVolume(const Solid& solid, double exact, double relative) {
  EXPECT_NEAR(exactVolume(solid, 400), exact, relative * exact) << solid.kind();
}

// The mesh at tolerance t lies inside the convex solid and within t of its
// surface, so it misses at most area · t of its volume.
void expectMeshVolume(const Primitive& p, double exact, double area, double t) {
  TriangleMesh mesh = p.tessellate(t, p.bounds());
  EXPECT_LE(mesh.volume(), exact * (1.0 + 1e-9));
  EXPECT_GE(mesh.volume(), exact - area * t);
}

const Primitive& primitiveOf(const SolidPtr& s) { return dynamic_cast<const Primitive&>(*s); }

TEST(Minkowski, BoxAndBallIsExact) {
  const dvec3 size(3.0, 2.0, 1.0);
  const double r = 0.5;
  SolidPtr sum = minkowskiShape({cuboid(size, dvec3(1.0, -2.0, 0.5)), ball(r)});
  ASSERT_EQ(sum->kind(), "minkowski");
  expectVolume(*sum, roundedBoxVolume(size, r), 1e-4);
  EXPECT_EQ(sum->bounds().lo, dvec3(0.5, -2.5, 0.0));
  EXPECT_EQ(sum->bounds().hi, dvec3(4.5, 0.5, 2.0));
  test::expectSpansAgreeWithContainsOnRandomLines(*sum);
  test::expectOutwardUnitNormals(primitiveOf(sum));
  // Points just inside and outside a corner's ball, an edge's cylinder and
  // a face's slab.
  const dvec3 corner(4.0, 0.0, 1.5);
  const dvec3 diagonal = glm::normalize(dvec3(1.0));
  EXPECT_TRUE(sum->contains(corner + (r - 1e-9) * diagonal));
  EXPECT_FALSE(sum->contains(corner + (r + 1e-9) * diagonal));
  EXPECT_TRUE(sum->contains(dvec3(2.0, 0.0, 1.5) + (r - 1e-9) * glm::normalize(dvec3(0, 1, 1))));
  EXPECT_FALSE(sum->contains(dvec3(2.0, 0.0, 1.5) + (r + 1e-9) * glm::normalize(dvec3(0, 1, 1))));
  EXPECT_TRUE(sum->contains(dvec3(2.0, -1.0, 1.5 + r - 1e-9)));
  EXPECT_FALSE(sum->contains(dvec3(2.0, -1.0, 1.5 + r + 1e-9)));
}

TEST(Minkowski, AConvexPolygonExtrudedIsAPolytope) {
  // A square 3 × 2 extruded 1 high is the box: plus a ball, the rounded
  // box. Extruded to a point (scale 0), a pyramid of 3 · 2 · 1 / 3, whose
  // hull is itself. An L-shaped polygon extruded is not convex, and is
  // refused.
  const double r = 0.5;
  const RegionPtr rectangle = rectangleRegion("rectangle", 3.0, 2.0, false);
  const SolidPtr prism = Primitive::create<LinearExtrusion>(rectangle, 1.0, false, 0.0, dvec2(1.0));
  expectVolume(*minkowskiShape({prism, ball(r)}), roundedBoxVolume(dvec3(3.0, 2.0, 1.0), r), 1e-4);
  const SolidPtr pyramid =
      Primitive::create<LinearExtrusion>(rectangle, 1.0, false, 0.0, dvec2(0.0));
  expectVolume(*hullShape({pyramid}), 2.0, 1e-4);
  const RegionPtr ell = polygonRegion(
      {dvec2(0, 0), dvec2(3, 0), dvec2(3, 1), dvec2(1, 1), dvec2(1, 3), dvec2(0, 3)}, {});
  EXPECT_THROW(minkowskiShape(
                   {Primitive::create<LinearExtrusion>(ell, 1.0, false, 0.0, dvec2(1.0)), ball(r)}),
               std::invalid_argument);
}

TEST(Minkowski, ExportsOneValidMesh) {
  const dvec3 size(3.0, 2.0, 1.0);
  const double r = 0.5, t = 0.01;
  SolidPtr sum = minkowskiShape({cuboid(size), ball(r)});
  double area = 2.0 * (size.x * size.y + size.y * size.z + size.z * size.x) +
                2.0 * kPi * r * (size.x + size.y + size.z) + 4.0 * kPi * r * r;
  expectMeshVolume(primitiveOf(sum), roundedBoxVolume(size, r), area, t);
  EXPECT_TRUE(test::checksOut(*sum, t));
}

TEST(Minkowski, SkewPolyhedronAndBall) {
  // A tetrahedron has sharp edges and corners: its patches are large.
  SolidPtr tetra = solidOf("return tetrahedron{r=2}:rotate(10, 20, 30)");
  SolidPtr sum = minkowskiShape({tetra, ball(0.3)});
  test::expectSpansAgreeWithContainsOnRandomLines(*sum);
  test::expectOutwardUnitNormals(primitiveOf(sum));
  EXPECT_TRUE(test::checksOut(*sum));
}

TEST(Minkowski, DistributesOverUnions) {
  const double r = 0.25;
  SolidPtr pair =
      booleanShape(Boolean::Op::Union, {cuboid(dvec3(1.0)), cuboid(dvec3(1.0), {3, 0, 0})});
  SolidPtr sum = minkowskiShape({pair, ball(r)});
  EXPECT_EQ(sum->kind(), "union");
  expectVolume(*sum, 2.0 * roundedBoxVolume(dvec3(1.0), r), 1e-4);
  EXPECT_TRUE(test::checksOut(*sum));
}

TEST(Minkowski, PolyhedraAddTheirVertices) {
  SolidPtr sum = minkowskiShape({cuboid({1, 2, 3}), cuboid({2, 2, 2}, {-1, -1, -1})});
  expectVolume(*sum, 3.0 * 4.0 * 5.0, 1e-9);
  EXPECT_EQ(sum->bounds().lo, dvec3(-1.0));
  EXPECT_EQ(sum->bounds().hi, dvec3(2.0, 3.0, 4.0));
}

TEST(Minkowski, BallsAddTheirRadii) {
  SolidPtr sum = minkowskiShape({ball(1.0, {1, 0, 0}), ball(2.0, {0, 1, 0})});
  EXPECT_EQ(sum->kind(), "sphere");
  EXPECT_EQ(sum->bounds().lo, dvec3(-2.0, -2.0, -3.0));
  EXPECT_EQ(sum->bounds().hi, dvec3(4.0, 4.0, 3.0));
}

TEST(Minkowski, CylinderAndBallIsARoundedCylinder) {
  CylinderParams p;
  p.r = 2.0, p.h = 3.0;
  SolidPtr sum = minkowskiShape({cylinderShape("cylinder", p), ball(0.5)});
  expectVolume(*sum, roundedCylinderVolume(2.5, 4.0, 0.5), 1e-4);
  EXPECT_NEAR(sum->bounds().lo.z, -0.5, 1e-12);
  EXPECT_NEAR(sum->bounds().hi.z, 3.5, 1e-12);
  EXPECT_TRUE(test::checksOut(*sum));
}

// A box a × b × h₁ plus an upright cylinder of radius r and height h₂ is
// the rectangle grown by r (ab + 2r(a + b) + πr²) over h₁ + h₂; the hull of
// two upright cylinders d apart, the stadium πr² + 2rd over their height.
TEST(Minkowski, PrismAndCylinderAreExtruded) {
  CylinderParams p;
  p.r = 1.0, p.h = 2.0;
  SolidPtr rod = cylinderShape("cylinder", p);
  SolidPtr plate = minkowskiShape({cuboid({4, 3, 1}), rod});
  EXPECT_EQ(plate->kind(), "linear_extrude");
  expectVolume(*plate, (12.0 + 2.0 * 7.0 + kPi) * 3.0, 1e-4);
  EXPECT_NEAR(plate->bounds().lo.x, -1.0, 1e-9);
  EXPECT_NEAR(plate->bounds().hi.z, 3.0, 1e-9);
  SolidPtr slot = hullShape({rod, rod->transformed(Affine::translation({3, 4, 0}))});
  EXPECT_EQ(slot->kind(), "linear_extrude");
  expectVolume(*slot, (kPi + 2.0 * 5.0) * 2.0, 1e-4);
  EXPECT_TRUE(test::checksOut(*slot));
  // Cylinders of different lengths have no such hull: their meshes'.
  p.h = 3.0;
  SolidPtr longer = cylinderShape("cylinder", p)->transformed(Affine::translation({3, 4, 0}));
  EXPECT_EQ(hullShape({rod, longer})->kind(), "hull");
}

TEST(RoundedShapes, RoundedBoxIsTheSumOfItsCore) {
  SolidPtr rounded = roundedBoxShape(dvec3(4, 3, 2), 0.5, true);
  EXPECT_EQ(rounded->kind(), "rounded_box");
  EXPECT_EQ(rounded->bounds().lo, dvec3(-2.0, -1.5, -1.0));
  expectVolume(*rounded, roundedBoxVolume(dvec3(3, 2, 1), 0.5), 1e-4);
  // r half the smallest side: the core is a flat plate.
  SolidPtr plate = roundedBoxShape(dvec3(4, 3, 1), 0.5, false);
  expectVolume(*plate, roundedBoxVolume(dvec3(3, 2, 0), 0.5), 1e-4);
  test::expectSpansAgreeWithContainsOnRandomLines(*plate);
  EXPECT_TRUE(test::checksOut(*plate));
}

TEST(RoundedShapes, RoundedCylinderByPappus) {
  SolidPtr shape = roundedCylinderShape(2.0, 5.0, 0.5, false);
  expectVolume(*shape, roundedCylinderVolume(2.0, 5.0, 0.5), 1e-4);
  EXPECT_TRUE(test::checksOut(*shape));
  // fillet = r and h = 2·fillet: a ball.
  expectVolume(*roundedCylinderShape(1.0, 2.0, 1.0, true), 4.0 / 3.0 * kPi, 1e-4);
}

TEST(Hull, EqualBallsMakeARoundedBox) {
  std::vector<SolidPtr> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(ball(0.5, {i & 1 ? 3.0 : 0.0, i & 2 ? 2.0 : 0.0, i & 4 ? 1.0 : 0.0}));
  SolidPtr hull = hullShape(corners);
  EXPECT_EQ(hull->kind(), "hull");
  expectVolume(*hull, roundedBoxVolume({3, 2, 1}, 0.5), 1e-4);
  EXPECT_TRUE(test::checksOut(*hull));
}

TEST(Hull, TwoBallsAreExact) {
  for (double r2 : {1.0, 0.5}) {
    SolidPtr hull = hullShape({ball(1.0), ball(r2, {1.0, 2.0, 2.0})});
    expectVolume(*hull, twoBallHullVolume(1.0, r2, 3.0), 1e-4);
    EXPECT_TRUE(test::checksOut(*hull));
  }
  // One ball inside the other: the larger.
  EXPECT_EQ(hullShape({ball(3.0), ball(1.0, {1, 0, 0})})->kind(), "sphere");
}

TEST(Hull, PolyhedraAreConvexPolyhedra) {
  SolidPtr hull = hullShape({cuboid(dvec3(1.0)), cuboid(dvec3(1.0), {2, 0, 0})});
  ASSERT_EQ(hull->kind(), "hull");
  expectVolume(*hull, 3.0, 1e-9);
  EXPECT_EQ(hull->bounds().hi, dvec3(3.0, 1.0, 1.0));
  test::expectSpansAgreeWithContainsOnRandomLines(*hull);
  // The unit cube and a tetrahedron standing on three corners of its top
  // face: the cube and the pyramid of height 1 over that face, whose nine
  // faces (the cube's sides stay whole) meet at nine corners.
  SolidPtr pyramid = solidOf(
      "return hull(box(1), polyhedron{points={{0,0,1},{1,0,1},{0,1,1},{0.5,0.5,2}},"
      "faces={{0,2,1},{0,1,3},{1,2,3},{2,0,3}}})");
  const auto& planes = dynamic_cast<const ConvexPolyhedron&>(*pyramid);
  EXPECT_EQ(planes.planes().size(), 9u);
  EXPECT_EQ(planes.vertices().size(), 9u);
  expectVolume(*pyramid, 4.0 / 3.0, 1e-4);
  EXPECT_EQ(pyramid->bounds().hi, dvec3(1.0, 1.0, 2.0));
  EXPECT_TRUE(pyramid->contains({0.5, 0.5, 2.0 - 1e-9}));
  EXPECT_FALSE(pyramid->contains({0.5, 0.5, 2.0 + 1e-9}));
  EXPECT_FALSE(pyramid->contains({0.2, 0.5, 1.4 + 1e-9}));  // over the face z = 1 + 2x
  EXPECT_TRUE(pyramid->contains({0.2, 0.5, 1.4 - 1e-9}));
}

TEST(Hull, CurvedShapesWithinTheTolerance) {
  // An ellipsoid is its own hull: its mesh's at kHullTolerance of its size.
  SolidPtr egg = ellipsoidShape(dvec3(1, 2, 3));
  SolidPtr hull = hullShape({egg});
  double size = 2.0 * std::sqrt(14.0), area = 49.0;  // Knud Thomsen's approximation: 48.9
  EXPECT_NEAR(exactVolume(*hull, 200), 8.0 * kPi, area * kHullTolerance * size);
  EXPECT_TRUE(test::checksOut(*hull));
}

TEST(Hull, TheSamePointsGiveTheSamePolytopeWhateverTheHeap) {
  // OpenSCAD's hull of two polygon balls (15 rings of 30 points, 70
  // apart). CGAL's convex_hull_3 lists its result in an order that follows
  // where its data lay in memory: the polytope's corners and faces must
  // not, or the part's mesh changes with the heap (it changed with the
  // length of the output file's name).
  std::vector<dvec3> points;
  for (double x : {0.0, 70.0})
    for (int i = 0; i < 15; ++i)
      for (int j = 0; j < 30; ++j) {
        const double polar = kPi * (i + 0.5) / 15, azimuth = 2 * kPi * j / 30;
        points.push_back({x + 2 * std::sin(polar) * std::cos(azimuth),
                          2 * std::sin(polar) * std::sin(azimuth), 2 * std::cos(polar)});
      }
  const Polytope first = pointHull(points);
  ASSERT_EQ(first.dimension, 3);
  // Blocks of many sizes, every other one freed: a heap laid out otherwise.
  std::vector<std::vector<char>> blocks;
  for (std::size_t i = 1; i < 400; ++i) blocks.emplace_back(40 * i + 24 * (i % 7));
  for (std::size_t i = 0; i < blocks.size(); i += 2) blocks[i] = {};
  for (int round = 0; round < 3; ++round) {
    blocks.emplace_back(1000 + 333 * round);
    const Polytope again = pointHull(points);
    ASSERT_EQ(again.vertices, first.vertices);
    ASSERT_EQ(again.faces.size(), first.faces.size());
    for (std::size_t f = 0; f < first.faces.size(); ++f) {
      EXPECT_EQ(again.faces[f].loop, first.faces[f].loop);
      EXPECT_EQ(again.faces[f].normal, first.faces[f].normal);
    }
  }
}

TEST(HullScript, RegionsAndSolidsShareTheName) {
  EXPECT_EQ(solidOf("return linear_extrude(hull(circle(1), circle(1):translate(3, 0)), {height=1})")
                ->kind(),
            "linear_extrude");
  EXPECT_EQ(solidOf("return hull(sphere(1), sphere(1):translate(3, 0, 0))")->kind(),
            "rotate_extrude");
  EXPECT_EQ(solidOf("return minkowski(box(1), sphere(0.1))")->kind(), "minkowski");
  EXPECT_EQ(solidOf("return rounded_cylinder{r=2, h=3, fillet=0.5}")->kind(), "rotate_extrude");
}

// A square of side s plus a disc of radius r: s² + 4sr + πr² (its sides
// moved out, a quarter disc at each corner), placed by the disc's centre.
TEST(HullScript, RegionPlusCircleIsItsRoundedOffset) {
  Scene scene = runScript(
      "local m = minkowski(square(2), circle(0.5):translate(1, 0))\n"
      "assert(math.abs(m:area() - (4 + 4 + math.pi * 0.25)) < 1e-9, m:area())\n"
      "local lo, hi = m:bounds()\n"
      "assert(lo[1] == 0.5 and hi[1] == 3.5, lo[1])\n"
      "return linear_extrude(m, {height=1})",
      "part.lua");
  EXPECT_EQ(scene.objects.size(), 1u);
  // Two convex regions, one a polygon: the hull of copies of one at the
  // other's corners (a square of 2 and one of 1 make one of 3; a square
  // of 2 and a disc of 0.5 the rounded square).
  runScript(
      "local s = minkowski(square(2), square(1):translate(-0.5, -0.5))\n"
      "assert(math.abs(s:area() - 9) < 1e-9, s:area())\n"
      "local r = minkowski(regular_polygon{n=6, r=1}, square(2))\n"
      "assert(math.abs(r:area() - (1.5 * math.sqrt(3) + 4 + 2 * (2 + math.sqrt(3)))) < 1e-9,\n"
      "       r:area())\n"
      "return linear_extrude(s, {height=1})",
      "part.lua");
  // A shape of straight edges that is not convex, with a convex one: the
  // shape moved, and each of its edges swept over the other. An L of three
  // unit squares and a unit square make a square of 3 less its far corner;
  // a square of 10 with a hole of 4 and a disc-ended bar keep a hole.
  runScript(
      "local L = square(2) - square(1):translate(1, 1)\n"
      "local m = minkowski(L, square(1))\n"
      "assert(math.abs(m:area() - 8) < 1e-9, m:area())\n"
      "local ring = square(10) - square(4):translate(3, 3)\n"
      "local bar = hull(circle(0.5), circle(0.5):translate(1, 0))\n"
      "local r = minkowski(ring, bar)\n"
      // Outside, 12 by 11 with corners rounded by 0.5; the hole shrinks
      // by the bar's length across and its width both ways: 2 by 3.
      "local outside = 12 * 11 - (4 - math.pi) * 0.25\n"
      "assert(math.abs(r:area() - (outside - 2 * 3)) < 1e-9, r:area())\n"
      // A ring and a unit square: the disc of 5 grown (its area, the
      // square's and the mixed term 5 · 4), less the hole: the points whose
      // square lies in the disc of 3, the four discs at its corners met. The
      // arcs are cut within 10⁻⁴ of the ring's size: the area within that
      // times the ring's perimeter.
      "local ringSum = minkowski(circle(5) - circle(3), square(1))\n"
      "local hole = intersection(circle(3), circle(3):translate(1, 0), circle(3):translate(0, 1),\n"
      "                          circle(3):translate(1, 1))\n"
      "local want = math.pi * 25 + 1 + 5 * 4 - hole:area()\n"
      "assert(math.abs(ringSum:area() - want) < 16 * math.pi * 1e-3, ringSum:area() - want)\n"
      "return linear_extrude(m, {height=1})",
      "part.lua");
  EXPECT_EQ(scriptError("local L = square(2) - square(1):translate(1, 1)\n"
                        "return minkowski(L, L)"),
            "part.lua:2: minkowski: of two regions, one must be convex or a circle");
}

TEST(HullScript, ErrorsNameTheLine) {
  EXPECT_EQ(scriptError("local a = box(2)\nreturn minkowski(a - sphere(1), sphere(1))"),
            "part.lua:2: minkowski: takes shapes and unions of them, not a difference");
  EXPECT_EQ(scriptError("return hull(box(2) * sphere(1.2), sphere(1))"),
            "part.lua:1: hull: takes shapes and unions of them, not an intersection");
  EXPECT_EQ(
      scriptError("return\nminkowski(torus{R=3, r=1}, sphere(1))"),
      "part.lua:2: minkowski: the torus is not convex; its sum is not supported: give it as a "
      "union of convex pieces, whose sums are joined");
  EXPECT_EQ(
      scriptError("local L = linear_extrude{square(2) - square(1):translate(1, 1), height=1}\n"
                  "return minkowski(L, sphere(0.2))"),
      "part.lua:2: minkowski: the linear_extrude is not convex; its sum is not supported: "
      "give it as a union of convex pieces, whose sums are joined, or round the profile "
      "with offset{r=...} before extruding it");
  EXPECT_EQ(scriptError("return rounded_box{size={4, 3, 2}, r=1.5}"),
            "part.lua:1: rounded_box: r must be at most half the smallest side, 1 (got 1.5)");
  EXPECT_EQ(scriptError("return rounded_cylinder{r=1, h=4, fillet=2}"),
            "part.lua:1: rounded_cylinder: fillet must be at most r and half of h, 1 (got 2)");
  EXPECT_EQ(scriptError("return hull(half_space{normal={0, 0, 1}}, sphere(1))"),
            "part.lua:1: hull: the half_space is unbounded");
  EXPECT_EQ(scriptError("return hull(box(1), box{1, 1, 0.5})"), "(no error)");
  EXPECT_EQ(scriptError("return hull(sphere(1))"), "(no error)");
  // An L of two boxes as one polyhedron is not convex.
  EXPECT_EQ(
      scriptError("local l = polyhedron{points={{0,0,0},{2,0,0},{2,1,0},{1,1,0},{1,2,0},{0,2,0},"
                  "{0,0,1},{2,0,1},{2,1,1},{1,1,1},{1,2,1},{0,2,1}},"
                  "faces={{0,1,2,3,4,5},{11,10,9,8,7,6},{0,6,7,1},{1,7,8,2},{2,8,9,3},{3,9,10,4},"
                  "{4,10,11,5},{5,11,6,0}}}\nreturn minkowski(l, sphere(0.1))"),
      "part.lua:2: minkowski: the polyhedron is not convex: give it as a union of convex "
      "pieces, whose sums are joined");
}

// Edge-on: an orthographic camera looking along y at a rounded box sees
// the rectangle of its x and z sides grown by r with rounded corners, and
// every pixel whose centre is more than a hair from that outline must be
// shown as the outline says.
TEST(MinkowskiRender, EdgeOnSilhouette) {
  const dvec3 size(3.0, 2.0, 1.0);
  const double r = 0.5;
  Scene scene;
  scene.objects.push_back(minkowskiShape({cuboid(size, -0.5 * size), ball(r)}));
  scene.camera = CameraSpec{dvec3(0, -20, 0), dvec3(0), dvec3(0, 0, 1), 45.0, true, 6.0};
  scene.background = dvec3(0.0);
  const int w = 300, h = 150;
  Image image = Renderer(scene, {w, h, 0}).render();
  Camera camera(*scene.camera, w, h);
  int hits = 0, misses = 0, wrong = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      Ray ray = camera.ray(x + 0.5, y + 0.5);
      double dx = std::max(std::abs(ray.origin.x) - size.x / 2, 0.0);
      double dz = std::max(std::abs(ray.origin.z) - size.z / 2, 0.0);
      double outside = std::hypot(dx, dz) - r;
      if (std::abs(outside) < 1e-9) continue;
      bool hit = outside < 0.0, shown = image.at(x, y) != dvec3(0.0);
      hits += hit, misses += !hit;
      if (hit != shown && ++wrong <= 5)
        ADD_FAILURE() << "pixel (" << x << ", " << y << "): outline says "
                      << (hit ? "hit" : "miss");
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(hits, 5000);
  EXPECT_GT(misses, 5000);
}

}  // namespace
}  // namespace csgray::detail
