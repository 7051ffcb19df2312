#include "profile/glyph_outlines.h"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>

#include "profile/shapes.h"
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include <hb-ot.h>
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "profile/bezier.h"
#include "profile/region_evaluation.h"

namespace csgray::detail {

namespace {

[[noreturn]] void fail(const std::string& message) {
  throw std::invalid_argument("text: " + message);
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// fontconfig's generic names, which stand for whatever font it prefers.
bool genericFamily(const std::string& family) {
  for (const char* g : {"sans-serif", "sans", "serif", "monospace", "mono"})
    if (FcStrCmpIgnoreCase(reinterpret_cast<const FcChar8*>(g),
                           reinterpret_cast<const FcChar8*>(family.c_str())) == 0)
      return true;
  return false;
}

// Does some value of the pattern's property equal `wanted` (case aside)?
bool hasValue(FcPattern* pattern, const char* property, const FcChar8* wanted) {
  FcChar8* value = nullptr;
  for (int i = 0; FcPatternGetString(pattern, property, i, &value) == FcResultMatch; ++i)
    if (FcStrCmpIgnoreCase(value, wanted) == 0) return true;
  return false;
}

// Is the match's family one the name stands for: the name's own, or one
// the configuration binds to it strongly, as a font's own configuration
// does (DejaVu Sans for "Bitstream Vera Sans", Liberation Sans for
// "Arial")? The families fontconfig adds as a last resort are bound weakly.
bool boundFamily(FcPattern* substituted, FcPattern* match) {
  FcValue value;
  FcValueBinding binding;
  for (int i = 0;
       FcPatternGetWithBinding(substituted, FC_FAMILY, i, &value, &binding) == FcResultMatch; ++i)
    if (binding != FcValueBindingWeak && value.type == FcTypeString &&
        hasValue(match, FC_FAMILY, value.u.s))
      return true;
  return false;
}

struct PatternDeleter {
  void operator()(FcPattern* p) const { FcPatternDestroy(p); }
};
using Pattern = std::unique_ptr<FcPattern, PatternDeleter>;

struct FontFile {
  std::string path;
  int index = 0;
};

// fontconfig always answers with some font; a name it does not have must
// be an error, not another font: the answer's family (and style, when one
// was asked for) must be the name's.
FontFile findFont(const std::string& name) {
  static std::mutex mutex;  // fontconfig's current configuration is shared
  const std::lock_guard<std::mutex> lock(mutex);
  if (!FcInit()) fail("fontconfig could not be started");
  Pattern pattern(FcNameParse(reinterpret_cast<const FcChar8*>(name.c_str())));
  if (!pattern) fail("cannot read the font name " + quoted(name));
  FcChar8* value = nullptr;
  if (FcPatternGetString(pattern.get(), FC_FILE, 0, &value) == FcResultMatch)
    fail("fonts are named (\"DejaVu Sans:style=Bold\"), not given as files");
  FcChar8* family = nullptr;
  if (FcPatternGetString(pattern.get(), FC_FAMILY, 0, &family) != FcResultMatch)
    fail("the font name " + quoted(name) + " names no family (\"DejaVu Sans:style=Bold\")");
  const std::string wantedFamily(reinterpret_cast<const char*>(family));
  FcChar8* style = nullptr;
  const bool styled = FcPatternGetString(pattern.get(), FC_STYLE, 0, &style) == FcResultMatch;
  const std::string wantedStyle = styled ? reinterpret_cast<const char*>(style) : "";
  FcConfigSubstitute(nullptr, pattern.get(), FcMatchPattern);
  FcDefaultSubstitute(pattern.get());
  FcResult result = FcResultNoMatch;
  Pattern match(FcFontMatch(nullptr, pattern.get(), &result));
  if (!match) fail("no font found for " + quoted(name));
  if (!genericFamily(wantedFamily) && !boundFamily(pattern.get(), match.get()))
    fail("font " + quoted(wantedFamily) + " not found (fc-list lists the installed fonts)");
  if (styled &&
      !hasValue(match.get(), FC_STYLE, reinterpret_cast<const FcChar8*>(wantedStyle.c_str())))
    fail("font " + quoted(wantedFamily) + " has no style " + quoted(wantedStyle));
  FontFile found;
  if (FcPatternGetString(match.get(), FC_FILE, 0, &value) != FcResultMatch)
    fail("no font file found for " + quoted(name));
  found.path = reinterpret_cast<const char*>(value);
  FcPatternGetInteger(match.get(), FC_INDEX, 0, &found.index);
  return found;
}

// One glyph's contours as FreeType decomposes them, in font units moved to
// the glyph's place.
struct OutlineBuilder {
  dvec2 origin{0.0};
  std::vector<ProfileLoop> contours;
  dvec2 pen{0.0};

  double units = 1.0;  // font units per unit of FreeType's coordinates
  dvec2 point(const FT_Vector* v) const {
    return origin + units * dvec2(double(v->x), double(v->y));
  }
  int curveSegments = 0;  // TextLayout::curveSegments

  void add(const ProfileEdge& e) {
    if (contours.empty()) contours.emplace_back();
    contours.back().edges.push_back(e);
    pen = e.to;
  }
  void addCurve(const ProfileEdge& e) {
    if (curveSegments == 0) return add(e);
    for (int k = 1; k <= curveSegments; ++k)
      add(ProfileEdge::segment(
          pen, k == curveSegments ? e.to : bezierPoint(e, double(k) / curveSegments)));
  }

  static OutlineBuilder& of(void* user) { return *static_cast<OutlineBuilder*>(user); }
  static int moveTo(const FT_Vector* to, void* user) {
    OutlineBuilder& b = of(user);
    b.contours.emplace_back();
    b.pen = b.point(to);
    return 0;
  }
  static int lineTo(const FT_Vector* to, void* user) {
    OutlineBuilder& b = of(user);
    const dvec2 p = b.point(to);
    if (p != b.pen) b.add(ProfileEdge::segment(b.pen, p));  // FreeType closes with one
    return 0;
  }
  static int conicTo(const FT_Vector* control, const FT_Vector* to, void* user) {
    OutlineBuilder& b = of(user);
    b.addCurve(ProfileEdge::quadratic(b.pen, b.point(control), b.point(to)));
    return 0;
  }
  static int cubicTo(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    OutlineBuilder& b = of(user);
    b.addCurve(ProfileEdge::cubic(b.pen, b.point(c1), b.point(c2), b.point(to)));
    return 0;
  }
};

double loopArea(const ProfileLoop& loop) {
  Profile one;
  one.loops.push_back(loop);
  return area(one);
}

// An outer contour with the holes inside it.
struct Piece {
  Profile profile;
  ProfileBounds box;
};

// Contours filled by the non-zero rule, as fonts are, into even-odd
// leaves: the outer contours turn the way the largest one does, each hole
// (turning the other way) goes with the smallest outer contour that holds
// it, and outer contours whose boxes overlap go into different leaves.
std::vector<Profile> leavesOf(std::vector<ProfileLoop> contours) {
  std::vector<double> areas;
  double largest = 0.0;
  for (const ProfileLoop& c : contours) {
    areas.push_back(loopArea(c));
    if (std::abs(areas.back()) > std::abs(largest)) largest = areas.back();
  }
  std::vector<Piece> pieces;
  std::vector<double> pieceAreas;
  for (std::size_t i = 0; i < contours.size(); ++i) {
    if (areas[i] * largest <= 0.0) continue;
    Piece& p = pieces.emplace_back();
    p.profile.loops.push_back(contours[i]);
    p.box = p.profile.bounds();
    pieceAreas.push_back(std::abs(areas[i]));
  }
  for (std::size_t i = 0; i < contours.size(); ++i) {
    if (areas[i] * largest > 0.0 || areas[i] == 0.0 || contours[i].edges.empty()) continue;
    std::size_t best = 0;
    double bestArea = 1e300;
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (pieceAreas[k] < bestArea && pieces[k].profile.contains(contours[i].edges[0].from))
        best = k, bestArea = pieceAreas[k];
    pieces[best].profile.loops.push_back(contours[i]);
  }
  std::vector<Profile> leaves;
  std::vector<std::vector<ProfileBounds>> boxes;
  const auto overlap = [](const ProfileBounds& a, const ProfileBounds& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
  };
  for (Piece& p : pieces) {
    std::size_t k = 0;
    for (; k < leaves.size(); ++k)
      if (std::none_of(boxes[k].begin(), boxes[k].end(),
                       [&](const ProfileBounds& b) { return overlap(b, p.box); }))
        break;
    if (k == leaves.size()) leaves.emplace_back(), boxes.emplace_back();
    for (ProfileLoop& loop : p.profile.loops) leaves[k].loops.push_back(std::move(loop));
    boxes[k].push_back(p.box);
  }
  return leaves;
}

hb_direction_t hbDirection(TextLayout::Direction d) {
  switch (d) {
    case TextLayout::Direction::LeftToRight:
      return HB_DIRECTION_LTR;
    case TextLayout::Direction::RightToLeft:
      return HB_DIRECTION_RTL;
    case TextLayout::Direction::TopToBottom:
      return HB_DIRECTION_TTB;
    case TextLayout::Direction::BottomToTop:
      return HB_DIRECTION_BTT;
  }
  return HB_DIRECTION_LTR;
}

// The move that puts x = 0 at the left, the middle or the right of
// [left, right].
double alignedOffset(TextLayout::HAlign halign, double left, double right) {
  switch (halign) {
    case TextLayout::HAlign::Left:
      return -left;
    case TextLayout::HAlign::Center:
      return -0.5 * (left + right);
    case TextLayout::HAlign::Right:
      return -right;
  }
  return 0.0;
}

// The move that puts y = 0 at the baseline (where it is), or at the
// bottom, the middle or the top of [bottom, top].
double alignedOffset(TextLayout::VAlign valign, double bottom, double top) {
  switch (valign) {
    case TextLayout::VAlign::Baseline:
      return 0.0;
    case TextLayout::VAlign::Bottom:
      return -bottom;
    case TextLayout::VAlign::Center:
      return -0.5 * (bottom + top);
    case TextLayout::VAlign::Top:
      return -top;
  }
  return 0.0;
}

// OpenSCAD 2021.01's FreetypeRenderer (src/FreetypeRenderer.cc) asks
// FreeType for a character size of 10^5/64 points at 100 dpi and divides
// the outlines' 26.6 coordinates by 10^5 before multiplying them by size:
// an em is size·100/72 long. It divides HarfBuzz's positions, and the
// glyph boxes it aligns by, by 1.024·10^5 instead, so letters stand
// 1/1.024 as far apart as the font says and the alignment is short by as
// much.
constexpr double kOpenScadCharSize = 1e5;  // 26.6 points, at 100 dpi
constexpr double kOpenScadEmPerSize = 100.0 / 72.0;
constexpr double kOpenScadAdvanceFactor = 1.0 / 1.024;
constexpr double kOpenScadPixelsPerEm = kOpenScadCharSize / 64.0 * 100.0 / 72.0;

// What OpenSCAD aligns text by: for horizontal text the advance (width)
// and the highest top and lowest bottom of the glyphs' control boxes,
// the baseline included (ascend, descend); for vertical text the widest
// box and the advance. Its boxes are FreeType's grid-fitted control boxes
// (all the outline's points, rounded out to whole pixels at its size).
struct OpenScadBoxes {
  double ascend = 0.0, descend = 0.0, widest = 0.0;  // font units

  // units: font units per unit of the outline's coordinates.
  void add(FT_Outline& outline, int unitsPerEm, double units) {
    FT_BBox box;
    FT_Outline_Get_CBox(&outline, &box);
    const double pixel = unitsPerEm / kOpenScadPixelsPerEm;
    auto down = [&](FT_Pos v) {
      return std::floor(v * units / pixel) * pixel * kOpenScadAdvanceFactor;
    };
    auto up = [&](FT_Pos v) {
      return std::ceil(v * units / pixel) * pixel * kOpenScadAdvanceFactor;
    };
    ascend = std::max(ascend, up(box.yMax));
    descend = std::max(descend, -down(box.yMin));
    widest = std::max(widest, up(box.xMax) - down(box.xMin));
  }

  // The move that puts the text where OpenSCAD's halign and valign do;
  // pen: where the next glyph would go.
  dvec2 shift(const TextLayout& layout, bool horizontal, const dvec2& pen) const {
    if (horizontal)
      return {alignedOffset(layout.halign, 0.0, pen.x),
              alignedOffset(layout.valign, -descend, ascend)};
    return {alignedOffset(layout.halign, 0.0, widest), alignedOffset(layout.valign, 0.0, pen.y)};
  }
};

}  // namespace

std::string fontFile(const std::string& name) { return findFont(name).path; }

RegionPtr textRegion(const TextLayout& layout) {
  if (layout.text.empty()) {
    if (layout.blankMakesNothing) return nullptr;
    fail("the string is empty");
  }
  // The script's text() and a .csg file's alike.
  if (layout.text.size() > kMaxTextBytes)
    fail("the string is longer than " + std::to_string(kMaxTextBytes) + " bytes");
  if (!std::isfinite(layout.size) || !(layout.size > 0.0)) {
    std::ostringstream msg;
    msg << "size must be a positive number (got " << layout.size << ")";
    fail(msg.str());
  }
  // (A line of letters reaches far past its size: a hundredth of the
  // coordinates' limit leaves room for about a hundred of them.)
  if (layout.size > kLargestCoordinate / 100.0) {
    std::ostringstream msg;
    msg << "size is too large (at most 1e148; got " << layout.size << ")";
    fail(msg.str());
  }
  if (!std::isfinite(layout.spacing) || !(layout.spacing > 0.0)) {
    std::ostringstream msg;
    msg << "spacing must be a positive number (got " << layout.spacing << ")";
    fail(msg.str());
  }
  const FontFile font = findFont(layout.font);
  const bool openscad = layout.metrics == TextLayout::Metrics::OpenScad;

  FT_Library library = nullptr;
  if (FT_Init_FreeType(&library)) fail("FreeType could not be started");
  const std::unique_ptr<FT_LibraryRec_, FT_Error (*)(FT_Library)> libraryOwner(library,
                                                                               FT_Done_FreeType);
  FT_Face face = nullptr;
  if (FT_New_Face(library, font.path.c_str(), font.index, &face))
    fail("cannot read the font " + quoted(layout.font));
  const std::unique_ptr<FT_FaceRec_, FT_Error (*)(FT_Face)> faceOwner(face, FT_Done_Face);
  if (!FT_IS_SCALABLE(face)) fail("the font " + quoted(layout.font) + " has no outlines");
  const int unitsPerEm = face->units_per_EM;
  const double ascent = face->ascender > 0 ? double(face->ascender) : double(unitsPerEm);

  // Shaping, in font units.
  hb_blob_t* blob = hb_blob_create_from_file(font.path.c_str());
  hb_face_t* hbFace = hb_face_create(blob, unsigned(font.index));
  hb_font_t* hbFont = hb_font_create(hbFace);
  hb_font_set_scale(hbFont, unitsPerEm, unitsPerEm);
  hb_buffer_t* buffer = hb_buffer_create();
  hb_buffer_add_utf8(buffer, layout.text.data(), int(layout.text.size()), 0,
                     int(layout.text.size()));
  hb_buffer_set_direction(buffer, hbDirection(layout.direction));
  if (!layout.language.empty())
    hb_buffer_set_language(buffer, hb_language_from_string(layout.language.c_str(), -1));
  if (!layout.script.empty())
    hb_buffer_set_script(buffer, hb_script_from_string(layout.script.c_str(), -1));
  hb_buffer_guess_segment_properties(buffer);
  hb_shape(hbFont, buffer, nullptr, 0);
  unsigned count = 0;
  const hb_glyph_info_t* infos = hb_buffer_get_glyph_infos(buffer, &count);
  const hb_glyph_position_t* positions = hb_buffer_get_glyph_positions(buffer, &count);
  struct Placed {
    unsigned glyph;
    dvec2 origin;
  };
  std::vector<Placed> placed;
  const double advanceFactor = openscad ? kOpenScadAdvanceFactor : 1.0;
  dvec2 pen(0.0);
  for (unsigned i = 0; i < count; ++i) {
    const hb_glyph_position_t& p = positions[i];
    placed.push_back({infos[i].codepoint, pen + advanceFactor * dvec2(p.x_offset, p.y_offset)});
    pen += advanceFactor * layout.spacing * dvec2(p.x_advance, p.y_advance);
  }
  hb_buffer_destroy(buffer);
  hb_font_destroy(hbFont);
  hb_face_destroy(hbFace);
  hb_blob_destroy(blob);

  OutlineBuilder builder;
  builder.curveSegments = std::max(layout.curveSegments, 0);
  FT_Outline_Funcs funcs{};
  funcs.move_to = OutlineBuilder::moveTo;
  funcs.line_to = OutlineBuilder::lineTo;
  funcs.conic_to = OutlineBuilder::conicTo;
  funcs.cubic_to = OutlineBuilder::cubicTo;
  OpenScadBoxes boxes;
  FT_Int32 load = FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP;
  if (openscad) {
    // OpenSCAD's glyphs are FreeType's at its size, hinted: at 2170
    // pixels to the em the font's instructions move points by fractions
    // of a pixel, which is still 3.5·10⁻⁴ of the area of an "O" in
    // Liberation Sans. Their coordinates are then 26.6 pixels.
    if (FT_Set_Char_Size(face, 0, FT_F26Dot6(kOpenScadCharSize), 100, 100))
      fail("cannot size the font " + quoted(layout.font));
    load = FT_LOAD_DEFAULT;
    builder.units = unitsPerEm / (64.0 * kOpenScadPixelsPerEm);
  }
  for (const Placed& g : placed) {
    if (FT_Load_Glyph(face, g.glyph, load))
      fail("cannot read a glyph of the font " + quoted(layout.font));
    if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
      fail("the font " + quoted(layout.font) + " has no outlines");
    builder.origin = g.origin;
    FT_Outline_Decompose(&face->glyph->outline, &funcs, &builder);
    if (openscad) boxes.add(face->glyph->outline, unitsPerEm, builder.units);
  }
  std::vector<ProfileLoop> contours;
  for (ProfileLoop& c : builder.contours) {
    if (c.edges.empty()) continue;
    // Close exactly: FreeType's closing segment is skipped when it has no
    // length, and each edge starts where the previous one ends.
    if (c.edges.back().to != c.edges.front().from)
      c.edges.push_back(ProfileEdge::segment(c.edges.back().to, c.edges.front().from));
    contours.push_back(std::move(c));
  }
  if (contours.empty()) {
    if (layout.blankMakesNothing) return nullptr;
    // Spaces have no outline; letters without one come from a damaged font.
    const bool blank = std::all_of(layout.text.begin(), layout.text.end(), [](char c) {
      return c == ' ' || c == '\t' || c == '\n' || c == '\r';
    });
    fail(quoted(layout.text) + (blank ? " has no outline (only spaces)"
                                      : " has no outline in the font " + quoted(layout.font) +
                                            ": its glyphs are empty (is the font file damaged?)"));
  }

  // From font units to the size, then aligned.
  const double scale =
      openscad ? layout.size * kOpenScadEmPerSize / unitsPerEm : layout.size / ascent;
  const bool horizontal = layout.direction == TextLayout::Direction::LeftToRight ||
                          layout.direction == TextLayout::Direction::RightToLeft;
  dvec2 shift(0.0);
  if (openscad) {
    shift = boxes.shift(layout, horizontal, pen);
  } else {
    Profile all;
    for (const ProfileLoop& c : contours) all.loops.push_back(c);
    const ProfileBounds ink = all.bounds();
    // Horizontal text is aligned along its line by the pen's advance (where
    // the next letter would go), as a typesetter does; the rest by the ink.
    const double left = horizontal ? std::min(0.0, pen.x) : ink.lo.x;
    const double right = horizontal ? std::max(0.0, pen.x) : ink.hi.x;
    shift = {alignedOffset(layout.halign, left, right),
             alignedOffset(layout.valign, ink.lo.y, ink.hi.y)};
  }
  const Affine2 place{dmat2(scale), scale * shift};
  std::vector<RegionPtr> leaves;
  for (const Profile& leaf : leavesOf(std::move(contours)))
    leaves.push_back(Region::leaf(leaf.transformed(place)));
  if (leaves.size() == 1) return leaves.front();
  return Region::boolean(Region::Op::Union, std::move(leaves));
}

}  // namespace csgray::detail
