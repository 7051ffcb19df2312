// SVG's path data (the d attribute of <path>) as exact edges: straight
// segments, quadratic and cubic Bézier curves and arcs of ellipses, in the
// path's own coordinates (y pointing down, as SVG draws). Every command is
// read: M m L l H h V v C c S s Q q T t A a Z z, with implicit repeats, the
// compact forms of numbers ("1.5.5" is 1.5 and .5, "1-2" is 1 and −2,
// "1e-3") and arc flags written without separators ("a1 1 0 011 1").
//
// The grammar: W3C, "Scalable Vector Graphics (SVG) 1.1", 2nd ed., 2011,
// section 8.3 (https://www.w3.org/TR/SVG11/paths.html); arcs from their
// end points to their centres by its appendix F.6.5, radii too small for
// the ends scaled up by F.6.6.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "profile/profile.h"

namespace csgray::detail {

struct SvgSubpath {
  std::vector<ProfileEdge> edges;  // each edge's `to` the next one's `from`
  bool closed = false;             // ended by Z (the edge back to its start included)
};

// The subpaths the data draws; a subpath of no edges (a lone moveto) is
// left out. Throws std::invalid_argument with a message that says what is
// wrong and where in the data ("after 'L 10 20': expected a number, found
// 'x'"): a command letter that SVG does not have, data that does not start
// with a moveto, a number missing, an arc flag other than 0 or 1, a number
// that is not finite.
std::vector<SvgSubpath> parseSvgPath(std::string_view data);

// The arc from `from` to `to` on the ellipse of radii rx, ry whose x axis
// is turned by `rotationDegrees`, large or small, clockwise (sweep) or
// counterclockwise in SVG's frame; a segment for a radius of 0, nothing
// (an empty vector) when the ends are one point.
std::vector<ProfileEdge> svgArc(const dvec2& from, double rx, double ry, double rotationDegrees,
                                bool large, bool sweep, const dvec2& to);

// Where the number that starts at `at` ends by SVG's grammar, sign?
// (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?, which
// stops where the grammar does ("1.5.5" ends after "1.5"); `at` itself when
// no number starts there.
std::size_t svgNumberEnd(std::string_view text, std::size_t at);
// The value of a number so scanned; nullopt past ±10¹⁵ or not finite.
std::optional<double> svgNumber(std::string_view text);
// A piece of the file's text as messages quote it: on one line (its white
// space made single spaces, other control bytes shown as "?"), at most 30
// characters (then "...").
std::string svgExcerpt(std::string_view text);

// A list of numbers separated by white space and commas (the points of
// <polygon>, a viewBox, a transform's arguments). Throws
// std::invalid_argument for anything else in it.
std::vector<double> parseSvgNumbers(std::string_view text);

}  // namespace csgray::detail
