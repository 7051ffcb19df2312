// Linear extrusions of regions: analytic hits, volumes from spans (prisms,
// uniformly and non-uniformly scaled, twisted, of region booleans),
// agreement of spans with contains(), outward normals, meshes that are
// valid solids of the right volume, refused parameters, and edge-on views
// of a twisted extrusion with no pixel lost.
#include "primitives/linear_extrusion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "check_support.h"
#include "engine/boolean.h"
#include "engine/cancellation.h"
#include "export/cgal/mesh_validity.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/sphere.h"
#include "primitives/sweep_checks.h"
#include "primitives/sweep_shapes.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "tessellation/triangle_mesh.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

std::shared_ptr<LinearExtrusion> extrude(RegionPtr region, double h, double twist = 0.0,
                                         dvec2 scale = dvec2(1.0), bool center = false) {
  return Primitive::create<LinearExtrusion>(std::move(region), h, center, twist, scale);
}

using test::expectValidMesh;
using test::expectVolume;

// ∫₀¹ σx·σy dζ = 1 + (a + b)/2 + ab/3 with a = sx − 1, b = sy − 1: the
// volume of a scaled extrusion over that of the prism.
double scaleFactor(const dvec2& s) {
  const double a = s.x - 1, b = s.y - 1;
  return 1 + (a + b) / 2 + a * b / 3;
}

RegionPtr squareWithHole() {
  return test::regionOf({test::rectangleLoop({-1, -1}, {1, 1}), test::circleLoop({0.2, 0}, 0.5)});
}
const double kSquareWithHoleArea = 4.0 - kPi * 0.25;

TEST(LinearExtrusion, RaysAlongTheAxesHitThePrism) {
  auto prism = extrude(test::rectangle({0, 0}, {2, 1}), 3.0);
  SpanList spans = test::spansOf(*prism, Ray(dvec3(1, 0.5, -5), dvec3(0, 0, 1)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 5.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 8.0, 1e-12);
  EXPECT_EQ(spans[0].in.face, kSweepStartFace);
  EXPECT_EQ(spans[0].out.face, kSweepEndFace);
  spans = test::spansOf(*prism, Ray(dvec3(-5, 0.5, 1), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].in.t, 5.0, 1e-12);
  EXPECT_NEAR(spans[0].out.t, 7.0, 1e-12);
  test::expectVecNear(prism->normal(dvec3(0, 0.5, 1), spans[0].in.face), dvec3(-1, 0, 0), 1e-12);
  test::expectVecNear(prism->normal(dvec3(2, 0.5, 1), spans[0].out.face), dvec3(1, 0, 0), 1e-12);
  // Through the hole of a square with a hole: two spans.
  auto holed = extrude(squareWithHole(), 1.0, 0.0, dvec2(1.0), true);
  spans = test::spansOf(*holed, Ray(dvec3(-5, 0, 0), dvec3(1, 0, 0)));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0].out.t, 5.0 - 0.3, 1e-12);
  EXPECT_NEAR(spans[1].in.t, 5.0 + 0.7, 1e-12);
  test::expectVecNear(holed->normal(dvec3(-0.3, 0, 0), spans[0].out.face), dvec3(1, 0, 0), 1e-12);
  EXPECT_TRUE(holed->contains(dvec3(0.9, 0.9, 0.4)));
  EXPECT_FALSE(holed->contains(dvec3(0.2, 0, 0)));
  EXPECT_FALSE(holed->contains(dvec3(0.9, 0.9, 0.6)));
}

TEST(LinearExtrusion, RaysAlongThePyramidsAxisOverItsCornersHitIt) {
  // A scale of 0 makes a pyramid: a ray along the axis at distance ρ from
  // it, over the line from the centre to a corner, is inside for a height
  // of h (1 − ρ/r). The ray's image in the profile plane runs out from the
  // point to 10¹² times the region's size, and through the corner: a ray
  // going down, as over the mirror image of a pyramid, lost the corner's
  // crossing to that far end's rounding and found nothing.
  const double r = 9.5, h = 10.0;
  std::vector<dvec2> corners;
  for (int k = 0; k < 6; ++k)
    corners.push_back(r * dvec2(std::cos(k * kPi / 3), std::sin(k * kPi / 3)));
  auto pyramid = extrude(test::regionOf({test::polygonLoop(corners)}), h, 0.0, dvec2(0.0));
  for (const dvec2& corner : corners)
    for (int step = 1; step < 100; ++step)
      for (const double off : {0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6}) {
        // Over the line to the corner, or a hair to either side of it.
        const dvec2 p = corner * (step / 100.0) + off * dvec2(-corner.y, corner.x) / r;
        const double inside = h * (1.0 - step / 100.0);
        for (const double dz : {1.0, -1.0}) {
          const Ray ray(dvec3(p, dz > 0 ? -0.02 : h + 0.02), dvec3(0, 0, dz));
          const SpanList spans = test::spansOf(*pyramid, ray);
          ASSERT_EQ(spans.size(), 1u) << p.x << ", " << p.y << " dz " << dz;
          EXPECT_NEAR(spans[0].length(), inside, 1e-5) << p.x << ", " << p.y << " dz " << dz;
        }
      }
}

// OpenSCAD's convention: a positive twist turns the profile clockwise seen
// from +z, so a bar along +x ends along −y after a quarter turn.
TEST(LinearExtrusion, PositiveTwistTurnsClockwise) {
  auto bar = extrude(test::rectangle({0.5, -0.1}, {1.0, 0.1}), 2.0, 90.0);
  EXPECT_TRUE(bar->contains(dvec3(0.75, 0, 0.01)));
  EXPECT_TRUE(bar->contains(dvec3(0, -0.75, 1.99)));
  EXPECT_FALSE(bar->contains(dvec3(0, 0.75, 1.99)));
  SpanList spans = test::spansOf(*bar, Ray(dvec3(0, -5, 1.99), dvec3(0, 1, 0)));
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_LT(spans[0].out.t, 5.0);
}

// A rectangle turned a whole turn as it shrinks to a point: near the apex
// a ray's image in the profile plane runs out to infinity.
SolidPtr twistedToAPoint() {
  return extrude(test::rectangle({-10, -5}, {10, 5}), 40.0, -360.0, dvec2(0.0), true);
}

TEST(LinearExtrusion, PrismVolumeIsAreaTimesHeight) {
  expectVolume(extrude(squareWithHole(), 2.5), kSquareWithHoleArea * 2.5);
  const std::vector<dvec2> star = test::starPoints(40, 2.0, 1.4);
  expectVolume(extrude(test::regionOf({test::polygonLoop(star)}), 1.5),
               test::polygonArea(star) * 1.5);
}

// ∫₀¹ σ(ζ)² dζ = (1 + s + s²)/3 for a uniform scale s.
TEST(LinearExtrusion, UniformScaleVolume) {
  for (double s : {0.0, 0.5, 2.0}) {
    SCOPED_TRACE(s);
    expectVolume(extrude(test::circle({0.3, 0}, 1.0), 2.0, 0.0, dvec2(s)),
                 kPi * 2.0 * (1 + s + s * s) / 3.0);
  }
}

TEST(LinearExtrusion, NonUniformScaleVolume) {
  const dvec2 s(2.0, 0.5);
  expectVolume(extrude(squareWithHole(), 2.0, 0.0, s), kSquareWithHoleArea * 2.0 * scaleFactor(s));
}

TEST(LinearExtrusion, TwistKeepsTheVolume) {
  expectVolume(extrude(test::rectangle({-1, -0.5}, {1.5, 0.5}), 2.0, 90.0), 2.5 * 2.0, 0.01);
  expectVolume(extrude(squareWithHole(), 2.0, -200.0, dvec2(0.7)),
               kSquareWithHoleArea * 2.0 * (1 + 0.7 + 0.49) / 3.0, 0.01);
  // Twisted to a point (OpenSCAD's linear_extrude example): a pyramid's
  // third of the base times the height, whatever the turn.
  expectVolume(twistedToAPoint(), 20.0 * 10.0 * 40.0 / 3.0, 0.01);
}

TEST(LinearExtrusion, RegionBooleansCommuteWithTheExtrusion) {
  RegionPtr square = test::rectangle({-1, -1}, {1, 1});
  RegionPtr disc = test::circle({0.2, 0}, 0.5);
  RegionPtr difference = Region::boolean(Region::Op::Difference, {square, disc});
  expectVolume(extrude(difference, 2.0), kSquareWithHoleArea * 2.0);
  RegionPtr united = Region::boolean(Region::Op::Union, {square, test::circle({1.0, 0}, 0.5)});
  expectVolume(extrude(united, 1.0), 4.0 + kPi * 0.25 / 2.0);
  RegionPtr common =
      Region::boolean(Region::Op::Intersection, {square, test::circle({1.0, 0}, 0.5)});
  expectVolume(extrude(common, 1.0), kPi * 0.25 / 2.0);
}

std::vector<std::pair<std::string, SolidPtr>> assorted() {
  RegionPtr square = test::rectangle({-1, -1}, {1, 1});
  RegionPtr difference =
      Region::boolean(Region::Op::Difference, {square, test::circle({0.2, 0}, 0.5)});
  const Affine skew = Affine::rotation(0.7, glm::normalize(dvec3(1, 2, 3)))
                          .then(Affine::translation(dvec3(0.5, -2, 1)));
  return {
      {"prism", extrude(squareWithHole(), 2.0)},
      {"star", extrude(test::regionOf({test::polygonLoop(test::starPoints(40, 2.0, 1.4))}), 1.0)},
      {"scaled", extrude(squareWithHole(), 2.0, 0.0, dvec2(0.4))},
      {"apex", extrude(test::circle({0.5, 0}, 1.0), 2.0, 0.0, dvec2(0.0))},
      {"non-uniform", extrude(squareWithHole(), 2.0, 0.0, dvec2(1.5, 0.3))},
      {"twisted", extrude(squareWithHole(), 2.0, 120.0, dvec2(0.8, 1.2), true)},
      {"twisted to a point", twistedToAPoint()},
      {"difference", extrude(difference, 2.0)->transformed(skew)},
  };
}

TEST(LinearExtrusion, SpansAgreeWithContainsOnRandomLines) {
  for (const auto& [name, solid] : assorted()) {
    SCOPED_TRACE(name);
    test::expectSpansAgreeWithContainsOnRandomLines(*solid, 3000, 3);
  }
}

// spansToFirstBoundary follows a ray's curve only to its first boundary
// (the pieces of a twisted path in order, up to the first crossing): that
// boundary is the one of the whole spans, bit for bit, from outside and
// inside, over windows that start and end anywhere.
TEST(LinearExtrusion, FirstBoundaryAgreesWithTheWholeSpans) {
  auto solids = assorted();
  const RegionPtr star = test::regionOf({test::polygonLoop(test::starPoints(24, 2.0, 1.6))});
  solids.push_back({"twisted star", extrude(star, 3.0, 40.0)});
  // A union, each leaf followed to its own first boundary: the star, a
  // disc across its rim and one apart.
  solids.push_back({"twisted union",
                    extrude(Region::boolean(Region::Op::Union, {star, test::circle({1.8, 0.5}, 0.6),
                                                                test::circle({-1.0, -2.6}, 0.4)}),
                            3.0, 40.0)});
  for (const auto& [name, solid] : solids) {
    SCOPED_TRACE(name);
    const auto [hits, entries] = test::expectFirstBoundaryAgreesWithTheWholeSpans(*solid, 3000, 13);
    // Most rays meet the solid, both entering and leaving first.
    EXPECT_GT(hits, 500);
    EXPECT_GT(entries, 300);
    EXPECT_LT(entries, hits - 50);
  }
}

// A ray from inside an L-shaped prism, scaled unevenly (a path of many
// pieces), that touches the L's inner corner and leaves by the far side:
// the touch is a crossing of two edges at one point, which the first-
// boundary mode stops a margin past, still inside. The exit lies beyond
// what it followed, so the whole spans are asked for.
TEST(LinearExtrusion, FirstBoundaryFromInsidePastATouchedCorner) {
  const auto l =
      extrude(test::regionOf({test::polygonLoop({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})}),
              2.0, 0.0, dvec2(0.5, 1.0));
  // At z = 1 the x axis is scaled by 0.75: the profile point (0.5, 1.25)
  // moves by (2, −1) a unit of t, through the corner (1, 1) at t = 0.25
  // (exactly), and leaves through x = 2 at t = 0.75.
  const Ray ray(dvec3(0.375, 1.25, 1.0), dvec3(1.5, -1.0, 0.0));
  SpanList whole, first;
  l->spans(ray, whole);
  l->spansToFirstBoundary(ray, first);
  const auto expected = test::firstBoundary(whole, ray), actual = test::firstBoundary(first, ray);
  ASSERT_TRUE(expected && actual);
  EXPECT_NEAR(expected->first.t, 0.75, 1e-12);
  EXPECT_FALSE(expected->second);
  EXPECT_EQ(actual->first.t, expected->first.t);
  EXPECT_EQ(actual->first.face, expected->first.face);
  EXPECT_EQ(actual->second, expected->second);
}

// A difference asks its first operand for the first boundary only; where a
// hole covers that boundary, the operand's spans beyond it are asked for
// after all. Holes through the twisted star, along it and across it, and
// a nest of balls, so that most rays that meet the part start in a hole.
TEST(LinearExtrusion, FirstBoundaryOfADifferenceLiesPastItsHoles) {
  const SolidPtr star =
      extrude(test::regionOf({test::polygonLoop(test::starPoints(24, 2.0, 1.6))}), 3.0, 40.0);
  std::vector<SolidPtr> parts{star};
  parts.push_back(Primitive::create<Cylinder>(0.8, 0.8, 5.0)
                      ->transformed(Affine::translation(dvec3(0, 0, -1))));
  parts.push_back(Primitive::create<Box>(dvec3(6.0, 0.6, 0.6))
                      ->transformed(Affine::translation(dvec3(-3.0, -0.3, 1.2))));
  for (int i = 0; i < 8; ++i) {
    const double a = 2.0 * kPi * i / 8.0;
    parts.push_back(Primitive::create<Sphere>(0.7)->transformed(
        Affine::translation(dvec3(1.6 * std::cos(a), 1.6 * std::sin(a), 3.0 * (i % 2)))));
  }
  const SolidPtr part = differenceOf(parts);
  const auto [hits, entries] = test::expectFirstBoundaryAgreesWithTheWholeSpans(*part, 6000, 17);
  EXPECT_GT(hits, 1000);
  EXPECT_GT(entries, 500);
}

TEST(LinearExtrusion, NormalsFaceOutward) {
  for (const auto& [name, solid] : assorted()) {
    SCOPED_TRACE(name);
    auto p = std::dynamic_pointer_cast<const Primitive>(solid);
    ASSERT_TRUE(p);
    test::expectOutwardUnitNormals(*p, 1e-9, 500, 7);
  }
}

TEST(LinearExtrusion, FlaredExtrusionsAreMeshedWithinTheTolerance) {
  // A scale above 1 stretches the polygons of the region's circles with
  // the profile: cut for the base, their chords were up to 1.4 tolerances
  // off the exact sides at the top (a tube flared to three times its
  // size, a cone opening to four, flared and twisted rings).
  const std::string sources[] = {
      "return linear_extrude{circle{r=10} - circle{r=8}, height=50, scale=3}",
      "return linear_extrude{circle{r=10}, height=20, scale=4}",
      "return linear_extrude{circle{r=10} - circle{r=8}, height=50, twist=90, scale=2}",
      "return linear_extrude{square{size=10, center=true} - circle{r=3}, height=30, twist=120, "
      "scale=2.5}"};
  for (const std::string& source : sources)
    EXPECT_TRUE(test::checksOut(*test::solidOf(source), 0.01)) << source;
}

// A scale of other factors on x and y bends each side quad over an edge
// of length ℓ by |sx − sy|·ℓ/(4N) between slices N apart: the long edges
// are cut, rather than every edge sliced N times as the longest needs (a
// bar of 20 with a ball of short chords on it: 38 488 triangles then; a
// letter's stem: 864 000). The mesh still holds the tolerance.
TEST(LinearExtrusion, ASkewCutsTheLongEdgesRatherThanSlicingAll) {
  const SolidPtr bar = test::solidOf(
      "return linear_extrude{square{size={20, 1}} + circle{r=2}, height=2, scale={1, 0.5}}");
  EXPECT_TRUE(test::checksOut(*bar, 0.01));
  const TriangleMesh mesh =
      std::dynamic_pointer_cast<const Primitive>(bar)->tessellate(0.01, bar->bounds());
  EXPECT_LT(mesh.triangles.size(), 5000u);
}

TEST(LinearExtrusion, MeshesAreValidSolids) {
  expectValidMesh(*extrude(squareWithHole(), 2.5), 0.001, kSquareWithHoleArea * 2.5);
  expectValidMesh(*extrude(squareWithHole(), 2.0, 0.0, dvec2(0.5)), 0.001,
                  kSquareWithHoleArea * 2.0 * (1 + 0.5 + 0.25) / 3.0);
  expectValidMesh(*extrude(test::circle({0.5, 0}, 1.0), 2.0, 0.0, dvec2(0.0)), 0.001,
                  kPi * 2.0 / 3.0);
  expectValidMesh(*extrude(squareWithHole(), 2.0, 0.0, dvec2(1.5, 0.3)), 0.001,
                  kSquareWithHoleArea * 2.0 * scaleFactor(dvec2(1.5, 0.3)));
  expectValidMesh(*extrude(squareWithHole(), 2.0, 120.0, dvec2(1.0), true), 0.001,
                  kSquareWithHoleArea * 2.0);
  const std::vector<dvec2> star = test::starPoints(1200, 2.0, 1.9);
  expectValidMesh(*extrude(test::regionOf({test::polygonLoop(star)}), 1.0, 30.0), 0.001,
                  test::polygonArea(star));
}

// A scale of 0 on one axis folds the top onto a segment (OpenSCAD's
// wedge, linear_extrude with scale [1, 0]): each loop's two chains meet
// face to face along it, sharing every point of the seam. Volumes from
// ∫σx·σy dζ; regions that would fold onto one piece of the seam more than
// twice (a C, whose arms run back along it; a hole; two islands side by
// side along it) are refused with a message saying so.
TEST(LinearExtrusion, TopsFoldedOntoASegmentAreValidSolids) {
  const RegionPtr square = test::rectangle({-1, -1}, {1, 1});
  expectValidMesh(*extrude(square, 2.0, 0.0, dvec2(1.0, 0.0)), 0.001, 4.0 * 2.0 * 0.5);
  expectVolume(extrude(square, 2.0, 0.0, dvec2(1.0, 0.0)), 4.0);
  // Off the axis, flared along the seam, twisted, centred.
  const RegionPtr offset = test::rectangle({3, 8}, {7, 14});
  expectValidMesh(*extrude(offset, 10.0, 45.0, dvec2(2.0, 0.0), true), 0.001,
                  24.0 * 10.0 * scaleFactor(dvec2(2.0, 0.0)));
  expectValidMesh(*extrude(test::circle({0.5, 0.2}, 1.0), 2.0, 60.0, dvec2(0.0, 0.5)), 0.001,
                  kPi * 2.0 * scaleFactor(dvec2(0.0, 0.5)));
  // An L runs once along x and once back: its long side and its short
  // arms meet the seam at different points.
  const RegionPtr l =
      test::regionOf({test::polygonLoop({{0, 0}, {10, 0}, {10, 2}, {2, 2}, {2, 8}, {0, 8}})});
  expectValidMesh(*extrude(l, 10.0, 0.0, dvec2(1.0, 0.0)), 0.001, 32.0 * 10.0 * 0.5);
  expectValidMesh(*extrude(l, 10.0, 0.0, dvec2(0.0, 1.0)), 0.001, 32.0 * 10.0 * 0.5);
  // Two islands apart along the seam.
  const RegionPtr islands = Region::boolean(
      Region::Op::Union, {test::rectangle({-10, 0}, {-6, 4}), test::circle({8, 0}, 2.0)});
  expectValidMesh(*extrude(islands, 10.0, 0.0, dvec2(1.0, 0.0)), 0.001,
                  (16.0 + 4.0 * kPi) * 10.0 * 0.5);
  auto refusal = [](const std::shared_ptr<LinearExtrusion>& s) {
    try {
      s->tessellate(0.001, Bounds::everything());
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const RegionPtr c = test::regionOf(
      {test::polygonLoop({{0, 0}, {10, 0}, {10, 2}, {2, 2}, {2, 6}, {10, 6}, {10, 8}, {0, 8}})});
  EXPECT_NE(refusal(extrude(c, 10.0, 0.0, dvec2(1.0, 0.0))).find("back and forth"),
            std::string::npos);
  // Folded the other way, the C runs once up and once down.
  expectValidMesh(*extrude(c, 10.0, 0.0, dvec2(0.0, 1.0)), 0.001, 48.0 * 10.0 * 0.5);
  EXPECT_NE(refusal(extrude(squareWithHole(), 2.0, 0.0, dvec2(1.0, 0.0))).find("would meet"),
            std::string::npos);
  EXPECT_NE(refusal(extrude(islands, 10.0, 0.0, dvec2(0.0, 1.0))).find("would meet"),
            std::string::npos);
}

// Holes are joined to the outline by bridges, each from a hole's
// rightmost point to a corner it sees; a later hole's bridge may meet an
// earlier bridge and end at its corner, which the polygon then holds
// twice. A plate with holes on rows and columns (bridges along the rows,
// through the holes' corners on them, and crossing earlier bridges) caps
// into a valid mesh.
TEST(LinearExtrusion, HolesWhoseBridgesMeetStayValid) {
  const double area = 60.0 * 40.0;
  std::vector<ProfileLoop> three = {test::rectangleLoop({0, 0}, {60, 40})};
  for (dvec2 c : {dvec2(10, 10), dvec2(50, 10), dvec2(30, 30)})
    three.push_back(test::circleLoop(c, 3.0));
  const double hole = kPi * 9.0;
  expectValidMesh(*extrude(test::regionOf(three), 5.0), 0.01, (area - 3.0 * hole) * 5.0);
  std::vector<ProfileLoop> grid = {test::rectangleLoop({0, 0}, {60, 40})};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j)
      grid.push_back(test::circleLoop({8.0 + 11.0 * i, 8.0 + 12.0 * j}, 3.0));
  expectValidMesh(*extrude(test::regionOf(grid), 5.0), 0.01, (area - 15.0 * hole) * 5.0);
}

// A cap is cut into triangles near their neighbours, not fanned out from a
// few corners: the export's booleans and its validity check test pairs of
// triangles whose boxes overlap, and slivers across the whole cap overlap
// nearly all. On a 1 200-point star (600 spikes) the corners' triangle
// counts stay small (a fan from one corner would hold hundreds) and the
// triangles' boxes together cover a few times the cap's area, not
// hundreds of times.
TEST(LinearExtrusion, CapsAreCutIntoLocalTriangles) {
  const std::vector<dvec2> star = test::starPoints(1200, 2.0, 1.9);
  const TriangleMesh mesh = extrude(test::regionOf({test::polygonLoop(star)}), 1.0)
                                ->tessellate(0.001, Bounds::everything());
  std::vector<int> uses(mesh.points.size(), 0);
  double boxes = 0.0;
  int capTriangles = 0;
  for (const auto& t : mesh.triangles) {
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    if (a.z != 0.0 || b.z != 0.0 || c.z != 0.0) continue;
    ++capTriangles;
    for (std::uint32_t v : t) ++uses[v];
    const dvec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    boxes += (hi.x - lo.x) * (hi.y - lo.y);
  }
  EXPECT_EQ(capTriangles, 1198);  // n − 2
  EXPECT_LE(*std::max_element(uses.begin(), uses.end()), 24);
  EXPECT_LE(boxes, 4.0 * test::polygonArea(star));
}

// A large sweep's mesh reads the caller's cancel at each slice and level
// of sides: set, it stops; clear, it is made.
TEST(LinearExtrusion, AMeshStopsWhenCancelled) {
  const auto twisted = extrude(squareWithHole(), 2.0, 720.0);
  std::atomic<bool> cancel = true;
  const CancelScope scope(&cancel);
  EXPECT_THROW(twisted->tessellate(0.001, Bounds::everything()), Cancelled);
  cancel = false;
  EXPECT_GT(twisted->tessellate(0.001, Bounds::everything()).size(), 1000u);
}

TEST(LinearExtrusion, RefusesBadParameters) {
  RegionPtr r = test::rectangle({0, 0}, {1, 1});
  auto make = [&](double h, double twist, dvec2 s) {
    return Primitive::create<LinearExtrusion>(r, h, false, twist, s);
  };
  EXPECT_THROW(make(0.0, 0, dvec2(1)), std::invalid_argument);
  EXPECT_THROW(make(-1.0, 0, dvec2(1)), std::invalid_argument);
  EXPECT_THROW(make(std::nan(""), 0, dvec2(1)), std::invalid_argument);
  EXPECT_THROW(make(1.0, 1e9, dvec2(1)), std::invalid_argument);
  EXPECT_THROW(make(1.0, std::nan(""), dvec2(1)), std::invalid_argument);
  EXPECT_THROW(make(1.0, 0, dvec2(-1, 1)), std::invalid_argument);
  EXPECT_THROW(make(1.0, 0, dvec2(1, std::nan(""))), std::invalid_argument);
  EXPECT_THROW(Primitive::create<LinearExtrusion>(nullptr, 1.0, false, 0.0, dvec2(1)),
               std::invalid_argument);
  EXPECT_NO_THROW(make(1.0, 360000.0, dvec2(0)));
}

// Edge-on views of a twisted square prism, rays along y (orthographic):
// the pixel at (x, z) is solid where the square turned by −twist·ζ spans
// x, which its corners say without the solver. Rays near that edge graze
// the helices the corners sweep; none may be lost. Also turned, with the
// camera's rays across the axis at an angle.
TEST(LinearExtrusionRender, TwistedPrismEdgeOnHasNoMissingPixel) {
  const double half = 1.0, h = 4.0, twist = 135.0;
  auto prism = extrude(test::rectangle({-half, -half}, {half, half}), h, twist, dvec2(1.0), true);
  const int w = 300, hgt = 300;
  Scene scene;
  scene.objects.push_back(prism);
  scene.camera = CameraSpec{dvec3(0, -20, 0), dvec3(0), dvec3(0, 0, 1), 45.0, true, 5.0};
  scene.background = dvec3(0.0);
  Image image = Renderer(scene, {w, hgt, 1}).render();
  Camera camera(*scene.camera, w, hgt);
  int hits = 0, misses = 0, skipped = 0, wrong = 0;
  for (int y = 0; y < hgt; ++y)
    for (int x = 0; x < w; ++x) {
      const Ray ray = camera.ray(x + 0.5, y + 0.5);
      const double px = ray.origin.x, pz = ray.origin.z;
      if (std::abs(pz) > h / 2 - 1e-9) {
        // Above or below: nothing; on the caps' planes: skip.
        if (std::abs(pz) < h / 2 + 1e-9) {
          ++skipped;
          continue;
        }
      }
      const double angle = -twist * kPi / 180.0 * (pz + h / 2) / h;
      double reach = 0.0;
      for (const dvec2& c : {dvec2(half, half), dvec2(half, -half)})
        reach = std::max(reach, std::abs(std::cos(angle) * c.x - std::sin(angle) * c.y));
      const bool hit = std::abs(pz) <= h / 2 && std::abs(px) < reach;
      if (std::abs(pz) <= h / 2 && std::abs(std::abs(px) - reach) < 1e-9) {
        ++skipped;
        continue;
      }
      const bool shown = image.at(x, y) != dvec3(0.0);
      hits += hit;
      misses += !hit;
      if (hit != shown && ++wrong <= 10)
        ADD_FAILURE() << "pixel (" << x << ", " << y << "): silhouette says "
                      << (hit ? "hit" : "miss") << " at x = " << px << ", z = " << pz;
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(hits, 10000);
  EXPECT_GT(misses, 10000);
  EXPECT_LT(skipped, 400);
}

}  // namespace
}  // namespace csgray::detail
