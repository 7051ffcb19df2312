// Text as a region (profile/glyph_outlines.h) and text{} in the script:
// glyph areas from the font's own units, exact Bézier areas against fine
// polygons, kerning, alignment, extruded letters' volumes, and the
// one-line errors of bad input. The numbers of DejaVu Sans (2.37, Debian's
// fonts-dejavu-core) are read from its glyphs: 2048 units to the em, an
// ascent of 1901; "I" is the rectangle 201..403 × 0..1493, "H" is 1493
// tall, advance 1540.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "primitives/linear_extrusion.h"
#include "primitives/sweep_checks.h"
#include "profile/glyph_outlines.h"
#include "profile/region_evaluation.h"
#include "scene/region_surface.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kAscent = 1901.0;

RegionPtr textOf(const std::string& s, double size = 10.0,
                 TextLayout::HAlign h = TextLayout::HAlign::Left,
                 TextLayout::VAlign v = TextLayout::VAlign::Baseline) {
  TextLayout layout;
  layout.text = s;
  layout.size = size;
  layout.halign = h;
  layout.valign = v;
  return textRegion(layout);
}

// The signed area of one leaf's loops (glyphs whose contours do not cross).
double leafArea(const RegionPtr& r) {
  EXPECT_EQ(r->op(), Region::Op::Leaf);
  return std::abs(area(r->profile()));
}

double shoelace(const std::vector<dvec2>& p) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const dvec2& a = p[i];
    const dvec2& b = p[(i + 1) % p.size()];
    sum += a.x * b.y - a.y * b.x;
  }
  return 0.5 * sum;
}

TEST(Text, TheLetterIIsTheFontsRectangle) {
  const double size = 20.0, k = size / kAscent;
  const RegionPtr i = textOf("I", size);
  EXPECT_NEAR(leafArea(i), 202 * 1493 * k * k, 1e-9);
  EXPECT_NEAR(i->bounds().lo.x, 201 * k, 1e-12);
  EXPECT_NEAR(i->bounds().hi.x, 403 * k, 1e-12);
  EXPECT_NEAR(i->bounds().lo.y, 0.0, 1e-12);
  EXPECT_NEAR(i->bounds().hi.y, 1493 * k, 1e-12);
}

// "O": two loops of quadratic curves; Green's theorem on the curves against
// the shoelace of polygons a millionth of the size close to them.
TEST(Text, CurvedLettersAreasAreExact) {
  for (const char* letter : {"O", "e", "S", "g"}) {
    SCOPED_TRACE(letter);
    const RegionPtr r = textOf(letter);
    const double exact = leafArea(r);
    double polygons = 0.0;
    for (const std::vector<dvec2>& loop : flatten(r->profile(), 1e-7)) polygons += shoelace(loop);
    EXPECT_GT(exact, 5.0);
    // Inscribed polygons lose at most the tolerance times the perimeter.
    EXPECT_NEAR(std::abs(polygons), exact, 1e-7 * 200.0);
    EXPECT_NE(std::abs(polygons), exact);
  }
}

// Advances: "H" with halign="right" ends where the pen stops.
double advance(const std::string& s) {
  return textOf(s)->bounds().lo.x - textOf(s, 10.0, TextLayout::HAlign::Right)->bounds().lo.x;
}

TEST(Text, KerningPullsAVTogether) {
  const double k = 10.0 / kAscent;
  EXPECT_NEAR(advance("H"), 1540 * k, 1e-9);
  // Without kerning "V" would start one advance of "A" along.
  const double apart = advance("A") + textOf("V")->bounds().hi.x;
  const double together = textOf("AV")->bounds().hi.x;
  EXPECT_LT(together, apart - 0.1);
  EXPECT_LT(advance("AV"), advance("A") + advance("V") - 0.1);
  // Spacing multiplies the advances.
  TextLayout wide;
  wide.text = "II";
  wide.spacing = 2.0;
  const double step = textRegion(wide)->bounds().hi.x - textOf("II")->bounds().hi.x;
  EXPECT_NEAR(step, 604 * k, 1e-9);
}

TEST(Text, AlignmentMovesTheBounds) {
  using H = TextLayout::HAlign;
  using V = TextLayout::VAlign;
  const double k = 10.0 / kAscent;
  const ProfileBounds left = textOf("H")->bounds();
  EXPECT_NEAR(left.lo.x, 201 * k, 1e-12);  // the pen starts at x = 0
  EXPECT_NEAR(textOf("H", 10, H::Center)->bounds().lo.x, (201 - 770) * k, 1e-9);
  EXPECT_NEAR(textOf("H", 10, H::Right)->bounds().lo.x, (201 - 1540) * k, 1e-9);
  EXPECT_NEAR(left.lo.y, 0.0, 1e-12);  // on the baseline
  EXPECT_NEAR(left.hi.y, 1493 * k, 1e-12);
  EXPECT_NEAR(textOf("g", 10, H::Left, V::Bottom)->bounds().lo.y, 0.0, 1e-12);
  EXPECT_NEAR(textOf("H", 10, H::Left, V::Top)->bounds().hi.y, 0.0, 1e-12);
  const ProfileBounds centred = textOf("Hg", 10, H::Left, V::Center)->bounds();
  EXPECT_NEAR(centred.lo.y + centred.hi.y, 0.0, 1e-12);
  EXPECT_LT(centred.lo.y, -1.0);
}

TEST(Text, DirectionsLayTheLettersOut) {
  TextLayout down;
  down.text = "II";
  down.direction = TextLayout::Direction::TopToBottom;
  const ProfileBounds b = textRegion(down)->bounds();
  // One above the other: taller than two letters, as wide as one.
  EXPECT_GT(b.hi.y - b.lo.y, 2 * 1493 * 10.0 / kAscent);
  EXPECT_NEAR(b.hi.x - b.lo.x, 202 * 10.0 / kAscent, 1e-9);
  TextLayout rtl;
  rtl.text = "AV";
  rtl.direction = TextLayout::Direction::RightToLeft;
  // Right to left: "V" first from the left, then "A" (the visual order).
  EXPECT_NEAR(textRegion(rtl)->bounds().hi.x, advance("VA") - (1401 - 1384) * 10.0 / kAscent, 1e-9);
}

TEST(Text, ExtrudedLettersVolumeIsAreaTimesHeight) {
  const RegionPtr o = textOf("O", 10.0);
  auto solid = Primitive::create<LinearExtrusion>(o, 2.0, false, 0.0, dvec2(1.0));
  test::expectVolume(solid, leafArea(o) * 2.0);
  test::expectValidMesh(*solid, 0.01, leafArea(o) * 2.0);
  test::expectSpansAgreeWithContainsOnRandomLines(*solid, 1000, 3);
}

// A font whose letters overlap (kerned "AV" in an oblique face): the
// glyphs are united, not cancelled by the even-odd rule.
TEST(Text, OverlappingGlyphsAreUnited) {
  TextLayout layout;
  layout.text = "AV";
  layout.font = "DejaVu Sans:style=Bold Oblique";
  const RegionPtr r = textRegion(layout);
  const double together = area(evaluate(*r, 1e-6));
  layout.text = "A";
  const double a = area(evaluate(*textRegion(layout), 1e-6));
  layout.text = "V";
  const double v = area(evaluate(*textRegion(layout), 1e-6));
  EXPECT_GT(together, 0.0);
  EXPECT_LE(together, a + v + 1e-6);
  EXPECT_GT(together, 0.9 * (a + v));
}

std::string errorOf(const TextLayout& layout) {
  try {
    textRegion(layout);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Text, BadInputIsRefused) {
  TextLayout layout;
  layout.text = "";
  EXPECT_EQ(errorOf(layout), "text: the string is empty");
  layout.text = "x";
  layout.size = 0.0;
  EXPECT_EQ(errorOf(layout), "text: size must be a positive number (got 0)");
  layout.size = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(errorOf(layout), "text: size must be a positive number (got nan)");
  layout.size = 10.0;
  layout.font = "No Such Font";
  EXPECT_EQ(errorOf(layout),
            "text: font \"No Such Font\" not found (fc-list lists the installed fonts)");
  // A family the configuration only offers as a last resort is not the
  // name's: "Helvetica" is not DejaVu Sans (nor Liberation Sans, which
  // fontconfig offers for it among the metric-compatible fonts it lacks).
  layout.font = "Helvetica";
  EXPECT_NE(errorOf(layout).find("font \"Helvetica\" not found"), std::string::npos);
  layout.font = "DejaVu Sans:style=Wobbly";
  EXPECT_EQ(errorOf(layout), "text: font \"DejaVu Sans\" has no style \"Wobbly\"");
  layout.font = ":file=/etc/passwd";
  EXPECT_NE(errorOf(layout).find("not given as files"), std::string::npos);
  layout.font = "DejaVu Sans";
  layout.text = "   ";
  EXPECT_EQ(errorOf(layout), "text: \"   \" has no outline (only spaces)");
}

// A name the font's own configuration binds to it (fonts-dejavu-core's
// 57-dejavu-sans.conf: "Bitstream Vera Sans", the font DejaVu grew from)
// is that font.
TEST(Text, AFontsConfiguredAliasIsTheFont) {
  TextLayout layout;
  layout.text = "Vera";
  layout.font = "Bitstream Vera Sans";
  const double alias = area(evaluate(*textRegion(layout), 1e-3));
  layout.font = "DejaVu Sans";
  EXPECT_EQ(alias, area(evaluate(*textRegion(layout), 1e-3)));
}

std::string scriptError(const std::string& source) { return test::scriptError(source); }

TEST(TextScript, TextIsARegion) {
  Scene scene = runScript("return text{\"csgray\", size=5, halign=\"center\", valign=\"center\"}",
                          "part.lua", {});
  ASSERT_EQ(scene.surfaces.size(), 1u);
  const RegionPtr r = regionInPlane(*scene.surfaces[0]);
  ASSERT_TRUE(r);
  const ProfileBounds b = r->bounds();
  EXPECT_NEAR(b.lo.y + b.hi.y, 0.0, 1e-9);
  EXPECT_GT(b.hi.x - b.lo.x, 15.0);
  EXPECT_NO_THROW(runScript("return linear_extrude(text(\"A\"), {height=1})", "part.lua", {}));
}

TEST(TextScript, BadInputIsOneLine) {
  EXPECT_EQ(scriptError("return text{\"\"}"), "part.lua:1: text: the string is empty");
  EXPECT_EQ(scriptError("return text{string.rep('x', 10001)}"),
            "part.lua:1: text: the string is longer than 10000 bytes");
  EXPECT_EQ(scriptError("return text{\"a\", size=-1}"),
            "part.lua:1: text: size must be a positive number (got -1)");
  EXPECT_EQ(scriptError("\nreturn text{\"a\", font=\"Nope\"}"),
            "part.lua:2: text: font \"Nope\" not found (fc-list lists the installed fonts)");
  EXPECT_EQ(scriptError("return text{\"a\", halign=\"middle\"}"),
            "part.lua:1: text: halign must be one of \"left\", \"center\", \"right\" (got "
            "\"middle\")");
  EXPECT_EQ(scriptError("return text(3)"), "part.lua:1: text: needs a string, got number");
}

}  // namespace
}  // namespace csgray::detail
