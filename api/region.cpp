// csgray::Region: the script's 2D regions (profile/shapes.h,
// region_operations.h) with the same checks and messages, their sweeps
// (Solid::linearExtrude, rotateExtrude) and their outlines.
#include "csgray/region.h"

#include <cctype>
#include <filesystem>
#include <functional>
#include <stdexcept>

#include "api/access.h"
#include "api/errors.h"
#include "csgray/solid.h"
#include "export/solid_projection.h"
#include "io/input_file.h"
#include "meshio/outline_writer.h"
#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"
#include "profile/dxf_reader.h"
#include "profile/glyph_outlines.h"
#include "profile/region_evaluation.h"
#include "profile/region_operations.h"
#include "profile/shapes.h"
#include "profile/svg_reader.h"
#include "scene/resize.h"
#include "scene/value_checks.h"

namespace csgray {

using detail::Access;
using detail::guarded;

namespace {

// Drawings larger than this are refused, as a script's are.
constexpr std::size_t kMaxDrawingBytes = std::size_t{64} << 20;

Region wrap(detail::RegionPtr p) { return Access::region(std::move(p)); }

detail::dvec2 toDetail(const Vec2& v) { return {v.x, v.y}; }
Vec2 toPublic(const detail::dvec2& v) { return {v.x, v.y}; }

std::vector<detail::RegionPtr> internals(const std::vector<Region>& regions) {
  std::vector<detail::RegionPtr> out;
  out.reserve(regions.size());
  for (const Region& r : regions) out.push_back(Access::of(r));
  return out;
}

Region booleanOf(detail::Region::Op op, const std::vector<Region>& regions) {
  return guarded([&] { return wrap(detail::Region::boolean(op, internals(regions))); });
}

Region mapped(const Region& region, const char* function,
              const std::function<detail::Affine2()>& map) {
  return guarded([&] { return wrap(detail::mappedRegion(*Access::of(region), map(), function)); });
}

}  // namespace

Region::Region(std::shared_ptr<const detail::Region> impl) : impl_(std::move(impl)) {}

Region Region::rectangle(const Vec2& size, bool center) {
  return guarded(
      [&] { return wrap(detail::rectangleRegion("rectangle", size.x, size.y, center)); });
}

Region Region::square(double size, bool center) {
  return guarded([&] { return wrap(detail::rectangleRegion("square", size, size, center)); });
}

Region Region::circle(double r) {
  return guarded([&] { return wrap(detail::circleRegion(r, std::nullopt)); });
}

Region Region::ellipse(double rx, double ry) {
  return guarded([&] { return wrap(detail::ellipseRegion(rx, ry)); });
}

Region Region::polygon(const std::vector<Vec2>& points,
                       const std::vector<std::vector<std::size_t>>& paths) {
  return guarded([&] {
    std::vector<detail::dvec2> corners;
    corners.reserve(points.size());
    for (const Vec2& p : points) corners.push_back(toDetail(p));
    return wrap(detail::polygonRegion(corners, paths));
  });
}

Region Region::regularPolygon(int n, double r) {
  return guarded([&] { return wrap(detail::regularPolygonRegion(n, r, std::nullopt)); });
}

Region Region::regularPolygonAcrossFlats(int n, double flats) {
  return guarded([&] { return wrap(detail::regularPolygonRegion(n, std::nullopt, flats)); });
}

// TextOptions' choices name TextLayout's in the same order.
static_assert(int(TextOptions::HAlign::Right) == int(detail::TextLayout::HAlign::Right));
static_assert(int(TextOptions::VAlign::Top) == int(detail::TextLayout::VAlign::Top));
static_assert(int(TextOptions::Direction::BottomToTop) ==
              int(detail::TextLayout::Direction::BottomToTop));

Region Region::text(const std::string& text, const TextOptions& options) {
  return guarded([&] {
    detail::TextLayout layout;
    layout.text = text;
    layout.size = options.size;
    layout.font = options.font;
    layout.halign = detail::TextLayout::HAlign(int(options.halign));
    layout.valign = detail::TextLayout::VAlign(int(options.valign));
    layout.spacing = options.spacing;
    layout.direction = detail::TextLayout::Direction(int(options.direction));
    layout.language = options.language;
    layout.script = options.script;
    return wrap(detail::textRegion(layout));
  });
}

Region Region::fromDrawingFile(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".dxf" && extension != ".svg")
    throw Error(ErrorCode::InvalidArgument, name + ": unknown drawing format; use .dxf or .svg");
  std::string text;
  try {
    text = detail::readInputFile(path, name, kMaxDrawingBytes);
  } catch (const std::exception& e) {
    throw Error(ErrorCode::IoError, e.what());
  }
  // A drawing that is not its format: IoError, as a mesh file's.
  return guarded(ErrorCode::IoError, [&] {
    try {
      return wrap(extension == ".dxf" ? detail::readDxf(text, name, detail::DxfOptions{})
                                      : detail::readSvg(text, name, detail::SvgOptions{}));
    } catch (const std::invalid_argument& e) {
      throw Error(ErrorCode::IoError, e.what());
    }
  });
}

Region Region::projection(const Solid& solid, bool cut) {
  // An unbounded solid is a bad argument; booleans that cannot be meshed
  // (a std::runtime_error) make no printable part, as in exportMesh.
  return guarded(ErrorCode::NotPrintable, [&] {
    return wrap(detail::Region::leaf(detail::solidProjection(Access::of(solid), cut)));
  });
}

Region Region::unionOf(const std::vector<Region>& regions) {
  return booleanOf(detail::Region::Op::Union, regions);
}

Region Region::intersectionOf(const std::vector<Region>& regions) {
  return booleanOf(detail::Region::Op::Intersection, regions);
}

Region Region::differenceOf(const std::vector<Region>& regions) {
  return booleanOf(detail::Region::Op::Difference, regions);
}

Region Region::operator+(const Region& other) const { return unionOf({*this, other}); }
Region Region::operator-(const Region& other) const { return differenceOf({*this, other}); }
Region Region::operator*(const Region& other) const { return intersectionOf({*this, other}); }

Region Region::hull(const std::vector<Region>& regions) {
  return guarded([&] { return wrap(detail::hullOfRegions(internals(regions))); });
}

Region Region::minkowski(const std::vector<Region>& regions) {
  return guarded([&] { return wrap(detail::minkowskiOfRegions(internals(regions))); });
}

Region Region::offset(double r) const {
  return guarded([&] { return wrap(detail::offsetRegion(*impl_, r, std::nullopt, std::nullopt)); });
}

Region Region::offsetDelta(double delta, bool chamfer) const {
  return guarded([&] { return wrap(detail::offsetRegion(*impl_, std::nullopt, delta, chamfer)); });
}

Region Region::translate(const Vec2& offset) const {
  return mapped(*this, "translate", [&] {
    detail::checkFinite("translate", "x", offset.x);
    detail::checkFinite("translate", "y", offset.y);
    detail::Affine2 map;
    map.offset = toDetail(offset);
    return map;
  });
}

Region Region::rotate(double degrees) const {
  return mapped(*this, "rotate", [&] { return detail::turnMap(degrees); });
}

Region Region::scale(const Vec2& factors) const {
  return mapped(*this, "scale", [&] {
    detail::checkFinite("scale", "x", factors.x);
    detail::checkFinite("scale", "y", factors.y);
    return detail::scaleMap(toDetail(factors), "scale");
  });
}

Region Region::scale(double factor) const { return scale(Vec2{factor, factor}); }

Region Region::mirror(const Vec2& normal) const {
  return mapped(*this, "mirror", [&] { return detail::mirrorMap(toDetail(normal), "mirror"); });
}

Region Region::resize(const Vec2& size, const std::array<bool, 2>& autoAxes) const {
  return mapped(*this, "resize",
                [&] { return detail::regionResizeMap(*impl_, toDetail(size), autoAxes); });
}

double Region::area() const {
  return guarded([&] { return detail::regionArea(*impl_); });
}

Bounds2 Region::bounds() const {
  const detail::ProfileBounds& b = impl_->bounds();
  return {toPublic(b.lo), toPublic(b.hi)};
}

bool Region::contains(const Vec2& point) const { return impl_->contains(toDetail(point)); }

void writeOutline(const Region& region, const std::string& path, double tolerance) {
  if (!(tolerance >= 1e-6 && tolerance <= 1e3))
    throw Error(ErrorCode::InvalidArgument,
                "writeOutline: tolerance must be a number from 1e-6 to 1000 (model units)");
  if (!detail::outlineFormatFor(path))
    throw Error(ErrorCode::InvalidArgument, path + ": unknown outline format; use .svg or .dxf");
  const detail::Profile outline =
      guarded([&] { return detail::evaluate(*Access::of(region), tolerance); });
  if (outline.loops.empty())
    throw Error(ErrorCode::InvalidArgument, "writeOutline: the region is empty");
  guarded(ErrorCode::IoError, [&] { detail::writeOutlineFile(path, outline, tolerance); });
}

Solid Solid::linearExtrude(const Region& region, double height, const ExtrudeOptions& options) {
  return guarded([&] {
    return Access::solid(detail::Primitive::create<detail::LinearExtrusion>(
        Access::of(region), height, options.center, options.twist, toDetail(options.scale)));
  });
}

Solid Solid::rotateExtrude(const Region& region, double angle) {
  return guarded([&] { return Access::solid(detail::revolutionSolid(Access::of(region), angle)); });
}

}  // namespace csgray
