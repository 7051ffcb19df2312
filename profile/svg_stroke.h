// The outline of a stroke along a polyline, as OpenSCAD 2021.01 makes it
// of an SVG drawing's open paths, lines and polylines (its libsvg offsets
// them with Clipper's ClipperOffset, open ends): a band of the stroke's
// width along each segment, the corners joined and the ends capped, with
// arcs exact where Clipper draws polygons. The band's pieces are united.
//
// Clipper: A. Johnson, "Clipper - an open source freeware library for
// clipping and offsetting lines and polygons", ClipperOffset (JoinType,
// EndType, MiterLimit); the SVG names: SVG 1.1, 11.4 (stroke-linecap,
// stroke-linejoin).
#pragma once

#include <vector>

#include "profile/region.h"

namespace csgray::detail {

struct StrokeStyle {
  double width = 1.0;
  // butt: the band ends at the end; square: it goes on half the width
  // (OpenSCAD's default); round: a half disc.
  enum class Cap { Butt, Square, Round } cap = Cap::Square;
  // miter: the band's sides meet, unless they would meet farther than
  // twice the half width from the corner (Clipper's mitre limit 2: corners
  // sharper than 60°), where the corner is cut square as for bevel;
  // bevel: cut square across the corner's bisector at half the width from
  // it (Clipper's jtSquare, which OpenSCAD makes of SVG's bevel); round: a
  // disc.
  enum class Join { Miter, Bevel, Round } join = Join::Miter;
};

// The stroke's region along the points (repeated points are one); nullptr
// for fewer than two distinct points.
RegionPtr strokeRegion(const std::vector<dvec2>& points, const StrokeStyle& style);

}  // namespace csgray::detail
