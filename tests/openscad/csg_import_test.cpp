// OpenSCAD's .csg files (docs/openscad.md): the parser reads the format and
// says where it is broken; each node makes the solid or region OpenSCAD
// means, exact or with OpenSCAD's own polygons; and OpenSCAD's bundled
// examples (tests/data/openscad/) import, render and export with OpenSCAD's
// volumes.
#include "openscad/csg_import.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "check/exact_volume.h"
#include "engine/boolean.h"
#include "engine/tight_bounds.h"
#include "export/cgal/mesh_boolean.h"
#include "export/cgal/mesh_validity.h"
#include "export/solid_projection.h"
#include "io/image_file.h"
#include "profile/region_evaluation.h"
#include "raytrace/renderer.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using std::numbers::pi;

std::string parseError(const std::string& text) {
  try {
    parseCsg(text, "part.csg");
  } catch (const CsgError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CsgParser, ReadsNodesArgumentsAndModifiers) {
  const std::vector<CsgNode> nodes = parseCsg(
      "group() {\n"
      "  // a comment\n"
      "  %cube(size = [1, 2.5e1, -3], center = true);\n"
      "  multmatrix([[1, 0], [0, 1]]) { #sphere($fn = 0, r = 5); }\n"
      "  import(file = \"a \\\"b\\\".stl\", layer = undef);\n"
      "}\n",
      "part.csg");
  ASSERT_EQ(nodes.size(), 1u);
  const CsgNode& group = nodes[0];
  EXPECT_EQ(group.name, "group");
  ASSERT_EQ(group.children.size(), 3u);
  const CsgNode& cube = group.children[0];
  EXPECT_EQ(cube.modifier, '%');
  EXPECT_EQ(cube.line, 3);
  const CsgValue& size = cube.named.at("size");
  ASSERT_EQ(size.items.size(), 3u);
  EXPECT_EQ(size.items[1].number, 25.0);
  EXPECT_EQ(size.items[2].number, -3.0);
  EXPECT_TRUE(cube.named.at("center").boolean);
  const CsgNode& matrix = group.children[1];
  EXPECT_EQ(matrix.positional.size(), 1u);
  EXPECT_EQ(matrix.children.at(0).modifier, '#');
  EXPECT_EQ(matrix.children.at(0).named.at("$fn").number, 0.0);
  const CsgNode& import = group.children[2];
  EXPECT_EQ(import.named.at("file").text, "a \"b\".stl");
  EXPECT_EQ(import.named.at("layer").kind, CsgValue::Kind::Undef);
  EXPECT_EQ(import.line, 5);
}

TEST(CsgParser, BadInputIsOneLineWithTheLine) {
  EXPECT_EQ(parseError("group() {\n  cube(size = [1, 1, 1]\n}\n"),
            "part.csg:3: expected ',' or ')' between the arguments of cube, found '}'");
  EXPECT_EQ(parseError("group() {\n  cube();\n"), "part.csg:3: the { of group is not closed");
  EXPECT_EQ(parseError("cube(size = 1x);"),
            "part.csg:1: expected ',' or ')' between the arguments of cube, found 'x'");
  EXPECT_EQ(parseError("\n\ncube(size = @);"), "part.csg:3: expected a value, found '@'");
  EXPECT_EQ(parseError("text(text = \"hi);"), "part.csg:1: a string is not closed");
  EXPECT_EQ(parseError("cube(r = 1, r = 2);"), "part.csg:1: cube: r is given twice");
  EXPECT_EQ(parseError("12(r = 1);"), "part.csg:1: expected the name of a node, found '12'");
  EXPECT_EQ(parseError("cube()"),
            "part.csg:1: expected ';' or '{' after cube(...), found the end of the file");
  EXPECT_EQ(parseError(std::string(2000, '[')),
            "part.csg:1: expected the name of a node, found '['");
  EXPECT_EQ(parseError("cube(size = " + std::string(2000, '[') + ");"),
            "part.csg:1: vectors nested deeper than 1000");
}

CsgModel importText(const std::string& text, CsgFacets facets = CsgFacets::Exact) {
  CsgImportOptions options;
  options.facets = facets;
  return importCsg(text, "part.csg", options);
}

std::string importError(const std::string& text) {
  try {
    importText(text);
  } catch (const CsgError& e) {
    return e.what();
  }
  return "(no error)";
}

double exportedVolume(const SolidPtr& solid) { return meshOfSolid(*solid, 1e-4).mesh.volume(); }

SolidPtr onlySolid(const std::string& text, CsgFacets facets = CsgFacets::Exact) {
  CsgModel model = importText(text, facets);
  EXPECT_EQ(model.solids.size(), 1u) << text;
  return model.solids.at(0);
}

TEST(CsgImport, PrimitivesAreExactByDefault) {
  const char* sphere = "sphere($fn = 0, $fa = 12, $fs = 2, r = 5);";
  EXPECT_NEAR(exportedVolume(onlySolid(sphere)), 4.0 / 3.0 * pi * 125.0, 0.05);
  EXPECT_TRUE(onlySolid(sphere)->contains({0.0, 0.0, 4.999}));
  const char* cone = "cylinder($fn = 0, $fa = 12, $fs = 2, h = 6, r1 = 3, r2 = 0, center = true);";
  EXPECT_NEAR(exportedVolume(onlySolid(cone)), pi * 9.0 * 6.0 / 3.0, 0.02);
  EXPECT_TRUE(onlySolid(cone)->contains({2.99, 0.0, -2.999}));
  const Bounds box = onlySolid("cube(size = [1, 2, 3], center = true);")->bounds();
  test::expectVecNear(box.lo, {-0.5, -1, -1.5}, 1e-12);
}

// Each solid names the line of the .csg that made it, as a script's do
// theirs: export's messages and csgray view's pick show it.
TEST(CsgImport, SolidsNameTheirLines) {
  const SolidPtr part = onlySolid(
      "difference() {\n"
      "  cube(size = [10, 10, 10]);\n"
      "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
      "    cylinder($fn = 0, $fa = 12, $fs = 2, h = 10, r1 = 2, r2 = 2, center = false);\n"
      "  }\n"
      "}\n");
  EXPECT_EQ(part->origin().text(), "part.csg:1");
  ASSERT_EQ(part->children().size(), 2u);
  EXPECT_EQ(part->children()[0]->origin().text(), "part.csg:2");
  EXPECT_EQ(part->children()[1]->origin().text(), "part.csg:4");
}

TEST(CsgImport, OpenScadFacetsAreOpenScadsPolygons) {
  // OpenSCAD's circle of r = 10 with the default $fa = 12, $fs = 2 has
  // min(360/12, 2π·10/2) = 30 sides: a 30-gon's area.
  EXPECT_EQ(openscadFragments(10.0, 0.0, 12.0, 2.0), 30);
  EXPECT_EQ(openscadFragments(1.0, 0.0, 12.0, 2.0), 5);
  EXPECT_EQ(openscadFragments(1.0, 2.0, 12.0, 2.0), 3);
  EXPECT_EQ(openscadFragments(1.0, 64.0, 12.0, 2.0), 64);
  const SolidPtr cylinder =
      onlySolid("cylinder($fn = 0, $fa = 12, $fs = 2, h = 2, r1 = 10, r2 = 10, center = false);",
                CsgFacets::OpenScad);
  EXPECT_NEAR(exportedVolume(cylinder), 2.0 * 15.0 * 100.0 * std::sin(2.0 * pi / 30.0), 1e-9);
  // A corner at (r, 0), as OpenSCAD puts it.
  EXPECT_TRUE(cylinder->contains({9.999, 0.0, 1.0}));
  EXPECT_FALSE(cylinder->contains({0.0, 9.99, 1.0}));
  // OpenSCAD's sphere of $fn = 8: 4 rings of octagons at latitudes
  // 22.5°·(2i + 1), a polyhedron whose volume is its frusta's.
  const SolidPtr sphere = onlySolid("sphere($fn = 8, r = 1);", CsgFacets::OpenScad);
  double volume = 0.0;
  auto octagon = [](double r) { return 4.0 * r * r * std::sin(pi / 4.0); };
  for (int i = 0; i < 3; ++i) {
    const double a = pi * (i + 0.5) / 4.0, b = pi * (i + 1.5) / 4.0;
    const double ra = std::sin(a), rb = std::sin(b), h = std::cos(a) - std::cos(b);
    // A frustum of similar octagons: h/3 (A1 + A2 + √(A1·A2)).
    volume += h / 3.0 * (octagon(ra) + octagon(rb) + std::sqrt(octagon(ra) * octagon(rb)));
  }
  EXPECT_NEAR(exportedVolume(sphere), volume, 1e-9);
}

// OpenSCAD's files repeat subtrees (its GEB example offsets each letter
// three times): an offset written alike is made once and shared; one whose
// radius differs in the last bit, or whose child differs, is made apart.
TEST(CsgImport, AnOffsetWrittenAlikeTwiceIsMadeOnce) {
  const CsgModel model = importText(
      "offset(r = 1) { square(size = [2, 2]); }\n"
      "offset(r = 1) {\n  square(size = [2, 2]);\n}\n"
      "offset(r = 1.0000000000000002) { square(size = [2, 2]); }\n"
      "offset(r = 1) { square(size = [2, 3]); }\n");
  ASSERT_EQ(model.regions.size(), 4u);
  EXPECT_EQ(model.regions[0], model.regions[1]);
  EXPECT_NE(model.regions[0], model.regions[2]);
  EXPECT_NE(model.regions[0], model.regions[3]);
  // A w × h rectangle rounded out by r: wh + 2r(w + h) + πr².
  EXPECT_NEAR(area(evaluate(*model.regions[1], 1e-9)), 4.0 + 8.0 + pi, 1e-6);
  EXPECT_NEAR(area(evaluate(*model.regions[3], 1e-9)), 6.0 + 10.0 + pi, 1e-6);
}

// OpenSCAD's polygons of more sides or triangles than csgray makes are
// refused with one line, before any memory is taken: a $fa and $fs near 0
// ask for billions of sides, whose count once overflowed an int.
TEST(CsgImport, OpenScadPolygonsPastTheBudgetAreRefused) {
  const auto error = [](const std::string& text) {
    try {
      importText(text, CsgFacets::OpenScad);
    } catch (const CsgError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error("sphere($fn = 0, $fa = 1e-9, $fs = 1e-9, r = 1);"),
            "part.csg:1: sphere: $fn, $fa and $fs ask for 6283185308 sides of a circle, more "
            "than 1000000");
  EXPECT_EQ(error("\ncylinder($fn = 1e300, h = 1, r1 = 1, r2 = 1);"),
            "part.csg:2: cylinder: $fn, $fa and $fs ask for 1000000000000000000 sides of a "
            "circle, more than 1000000");
  EXPECT_EQ(error("circle($fn = 0, $fa = 1e-9, $fs = 1e-9, r = 1);"),
            "part.csg:1: circle: $fn, $fa and $fs ask for 6283185308 sides of a circle, more "
            "than 1000000");
  // 100 000 sides: a circle may have them, a sphere of 50 000 rings not.
  EXPECT_EQ(error("circle($fn = 100000, r = 1);"), "(no error)");
  EXPECT_EQ(error("sphere($fn = 100000, r = 1);"),
            "part.csg:1: sphere: OpenSCAD's polygons would take 10000000000 triangles, more "
            "than 20000000");
  // The exact import takes no polygons.
  EXPECT_EQ(importError("sphere($fn = 0, $fa = 1e-9, $fs = 1e-9, r = 1);"), "(no error)");
}

TEST(CsgImport, ALowFnIsAShapeEitherWay) {
  // cylinder($fn = 6): a hexagonal prism, exact as such.
  for (CsgFacets facets : {CsgFacets::Exact, CsgFacets::OpenScad}) {
    const SolidPtr hex =
        onlySolid("cylinder($fn = 6, h = 1, r1 = 2, r2 = 2, center = false);", facets);
    EXPECT_NEAR(exportedVolume(hex), 1.5 * std::sqrt(3.0) * 4.0, 1e-9);
    CsgModel model = importText("circle($fn = 6, r = 2);", facets);
    ASSERT_EQ(model.regions.size(), 1u);
    EXPECT_NEAR(area(evaluate(*model.regions[0], 1e-9)), 1.5 * std::sqrt(3.0) * 4.0, 1e-9);
  }
  // A $fn above kShapeFacets is a quality setting: exact.
  EXPECT_NEAR(exportedVolume(onlySolid("cylinder($fn = 13, h = 1, r1 = 1, r2 = 1);")), pi, 1e-3);
}

TEST(CsgImport, BooleansTransformsAndSweeps) {
  const SolidPtr part = onlySolid(
      "difference() {\n"
      "  cube(size = [10, 10, 10]);\n"
      "  multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, -1], [0, 0, 0, 1]]) {\n"
      "    cylinder($fn = 4, h = 12, r1 = 2, r2 = 2);\n"
      "  }\n"
      "  group();\n"
      "}\n");
  // A square hole of diagonal 4: area 8.
  EXPECT_NEAR(exportedVolume(part), 1000.0 - 80.0, 1e-9);
  const SolidPtr extruded = onlySolid(
      "linear_extrude(height = 4, center = true, convexity = 1, scale = [0, 0]) {\n"
      "  offset(delta = 1, chamfer = false) { square(size = [2, 2], center = true); }\n"
      "}\n");
  EXPECT_NEAR(exportedVolume(extruded), 16.0 * 4.0 / 3.0, 1e-9);  // a pyramid
  const SolidPtr ring = onlySolid(
      "rotate_extrude(angle = 360, convexity = 2) {\n"
      "  multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
      "    square(size = [1, 1], center = true);\n"
      "  }\n"
      "}\n");
  EXPECT_NEAR(exportedVolume(ring), 2.0 * pi * 3.0, 1e-3);  // Pappus
  // A profile wholly on the side x < 0, which OpenSCAD takes as well: the
  // same ring, and a quarter turn lies half a turn on.
  const SolidPtr mirrored = onlySolid(
      "rotate_extrude(angle = 360, convexity = 2) {\n"
      "  multmatrix([[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
      "    square(size = [1, 1], center = true);\n"
      "  }\n"
      "}\n");
  EXPECT_NEAR(exportedVolume(mirrored), 2.0 * pi * 3.0, 1e-3);
  const SolidPtr quarter = onlySolid(
      "rotate_extrude(angle = 90) { multmatrix([[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0], "
      "[0, 0, 0, 1]]) { square(size = [1, 1], center = true); } }");
  const double r = 3.0 / std::sqrt(2.0);
  EXPECT_TRUE(quarter->contains({-r, -r, 0.0}));  // at 225°
  EXPECT_FALSE(quarter->contains({r, r, 0.0}));   // at 45°, where x > 0 would sweep
  EXPECT_FALSE(quarter->contains({-r, r, 0.0}));
  const SolidPtr resized = onlySolid(
      "resize(newsize = [4, 0, 0], auto = [false, true, false]) { cube(size = [2, 2, 2]); }");
  test::expectVecNear(resized->bounds().hi, {4, 4, 2}, 1e-12);
  // resize measures the shape's own box, as OpenSCAD does (its bounds()
  // keep the whole cube, and a turned ball's the turned cube about it).
  const SolidPtr halfResized = onlySolid(
      "resize(newsize = [30, 0, 0]) { difference() { cube(size = [20, 20, 20]); "
      "multmatrix([[1, 0, 0, 10], [0, 1, 0, -1], [0, 0, 1, -1], [0, 0, 0, 1]]) { "
      "cube(size = [22, 22, 22]); } } }");
  EXPECT_NEAR(exportedVolume(halfResized), 30.0 * 20.0 * 20.0, 1e-9);
  const SolidPtr ballResized = onlySolid(
      "resize(newsize = [20, 0, 0]) { multmatrix([[0.707107, -0.707107, 0, 0], "
      "[0.707107, 0.707107, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(r = 5); } }");
  EXPECT_NEAR(tightBounds(*ballResized).hi.x, 10.0, 1e-9);
  const SolidPtr hulled = onlySolid(
      "hull() { cube(size = [1, 1, 1]); multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], "
      "[0, 0, 1, 0], [0, 0, 0, 1]]) { cube(size = [1, 1, 1]); } }");
  EXPECT_NEAR(exportedVolume(hulled), 4.0, 1e-9);
  // An empty child empties an intersection, as in OpenSCAD (cube(0), or
  // the group() an if that fails leaves); a union skips it.
  for (const char* empty : {"cube(size = [0, 0, 0]);", "group();"}) {
    const std::string children = std::string("{ cube(size = [10, 10, 10]); ") + empty + " }";
    EXPECT_TRUE(importText("intersection() " + children, CsgFacets::Exact).solids.empty()) << empty;
    EXPECT_NEAR(exportedVolume(onlySolid("union() " + children)), 1000.0, 1e-9) << empty;
  }
}

// The area of a 2D file's region: exact for segments and arcs, Bézier
// curves as polygons within 10⁻⁶.
double regionArea(const std::string& text, CsgFacets facets) {
  CsgModel model = importText(text, facets);
  EXPECT_EQ(model.regions.size(), 1u) << text;
  return area(evaluate(*model.regions.at(0), 1e-6));
}

// A child that a modifier leaves out (a region's % or *) is no operand,
// as in OpenSCAD: the intersection of the others stands, where a child
// that makes nothing would empty it.
TEST(CsgImport, AChildLeftOutIsNoOperand) {
  EXPECT_NEAR(regionArea("intersection() { square(size = [4, 4]); %square(size = [1, 1]); "
                         "*square(size = [1, 1]); square(size = [2, 8]); }",
                         CsgFacets::Exact),
              8.0, 1e-9);
}

std::string helloText(const char* cut, const char* options) {
  return std::string("intersection() {\n  ") + cut +
         "\n  text(text = \"Hello\", size = 10, spacing = 1.2, font = \"\", " + options +
         ", $fn = 16, $fa = 12, $fs = 2);\n}\n";
}

// A 2D minkowski: a square and a circle is the rounded square, s² + 4sr +
// πr² exactly, or with OpenSCAD's polygons the square grown by the n-gon
// (s² + 2s·(its widths) + its area); a pair neither convex nor with a
// circle is one line naming the file's line.
TEST(CsgImport, MinkowskiOfShapes) {
  constexpr double kPi = std::numbers::pi;
  const std::string rounded =
      "minkowski() {\n square(size = [10, 10]);\n circle(r = 2, $fn = 0, $fa = 12, $fs = 2);\n}";
  EXPECT_NEAR(regionArea(rounded, CsgFacets::Exact), 100.0 + 80.0 + 4.0 * kPi, 1e-6);
  // $fs = 2 at r = 2: 7 sides (ceil(2π)), a corner on +x.
  const int n = 7;
  double width = 0.0, height = 0.0, polygon = 0.0;
  double lo = 1e9, hi = -1e9, bottom = 1e9, top = -1e9;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * k / n;
    lo = std::min(lo, 2.0 * std::cos(a)), hi = std::max(hi, 2.0 * std::cos(a));
    bottom = std::min(bottom, 2.0 * std::sin(a)), top = std::max(top, 2.0 * std::sin(a));
  }
  width = hi - lo, height = top - bottom;
  polygon = 0.5 * n * 4.0 * std::sin(2.0 * kPi / n);
  EXPECT_NEAR(regionArea(rounded, CsgFacets::OpenScad), 100.0 + 10.0 * (width + height) + polygon,
              1e-9);
  EXPECT_EQ(
      importError("minkowski() {\n difference() { square(size = [2, 2]); square(size = [1, "
                  "1]); }\n difference() { square(size = [2, 2]); square(size = [1, 1]); }\n}"),
      "part.csg:1: minkowski: of two regions, one must be convex or a circle");
}

// OpenSCAD's text: its size (an em of size/0.72), its layout (advances and
// alignment boxes short by 1/1.024) and its chords, held against the areas
// of OpenSCAD 2021.01's own exports (openscad -o x.stl of linear_extrude(1)
// of the same, Liberation Sans 1.07): a letter alone, and the halves of a
// centred line (which the alignment moves), and a serif italic's top aligned
// at y = 0, of which only the grid-fitted rounding shows above it.
TEST(CsgImport, TextIsOpenScadsText) {
  const char* o = "text(text = \"O\", size = 10, $fn = 16, $fa = 12, $fs = 2);";
  EXPECT_NEAR(regionArea(o, CsgFacets::OpenScad), 32.660824, 1e-5 * 32.66);
  const char* right =
      "multmatrix([[1, 0, 0, 0], [0, 1, 0, -50], [0, 0, 1, 0], [0, 0, 0, 1]]) {"
      " square(size = [100, 100]); }";
  const char* top =
      "multmatrix([[1, 0, 0, -50], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {"
      " square(size = [100, 100]); }";
  const char* centred = "halign = \"center\", valign = \"center\"";
  EXPECT_NEAR(regionArea(helloText(right, centred), CsgFacets::OpenScad), 46.472718, 1e-5 * 46.5);
  EXPECT_NEAR(regionArea(helloText(top, centred), CsgFacets::OpenScad), 43.801482, 1e-5 * 43.8);
  const std::string italic =
      "intersection() {\n  " + std::string(top) +
      "\n  text(text = \"Hello\", size = 10, font = \"DejaVu Serif:style=Italic\", halign = "
      "\"right\", valign = \"top\", $fn = 16);\n}\n";
  EXPECT_NEAR(regionArea(italic, CsgFacets::OpenScad), 1.200867, 1e-4);
  // Exact, the letters are the curves OpenSCAD's chords approach: 101
  // chords a curve at $fn = 800 come within 10⁻⁵.
  const double exact = regionArea(o, CsgFacets::Exact);
  const char* fine = "text(text = \"O\", size = 10, $fn = 800, $fa = 12, $fs = 2);";
  EXPECT_NEAR(regionArea(fine, CsgFacets::OpenScad), exact, 1e-5 * exact);
  EXPECT_GT(std::abs(exact - 32.660824), 1e-3);  // 3 chords a curve at $fn = 16
  // "Bitstream Vera Sans" is DejaVu Sans (its fontconfig file says so), as
  // for OpenSCAD; an empty string or spaces make nothing, as in OpenSCAD.
  EXPECT_EQ(regionArea("text(text = \"M\", font = \"Bitstream Vera Sans\");", CsgFacets::Exact),
            regionArea("text(text = \"M\", font = \"DejaVu Sans\");", CsgFacets::Exact));
  EXPECT_EQ(regionArea("union() { square(size = [1, 1]); text(text = \"\"); text(text = \"  \"); }",
                       CsgFacets::Exact),
            1.0);
}

// OpenSCAD 2021.01 cuts a twisted or unevenly scaled linear_extrude into
// flat slices and turns rotate_extrude in steps; with its polygons the
// volumes are those of its own exports of the same .scad (openscad -o
// x.stl, by the divergence theorem), up to the rounding of its STL's
// single-precision points and of Clipper's integer grid.
TEST(CsgImport, OpenScadFacetsSliceSweepsAsOpenScadDoes) {
  struct Case {
    const char* csg;
    double openscadVolume;
  };
  const Case cases[] = {
      // 8 slices: 90°/$fa = 7.5, rounded up, fewer than the helix's by $fs.
      {"linear_extrude(height = 20, center = false, convexity = 1, twist = 90, scale = [1, 1], "
       "$fn = 0, $fa = 12, $fs = 2) { square(size = [20, 10], center = true); }",
       4299.524190},
      // A conical helix (a uniform scale), a hole off the axis.
      {"linear_extrude(height = 10, center = true, convexity = 1, twist = -120, scale = [0.5, "
       "0.5], $fn = 0, $fa = 12, $fs = 2) { difference() { circle($fn = 0, $fa = 12, $fs = 2, "
       "r = 10); multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { "
       "circle($fn = 0, $fa = 12, $fs = 2, r = 4); } } }",
       1534.535125},
      // A scale per axis without twist: slices by the longest diagonal.
      {"linear_extrude(height = 10, center = false, convexity = 1, scale = [0.3, 1.5], $fn = 0, "
       "$fa = 12, $fs = 2) { multmatrix([[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 0], [0, 0, 0, "
       "1]]) { square(size = [5, 5], center = false); } }",
       195.833317},
      // slices= given, ending in a point.
      {"linear_extrude(height = 40, center = true, convexity = 1, twist = -360, slices = 200, "
       "scale = [0, 0]) { square(size = [20, 10], center = true); }",
       2701.129101},
      // A twist with a scale per axis and $fn: ceil(200/360·10) slices.
      {"linear_extrude(height = 30, center = false, convexity = 1, twist = 200, scale = [2, "
       "0.5], $fn = 10, $fa = 12, $fs = 2) { multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, "
       "0], [0, 0, 0, 1]]) { square(size = [6, 4], center = true); } }",
       849.150781},
  };
  for (const Case& c : cases) {
    EXPECT_NEAR(exportedVolume(onlySolid(c.csg, CsgFacets::OpenScad)), c.openscadVolume,
                1e-5 * c.openscadVolume)
        << c.csg;
  }
  // A profile of area A whose centroid is x̄ from the axis, turned in n
  // flat steps of Δ: each step's piece is the profile's points x swept
  // along a chord, A·x̄·sin Δ (Pappus's 2π·A·x̄ as n grows). A 10-gon of
  // r = 3 at x = 10 in 30 steps (OpenSCAD's fragments for r = 13).
  const SolidPtr ring = onlySolid(
      "rotate_extrude(angle = 360, convexity = 2, $fn = 0, $fa = 12, $fs = 2) { "
      "multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { circle($fn = 0, "
      "$fa = 12, $fs = 2, r = 3); } }",
      CsgFacets::OpenScad);
  const double decagon = 5.0 * 9.0 * std::sin(2.0 * pi / 10.0);
  EXPECT_NEAR(exportedVolume(ring), decagon * 10.0 * 30.0 * std::sin(2.0 * pi / 30.0), 1e-9);
  // OpenSCAD 2021.01 starts a whole turn on −x: a corner there.
  EXPECT_TRUE(ring->contains({-12.999, 0.0, 0.0}));
  // A partial turn starts on +x, turning clockwise for a negative angle;
  // $fn = 7 over 120° is 2 steps. The triangle (0, 0), (6, 0), (0, 8):
  // A = 24, x̄ = 2.
  const SolidPtr wedge = onlySolid(
      "rotate_extrude(angle = -120, convexity = 2, $fn = 7, $fa = 12, $fs = 2) { polygon(points "
      "= [[0, 0], [6, 0], [0, 8]], paths = undef, convexity = 1); }",
      CsgFacets::OpenScad);
  EXPECT_NEAR(exportedVolume(wedge), 24.0 * 2.0 * 2.0 * std::sin(pi / 3.0), 1e-9);
  const Bounds b = wedge->bounds();
  test::expectVecNear(b.lo, {-3.0, -6.0 * std::sin(pi * 2.0 / 3.0), 0.0}, 1e-9);
  test::expectVecNear(b.hi, {6.0, 0.0, 8.0}, 1e-9);
  // A profile without area makes nothing, as in OpenSCAD.
  for (const char* sweep : {"linear_extrude(height = 1, twist = 10)", "rotate_extrude()"})
    EXPECT_TRUE(
        importText(std::string(sweep) +
                       " { difference() { square(size = [1, 1]); square(size = [1, 1]); } }",
                   CsgFacets::OpenScad)
            .solids.empty())
        << sweep;
  // Past the triangle budget: one line, before any memory is taken.
  try {
    importText("linear_extrude(height = 1, twist = 10, slices = 100000000) { square(size = 1); }",
               CsgFacets::OpenScad);
    ADD_FAILURE() << "no error";
  } catch (const CsgError& e) {
    EXPECT_EQ(std::string(e.what()),
              "part.csg:1: linear_extrude: OpenSCAD's polygons would take 800000008 triangles, "
              "more than 20000000");
  }
  // The exact import starts a partial turn on +x too.
  const SolidPtr quarter =
      onlySolid("rotate_extrude(angle = 90) { polygon(points = [[0, 0], [6, 0], [0, 8]]); }");
  EXPECT_TRUE(quarter->contains({2.0, 2.0, 1.0}));
  EXPECT_FALSE(quarter->contains({-2.0, -2.0, 1.0}));
}

// OpenSCAD writes a turn to 6 digits, so its matrix is orthonormal only
// to 10⁻⁶: the export still evaluates the turned part in its own axes,
// where the faces that are flush stay flush. A cube less two levels of
// Menger bars (3 of 100/3 and 24 of 100/9, each sharing faces with others)
// turned has the volume of the unturned one times the matrix's
// determinant, and a valid mesh.
TEST(CsgImport, ASixDigitTurnKeepsFlushFacesFlush) {
  std::string bars;
  auto bar = [&](int axis, double side, double a, double b) {
    dvec3 size(side), at(0.0);
    size[axis] = 110.0;
    at[(axis + 1) % 3] = a;
    at[(axis + 2) % 3] = b;
    std::ostringstream text;
    text << "multmatrix([[1, 0, 0, " << at.x << "], [0, 1, 0, " << at.y << "], [0, 0, 1, " << at.z
         << "], [0, 0, 0, 1]]) { cube(size = [" << size.x << ", " << size.y << ", " << size.z
         << "], center = true); }\n";
    bars += text.str();
  };
  const double third = 33.3333, ninth = 11.1111;
  for (int axis = 0; axis < 3; ++axis) {
    bar(axis, third, 0.0, 0.0);
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        if (i || j) bar(axis, ninth, i * third, j * third);
  }
  const std::string sponge =
      "difference() { cube(size = [100, 100, 100], center = true); union() {\n" + bars + "} }\n";
  const double turn[3][3] = {
      {0.816497, 0.408248, 0.408248}, {0, 0.707107, -0.707107}, {-0.57735, 0.57735, 0.57735}};
  std::ostringstream turned;
  turned << "multmatrix([";
  for (int r = 0; r < 3; ++r)
    turned << "[" << turn[r][0] << ", " << turn[r][1] << ", " << turn[r][2] << ", 0], ";
  turned << "[0, 0, 0, 1]]) { " << sponge << "}";
  const double det = glm::determinant(
      glm::transpose(glm::dmat3(turn[0][0], turn[0][1], turn[0][2], turn[1][0], turn[1][1],
                                turn[1][2], turn[2][0], turn[2][1], turn[2][2])));
  const PartMesh flat = meshOfSolid(*onlySolid(sponge, CsgFacets::OpenScad), 0.01);
  const PartMesh part = meshOfSolid(*onlySolid(turned.str(), CsgFacets::OpenScad), 0.01);
  EXPECT_NEAR(part.mesh.volume(), det * flat.mesh.volume(), 1e-9 * flat.mesh.volume());
  EXPECT_TRUE(meshDefect(part.mesh).valid()) << meshDefect(part.mesh).text;
}

TEST(CsgImport, ColourAndModifiers) {
  const std::string text =
      "difference() {\n"
      "  color([1, 0, 0, 0.5]) { cube(size = [10, 10, 10]); }\n"
      "  %sphere(r = 3);\n"
      "  #cylinder(h = 30, r1 = 1, r2 = 1, center = true);\n"
      "  *cube(size = [20, 20, 20]);\n"
      "}\n";
  std::ofstream(testing::TempDir() + "/modifiers.csg") << text;
  const Scene scene = runScriptFile(testing::TempDir() + "/modifiers.csg");
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.ghosts.size(), 1u);
  EXPECT_EQ(scene.highlights.size(), 1u);
  // The ghost cuts nothing, the highlighted cylinder cuts its hole (a
  // quarter of it is in the cube).
  EXPECT_NEAR(exportedVolume(scene.objects[0]), 1000.0 - 2.5 * pi, 0.01);
  EXPECT_TRUE(scene.objects[0]->contains({1.0, 1.0, 1.0}));
}

// A parameter no node reads is told of, with its line: a typo in a file
// written by hand, or a newer OpenSCAD's. Those OpenSCAD writes that mean
// nothing to an exact model are not; nor are the special variables (and
// OpenSCAD's own examples below raise none).
TEST(CsgImport, ParametersItDoesNotKnowAreWarnedOf) {
  std::vector<std::string> told;
  CsgImportOptions options;
  options.warn = [&](const std::string& message) { told.push_back(message); };
  const CsgModel model = importCsg(
      "group() {\n  cube(size = [1, 2, 3], centre = true);\n"
      "  sphere($fn = 0, $fa = 12, $fs = 2, r = 1, convexity = 2);\n"
      "  linear_extrude(height = 2, center = false, convexity = 10, twist = 0, slices = 1, "
      "scale = [1, 1], $fn = 0) {\n    square(size = [1, 1], center = false, roundness = 3);\n"
      "  }\n}\n",
      "part.csg", options);
  EXPECT_EQ(model.solids.size(), 1u);
  ASSERT_EQ(told.size(), 2u);
  EXPECT_EQ(told[0],
            "part.csg:2: cube: parameter 'centre' is not known here and was left out; did you "
            "mean 'center'?");
  EXPECT_EQ(told[1],
            "part.csg:5: square: parameter 'roundness' is not known here and was left out");
}

TEST(CsgImport, NodesItCannotMakeAreOneLineErrors) {
  EXPECT_EQ(importError("group() {\n  frobnicate(r = 1);\n}"),
            "part.csg:2: frobnicate: unknown node");
  EXPECT_EQ(
      importError("group() {\n  text(text = \"hi\", font = \"No Such Font\");\n}"),
      "part.csg:2: text: font \"No Such Font\" not found (fc-list lists the installed fonts)");
  EXPECT_EQ(importError("text(text = \"hi\", size = -1);"),
            "part.csg:1: text: size must be a positive number (got -1)");
  EXPECT_EQ(importError("text(text = 12);"), "part.csg:1: text: text must be a string");
  // As long a string as a script's text() takes, no longer.
  EXPECT_EQ(importError("text(text = \"" + std::string(10001, 'x') + "\");"),
            "part.csg:1: text: the string is longer than 10000 bytes");
  EXPECT_EQ(importError("\nprojection(cut = false) { cube(size = 1); }"),
            "part.csg:2: projection: this program cannot project solids");
  EXPECT_EQ(importError("surface(file = \"x.dat\");"),
            "part.csg:1: surface: this program cannot read files");
  EXPECT_EQ(importError("import(file = \"x.svg\");"),
            "part.csg:1: import: this program cannot read files");
  EXPECT_EQ(importError("union() { cube(size = 1); square(size = 1); }"),
            "part.csg:1: union: mixes 2D and 3D children; extrude the 2D ones first");
  EXPECT_EQ(importError("cube(size = \"big\");"),
            "part.csg:1: cube: size must be a vector of numbers");
  EXPECT_EQ(
      importError("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces = [[0, 1, 2]]);"),
      "part.csg:1: polyhedron: needs at least 4 points (got 3)");
  EXPECT_EQ(importError("sphere($fa = 0, r = 1);"), "part.csg:1: sphere: $fa and $fs must be > 0");
  // OpenSCAD writes nan for 0/0: refused where it stands, not left out as
  // a shape without volume would be.
  EXPECT_EQ(importError("group() {\n  cube(size = 1);\n  cube(size = [nan, 1, 1]);\n}"),
            "part.csg:3: cube: size is nan (an undefined number in the source)");
  EXPECT_EQ(importError("sphere(r = nan);"),
            "part.csg:1: sphere: r is nan (an undefined number in the source)");
  EXPECT_EQ(
      importError("multmatrix([[1, 0, 0, nan], [0, 1, 0, 0], [0, 0, 1, 0]]) { cube(size = "
                  "1); }"),
      "part.csg:1: multmatrix: a row of the matrix is nan (an undefined number in the source)");
  EXPECT_EQ(
      importError("multmatrix([[1, 0, 0, 0], [0, 0, 1, 0], [0, 1, 0, 0]]) { square(size = 1); }"),
      "part.csg:1: multmatrix: moves a 2D shape out of the plane z = 0; extrude it first");
  // A message that names the node itself names it once.
  EXPECT_EQ(importError("hull() { difference() { cube(size = 2); sphere(r = 1); } }"),
            "part.csg:1: hull: takes shapes and unions of them, not a difference");
}

TEST(CsgImport, ProjectionsAreRegions) {
  CsgImportOptions options;
  options.project = solidProjection;
  const auto regionArea = [&](const std::string& text) {
    const CsgModel model = importCsg(text, "part.csg", options);
    EXPECT_TRUE(model.solids.empty()) << text;
    return model.regions.empty() ? 0.0 : area(evaluate(*model.regions.at(0), 1e-9));
  };
  // A box standing on z = 0 is cut in its bottom face; its shadow turned
  // 90° about x is its side.
  EXPECT_NEAR(regionArea("projection(cut = true) { cube(size = [1, 2, 3]); }"), 2.0, 1e-12);
  EXPECT_NEAR(regionArea("projection(cut = false) { multmatrix([[1, 0, 0, 0], [0, 0, -1, 0], "
                         "[0, 1, 0, 0], [0, 0, 0, 1]]) { cube(size = [1, 2, 3]); } }"),
              3.0, 1e-12);
  // Above the plane: nothing, which a difference takes as nothing.
  EXPECT_NEAR(regionArea("difference() { square(size = [4, 4]);\n"
                         "  projection(cut = true) { multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], "
                         "[0, 0, 1, 1], [0, 0, 0, 1]]) { cube(size = 1); } } }"),
              16.0, 1e-12);
  EXPECT_THROW(importCsg("projection() { square(size = 1); }", "part.csg", options), CsgError);
  try {
    importCsg("group() {\n  projection(cut = true) { square(size = 1); }\n}", "part.csg", options);
  } catch (const CsgError& e) {
    EXPECT_STREQ(e.what(), "part.csg:2: projection: takes solids, not 2D shapes");
  }
}

// ---- OpenSCAD's examples -------------------------------------------------------

const std::string kData = CSGRAY_SOURCE_DIR "/tests/data/openscad/";

std::map<std::string, double> referenceVolumes() {
  std::map<std::string, double> volumes;
  std::ifstream in(kData + "volumes.txt");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name;
    double volume;
    fields >> name >> volume;
    volumes[name] = volume;
  }
  return volumes;
}

// The nodes that read files: surface() of a PNG and import() of a DXF
// drawing, against OpenSCAD 2021.01's exports of `surface(file =
// "surface_image.png", center = true);` and of `linear_extrude(height = 1)
// import(file = "example009.dxf", layer = "body", scale = 2);`.
TEST(CsgImport, SurfaceAndDxfNodes) {
  CsgImportOptions options;
  options.resolveFile = [](const std::string& name) { return kData + name; };
  options.loadImage = readTextureImage;
  const CsgModel png = importCsg(
      "surface(file = \"surface_image.png\", center = true, invert = false);", "part.csg", options);
  ASSERT_EQ(png.solids.size(), 1u);
  EXPECT_NEAR(exportedVolume(png.solids[0]), 87367.557376, 1e-5 * 87367.557376);
  const std::string body =
      "import(file = \"example009.dxf\", layer = \"body\", origin = [0, 0], scale = 2, $fn = 0, "
      "$fa = 12, $fs = 2);";
  options.facets = CsgFacets::OpenScad;
  const CsgModel facets = importCsg(body, "part.csg", options);
  ASSERT_EQ(facets.regions.size(), 1u);
  // OpenSCAD moves each point onto the first it met within 0.001 (its
  // GRID_COARSE), and its STL has 6 significant digits.
  EXPECT_NEAR(area(evaluate(*facets.regions[0], 1e-9)), 1230.880866, 1e-4 * 1230.880866);
  options.facets = CsgFacets::Exact;
  const CsgModel exact = importCsg(body, "part.csg", options);
  // The exact arcs: the round holes are larger than OpenSCAD's polygons.
  EXPECT_NEAR(area(evaluate(*exact.regions[0], 1e-9)), 1230.880866, 0.01 * 1230.880866);
  try {
    importCsg("group() {\n  import(file = \"example009.dxf\", layer = \"none\");\n}", "part.csg",
              options);
    ADD_FAILURE() << "no error";
  } catch (const CsgError& e) {
    EXPECT_EQ(std::string(e.what()),
              "part.csg:2: import: example009.dxf: layer \"none\" draws no closed outline (its "
              "layers: body, dim, fan_side, fan_side_center, fan_top, plate)");
  }
}

// import() of an SVG drawing, against OpenSCAD 2021.01's export of
// `linear_extrude(height = 1) import(file = "svg_drawing.svg");`: its
// volume, and its box, which shows where OpenSCAD puts the page (its
// bottom left corner at the origin). OpenSCAD draws the drawing's circle
// (radius 12 user units, 6 mm) as a 40-gon, 20·6²·sin 9° of area, where
// csgray's is π·6².
TEST(CsgImport, SvgNodes) {
  CsgImportOptions options;
  options.resolveFile = [](const std::string& name) { return kData + name; };
  const std::string node =
      "import(file = \"svg_drawing.svg\", layer = \"\", origin = [0, 0], center = false, dpi = "
      "72, scale = 1, convexity = 1, $fn = 0, $fa = 12, $fs = 2, timestamp = 1795666030);";
  const CsgModel model = importCsg(node, "part.csg", options);
  ASSERT_EQ(model.regions.size(), 1u);
  const double openscadVolume = 1275.132802;
  const double circle = pi * 36.0, openscadCircle = 20.0 * 36.0 * std::sin(pi / 20.0);
  const Profile evaluated = evaluate(*model.regions[0], 1e-9);
  // Its STL has 6 significant digits.
  EXPECT_NEAR(area(evaluated), openscadVolume - openscadCircle + circle, 1e-5 * openscadVolume);
  // With OpenSCAD's polygons, OpenSCAD's area.
  options.facets = CsgFacets::OpenScad;
  const CsgModel polygons = importCsg(node, "part.csg", options);
  EXPECT_NEAR(area(evaluate(*polygons.regions[0], 1e-9)), openscadVolume, 1e-6 * openscadVolume);
  options.facets = CsgFacets::Exact;
  const ProfileBounds box = evaluated.bounds();
  EXPECT_NEAR(box.lo.x, 5.0, 1e-9);
  EXPECT_NEAR(box.lo.y, 4.0, 1e-9);
  EXPECT_NEAR(box.hi.x, 76.0, 1e-9);
  EXPECT_NEAR(box.hi.y, 55.0, 1e-9);
  // center = true puts the box's middle on the origin; dpi = 144 halves
  // nothing here, since the page's size is in mm.
  const CsgModel centered = importCsg(
      "import(file = \"svg_drawing.svg\", center = true, dpi = 144);", "part.csg", options);
  const ProfileBounds middle = evaluate(*centered.regions[0], 1e-9).bounds();
  EXPECT_NEAR(middle.lo.x + middle.hi.x, 0.0, 1e-9);
  EXPECT_NEAR(middle.lo.y + middle.hi.y, 0.0, 1e-9);
  EXPECT_NEAR(middle.hi.x - middle.lo.x, 71.0, 1e-9);
  try {
    importCsg("group() {\n  import(file = \"svg_drawing.svg\", id = \"none\");\n}", "part.csg",
              options);
    ADD_FAILURE() << "no error";
  } catch (const CsgError& e) {
    EXPECT_EQ(std::string(e.what()),
              "part.csg:2: import: svg_drawing.svg: no element has the id \"none\"");
  }
}

// Curves, against OpenSCAD 2021.01's export of `linear_extrude(height = 1)
// import(file = "svg_curves.svg");` (volume 1272.657179): its chords with
// --facets openscad, and exact areas otherwise: a 40 × 20 rectangle with
// corners of radius 5, 800 − (4 − π)·25; a cubic lobe of width and height
// 20 (its control points 20 above its ends), 0.6·20·20; a half disc of
// radius 10; a parabola's segment, 2/3 of its control triangle (20 wide,
// 15 high).
TEST(CsgImport, SvgCurves) {
  CsgImportOptions options;
  options.resolveFile = [](const std::string& name) { return kData + name; };
  const std::string node = "import(file = \"svg_curves.svg\", center = false, dpi = 72);";
  const CsgModel exact = importCsg(node, "part.csg", options);
  EXPECT_NEAR(area(evaluate(*exact.regions[0], 1e-7)),
              800 - (4 - pi) * 25 + 0.6 * 400 + 50 * pi + 2.0 / 3.0 * 150, 1e-4);
  options.facets = CsgFacets::OpenScad;
  const CsgModel polygons = importCsg(node, "part.csg", options);
  EXPECT_NEAR(area(evaluate(*polygons.regions[0], 1e-9)), 1272.657179, 1e-6 * 1272.657179);
}

// Strokes, against OpenSCAD 2021.01's export of `linear_extrude(height =
// 1) import(file = "svg_strokes.svg");` (volume 456.920264, its box from
// (4.5, 7.99789) to (96.1157, 46)): OpenSCAD offsets the lines with
// Clipper's integer coordinates (10⁻⁴ of a user unit), csgray exactly.
TEST(CsgImport, SvgStrokes) {
  CsgImportOptions options;
  options.resolveFile = [](const std::string& name) { return kData + name; };
  const CsgModel model = importCsg("import(file = \"svg_strokes.svg\");", "part.csg", options);
  const Profile evaluated = evaluate(*model.regions[0], 1e-9);
  EXPECT_NEAR(area(evaluated), 456.920264, 1e-5 * 456.920264);
  const ProfileBounds box = evaluated.bounds();
  // Its STL's 6 digits, and Clipper's grid.
  EXPECT_NEAR(box.lo.x, 4.5, 1e-4);
  EXPECT_NEAR(box.lo.y, 7.99789, 1e-4);
  EXPECT_NEAR(box.hi.x, 96.1157, 1e-4);
  EXPECT_NEAR(box.hi.y, 46.0, 1e-4);
}

// Every parameter OpenSCAD writes is known: no warnings.
Scene exampleScene(const std::string& name, bool openscadFacets) {
  ScriptOptions options = test::exampleOptions();
  options.openscadFacets = openscadFacets;
  std::vector<std::string> told;
  options.warn = [&](const std::string& message) { told.push_back(message); };
  Scene scene = runScriptFile(kData + name + ".csg", options);
  EXPECT_TRUE(told.empty()) << told.front();
  return scene;
}

// What each example makes here: a solid (imported, rendered and exported,
// its volume held against OpenSCAD's), a 2D region (imported and
// rendered), or an error (what is missing, named at its line).
struct Example {
  const char* name;
  enum { Solid, Region, Refused } kind;
  // Solid: the largest relative difference of the exact import's volume
  // from OpenSCAD's, which OpenSCAD's polygons explain (its circles are
  // inside the true ones: its volumes are smaller). Refused: the error.
  double exactSlack = 0.0;
  const char* error = "";
  // Solid: when > 0, the exact import's volume is measured as `csgray
  // check` measures it, along three grids of n × n rays (exact along each
  // ray, check/exact_volume.h), rather than on its mesh, which for long
  // twists takes millions of triangles at the tests' tolerance.
  int exactRays = 0;
};

class OpenScadExample : public ::testing::TestWithParam<Example> {};

TEST_P(OpenScadExample, ImportsRendersAndExports) {
  const Example& example = GetParam();
  if (example.kind == Example::Refused) {
    std::string error;
    try {
      exampleScene(example.name, false);
    } catch (const ScriptError& e) {
      error = e.what();
    }
    EXPECT_NE(error.find(example.error), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    return;
  }
  const Scene facets = exampleScene(example.name, true);
  RenderResult image = [&] {
    RenderOptions options(64, 48, 0);
    options.depthAov = true;
    return Renderer(facets, options).renderAll();
  }();
  int hit = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) hit += std::isfinite(image.depth.at(x, y).x);
  EXPECT_GT(hit, 10);  // the part is seen (some are long and thin)
  if (example.kind == Example::Region) {
    EXPECT_TRUE(facets.objects.empty());
    EXPECT_FALSE(facets.surfaces.empty());
    return;
  }
  const double reference = referenceVolumes().at(example.name);
  ASSERT_FALSE(facets.objects.empty());
  const PartMesh withFacets = meshOfSolid(*unionOf(facets.objects), 0.01);
  EXPECT_FALSE(withFacets.mesh.empty());
  EXPECT_NEAR(withFacets.mesh.volume(), reference, 1e-3 * reference) << "with OpenSCAD's facets";
  const Scene exact = exampleScene(example.name, false);
  const SolidPtr exactPart = unionOf(exact.objects);
  const double exactPartVolume = example.exactRays > 0
                                     ? exactVolume(*exactPart, example.exactRays)
                                     : meshOfSolid(*exactPart, 0.01).mesh.volume();
  EXPECT_NEAR(exactPartVolume, reference, example.exactSlack * reference) << "exact";
}

std::string exampleTestName(const ::testing::TestParamInfo<Example>& info) {
  std::string name = info.param.name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// The exact import's volume is larger than OpenSCAD's where the model
// adds round parts, smaller where it subtracts them (Old_example004 cuts a
// ball out of a cube), by up to what OpenSCAD's coarse default polygons
// leave out: a 5-gon for Functions_functions' unit balls. OpenSCAD's flat
// slices of a twist bulge out of the helicoid: Basics_linear_extrude's
// twisted bar is 2.6 % larger there.
const Example kExamples[] = {
    {"Advanced_GEB", Example::Solid, 1e-4},
    {"Advanced_animation", Example::Solid, 0.02},
    {"Advanced_assert", Example::Solid, 1e-3},
    {"Advanced_children", Example::Solid, 0.02},
    {"Advanced_children_indexed", Example::Solid, 0.06},
    {"Advanced_offset", Example::Solid, 1e-3},
    {"Advanced_surface_image", Example::Solid, 1e-3},
    {"Basics_CSG-modules", Example::Solid, 2e-3},
    {"Basics_CSG", Example::Solid, 0.01},
    {"Basics_LetterBlock", Example::Solid, 1e-4},
    {"Basics_linear_extrude", Example::Solid, 0.03},
    {"Basics_logo", Example::Solid, 5e-3},
    {"Basics_logo_and_text", Example::Solid, 3e-3},
    {"Basics_rotate_extrude", Example::Solid, 5e-3},
    {"Basics_text_on_cube", Example::Solid, 1e-4},
    {"Functions_functions", Example::Solid, 0.2},
    {"Old_example001", Example::Solid, 0.03},
    {"Old_example002", Example::Solid, 0.01},
    {"Old_example003", Example::Solid, 1e-4},
    {"Old_example004", Example::Solid, 0.07},
    {"Old_example005", Example::Solid, 0.01},
    {"Old_example006", Example::Solid, 2e-3},
    // OpenSCAD turns 007's rotate_extrude in 30 steps (its volume is 0.8 %
    // smaller than the exact one), and cuts 009's twisted linear_extrude
    // into flat slices and turns its rotate_extrude in steps (5 % larger).
    // Their DXF drawings are imported as OpenSCAD imports them:
    // SurfaceAndDxfNodes holds an area to 10⁻⁴.
    {"Old_example007", Example::Solid, 0.01},
    {"Old_example008", Example::Solid, 1e-4},
    {"Old_example009", Example::Solid, 0.055},
    {"Old_example010", Example::Solid, 1e-4},
    {"Old_example011", Example::Solid, 1e-4},
    {"Old_example012", Example::Solid, 0.02},
    {"Old_example013", Example::Solid, 1e-4},
    {"Old_example014", Example::Solid, 1e-4},
    {"Old_example016", Example::Solid, 1e-4},
    {"Old_example017", Example::Solid, 0.01},
    {"Old_example018", Example::Solid, 6e-3},
    {"Old_example019", Example::Solid, 0.015},
    {"Old_example020", Example::Solid, 0.05, "", 200},
    {"Old_example022", Example::Solid, 6e-3},
    {"Old_example023", Example::Solid, 1e-4},
    // A Menger sponge (a cube less 219 bars), turned, cut by a plane
    // oblique to its bars: nothing round, so the exact import is
    // OpenSCAD's part.
    {"Old_example024", Example::Solid, 1e-4},
    // OpenSCAD's shadow and sections of an imported mesh, exact here too.
    {"Basics_projection", Example::Solid, 1e-5},
    // Sections of a ball with $fa = 30 (12-gons): the true ball's are larger.
    {"Old_example021", Example::Solid, 0.14},
    {"Parametric_candleStand", Example::Solid, 0.01},
    {"Parametric_sign", Example::Solid, 5e-4},
    {"Advanced_module_recursion", Example::Region},
    {"Functions_list_comprehensions", Example::Region},
    {"Functions_polygon_areas", Example::Region},
    {"Functions_recursion", Example::Region},
    {"Old_example015", Example::Region},
    {"Functions_echo", Example::Refused, 0, "Functions_echo.csg: the file makes nothing to show"},
};

INSTANTIATE_TEST_SUITE_P(Examples, OpenScadExample, ::testing::ValuesIn(kExamples),
                         exampleTestName);

}  // namespace
}  // namespace csgray::detail
