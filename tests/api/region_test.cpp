// The library's 2D regions (include/csgray/region.h) through the shared
// library, as a user links it: the shapes' areas against their formulas,
// booleans, offsets, hulls and maps, the sweeps' volumes (Pappus, the
// prismatoid), drawings read and outlines written and read back, and the
// script's messages for bad values.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "../io/scratch_folder.h"
#include "csgray/csgray.h"
#include "error_of.h"

namespace {

using csgray::Error;
using csgray::ErrorCode;
using csgray::Region;
using csgray::Solid;
using csgray::Vec2;
using csgray::test::errorOf;

constexpr double kPi = std::numbers::pi;

TEST(ApiRegion, ShapesHaveTheAreasOfTheirFormulas) {
  // Circles are exact arcs: their area to rounding.
  EXPECT_NEAR(Region::circle(3).area(), 9 * kPi, 1e-12);
  // An ellipse's arcs are evaluated as a polygon within a ten-millionth of its size.
  EXPECT_NEAR(Region::ellipse(4, 2).area(), 8 * kPi, 1e-5);
  EXPECT_DOUBLE_EQ(Region::rectangle({4, 2}).area(), 8.0);
  EXPECT_DOUBLE_EQ(Region::square(3, true).area(), 9.0);
  const csgray::Bounds2 centred = Region::square(3, true).bounds();
  EXPECT_EQ(centred.lo, (Vec2{-1.5, -1.5}));
  EXPECT_EQ(centred.hi, (Vec2{1.5, 1.5}));
  // A square with a square hole by paths, filled even-odd.
  const Region frame =
      Region::polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {8, 2}, {8, 8}, {2, 8}},
                      {{0, 1, 2, 3}, {4, 5, 6, 7}});
  EXPECT_DOUBLE_EQ(frame.area(), 100.0 - 36.0);
  EXPECT_FALSE(frame.contains({5, 5}));
  EXPECT_TRUE(frame.contains({1, 5}));
  // n corners of radius r: n r² sin(2π/n) / 2; a hexagon f across its
  // flats: (√3/2) f².
  EXPECT_NEAR(Region::regularPolygon(7, 2).area(), 7 * 4 * std::sin(2 * kPi / 7) / 2, 1e-12);
  EXPECT_NEAR(Region::regularPolygonAcrossFlats(6, 10).area(), std::sqrt(3.0) / 2 * 100, 1e-9);
}

TEST(ApiRegion, BooleansHullsAndOffsetsAreAnalytic) {
  // Two discs of radius r with centres d apart share a lens of area
  // 2r² acos(d/2r) − (d/2)√(4r² − d²) (Weisstein, "Circle-Circle
  // Intersection", MathWorld).
  const double r = 2, d = 3;
  const double lens = 2 * r * r * std::acos(d / (2 * r)) - d / 2 * std::sqrt(4 * r * r - d * d);
  const Region a = Region::circle(r), b = Region::circle(r).translate({d, 0});
  EXPECT_NEAR((a * b).area(), lens, 1e-12);
  EXPECT_NEAR((a + b).area(), 2 * kPi * r * r - lens, 1e-12);
  EXPECT_NEAR((a - b).area(), kPi * r * r - lens, 1e-12);
  EXPECT_NEAR(Region::unionOf({a, b}).area(), (a + b).area(), 1e-12);
  EXPECT_NEAR(Region::differenceOf({a, b, b}).area(), (a - b).area(), 1e-12);
  // The hull of two discs is a stadium: πr² + 2r·d.
  EXPECT_NEAR(Region::hull({a, b}).area(), kPi * r * r + 2 * r * d, 1e-9);
  // A square s offset by r: s² + 4 s r + πr² (Steiner), as its sum with a
  // disc; by delta with sharp corners (s + 2δ)²; chamfered, each corner
  // cut by the line δ from the square's corner across its bisector, a
  // right triangle of height (√2 − 1)δ and area that squared.
  const double s = 4, o = 0.5;
  const Region square = Region::square(s);
  EXPECT_NEAR(square.offset(o).area(), s * s + 4 * s * o + kPi * o * o, 1e-9);
  EXPECT_NEAR(Region::minkowski({square, Region::circle(o)}).area(), square.offset(o).area(), 1e-9);
  EXPECT_NEAR(square.offsetDelta(o).area(), (s + 2 * o) * (s + 2 * o), 1e-9);
  EXPECT_NEAR(square.offsetDelta(o, true).area(),
              (s + 2 * o) * (s + 2 * o) - 4 * std::pow((std::sqrt(2.0) - 1) * o, 2), 1e-9);
  EXPECT_NEAR(square.offset(-o).area(), (s - 2 * o) * (s - 2 * o), 1e-9);
  // Shrunk past its middle, nothing is left.
  EXPECT_EQ(square.offset(-3).area(), 0.0);
  EXPECT_TRUE(square.offset(-3).bounds().empty());
  EXPECT_FALSE(square.bounds().empty());
}

TEST(ApiRegion, MapsMoveTheRegionExactly) {
  const Region bar = Region::rectangle({4, 2});
  // A quarter turn is exact: the corners land on whole numbers.
  const csgray::Bounds2 turned = bar.rotate(90).bounds();
  EXPECT_EQ(turned.lo, (Vec2{-2, 0}));
  EXPECT_EQ(turned.hi, (Vec2{0, 4}));
  const csgray::Bounds2 mirrored = bar.mirror({1, 0}).bounds();
  EXPECT_EQ(mirrored.lo, (Vec2{-4, 0}));
  EXPECT_EQ(mirrored.hi, (Vec2{0, 2}));
  EXPECT_DOUBLE_EQ(bar.scale(3).area(), 72.0);
  EXPECT_DOUBLE_EQ(bar.scale({0.5, 3}).area(), 12.0);
  // resize: a unit circle 4 wide is an ellipse of half-axes 2 and 1, or
  // with y auto a circle of radius 2.
  EXPECT_NEAR(Region::circle(1).resize({4, 0}).area(), 2 * kPi, 1e-5);
  EXPECT_NEAR(Region::circle(1).resize({4, 0}, {false, true}).area(), 4 * kPi, 1e-5);
  EXPECT_TRUE(bar.translate({10, 10}).contains({12, 11}));
  // A point that is no point is in no region (an arc's crossing test
  // counted it in).
  const double inf = std::numeric_limits<double>::infinity();
  for (const Region& r : {Region::circle(5), Region::circle(5) - Region::square(1), bar})
    for (const Vec2& p : {Vec2{inf, 0}, Vec2{std::nan(""), 0}, Vec2{0, -inf}})
      EXPECT_FALSE(r.contains(p));
  EXPECT_FALSE(Solid::linearExtrude(Region::circle(5), 2).contains({std::nan(""), 0, 1}));
  EXPECT_FALSE(bar.translate({10, 10}).contains({1, 1}));
}

TEST(ApiRegion, SweepsHaveTheVolumesOfTheirFormulas) {
  const Region disc = Region::circle(2);
  const double area = 4 * kPi;
  EXPECT_NEAR(Solid::linearExtrude(disc, 5).volume(), 5 * area, 1e-3 * 5 * area);
  csgray::ExtrudeOptions centred;
  centred.center = true;
  const csgray::Bounds box = Solid::linearExtrude(disc, 5, centred).bounds();
  EXPECT_NEAR(box.lo.z, -2.5, 1e-12);
  EXPECT_NEAR(box.hi.z, 2.5, 1e-12);
  // A twist turns each slice: the volume stays area × height.
  csgray::ExtrudeOptions twisted;
  twisted.twist = 90;
  const Region square = Region::square(4, true);
  EXPECT_NEAR(Solid::linearExtrude(square, 10, twisted).volume(), 160.0, 0.2);
  // Scaled by σ(ζ) = 1 + (s − 1)ζ on each axis: A h ∫ σx σy dζ
  // = A h (1 + (sx − 1)/2 + (sy − 1)/2 + (sx − 1)(sy − 1)/3).
  csgray::ExtrudeOptions tapered;
  tapered.scale = {0.5, 2};
  const double factor = 1 - 0.25 + 0.5 - 0.5 / 3;
  EXPECT_NEAR(Solid::linearExtrude(square, 10, tapered).volume(), 160 * factor, 0.2);
  // Pappus: a region turned about z sweeps 2π x̄ A; a quarter turn a quarter.
  const Region ring = Region::rectangle({1, 1}).translate({2, 0});
  EXPECT_NEAR(Solid::rotateExtrude(ring).volume(), 2 * kPi * 2.5, 1e-3 * 5 * kPi);
  EXPECT_NEAR(Solid::rotateExtrude(ring, 90).volume(), kPi * 2.5 / 2, 1e-3 * 5 * kPi);
  // A negative angle turns clockwise, as OpenSCAD's: the quarter below +x.
  const Solid clockwise = Solid::rotateExtrude(ring, -90);
  EXPECT_NEAR(clockwise.volume(), kPi * 2.5 / 2, 1e-3 * 5 * kPi);
  EXPECT_TRUE(clockwise.contains({0.1, -2.5, 0.5}));
  EXPECT_FALSE(clockwise.contains({0.1, 2.5, 0.5}));
  EXPECT_TRUE(Solid::rotateExtrude(ring, 90).contains({0.1, 2.5, 0.5}));
  // A swept part exports closed, near the exact volume.
  const Solid plate =
      Solid::linearExtrude(Region::square(20) - Region::circle(4).translate({10, 10}), 3);
  const csgray::Mesh mesh = csgray::exportMesh(plate);
  EXPECT_NEAR(mesh.volume(), (400 - 16 * kPi) * 3, 0.01 * 2 * (400 + 8 * kPi));
  EXPECT_EQ(csgray::meshDefect(mesh).kind, csgray::MeshDefect::Kind::None);
}

// A boolean of regions that leaves nothing sweeps into nothing: a cutter
// of nothing cuts nothing, in the export as in the render; alone it is an
// empty part.
TEST(ApiRegion, ARegionWithoutPointsSweepsIntoNothing) {
  const Region none = Region::circle(1) - Region::circle(2);
  EXPECT_EQ(none.area(), 0.0);
  const Solid box = Solid::box(10);
  for (const Solid& cutter :
       {Solid::linearExtrude(none, 2), Solid::rotateExtrude(none.translate({5, 0}))}) {
    const csgray::Mesh mesh = csgray::exportMesh(box - cutter);
    EXPECT_NEAR(mesh.volume(), 1000.0, 1e-9);
    EXPECT_NEAR(Region::projection(box - cutter, true).area(), 100.0, 1e-9);
  }
  EXPECT_EQ(errorOf([&] { csgray::exportMesh(Solid::linearExtrude(none, 2)); }),
            std::make_pair(ErrorCode::NotPrintable, std::string("the part is empty")));
}

TEST(ApiRegion, TextIsTheFontsLetters) {
  const Region h = Region::text("H");
  ASSERT_GT(h.area(), 0.0);
  // Two letters side by side cover twice one's area.
  EXPECT_NEAR(Region::text("HH").area(), 2 * h.area(), 1e-6 * h.area());
  // size is the font's ascent: an H of size 20 is twice as tall as one of 10.
  csgray::TextOptions large;
  large.size = 20;
  const csgray::Bounds2 small = h.bounds(), big = Region::text("H", large).bounds();
  EXPECT_NEAR(big.hi.y - big.lo.y, 2 * (small.hi.y - small.lo.y), 1e-9);
  EXPECT_EQ(errorOf([] { Region::text(""); }).first, ErrorCode::InvalidArgument);
  csgray::TextOptions missing;
  missing.font = "No Such Font Family";
  EXPECT_EQ(errorOf([&] { Region::text("H", missing); }).first, ErrorCode::InvalidArgument);
}

// A ball of radius 5 raised by 3: the plane z = 0 cuts it in a circle of
// radius 4; its shadow is a disc of radius 5. Both come from meshes within
// 0.001 of the ball: the areas within that times the outline's length.
TEST(ApiRegion, ProjectionsAreASolidsSectionAndShadow) {
  const Solid ball = Solid::sphere(5).translate({0, 0, 3});
  EXPECT_NEAR(Region::projection(ball, true).area(), 16 * kPi, 1e-3 * 2 * kPi * 4);
  EXPECT_NEAR(Region::projection(ball).area(), 25 * kPi, 1e-3 * 2 * kPi * 5);
  // Above the plane: no section.
  EXPECT_EQ(Region::projection(Solid::sphere(1).translate({0, 0, 5}), true).area(), 0.0);
  EXPECT_EQ(errorOf([] {
              Region::projection(Solid::halfSpace({0, 0, 1}), true);
            }).first,
            ErrorCode::InvalidArgument);
}

// A region in a scene is a flat surface in z = 0: seen from above in an
// orthographic view 10 wide, a ring of radii 2 and 4 covers the pixels
// between those distances from the centre, not its hole or beyond.
TEST(ApiRegion, ARegionInASceneIsAFlatSurface) {
  const csgray::Surface ring = csgray::Surface::region(Region::circle(4) - Region::circle(2));
  EXPECT_EQ(ring.kind(), "region");
  const csgray::Bounds box = ring.bounds();
  // (A surface's box is padded by a billionth of its size.)
  EXPECT_NEAR(box.lo.x, -4, 1e-6);
  EXPECT_NEAR(box.hi.y, 4, 1e-6);
  EXPECT_NEAR(box.lo.z, 0.0, 1e-6);
  EXPECT_NEAR(box.hi.z, 0.0, 1e-6);
  csgray::Scene scene;
  scene.add(ring.material(csgray::Material{}));
  csgray::Camera above;
  above.eye = {0, 0, 10};
  above.up = {0, 1, 0};
  above.projection = csgray::Camera::Projection::Orthographic;
  above.width = 10;
  scene.setCamera(above).setBackground({0, 0, 0});
  const csgray::Image image = csgray::render(scene, {100, 100, 1, 1});
  // Pixel centres at 0.1 · (i + 0.5) − 5 from the middle.
  auto lit = [&](int x, int y) { return image.at(x, y).x > 0.0; };
  EXPECT_FALSE(lit(50, 50));  // the hole
  EXPECT_TRUE(lit(80, 50));   // 3.05 out
  EXPECT_FALSE(lit(95, 50));  // 4.55 out
  EXPECT_TRUE(lit(50, 20));   // 2.95 up
}

TEST(ApiRegion, BadValuesGetTheScriptsMessages) {
  EXPECT_EQ(errorOf([] { Region::circle(-1); }).first, ErrorCode::InvalidArgument);
  EXPECT_EQ(errorOf([] {
              Region::square(2).mirror({0, 0});
            }),
            std::make_pair(ErrorCode::InvalidArgument,
                           std::string("mirror: the normal must not be zero")));
  EXPECT_EQ(errorOf([] {
              Region::square(2).scale({0, 1});
            }),
            std::make_pair(ErrorCode::InvalidArgument,
                           std::string("scale: a factor of 0 squashes the region flat")));
  EXPECT_EQ(errorOf([] { Region::square(2).rotate(std::nan("")); }).first,
            ErrorCode::InvalidArgument);
  EXPECT_EQ(errorOf([] { Region::polygon({{0, 0}, {1, 1}}); }).first, ErrorCode::InvalidArgument);
  EXPECT_EQ(errorOf([] { Region::regularPolygon(2, 1); }).first, ErrorCode::InvalidArgument);
  EXPECT_EQ(errorOf([] { Region::unionOf({}); }).first, ErrorCode::InvalidArgument);
  EXPECT_EQ(errorOf([] { Solid::linearExtrude(Region::square(1), -1); }).first,
            ErrorCode::InvalidArgument);
  // A region across the axis cannot be turned about it.
  EXPECT_EQ(errorOf([] { Solid::rotateExtrude(Region::square(2, true)); }).first,
            ErrorCode::InvalidArgument);
}

using ApiOutline = csgray::test::ScratchFolder;

TEST_F(ApiOutline, OutlinesWrittenReadBackAsTheSameRegion) {
  // A plate with a hole and a slot: arcs stay arcs in both formats.
  const Region plate =
      Region::rectangle({40, 20}) - Region::circle(5).translate({10, 10}) -
      Region::hull({Region::circle(2).translate({25, 10}), Region::circle(2).translate({32, 10})});
  for (const char* name : {"plate.svg", "plate.dxf"}) {
    const std::string file = path(name);
    csgray::writeOutline(plate, file);
    EXPECT_NEAR(Region::fromDrawingFile(file).area(), plate.area(), 1e-9) << name;
  }
  EXPECT_EQ(errorOf([&] { csgray::writeOutline(plate, path("plate.stl")); }).first,
            ErrorCode::InvalidArgument);
  EXPECT_EQ(
      errorOf([&] { csgray::writeOutline(Region::square(1) - Region::square(2), path("e.svg")); }),
      std::make_pair(ErrorCode::InvalidArgument, std::string("writeOutline: the region is empty")));
  EXPECT_FALSE(std::filesystem::exists(path("e.svg")));
}

TEST_F(ApiOutline, DrawingsThatCannotBeReadSaySo) {
  EXPECT_EQ(errorOf([&] { Region::fromDrawingFile(path("none.svg")); }).first, ErrorCode::IoError);
  EXPECT_EQ(errorOf([&] { Region::fromDrawingFile(path("part.stl")); }),
            std::make_pair(ErrorCode::InvalidArgument,
                           std::string("part.stl: unknown drawing format; use .dxf or .svg")));
  std::ofstream(path("broken.svg"))
      << "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path d=\"M 0 0 L\"/>\n</svg>\n";
  const auto [code, message] = errorOf([&] { Region::fromDrawingFile(path("broken.svg")); });
  EXPECT_EQ(code, ErrorCode::IoError);
  EXPECT_EQ(message.rfind("broken.svg:2:", 0), 0u) << message;
}

}  // namespace
