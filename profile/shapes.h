// The shapes of the plane as users give them (the script's square{},
// circle{}, polygon{}, ...; docs/script.md, "2D regions"), each a region
// with one profile, with the checks and messages of the script ("circle:
// the radius must be > 0"). Loops run counterclockwise. Circles and
// ellipses are whole arcs, not polygons.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "profile/region.h"

namespace csgray::detail {

// Coordinates past this would overflow in the squares of the evaluation
// and the sweeps; no part is that large. Shapes, maps, offsets and text
// are refused past it.
inline constexpr double kLargestCoordinate = 1e150;

// A width × height rectangle from the origin, or centred on it with
// center; kind names it in messages ("square", "rectangle").
RegionPtr rectangleRegion(const char* kind, double width, double height, bool center);
// The disc of radius r or diameter d (one of them) about the origin.
RegionPtr circleRegion(std::optional<double> r, std::optional<double> d);
// The ellipse with half-axes rx along x and ry along y about the origin.
RegionPtr ellipseRegion(double rx, double ry);
// A polygon, filled by the even-odd rule as OpenSCAD's polygon(points,
// paths) is. paths (indices into points, from 0) make one loop each;
// without paths all points make one loop. A point repeated right after
// itself, and a last point equal to the first, are dropped. Refused: fewer
// than 3 distinct points in a loop, a coordinate that is not finite, an
// index out of range, and a loop whose points are collinear (it encloses
// no area).
RegionPtr polygonRegion(const std::vector<dvec2>& points,
                        const std::vector<std::vector<std::size_t>>& paths);
// The regular n-gon about the origin with a corner at (r, 0): r is the
// radius of its corners (circumradius). A nut's size is given across its
// flats f instead, twice the inradius: r = f / (2 cos(π/n)).
RegionPtr regularPolygonRegion(double n, std::optional<double> r, std::optional<double> flats);

}  // namespace csgray::detail
