// DXF drawings as regions: each entity draws what the DXF Reference says,
// pieces join end to end into outlines, arcs stay exact (or become
// OpenSCAD's polygons), and broken files are one-line errors, never a crash.
#include "profile/dxf_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "profile/region_evaluation.h"

namespace csgray::detail {
namespace {

using std::numbers::pi;

// An entity: its type and its groups, written as a DXF file writes them.
std::string entity(const std::string& type,
                   const std::vector<std::pair<int, std::string>>& groups) {
  std::string out = "0\n" + type + "\n";
  for (const auto& [code, value] : groups) out += std::to_string(code) + "\n" + value + "\n";
  return out;
}

std::string drawing(const std::string& entities, const std::string& blocks = "") {
  std::string out = "999\nmade by a test\n";
  if (!blocks.empty()) out += "0\nSECTION\n2\nBLOCKS\n" + blocks + "0\nENDSEC\n";
  return out + "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
}

std::string num(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

std::string line(double x0, double y0, double x1, double y1, const std::string& layer = "0") {
  return entity("LINE", {{8, layer}, {10, num(x0)}, {20, num(y0)}, {11, num(x1)}, {21, num(y1)}});
}

double areaOf(const std::string& text, const DxfOptions& options = {}) {
  return area(evaluate(*readDxf(text, "part.dxf", options), 1e-9));
}

std::string error(const std::string& text, const DxfOptions& options = {}) {
  try {
    readDxf(text, "part.dxf", options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DxfReader, LinesJoinInAnyOrderAndDirection) {
  // A 10 × 10 square of lines given out of order, two of them backwards,
  // and one end a rounding error off.
  const std::string square =
      line(0, 0, 10, 0) + line(0, 10, 10, 10) + line(10, 10.0000000001, 10, 0) + line(0, 0, 0, 10);
  RegionPtr region = readDxf(drawing(square), "part.dxf", {});
  ASSERT_EQ(region->profile().loops.size(), 1u);
  EXPECT_EQ(region->profile().loops[0].edges.size(), 4u);
  EXPECT_NEAR(areaOf(drawing(square)), 100.0, 1e-6);
  // A square inside: a hole (even-odd, as OpenSCAD fills).
  EXPECT_NEAR(areaOf(drawing(square + line(2, 2, 4, 2) + line(4, 2, 4, 4) + line(4, 4, 2, 4) +
                             line(2, 4, 2, 2))),
              96.0, 1e-6);
}

TEST(DxfReader, ArcsCirclesAndEllipsesStayExact) {
  const std::string circle = entity("CIRCLE", {{10, "1"}, {20, "2"}, {40, "5"}});
  EXPECT_NEAR(areaOf(drawing(circle)), 25.0 * pi, 1e-9);
  // A half disc: an arc from 0° to 180° and its diameter.
  const std::string halfDisc =
      entity("ARC", {{10, "0"}, {20, "0"}, {40, "5"}, {50, "0"}, {51, "180"}}) + line(-5, 0, 5, 0);
  EXPECT_NEAR(areaOf(drawing(halfDisc)), 12.5 * pi, 1e-9);
  // An ellipse of half-axes 4 (along (1, 1)) and 2.
  const std::string ellipse = entity("ELLIPSE", {{10, "0"},
                                                 {20, "0"},
                                                 {11, num(4 / std::sqrt(2.0))},
                                                 {21, num(4 / std::sqrt(2.0))},
                                                 {40, "0.5"},
                                                 {41, "0"},
                                                 {42, "6.283185307179586"}});
  EXPECT_NEAR(areaOf(drawing(ellipse)), 8.0 * pi, 1e-6);
  // An extrusion direction (0, 0, −1) mirrors x: the circle about (−1, 2).
  const std::string mirrored = entity("CIRCLE", {{10, "1"}, {20, "2"}, {40, "5"}, {230, "-1"}});
  RegionPtr region = readDxf(drawing(mirrored), "part.dxf", {});
  EXPECT_NEAR(region->bounds().lo.x, -6.0, 1e-9);
  EXPECT_NEAR(region->bounds().hi.x, 4.0, 1e-9);
}

TEST(DxfReader, OpenScadPolygonsOfArcs) {
  DxfOptions options;
  options.fragments = [](double) { return 30; };
  // OpenSCAD's circle of 30 sides, and its half: 15 chords.
  const std::string circle = entity("CIRCLE", {{10, "0"}, {20, "0"}, {40, "5"}});
  EXPECT_NEAR(areaOf(drawing(circle), options), 15.0 * 25.0 * std::sin(2.0 * pi / 30.0), 1e-9);
  const std::string halfDisc =
      entity("ARC", {{10, "0"}, {20, "0"}, {40, "5"}, {50, "0"}, {51, "180"}}) + line(-5, 0, 5, 0);
  EXPECT_NEAR(areaOf(drawing(halfDisc), options), 7.5 * 25.0 * std::sin(2.0 * pi / 30.0), 1e-9);
}

TEST(DxfReader, PolylinesWithBulges) {
  // A stadium: a 10 × 10 square whose right and left sides bulge out into
  // half circles (bulge 1 is a half turn counterclockwise).
  const std::string stadium = entity("LWPOLYLINE", {{8, "0"},
                                                    {90, "4"},
                                                    {70, "1"},
                                                    {10, "0"},
                                                    {20, "0"},
                                                    {10, "10"},
                                                    {20, "0"},
                                                    {42, "1"},
                                                    {10, "10"},
                                                    {20, "10"},
                                                    {10, "0"},
                                                    {20, "10"},
                                                    {42, "1"}});
  EXPECT_NEAR(areaOf(drawing(stadium)), 100.0 + 25.0 * pi, 1e-9);
  // The same with POLYLINE and VERTEX entities, a bulge of −1 cutting a
  // half disc out of the bottom instead.
  const std::string old = entity("POLYLINE", {{8, "0"}, {66, "1"}, {70, "1"}}) +
                          entity("VERTEX", {{8, "0"}, {10, "0"}, {20, "0"}, {42, "-1"}}) +
                          entity("VERTEX", {{8, "0"}, {10, "10"}, {20, "0"}}) +
                          entity("VERTEX", {{8, "0"}, {10, "10"}, {20, "10"}}) +
                          entity("VERTEX", {{8, "0"}, {10, "0"}, {20, "10"}}) +
                          entity("SEQEND", {});
  EXPECT_NEAR(areaOf(drawing(old)), 100.0 - 12.5 * pi, 1e-9);
}

TEST(DxfReader, LayersOriginScaleAndBlocks) {
  const std::string two = line(10, 10, 20, 10, "a") + line(20, 10, 20, 20, "a") +
                          line(20, 20, 10, 10, "a") + entity("CIRCLE", {{8, "b"}, {40, "1"}});
  DxfOptions a;
  a.layer = "a";
  a.origin = {10, 10};
  a.scale = 2;
  RegionPtr region = readDxf(drawing(two), "part.dxf", a);
  EXPECT_NEAR(region->bounds().lo.x, 0.0, 1e-12);
  EXPECT_NEAR(region->bounds().hi.y, 20.0, 1e-12);
  EXPECT_NEAR(areaOf(drawing(two), a), 200.0, 1e-9);
  EXPECT_NEAR(areaOf(drawing(two)), 50.0 + pi, 1e-9);
  DxfOptions missing;
  missing.layer = "c";
  EXPECT_EQ(error(drawing(two), missing),
            "part.dxf: layer \"c\" draws no closed outline (its layers: a, b)");
  // A block of a unit square with its base point at (1, 1), inserted
  // turned by 90°, scaled by 2 and 3, at (5, 0); and a block inserting it.
  const std::string blocks = entity("BLOCK", {{2, "sq"}, {10, "1"}, {20, "1"}}) + line(1, 1, 2, 1) +
                             line(2, 1, 2, 2) + line(2, 2, 1, 2) + line(1, 2, 1, 1) +
                             entity("ENDBLK", {}) + entity("BLOCK", {{2, "two"}}) +
                             entity("INSERT", {{2, "sq"}}) +
                             entity("INSERT", {{2, "sq"}, {10, "3"}}) + entity("ENDBLK", {});
  const std::string inserts =
      entity("INSERT", {{2, "sq"}, {10, "5"}, {20, "0"}, {41, "2"}, {42, "3"}, {50, "90"}});
  region = readDxf(drawing(inserts, blocks), "part.dxf", {});
  EXPECT_NEAR(region->bounds().lo.x, 2.0, 1e-12);
  EXPECT_NEAR(region->bounds().hi.x, 5.0, 1e-12);
  EXPECT_NEAR(region->bounds().hi.y, 2.0, 1e-12);
  EXPECT_NEAR(areaOf(drawing(inserts, blocks)), 6.0, 1e-9);
  EXPECT_NEAR(areaOf(drawing(entity("INSERT", {{2, "two"}}), blocks)), 2.0, 1e-9);
  // An array of 3 columns 4 apart and 2 rows 5 apart, turned by 90° with
  // the squares scaled by 2: six squares of 2 × 2 (the spacing is not
  // scaled), the columns along y, the rows along −x.
  const std::string array = entity(
      "INSERT",
      {{2, "sq"}, {41, "2"}, {42, "2"}, {50, "90"}, {70, "3"}, {71, "2"}, {44, "4"}, {45, "5"}});
  region = readDxf(drawing(array, blocks), "part.dxf", {});
  EXPECT_NEAR(areaOf(drawing(array, blocks)), 6 * 4.0, 1e-9);
  EXPECT_NEAR(region->bounds().lo.x, -5.0 - 2.0, 1e-12);
  EXPECT_NEAR(region->bounds().hi.x, 0.0, 1e-12);
  EXPECT_NEAR(region->bounds().lo.y, 0.0, 1e-12);
  EXPECT_NEAR(region->bounds().hi.y, 8.0 + 2.0, 1e-12);
  // Counts of 0 (no array, from some writers) and 1 are one copy.
  EXPECT_NEAR(
      areaOf(drawing(entity("INSERT", {{2, "sq"}, {70, "0"}, {71, "1"}, {44, "9"}}), blocks)), 1.0,
      1e-9);
  EXPECT_EQ(error(drawing(entity("INSERT", {{2, "sq"}, {70, "2.5"}}), blocks)),
            "part.dxf:92: group code 70: a count of copies must be a whole number, found 2.5");
}

// A SPLINE entity: degree (71), knots (40) and control points (10/20).
std::string spline(int degree, const std::vector<double>& knots, const std::vector<dvec2>& controls,
                   const std::vector<std::pair<int, std::string>>& more = {}) {
  std::vector<std::pair<int, std::string>> groups = {{8, "0"}, {71, std::to_string(degree)}};
  for (double k : knots) groups.push_back({40, num(k)});
  for (const dvec2& p : controls) {
    groups.push_back({10, num(p.x)});
    groups.push_back({20, num(p.y)});
  }
  groups.insert(groups.end(), more.begin(), more.end());
  return entity("SPLINE", groups);
}

TEST(DxfReader, SplinesAreExactCurves) {
  // A closed uniform quadratic spline on the corners of a square of side 2
  // (the first two corners repeated at the end): four parabolas from one
  // side's midpoint to the next, each cutting off two thirds of its
  // corner's triangle (Archimedes' quadrature of the parabola), so the
  // area is the inner diamond's 2 plus 4 · (2/3) · (1/2) = 10/3.
  const std::vector<dvec2> square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  EXPECT_NEAR(areaOf(drawing(spline(2, {0, 1, 2, 3, 4, 5, 6, 7, 8}, square))), 10.0 / 3.0, 1e-8);
  // Equal weights are a plain spline. A clamped cubic of four points is
  // one Bézier: from (0,0) by (0,3), (3,3) to (3,0), x = 9s² − 6s³ and
  // y = 9s(1 − s), so with the x axis back it encloses
  // ∫ y dx = ∫₀¹ 9s(1 − s) · 18s(1 − s) ds = 162 · B(3, 3) = 162/30.
  const std::string cubic = spline(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {0, 3}, {3, 3}, {3, 0}},
                                   {{41, "1"}, {41, "1"}, {41, "1"}, {41, "1"}});
  EXPECT_NEAR(areaOf(drawing(cubic + line(3, 0, 0, 0))), 162.0 / 30.0, 1e-8);
  // A circle of radius 2 as drawing programs write it: a rational
  // quadratic of four quarter arcs (weights 1 and cos 45°), read as the
  // arcs they are: the area of the circle, not of a polygon or a curve
  // near it.
  const std::vector<dvec2> corners = {{2, 0},   {2, 2},  {0, 2},  {-2, 2}, {-2, 0},
                                      {-2, -2}, {0, -2}, {2, -2}, {2, 0}};
  std::vector<std::pair<int, std::string>> weights;
  for (std::size_t i = 0; i < corners.size(); ++i)
    weights.push_back({41, i % 2 ? num(std::sqrt(0.5)) : "1"});
  const std::string circle =
      spline(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, corners, weights);
  EXPECT_NEAR(areaOf(drawing(circle)), 4.0 * std::numbers::pi, 1e-9);
  // A rational piece that is a hyperbola, and splines by fit points only,
  // are refused.
  EXPECT_EQ(error(drawing(spline(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}},
                                 {{41, "1"}, {41, "2"}, {41, "1"}}))),
            "part.dxf:7: SPLINE: a rational spline with a piece of a hyperbola (only arcs of "
            "circles, ellipses and parabolas are read)");
  EXPECT_EQ(error(drawing(entity("SPLINE", {{8, "0"}, {71, "3"}, {11, "0"}, {21, "0"}}))),
            "part.dxf:7: a SPLINE given by fit points only is not supported (give its control "
            "points and knots)");
  EXPECT_EQ(error(drawing(spline(3, {0, 0, 1, 1}, square))),
            "part.dxf:7: SPLINE: a spline with 6 control points of degree 3 needs 10 knots, not "
            "4");
}

TEST(DxfReader, BadFilesAreOneLineErrors) {
  EXPECT_EQ(error(""), "part.dxf: not a DXF drawing (no ENTITIES section)");
  EXPECT_EQ(error("0\nSECTION\n2\nENTITIES\nLINE\n"),
            "part.dxf:5: expected a group code (a whole number), found 'LINE'");
  EXPECT_EQ(error("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1.5x\n"),
            "part.dxf:8: expected a number for group code 10, found '1.5x'");
  EXPECT_EQ(error("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nnan\n"),
            "part.dxf:8: expected a number for group code 10, found 'nan'");
  EXPECT_EQ(error("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n1e16\n"),
            "part.dxf:8: the number 1e16 is too large (at most 1e15 either way)");
  EXPECT_EQ(error("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n"),
            "part.dxf:7: group code 10 has no value");
  EXPECT_EQ(error("0\nSECTION\n2\nENTITIES\n" + line(0, 0, 1, 1)),
            "part.dxf:16: the file ends inside the ENTITIES section (is it cut short?)");
  // A NUL byte in an entity's name: shown, not the end of the message.
  EXPECT_EQ(error(drawing(entity(std::string("CIR\0CLE", 7), {{8, "0"}})))
                .rfind("part.dxf:7: CIR?CLE entities are not supported", 0),
            0u);
  EXPECT_EQ(error(drawing(entity("3DFACE", {{8, "0"}}))),
            "part.dxf:7: 3DFACE entities are not supported (LINE, LWPOLYLINE, POLYLINE, ARC, "
            "CIRCLE, ELLIPSE, SPLINE and INSERT are)");
  EXPECT_EQ(error(drawing(entity("INSERT", {{2, "nothing"}}))),
            "part.dxf:7: INSERT of the block \"nothing\", which the file does not define");
  const std::string loop =
      entity("BLOCK", {{2, "me"}}) + entity("INSERT", {{2, "me"}}) + entity("ENDBLK", {});
  EXPECT_EQ(error(drawing(entity("INSERT", {{2, "me"}}), loop)),
            "part.dxf:11: blocks nested deeper than 32 (a block that inserts itself?)");
  EXPECT_EQ(error(drawing(entity("CIRCLE", {{40, "-1"}}))),
            "part.dxf:10: a CIRCLE's radius must be > 0");
  // Blocks that insert the one before ten times: a small file of a billion
  // circles, or of a billion inserts of nothing, stops at the insert that
  // goes past the limit.
  for (const std::string& first :
       {entity("CIRCLE", {{10, "0"}, {20, "0"}, {40, "1"}}), std::string()}) {
    std::string blocks = entity("BLOCK", {{2, "b0"}}) + first + entity("ENDBLK", {});
    for (int level = 1; level < 10; ++level) {
      blocks += entity("BLOCK", {{2, "b" + std::to_string(level)}});
      for (int k = 0; k < 10; ++k)
        blocks += entity("INSERT", {{2, "b" + std::to_string(level - 1)}, {10, num(3.0 * k)}});
      blocks += entity("ENDBLK", {});
    }
    const std::string message = error(drawing(entity("INSERT", {{2, "b9"}}), blocks));
    EXPECT_NE(message.find(": more than 200000 edges or 1000000 inserted blocks (with the copies "
                           "INSERT makes)"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.rfind("part.dxf:", 0), 0u) << message;
  }
  EXPECT_EQ(error(drawing(line(0, 0, 1, 0))),
            "part.dxf: the drawing draws no closed outline (its layers: 0)");
  // Layer names are cut short, and at most ten listed.
  std::string lines;
  for (int i = 0; i < 12; ++i)
    lines += line(0, 0, 1, 0, "L" + std::to_string(i) + std::string(50, 'x'));
  const std::string many = error(drawing(lines));
  EXPECT_NE(many.find("(its layers: L0" + std::string(38, 'x') + "..., L10x"), std::string::npos)
      << many;
  EXPECT_TRUE(many.ends_with("x... and 2 more)")) << many;
}

TEST(DxfReader, CutShortOrGarbledFilesNeverCrash) {
  // OpenSCAD's example009.dxf cut at many places and with bytes changed:
  // each is read or refused with one line naming the file.
  std::ifstream in(CSGRAY_SOURCE_DIR "/tests/data/openscad/example009.dxf");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string whole = buffer.str();
  ASSERT_GT(whole.size(), 10000u);
  DxfOptions body;
  body.layer = "body";
  EXPECT_GT(areaOf(whole, body), 0.0);
  std::vector<std::string> variants;
  for (std::size_t cut = 0; cut < whole.size(); cut += 997)
    variants.push_back(whole.substr(0, cut));
  for (std::size_t at = 1; at < whole.size(); at += 1499) {
    std::string garbled = whole;
    garbled[at] = "x7\n-."[at % 5];
    variants.push_back(garbled);
  }
  for (const std::string& text : variants) {
    try {
      readDxf(text, "part.dxf", body);
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("part.dxf", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  // The same for a drawing with a spline (examples/dxf_cam.lua's), whose
  // knots and control points a cut or a changed byte leave out of step.
  std::ifstream camFile(CSGRAY_SOURCE_DIR "/examples/drawings/cam.dxf");
  std::stringstream cam;
  cam << camFile.rdbuf();
  const std::string drawn = cam.str();
  DxfOptions lobe;
  lobe.layer = "cam";
  EXPECT_NO_THROW(readDxf(drawn, "part.dxf", lobe));
  for (std::size_t at = 1; at < drawn.size(); at += 59) {
    std::string garbled = drawn;
    garbled[at] = "x7\n-."[at % 5];
    for (const std::string& text : {drawn.substr(0, at), garbled}) {
      try {
        readDxf(text, "part.dxf", lobe);
      } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("part.dxf", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      }
    }
  }
}

}  // namespace
}  // namespace csgray::detail
