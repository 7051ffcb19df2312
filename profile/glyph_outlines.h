// Text as a region: a string shaped by HarfBuzz (kerning, ligatures, the
// order and joining of scripts) in a font fontconfig finds by name, each
// glyph's outline read by FreeType as it is drawn in the font: segments and
// quadratic (TrueType) or cubic (OpenType CFF) Bézier curves, kept exact
// (docs/script.md, "Text"). The only place FreeType, HarfBuzz and
// fontconfig are used.
#pragma once

#include <string>

#include "profile/region.h"

namespace csgray::detail {

// Longer strings are refused: each letter costs a shaping and its curves.
inline constexpr std::size_t kMaxTextBytes = 10000;

struct TextLayout {
  enum class HAlign { Left, Center, Right };
  enum class VAlign { Baseline, Bottom, Center, Top };
  enum class Direction { LeftToRight, RightToLeft, TopToBottom, BottomToTop };

  std::string text;  // UTF-8
  // The font's ascent (the height above the baseline it declares for its
  // tallest letters), in the region's units.
  double size = 10.0;
  std::string font = "DejaVu Sans";  // a fontconfig name: "family:style=Bold"
  HAlign halign = HAlign::Left;
  VAlign valign = VAlign::Baseline;
  double spacing = 1.0;  // a factor on the advances from glyph to glyph
  Direction direction = Direction::LeftToRight;
  std::string language, script;  // BCP 47 and ISO 15924 tags; empty: guessed from the text

  // How size and alignment are read: csgray's text{} (size is the font's
  // ascent; vertical alignment by the ink), or OpenSCAD 2021.01's text()
  // as its .csg files mean it (an em of size/0.72, the glyphs hinted at
  // OpenSCAD's size, its advances and alignment: glyph_outlines.cpp).
  enum class Metrics { Ascent, OpenScad };
  Metrics metrics = Metrics::Ascent;
  // 0: the font's curves, exact; n > 0: each curve drawn as n chords at
  // equal steps of its parameter, as OpenSCAD draws text.
  int curveSegments = 0;
  // A string with no outline (empty, or only spaces): an error, or no
  // region at all (nullptr), as OpenSCAD's text() makes nothing.
  bool blankMakesNothing = false;
};

// The text's outlines: one even-odd leaf per group of glyph contours that
// do not overlap (each outer contour with the holes inside it), united, so
// that overlapping strokes fill as the font's non-zero rule says.
// Throws std::invalid_argument, with a message that starts "text: ", for an
// empty string, one longer than kMaxTextBytes, a size that is not a positive
// finite number, a spacing that
// is not finite or not positive, a font fontconfig does not have (it would
// fall back to another silently), a font name that names a file, or a
// string with no outline (only spaces) unless blankMakesNothing.
RegionPtr textRegion(const TextLayout& layout);

// The file of the font fontconfig gives for the name, or the error above.
std::string fontFile(const std::string& name);

}  // namespace csgray::detail
