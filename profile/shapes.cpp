#include "profile/shapes.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/degrees.h"

namespace csgray::detail {

namespace {

std::string shown(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// A length the user gave: finite and > 0.
void requirePositive(const std::string& function, const char* what, double v) {
  if (!std::isfinite(v))
    throw std::invalid_argument(function + ": " + what + " must be finite (got " + shown(v) + ")");
  if (!(v > 0.0))
    throw std::invalid_argument(function + ": " + what + " must be > 0 (got " + shown(v) + ")");
  if (v > kLargestCoordinate)
    throw std::invalid_argument(function + ": " + what + " is too large (got " + shown(v) + ")");
}

double cross(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }

RegionPtr wholeEllipse(double rx, double ry) {
  Profile p;
  p.loops.push_back(
      {{ProfileEdge::arc(dvec2(0.0), dmat2(rx, 0.0, 0.0, ry), 0.0, 2.0 * std::numbers::pi)}});
  return Region::leaf(std::move(p));
}

// The loop through the points in order, closed from the last to the first.
ProfileLoop loopThrough(const std::vector<dvec2>& corners) {
  ProfileLoop loop;
  loop.edges.reserve(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i)
    loop.edges.push_back(ProfileEdge::segment(corners[i], corners[(i + 1) % corners.size()]));
  return loop;
}

// Are the points (at least 3) on one line? Each must lie within a
// relative 1e-12 of the line from the first to the point farthest from it
// (the measure Affine::fromMatrix and the surfaces use for "parallel").
bool collinear(const std::vector<dvec2>& corners) {
  const dvec2 origin = corners.front();
  dvec2 far = origin;
  double farthest = 0.0;
  for (const dvec2& p : corners) {
    const dvec2 d = p - origin;
    if (const double l = d.x * d.x + d.y * d.y; l > farthest) {
      farthest = l;
      far = p;
    }
  }
  if (!(farthest > 0.0)) return true;
  const dvec2 axis = far - origin;
  for (const dvec2& p : corners)
    if (std::abs(cross(axis, p - origin)) > 1e-12 * farthest) return false;
  return true;
}

}  // namespace

RegionPtr rectangleRegion(const char* kind, double width, double height, bool center) {
  const std::string function(kind);
  const std::string given = " (got " + shown(width) + ", " + shown(height) + ")";
  if (!std::isfinite(width) || !std::isfinite(height))
    throw std::invalid_argument(function + ": size must be finite" + given);
  if (!(width > 0.0) || !(height > 0.0))
    throw std::invalid_argument(function + ": size must be > 0" + given);
  if (width > kLargestCoordinate || height > kLargestCoordinate)
    throw std::invalid_argument(function + ": size is too large" + given);
  const dvec2 lo = center ? dvec2(-width / 2, -height / 2) : dvec2(0.0);
  const dvec2 hi = lo + dvec2(width, height);
  Profile p;
  p.loops.push_back(loopThrough({lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}));
  return Region::leaf(std::move(p));
}

RegionPtr circleRegion(std::optional<double> r, std::optional<double> d) {
  if (r && d) throw std::invalid_argument("circle: give r or d, not both");
  if (!r && !d) throw std::invalid_argument("circle: needs r (radius) or d (diameter)");
  if (r) {
    requirePositive("circle", "the radius", *r);
    return wholeEllipse(*r, *r);
  }
  requirePositive("circle", "the diameter", *d);
  return wholeEllipse(*d / 2, *d / 2);
}

RegionPtr ellipseRegion(double rx, double ry) {
  requirePositive("ellipse", "rx", rx);
  requirePositive("ellipse", "ry", ry);
  return wholeEllipse(rx, ry);
}

RegionPtr polygonRegion(const std::vector<dvec2>& points,
                        const std::vector<std::vector<std::size_t>>& paths) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const dvec2& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > kLargestCoordinate ||
        std::abs(p.y) > kLargestCoordinate)
      throw std::invalid_argument("polygon: points[" + std::to_string(i + 1) +
                                  "] must be finite and at most 1e150 (got " + shown(p.x) + ", " +
                                  shown(p.y) + ")");
  }
  std::vector<std::vector<std::size_t>> loops = paths;
  if (loops.empty()) {
    loops.emplace_back(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) loops.back()[i] = i;
  }
  Profile profile;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    // "polygon: paths[2]" or, without paths, "polygon".
    const std::string what =
        paths.empty() ? std::string("polygon") : "polygon: paths[" + std::to_string(l + 1) + "]";
    std::vector<dvec2> corners;
    corners.reserve(loops[l].size());
    for (std::size_t index : loops[l]) {
      if (index >= points.size())
        throw std::invalid_argument(what + ": index " + std::to_string(index) +
                                    " is not a point (there are " + std::to_string(points.size()) +
                                    ", from 0)");
      if (corners.empty() || corners.back() != points[index]) corners.push_back(points[index]);
    }
    while (corners.size() > 1 && corners.back() == corners.front()) corners.pop_back();
    if (corners.size() < 3)
      throw std::invalid_argument(what + ": needs at least 3 distinct points (got " +
                                  std::to_string(corners.size()) + ")");
    if (collinear(corners))
      throw std::invalid_argument(what + ": the points are collinear, so they enclose no area");
    profile.loops.push_back(loopThrough(corners));
  }
  return Region::leaf(std::move(profile));
}

RegionPtr regularPolygonRegion(double n, std::optional<double> r, std::optional<double> flats) {
  if (!(n >= 3.0) || n != std::floor(n) || n > 1e6)
    throw std::invalid_argument(
        "regular_polygon: n must be a whole number from 3 to 1000000 (got " + shown(n) + ")");
  if (r && flats) throw std::invalid_argument("regular_polygon: give r or flats, not both");
  if (!r && !flats)
    throw std::invalid_argument(
        "regular_polygon: needs r (the radius of the corners) or flats (the width across flats)");
  const std::size_t count = static_cast<std::size_t>(n);
  double radius;
  if (r) {
    requirePositive("regular_polygon", "r", *r);
    radius = *r;
  } else {
    requirePositive("regular_polygon", "flats", *flats);
    // The inradius is r·cos(π/n) (the apothem of a regular polygon).
    radius = *flats / (2.0 * std::cos(std::numbers::pi / n));
  }
  std::vector<dvec2> corners(count);
  for (std::size_t i = 0; i < count; ++i) {
    corners[i] = radius * unitCircleDegrees(360.0 * static_cast<double>(i) / n);
  }
  Profile p;
  p.loops.push_back(loopThrough(corners));
  return Region::leaf(std::move(p));
}

}  // namespace csgray::detail
