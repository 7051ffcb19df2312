// Booleans of boxes and straight extrusions on one slab are made one
// extrusion of the boolean of their regions, and only those: operands
// that fill the slab exactly, cutters and clips that pass through it, one
// material, frames that keep the plane and the axis.
#include "export/prism_booleans.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "primitives/box.h"
#include "primitives/linear_extrusion.h"
#include "profile/region_evaluation.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::primitivesOf;

// A frame 40 × 40 × 3 with walls 4 wide, and two bars 2 wide along the
// diagonals, clipped to the frame's outline.
const char* kLattice =
    "local frame = box{size = {40, 40, 3}} - box{size = {32, 32, 5}}:translate(4, 4, -1)\n"
    "local bar = box{size = {2, 80, 3}}:translate(-1, -40, 0)\n"
    "local bars = bar:rotate(0, 0, 45):translate(20, 20, 0) + "
    "bar:rotate(0, 0, -45):translate(20, 20, 0)\n"
    "local lattice = frame + bars * box{size = {40, 40, 3}}\n";

// The lattice's area: the frame's, and in the 32 × 32 opening two strips
// |x − y| ≤ √2 (each the square less two corner triangles of legs
// 32 − √2), less the square where they cross (a square of side 2).
double latticeArea() {
  const double inner = 32.0, c = std::sqrt(2.0);
  return (40.0 * 40.0 - inner * inner) + 2.0 * (inner * inner - (inner - c) * (inner - c)) - 4.0;
}

// Do the two solids hold the same points, at random points of a box?
void expectSameSolid(const Solid& a, const Solid& b, const dvec3& lo, const dvec3& hi) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const dvec3 p = lo + (hi - lo) * dvec3(unit(random), unit(random), unit(random));
    ASSERT_EQ(a.contains(p), b.contains(p)) << p.x << ", " << p.y << ", " << p.z;
  }
}

TEST(PrismBooleans, AFrameWithBarsClippedToItIsOneExtrusion) {
  const SolidPtr given = flattened(test::solidOf(std::string(kLattice) + "return lattice"));
  const SolidPtr part = prismBooleansMerged(given);
  auto* prism = dynamic_cast<const LinearExtrusion*>(part.get());
  ASSERT_NE(prism, nullptr) << part->kind();
  EXPECT_NEAR(area(evaluate(*prism->region(), 1e-4)), latticeArea(), 1e-9);
  EXPECT_DOUBLE_EQ(prism->height(), 3.0);
  expectSameSolid(*given, *part, {-1, -1, -1}, {41, 41, 4});
}

TEST(PrismBooleans, APartTurnedAsAWholeIsOneExtrusionToo) {
  // Every frame turned about a slanted axis: the frames seen from the
  // first keep its plane to rounding.
  const SolidPtr given = flattened(test::solidOf(
      std::string(kLattice) + "return lattice:rotate(30, 20, 10):translate(5, 6, 7)"));
  const SolidPtr part = prismBooleansMerged(given);
  ASSERT_EQ(primitivesOf(*part), 1);
  expectSameSolid(*given, *part, {-45, -45, -45}, {55, 55, 55});
}

TEST(PrismBooleans, CuttersAndClipsMayPassThroughTheSlab) {
  // Two plates side by side with a slot through both, and clipped by a
  // taller extrusion (before them or after): each one extrusion 2 high,
  // the plates'.
  for (const char* source :
       {"return box{size = {10, 10, 2}} + box{size = {10, 10, 2}}:translate(5, 3, 0) - "
        "box{size = {12, 2, 8}}:translate(2, 4, -3)",
        "return (box{size = {10, 10, 2}} + box{size = {10, 10, 2}}:translate(5, 3, 0)) * "
        "linear_extrude{circle(6), height = 9}:translate(8, 7, -4)",
        // The clip first, taller than the plates: the slab is theirs.
        "return linear_extrude{circle(6), height = 9}:translate(8, 7, -4) * "
        "(box{size = {10, 10, 2}} + box{size = {10, 10, 2}}:translate(5, 3, 0))"}) {
    SCOPED_TRACE(source);
    const SolidPtr given = test::solidOf(source);
    const SolidPtr part = prismBooleansMerged(given);
    auto* prism = dynamic_cast<const LinearExtrusion*>(part.get());
    ASSERT_NE(prism, nullptr) << part->kind();
    EXPECT_DOUBLE_EQ(prism->height(), 2.0);
    expectSameSolid(*given, *part, {-1, -1, -4}, {16, 14, 6});
  }
}

TEST(PrismBooleans, CutsThatOnlyPassThroughStayIn3D) {
  // Nothing face on face: holes and slots through a plate, a plate
  // clipped by a taller block. The booleans in 3D meet no coplanar faces
  // there, and are quicker than the plane's.
  for (const char* source :
       {"return box{size = {10, 10, 2}} - box{size = {6, 2, 8}}:translate(2, 4, -3) - "
        "box{size = {2, 2, 8}}:translate(2, 1, -3)",
        "return box{size = {10, 10, 2}} * box{size = {8, 8, 8}}:translate(1, 1, -3)"}) {
    SCOPED_TRACE(source);
    const SolidPtr given = test::solidOf(source);
    EXPECT_EQ(prismBooleansMerged(given), given);
  }
}

TEST(PrismBooleans, OnlyPrismsOfTheSlabMerge) {
  // A pocket (a cutter short of the far face), a union with a taller
  // block, a block on another plane, another material, a block turned
  // out of the plane, a sphere, a twist, blocks staggered in height (each
  // sticks out of the other): each stays as it was.
  for (const char* source :
       {"return box{size = {10, 10, 2}} - box{size = {6, 2, 8}}:translate(2, 4, 1)",
        "return box{size = {10, 10, 2}} + box{size = {2, 2, 3}}",
        "return box{size = {10, 10, 2}} + box{size = {10, 10, 2}}:translate(5, 0, 0.5)",
        "return box{size = {10, 10, 2}} + box{size = {10, 10, 2}}:translate(5, 0, 0)"
        ":material{color = {1, 0, 0}}",
        "return box{size = {10, 10, 2}} - box{size = {2, 2, 8}}:rotate(1, 0, 0):translate(2, 2, "
        "-3)",
        "return box{size = {10, 10, 2}} - sphere(1):translate(5, 5, 1)",
        "return box{size = {10, 10, 2}} + linear_extrude{square(10), height = 2, twist = 5}"
        ":translate(5, 0, 0)",
        "return box{size = {10, 10, 9}} * box{size = {20, 20, 9}}:translate(0, 0, -1)"}) {
    SCOPED_TRACE(source);
    const SolidPtr given = test::solidOf(source);
    EXPECT_EQ(prismBooleansMerged(given), given);
  }
}

TEST(PrismBooleans, APrismWhoseRegionTouchesItselfStaysApart) {
  // Blocks corner to corner: one extrusion would be pinched along the
  // line where they touch.
  const SolidPtr given =
      test::solidOf("return box{size = {2, 2, 3}} + box{size = {2, 2, 3}}:translate(2, 2, 0)");
  EXPECT_EQ(prismBooleansMerged(given), given);
}

TEST(PrismBooleans, TilesCornerToCornerAreBridged) {
  // A 4 × 4 checkerboard of unit tiles: their union touches itself at the
  // 9 inner grid points. Given a bridge, each point gets a square that
  // wide over it, which adds two quarters of it (the empty quadrants).
  const SolidPtr given = test::solidOf(
      "local tiles = {}\n"
      "for i = 0, 3 do for j = 0, 3 do\n"
      "  if (i + j) % 2 == 0 then tiles[#tiles + 1] = box{size = {1, 1, 2}}:translate(i, j, 0) "
      "end\n"
      "end end\n"
      "return union(tiles)");
  const double bridge = 0.01;
  const SolidPtr part = prismBooleansMerged(given, bridge);
  auto* prism = dynamic_cast<const LinearExtrusion*>(part.get());
  ASSERT_NE(prism, nullptr) << part->kind();
  EXPECT_NEAR(area(evaluate(*prism->region(), 1e-4)), 8.0 + 9.0 * bridge * bridge / 2.0, 1e-12);
  // The bridge over (1, 1) fills the corners of the empty tiles there.
  EXPECT_TRUE(part->contains({1.002, 0.998, 1.0}));
  EXPECT_FALSE(given->contains({1.002, 0.998, 1.0}));
  EXPECT_FALSE(part->contains({1.006, 0.994, 1.0}));
  // Without a bridge, the union stays as it is.
  EXPECT_EQ(prismBooleansMerged(given), given);
}

TEST(PrismBooleans, HolesCornerToCornerAreNotBridgedInTheirPlate) {
  // A bridge over a hole's corner would fill it: a difference stays a
  // boolean, and only its cutters' union, bridged, is one extrusion (the
  // cut then goes through where they meet, as a difference's cutters
  // that touch along an edge do).
  const SolidPtr given = test::solidOf(
      "return box{size = {4, 4, 2}} - (box{size = {1, 1, 2}}:translate(1, 1, 0) + "
      "box{size = {1, 1, 2}}:translate(2, 2, 0))");
  const SolidPtr part = prismBooleansMerged(given, 0.01);
  ASSERT_NE(part->asBoolean(), nullptr);
  EXPECT_EQ(part->asBoolean()->op(), Boolean::Op::Difference);
  EXPECT_NE(dynamic_cast<const LinearExtrusion*>(part->children()[1].get()), nullptr);
}

TEST(PrismBooleans, TilesBesideTheirPlateInOneUnionAreOneExtrusion) {
  // A union lists tiles on a plate beside the plate: the tiles, one slab,
  // are one extrusion; the plate, another slab, stays beside it.
  const SolidPtr given = test::solidOf(
      "local parts = {}\n"
      "for i = 0, 4 do parts[#parts + 1] = box{size = {1, 1, 2}}:translate(i, i % 2, 0) end\n"
      "parts[#parts + 1] = box{size = {5, 2, 1}}:translate(0, 0, -1)\n"
      "return union(parts)");
  const SolidPtr part = prismBooleansMerged(given, 0.01);
  ASSERT_EQ(part->children().size(), 2u);
  EXPECT_NE(dynamic_cast<const LinearExtrusion*>(part->children()[0].get()), nullptr);
  EXPECT_NE(dynamic_cast<const Box*>(part->children()[1].get()), nullptr);
  expectSameSolid(*given, *part, {-1, -1, -2}, {6, 3, 3});
}

TEST(PrismBooleans, TheSlabsBooleansUnderOthersMerge) {
  // The lattice less a pocket: the pocket stays a cutter of its own, the
  // lattice under it is one extrusion.
  const SolidPtr given = flattened(test::solidOf(
      std::string(kLattice) + "return lattice - box{size = {6, 6, 2}}:translate(1, 1, 2)"));
  const SolidPtr part = prismBooleansMerged(given);
  ASSERT_EQ(primitivesOf(*part), 2);
  EXPECT_NE(dynamic_cast<const LinearExtrusion*>(part->children()[0].get()), nullptr);
  expectSameSolid(*given, *part, {-1, -1, -1}, {41, 41, 4});
}

}  // namespace
}  // namespace csgray::detail
