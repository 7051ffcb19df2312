// SVG drawings as regions: each shape fills what SVG 1.1 says it draws,
// curves stay exact (areas known in closed form), transforms and units
// place the drawing where OpenSCAD puts it, and broken files are one-line
// errors, never a crash.
#include "profile/svg_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "profile/region_evaluation.h"
#include "profile/svg_path.h"
#include "profile/xml_reader.h"

namespace csgray::detail {
namespace {

using std::numbers::pi;

// A drawing of 100 × 100 user units on a page of 100 × 100 mm: a user
// unit is a millimetre, y runs down from the top.
std::string page(const std::string& content, const std::string& attributes = "") {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" "
         "viewBox=\"0 0 100 100\"" +
         attributes + ">\n" + content + "\n</svg>\n";
}

RegionPtr read(const std::string& text, const SvgOptions& options = {}) {
  return readSvg(text, "part.svg", options);
}

// The area of the region evaluated: exact for segments and circles, within
// 10⁻⁵ for ellipses and Bézier curves (made polygons within 10⁻⁷ of them).
double areaOf(const std::string& text, const SvgOptions& options = {}) {
  return area(evaluate(*read(text, options), 1e-7));
}

// The area of a drawing of one loop that does not cross itself, exact for
// every kind of edge (Green's theorem on the curves).
double loopArea(const std::string& text) {
  RegionPtr region = read(text);
  EXPECT_EQ(region->op(), Region::Op::Leaf);
  EXPECT_EQ(region->profile().loops.size(), 1u);
  return std::abs(area(region->profile()));
}

std::string error(const std::string& text, const SvgOptions& options = {}) {
  try {
    readSvg(text, "part.svg", options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

// The region's box, from its edges: arcs and curves by their extremes.
void expectBounds(const RegionPtr& region, dvec2 lo, dvec2 hi) {
  const ProfileBounds box = region->bounds();
  EXPECT_NEAR(box.lo.x, lo.x, 1e-9);
  EXPECT_NEAR(box.lo.y, lo.y, 1e-9);
  EXPECT_NEAR(box.hi.x, hi.x, 1e-9);
  EXPECT_NEAR(box.hi.y, hi.y, 1e-9);
}

TEST(XmlReader, ElementsAttributesAndLines) {
  const XmlElement root = readXml(
      "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n"
      "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \"x.dtd\" [\n"
      "  <!ENTITY ns \"http://www.w3.org/2000/svg\">\n"
      "  <!ATTLIST svg x CDATA \"a>b\">\n"
      "]>\n"
      "<!-- a comment with <tags> -->\n"
      "<svg xmlns='&ns;' a=\"&lt;&amp;&gt;&apos;&quot;\" b='&#65;&#x42;&#xe9;'>\n"
      "  <style><![CDATA[ path { fill: red } </svg> ]]></style>\n"
      "  <g\n    id=\"x\"><path d=\"M 0 0\"/></g>text\n"
      "</svg>\n",
      "part.svg");
  EXPECT_EQ(root.name, "svg");
  EXPECT_EQ(root.line, 7);
  EXPECT_EQ(root.attribute("xmlns")->value, "http://www.w3.org/2000/svg");
  EXPECT_EQ(root.attribute("a")->value, "<&>'\"");
  EXPECT_EQ(root.attribute("b")->value, "AB\xC3\xA9");
  ASSERT_EQ(root.children.size(), 2u);
  EXPECT_EQ(root.children[1].name, "g");
  EXPECT_EQ(root.children[1].line, 9);
  EXPECT_EQ(root.children[1].attribute("id")->line, 10);
  EXPECT_EQ(root.children[1].children[0].name, "path");
  EXPECT_EQ(root.children[1].children[0].line, 10);
}

TEST(XmlReader, BadDocumentsAreOneLineErrors) {
  const auto bad = [](const std::string& text) {
    try {
      readXml(text, "part.svg");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(bad(""), "part.svg: not an XML document (it has no element)");
  EXPECT_EQ(bad("<svg>\n<g>\n</svg>"),
            "part.svg:3: the end tag </svg> does not match <g> (line 2)");
  EXPECT_EQ(bad("<svg>\n<g>"),
            "part.svg:2: <g> is not closed: the file ends first (is it cut short?)");
  EXPECT_EQ(bad("<svg a=1/>"), "part.svg:1: the attribute a has no quoted value");
  EXPECT_EQ(bad("<svg a='1' a='2'/>"), "part.svg:1: the attribute a is given twice");
  EXPECT_EQ(bad("<svg a='&nbsp;'/>"), "part.svg:1: the entity &nbsp; is not declared");
  EXPECT_EQ(bad("<svg a='&#0;'/>"), "part.svg:1: &#0; is not a character");
  EXPECT_EQ(bad("<svg/>\n<svg/>"), "part.svg:2: a second root element");
  EXPECT_EQ(bad("hello <svg/>"), "part.svg:1: text outside the root element");
  EXPECT_EQ(bad("<svg>\n<!-- open"),
            "part.svg:2: a comment is not closed (is the file cut short?)");
  std::string deep;
  for (int i = 0; i < 300; ++i) deep += "<g>";
  EXPECT_EQ(bad(deep), "part.svg:1: elements nested deeper than 256");
}

TEST(SvgPath, NumbersAndFlagsInTheirCompactForms) {
  // "1.5.5" is 1.5 and .5; "3-2" is 3 and −2; exponents; a relative
  // lineto repeated; arc flags without separators.
  std::vector<SvgSubpath> paths = parseSvgPath("M1.5.5L3-2l1e1,0 0-1E-1z");
  ASSERT_EQ(paths.size(), 1u);
  const std::vector<ProfileEdge>& e = paths[0].edges;
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[0].from, dvec2(1.5, 0.5));
  EXPECT_EQ(e[0].to, dvec2(3, -2));
  EXPECT_EQ(e[1].to, dvec2(13, -2));
  EXPECT_EQ(e[2].to, dvec2(13, -2.1));
  EXPECT_EQ(e[3].to, dvec2(1.5, 0.5));
  EXPECT_TRUE(paths[0].closed);
  paths = parseSvgPath("M0 0a5 5 0 1110 0");  // large 1, sweep 1, to (10, 0)
  ASSERT_EQ(paths[0].edges.size(), 1u);
  EXPECT_EQ(paths[0].edges[0].kind, ProfileEdge::Kind::Arc);
  EXPECT_EQ(paths[0].edges[0].to, dvec2(10, 0));
  EXPECT_NEAR(std::abs(paths[0].edges[0].angle1 - paths[0].edges[0].angle0), pi, 1e-12);
  EXPECT_FALSE(paths[0].closed);
}

TEST(SvgReader, RectanglesCirclesAndEllipses) {
  // y runs down on the page and up in the plane: a rectangle 10 from the
  // page's top is 10 below the top of the 100 mm page.
  RegionPtr rect = read(page("<rect x='10' y='10' width='30' height='20'/>"));
  EXPECT_NEAR(area(evaluate(*rect, 1e-9)), 600.0, 1e-9);
  expectBounds(rect, {10, 70}, {40, 90});
  EXPECT_NEAR(areaOf(page("<circle cx='50' cy='50' r='5'/>")), 25 * pi, 1e-9);
  EXPECT_NEAR(loopArea(page("<ellipse cx='50' cy='50' rx='6' ry='3'/>")), 18 * pi, 1e-9);
  // Rounded corners: four quarter ellipses cut (4 − π)·rx·ry off.
  EXPECT_NEAR(areaOf(page("<rect width='40' height='20' rx='5'/>")), 800 - (4 - pi) * 25, 1e-9);
  EXPECT_NEAR(loopArea(page("<rect width='40' height='20' rx='5' ry='3'/>")), 800 - (4 - pi) * 15,
              1e-9);
  // Radii past half a side stop there: a 20 × 20 square with rx 50 is a disc.
  EXPECT_NEAR(areaOf(page("<rect width='20' height='20' ry='50'/>")), 100 * pi, 1e-9);
  EXPECT_NEAR(areaOf(page("<polygon points='0,0 10,0 10,10'/>")), 50.0, 1e-9);
}

TEST(SvgReader, PathsWithArcsAndBezierCurves) {
  // A 10 × 10 square with a half disc of radius 5 on its right.
  EXPECT_NEAR(areaOf(page("<path d='M0,0H10a5,5,0,0,1,0,10H0z'/>")), 100 + 12.5 * pi, 1e-9);
  // The same half disc the other way round (sweep 0) is cut out.
  EXPECT_NEAR(areaOf(page("<path d='M0 0h10a5 5 0 000 10H0Z'/>")), 100 - 12.5 * pi, 1e-9);
  // A parabola's segment is 2/3 of its control triangle (Archimedes).
  EXPECT_NEAR(loopArea(page("<path d='M0 0 Q5 10 10 0 Z'/>")), 2.0 / 3.0 * 50, 1e-9);
  // Under x = w(3t² − 2t³), y = 3ht(1 − t): ∫ y dx = 18wh∫t²(1 − t)² dt = 0.6wh.
  EXPECT_NEAR(loopArea(page("<path d='M0 0 C0 10 10 10 10 0 Z'/>")), 60.0, 1e-9);
  // S and T reflect the last control point: the same as C and Q written out.
  // The curves cross the chord from (0, 0) to (20, 0): two lobes of 60
  // (30 for quadratics), one each way round, so the loop's signed area is 0.
  EXPECT_NEAR(area(read(page("<path d='M0 0 C0 10 10 10 10 0 S20 -10 20 0 Z'/>"))->profile()), 0.0,
              1e-9);
  // Evaluated (the lobes apart) with polygons within 10⁻⁵ of the curves,
  // whose areas are within 10⁻⁵ times the length of the curves (< 60).
  const auto lobes = [](const std::string& d) {
    return area(evaluate(*read(page("<path d='" + d + "'/>")), 1e-5));
  };
  EXPECT_NEAR(lobes("M0 0 C0 10 10 10 10 0 S20 -10 20 0 Z"), 120.0, 6e-4);
  EXPECT_NEAR(lobes("M0 0 Q5 10 10 0 T20 0 Z"), 4.0 / 3.0 * 50, 6e-4);
  // An arc whose radii cannot reach its end grows to a half ellipse
  // (SVG 1.1, F.6.6): radius 1 asked, 5 drawn.
  EXPECT_NEAR(areaOf(page("<path d='M0 0 A1 1 0 0 1 10 0 Z'/>")), 12.5 * pi, 1e-9);
  // A turned ellipse (rx 6, ry 3, 90°: the long axis along y) from its two
  // halves, between the ends of its short axis.
  EXPECT_NEAR(loopArea(page("<path d='M47 50 A6 3 90 0 0 53 50 A6 3 90 0 0 47 50'/>")), 18 * pi,
              1e-9);
  expectBounds(read(page("<path d='M47 50 A6 3 90 0 0 53 50 A6 3 90 0 0 47 50'/>")), {47, 44},
               {53, 56});
}

TEST(SvgReader, FillRules) {
  // Two squares, the inner one the same way round: a hole by the even-odd
  // rule (also where the file names no rule, as OpenSCAD fills), none by
  // the non-zero rule unless the inner square runs the other way.
  const std::string same = "d='M0 0h10v10h-10z M2 2h6v6h-6z'";
  const std::string reversed = "d='M0 0h10v10h-10z M2 2v6h6v-6z'";
  EXPECT_NEAR(areaOf(page("<path " + same + "/>")), 64.0, 1e-9);
  EXPECT_NEAR(areaOf(page("<path fill-rule='evenodd' " + same + "/>")), 64.0, 1e-9);
  EXPECT_NEAR(areaOf(page("<path fill-rule='nonzero' " + same + "/>")), 100.0, 1e-9);
  EXPECT_NEAR(areaOf(page("<path style='fill:red;fill-rule:nonzero' " + reversed + "/>")), 64.0,
              1e-9);
  EXPECT_NEAR(areaOf(page("<g fill-rule='nonzero'><path " + same + "/></g>")), 100.0, 1e-9);
  // A pentagram: its middle winds twice, so the non-zero rule fills it.
  const std::string star = "points='50,0 79.39,90.45 2.45,34.55 97.55,34.55 20.61,90.45'";
  EXPECT_GT(areaOf(page("<polygon fill-rule='nonzero' " + star + "/>")),
            areaOf(page("<polygon " + star + "/>")) + 100.0);
  // Curved loops: two circles the same way round (the non-zero rule fills
  // the middle one), and a third inside them the other way round, which
  // winds back to 1: still filled.
  const std::string rings =
      "d='M0 50a50 50 0 1 0 100 0a50 50 0 1 0 -100 0z M20 50a30 30 0 1 0 60 0a30 30 0 1 0 -60 "
      "0z M40 50a10 10 0 1 1 20 0a10 10 0 1 1 -20 0z'";
  EXPECT_NEAR(areaOf(page("<path fill-rule='nonzero' " + rings + "/>")), 2500 * pi, 1e-6);
  EXPECT_NEAR(areaOf(page("<path " + rings + "/>")), (2500 - 900 + 100) * pi, 1e-6);
}

TEST(SvgReader, TransformsAndGroups) {
  // translate, scale (×4 in area), rotate: 400 wherever it lands.
  RegionPtr r =
      read(page("<g transform='translate(30 20)'><rect width='10' height='10' "
                "transform='scale(2) rotate(90 5 5)'/></g>"));
  EXPECT_NEAR(area(evaluate(*r, 1e-9)), 400.0, 1e-9);
  // rotate about (5, 5) keeps the square; scale 2 and the move put it at
  // x 30..50 and y 20..40 on the page, 60..80 in the plane.
  expectBounds(r, {30, 60}, {50, 80});
  EXPECT_NEAR(areaOf(page("<rect width='10' height='10' transform='skewX(45) skewY(-30)'/>")),
              100.0, 1e-9);
  EXPECT_NEAR(areaOf(page("<rect width='10' height='10' transform='matrix(2,0,0,3,1,1)'/>")), 600.0,
              1e-9);
  // A list is applied right to left: translate after scale.
  expectBounds(read(page("<rect width='10' height='10' transform='translate(10,0),scale(.5)'/>")),
               {10, 95}, {15, 100});
  // Shapes are united: two overlapping squares.
  EXPECT_NEAR(areaOf(page("<rect width='10' height='10'/><rect x='5' width='10' height='10'/>")),
              150.0, 1e-9);
}

TEST(SvgReader, UnitsAndThePage) {
  // A drawing 10 mm wide is 10 wide, whatever the viewBox.
  const std::string square = "<rect width='100' height='100'/>";
  const auto sized = [&](const std::string& w) {
    return "<svg width='" + w + "' height='" + w + "' viewBox='0 0 100 100'>" + square + "</svg>";
  };
  EXPECT_NEAR(areaOf(sized("10mm")), 100.0, 1e-9);
  for (const std::string inch : {"1in", "2.54cm", "72pt", "6pc", "96px", "72"})
    EXPECT_NEAR(areaOf(sized(inch)), 25.4 * 25.4, 1e-9) << inch;
  SvgOptions dpi;
  dpi.dpi = 96;
  EXPECT_NEAR(areaOf(sized("96"), dpi), 25.4 * 25.4, 1e-9);
  // No size: the viewBox at the dpi; no viewBox: a user unit is a mm.
  EXPECT_NEAR(areaOf("<svg viewBox='0 0 72 72'><rect width='72' height='72'/></svg>"), 25.4 * 25.4,
              1e-9);
  expectBounds(
      read("<svg width='50mm' height='30mm'><rect x='1' y='2' width='3' height='4'/></svg>"),
      {1, 24}, {4, 28});
  // preserveAspectRatio: a 10 × 10 viewBox on a 20 × 10 page, centred by
  // default, stretched by none, at the left by xMinYMid.
  const auto wide = [&](const std::string& ratio) {
    return read("<svg width='20mm' height='10mm' viewBox='0 0 10 10' " + ratio +
                "><rect width='10' height='10'/></svg>");
  };
  expectBounds(wide(""), {5, 0}, {15, 10});
  expectBounds(wide("preserveAspectRatio='none'"), {0, 0}, {20, 10});
  expectBounds(wide("preserveAspectRatio='xMinYMid'"), {0, 0}, {10, 10});
  // slice: scaled by 2 to fill the page, its bottom on the page's bottom.
  expectBounds(wide("preserveAspectRatio='xMaxYMax slice'"), {0, 0}, {20, 20});
  // A viewBox that starts elsewhere: its corner is the page's.
  expectBounds(read("<svg width='10mm' height='10mm' viewBox='-5 -5 10 10'><rect x='-5' y='-5' "
                    "width='2' height='2'/></svg>"),
               {0, 8}, {2, 10});
  SvgOptions center;
  center.center = true;
  expectBounds(read(page("<rect x='10' y='10' width='30' height='20'/>"), center), {-15, -10},
               {15, 10});
}

TEST(SvgReader, NestedSvgUseDefsAndHiddenShapes) {
  RegionPtr r = read(
      page("<defs><rect id='r' width='10' height='10'/></defs>"
           "<use href='#r' x='20' y='0'/><use xlink:href='#r' transform='translate(40 0)'/>"
           "<svg x='60' y='0' width='20' height='20' viewBox='0 0 10 10'><rect width='10' "
           "height='10'/></svg>"
           "<rect width='5' height='5' display='none'/><rect width='5' height='5' "
           "style='visibility:hidden'/><g style='display:none'><rect width='5' height='5'/></g>"));
  EXPECT_NEAR(area(evaluate(*r, 1e-9)), 100 + 100 + 400, 1e-9);
  expectBounds(r, {20, 80}, {80, 100});
  SvgOptions one;
  one.id = "part";
  EXPECT_NEAR(areaOf(page("<rect width='10' height='10'/><g id='part'><circle r='1'/></g>"), one),
              pi, 1e-9);
}

// Lines, polylines and open paths are the outlines of their strokes, as
// OpenSCAD makes them: stroke-width (1 unless given), square ends unless
// stroke-linecap says, mitred corners unless stroke-linejoin says.
TEST(SvgReader, StrokesOfOpenOutlines) {
  // A line 10 long: 11 × 1 with its square ends, 10 × 2 with butt ends,
  // and two half discs more with round ones.
  EXPECT_NEAR(areaOf(page("<line x1='0' y1='0' x2='10' y2='0'/>")), 11.0, 1e-9);
  EXPECT_NEAR(areaOf(page("<line x2='10' stroke-width='2' stroke-linecap='butt'/>")), 20.0, 1e-9);
  EXPECT_NEAR(areaOf(page("<line x2='10' style='stroke-width:2;stroke-linecap:round'/>")),
              20.0 + pi, 1e-9);
  // A right angle, 2 wide, butt ends: two 10 × 2 bands overlapping by 1,
  // and the corner's mitre, a unit square; a bevel cuts the square's
  // corner at 1 from the vertex, a right triangle of height √2 − 1; a
  // round join is a quarter disc.
  const std::string corner = "points='0 0 10 0 10 10' stroke-width='2' stroke-linecap='butt'";
  EXPECT_NEAR(areaOf(page("<polyline " + corner + "/>")), 40.0, 1e-9);
  EXPECT_NEAR(areaOf(page("<polyline " + corner + " stroke-linejoin='bevel'/>")),
              40.0 - (std::sqrt(2.0) - 1) * (std::sqrt(2.0) - 1), 1e-9);
  EXPECT_NEAR(areaOf(page("<polyline " + corner + " stroke-linejoin='round'/>")), 39.0 + pi / 4,
              1e-9);
  // An open path is the same stroke; a polyline around a square is its
  // stroke too (not filled): the 12 × 12 band less the 8 × 8 inside, less
  // the corner its butt ends leave open.
  EXPECT_NEAR(areaOf(page("<path d='M0 0 h10 v10' stroke-width='2' stroke-linecap='butt'/>")), 40.0,
              1e-9);
  EXPECT_NEAR(areaOf(page("<polyline points='0 0 10 0 10 10 0 10 0 0' stroke-width='2' "
                          "stroke-linecap='butt'/>")),
              144.0 - 64.0 - 1.0, 1e-9);
  // A corner sharper than 60° is cut square rather than mitred (Clipper's
  // mitre limit): the stroke of a 30° corner is the same either way.
  const std::string sharp = "points='0 0 10 0 1.339746 5' stroke-width='2' stroke-linecap='butt'";
  EXPECT_NEAR(areaOf(page("<polyline " + sharp + "/>")),
              areaOf(page("<polyline " + sharp + " stroke-linejoin='bevel'/>")), 1e-9);
  // Ends within 0.1 of each other close the path, as OpenSCAD closes it.
  EXPECT_NEAR(areaOf(page("<path d='M0 0 h10 v10 h-10 v-9.95'/>")), 100.0, 1e-9);
}

TEST(SvgReader, BadDrawingsAreOneLineErrors) {
  EXPECT_EQ(error("<html/>"),
            "part.svg:1: not an SVG drawing (its root element is <html>, not <svg>)");
  EXPECT_EQ(error(page("<path\n d='M0 0 L10 x'/>")),
            "part.svg:3: <path> d: after 'L10 ': expected a number, found 'x'");
  EXPECT_EQ(error(page("<path d='L0 0'/>")),
            "part.svg:2: <path> d: path data must start with a moveto (M or m)");
  EXPECT_EQ(error(page("<path d='M0 0 K1 1'/>")),
            "part.svg:2: <path> d: after 'M0 0 ': 'K' is not a path command");
  EXPECT_EQ(error(page("<path d='M0 0 A1 1 0 2 0 1 1'/>")),
            "part.svg:2: <path> d: after 'A1 1 0 ': an arc flag must be 0 or 1");
  EXPECT_EQ(error("<svg width='1em' height='1mm'/>"),
            "part.svg:1: width: lengths in em depend on a font; give them in mm, cm, in, pt, pc or "
            "px");
  EXPECT_EQ(error("<svg width='1e400mm'/>"), "part.svg:1: width: the number 1e400 is out of range");
  EXPECT_EQ(error(page("<rect width='1e20' height='1'/>")),
            "part.svg:2: width: the number 1e20 is out of range");
  EXPECT_EQ(error("<svg width='10furlongs'/>"),
            "part.svg:1: width: \"furlongs\" is not a unit of length");
  // What the file says is quoted on one line, and cut short.
  EXPECT_EQ(error("<svg width='1mm\n   CAD and more words than a message should hold'/>"),
            "part.svg:1: width: \"mm CAD and more words than ...\" is not a unit of length");
  EXPECT_EQ(error(page("<rect width='10' height='10' transform='turn(3)'/>")),
            "part.svg:2: transform: \"turn\" is not a transform");
  // A NUL byte (or another control byte) quoted as '?': it would end the
  // message there, or reach the terminal.
  constexpr char kControlBytes[] = "<rect width='10' height='10' transform='tu\0rn\x1b(3)'/>";
  EXPECT_EQ(error(page(std::string(kControlBytes, sizeof kControlBytes - 1))),
            "part.svg:2: transform: expected matrix(...), translate(...), scale(...), rotate(...), "
            "skewX(...) or skewY(...), found \"tu?rn?(3)\"");
  EXPECT_EQ(error(page("<rect width='10' height='10' transform='rotate(1 2)'/>")),
            "part.svg:2: transform: rotate takes 1 or 3 numbers, not 2");
  EXPECT_EQ(error(page("<line x2='10' stroke-width='2mm'/>")),
            "part.svg:2: stroke-width: expected a number (user units), found \"2mm\"");
  EXPECT_EQ(error(page("<use href='#nothing'/>")),
            "part.svg:2: <use> of \"#nothing\", which no element has as its id");
  EXPECT_EQ(error(page("<g id='a'><use href='#a'/><rect width='1' height='1'/></g>")),
            "part.svg:2: <use> nested deeper than 32 (an element that uses itself?)");
  EXPECT_EQ(error(page("")), "part.svg: the drawing fills no closed outline");
  SvgOptions missing;
  missing.id = "x";
  EXPECT_EQ(error(page("<rect width='1' height='1'/>"), missing),
            "part.svg: no element has the id \"x\"");
  SvgOptions dpi;
  dpi.dpi = 0;
  EXPECT_EQ(error(page(""), dpi), "dpi must be a number >= 0.001");
}

TEST(SvgReader, CutShortOrGarbledFilesNeverCrash) {
  // The example's drawing cut at many places and with bytes changed: each
  // is read or refused with one line naming the file.
  std::ifstream in(CSGRAY_SOURCE_DIR "/examples/drawings/badge.svg");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string whole = buffer.str();
  ASSERT_GT(whole.size(), 1000u);
  EXPECT_GT(areaOf(whole), 0.0);
  std::vector<std::string> variants;
  for (std::size_t cut = 0; cut < whole.size(); cut += 37) variants.push_back(whole.substr(0, cut));
  for (std::size_t at = 1; at < whole.size(); at += 23) {
    std::string garbled = whole;
    garbled[at] = "<x7&\"-.>/;#"[at % 11];
    variants.push_back(garbled);
  }
  for (const std::string& text : variants) {
    try {
      readSvg(text, "part.svg", {});
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("part.svg", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace csgray::detail
