// 2D regions: the shapes of the plane that sweeps turn into solids
// (Solid::linearExtrude, Solid::rotateExtrude), as a part script's 2D
// regions are (docs/script.md, "2D regions"). Circles and circular arcs
// stay exact, and so do booleans, offsets and areas of them; an ellipse's
// arcs (and a circle scaled unevenly) are evaluated as polygons within a
// ten-millionth of the region's size. Coordinates are limited to 1e150. A Region is an immutable
// value, cheap to copy, as a Solid is. Invalid parameters throw csgray::Error with code
// InvalidArgument and the message the script function of the same name
// gives.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "csgray/types.h"

namespace csgray {

namespace detail {
class Region;
struct Access;
}  // namespace detail

class Solid;

// The box of a region: its low and high corners; empty (lo > hi) for a
// region without points (a shape offset inward past its middle).
struct Bounds2 {
  Vec2 lo, hi;

  bool empty() const { return lo.x > hi.x || lo.y > hi.y; }
};

// What Region::text() writes and how (OpenSCAD's text() parameters).
struct TextOptions {
  double size = 10.0;                // the font's ascent, in model units
  std::string font = "DejaVu Sans";  // a fontconfig name: "Liberation Serif:style=Bold"
  enum class HAlign { Left, Center, Right } halign = HAlign::Left;
  enum class VAlign { Baseline, Bottom, Center, Top } valign = VAlign::Baseline;
  double spacing = 1.0;  // a factor on the advances from letter to letter
  enum class Direction {
    LeftToRight,
    RightToLeft,
    TopToBottom,
    BottomToTop
  } direction = Direction::LeftToRight;
  std::string language, script;  // BCP 47 and ISO 15924 tags; empty: guessed from the text
};

class CSGRAY_API Region {
 public:
  // ---- Shapes ------------------------------------------------------------------
  // A w × h rectangle with a corner at the origin, or centred on it.
  static Region rectangle(const Vec2& size, bool center = false);
  static Region square(double size, bool center = false);
  static Region circle(double r);
  // Half-axes rx along x and ry along y, about the origin.
  static Region ellipse(double rx, double ry);
  // Filled by the even-odd rule, as OpenSCAD's polygon(points, paths): each
  // path lists indices into points (from 0) and makes one loop; without
  // paths all points make one loop.
  static Region polygon(const std::vector<Vec2>& points,
                        const std::vector<std::vector<std::size_t>>& paths = {});
  // n corners about the origin, one at (r, 0): r is the corners' radius.
  static Region regularPolygon(int n, double r);
  // The same given across its flats (a nut's size): r = flats / (2 cos(π/n)).
  static Region regularPolygonAcrossFlats(int n, double flats);
  // The text's letters with the font's curves, baseline on the x axis.
  static Region text(const std::string& text, const TextOptions& options = {});
  // The region a DXF or SVG drawing fills (by the extension), read as a
  // script's import_dxf{file=} and import_svg{file=} read it with their
  // defaults: every layer, 72 dpi.
  static Region fromDrawingFile(const std::string& path);
  // A solid's section by the plane z = 0 (cut), or its shadow on that plane,
  // as OpenSCAD's projection(): taken from its meshes, within a
  // ten-thousandth of its size (at most 0.001) of the exact one (a shadow
  // of a difference or an intersection, meshed by the export's booleans
  // first, within ten times that). Error InvalidArgument for an unbounded
  // solid, NotPrintable when its booleans cannot be meshed.
  static Region projection(const Solid& solid, bool cut = false);

  // ---- Booleans, hulls, offsets -----------------------------------------------
  static Region unionOf(const std::vector<Region>& regions);
  static Region intersectionOf(const std::vector<Region>& regions);
  static Region differenceOf(const std::vector<Region>& regions);  // the first minus the rest
  Region operator+(const Region& other) const;                     // union
  Region operator-(const Region& other) const;                     // difference
  Region operator*(const Region& other) const;                     // intersection
  static Region hull(const std::vector<Region>& regions);
  // Pair by pair from the first: a region and a circle, two convex
  // regions one of them a polygon, or any region and a convex one.
  static Region minkowski(const std::vector<Region>& regions);
  // Every point within r of the region, corners rounded (r < 0: shrunk,
  // its inner corners rounded), as OpenSCAD's offset(r).
  Region offset(double r) const;
  // Moved out by delta, corners kept sharp or cut off (chamfer), as
  // OpenSCAD's offset(delta, chamfer).
  Region offsetDelta(double delta, bool chamfer = false) const;

  // ---- Transforms --------------------------------------------------------------
  Region translate(const Vec2& offset) const;
  Region rotate(double degrees) const;  // counterclockwise about the origin
  Region scale(const Vec2& factors) const;
  Region scale(double factor) const;
  // Reflection in the line through the origin with this normal.
  Region mirror(const Vec2& normal) const;
  // OpenSCAD's resize(): scaled about the origin so that the region's own
  // box gets these sizes; a size of 0 keeps its axis, or with autoAxes set
  // for it scales it by the largest factor of the axes given.
  Region resize(const Vec2& size, const std::array<bool, 2>& autoAxes = {}) const;

  // ---- Questions ---------------------------------------------------------------
  double area() const;
  // A box about the region (of a boolean, the box of its operands' boxes).
  Bounds2 bounds() const;
  // Is the point in the region? A point on its outline may go either way.
  bool contains(const Vec2& point) const;

 private:
  explicit Region(std::shared_ptr<const detail::Region> impl);
  detail::Shared<detail::Region> impl_;
  friend struct detail::Access;
};

// Writes the region's outline as SVG or DXF (by the extension), as `csgray
// export part.svg` writes a script's regions: circular arcs as arcs, an
// ellipse's arcs as lines within tolerance. Atomic, as writeImage. DXF
// keeps the coordinates; an SVG's page is the outline's box, so a drawing
// read back from it (fromDrawingFile, OpenSCAD's import) has that box's
// lower left corner at the origin.
CSGRAY_API void writeOutline(const Region& region, const std::string& path,
                             double tolerance = 0.01);

}  // namespace csgray
