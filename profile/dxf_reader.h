// A region from a DXF drawing (AutoCAD's Drawing Interchange Format, ASCII):
// OpenSCAD's import() of a .dxf file, and import_dxf{} in scripts
// (docs/script.md, "DXF drawings"). The entities LINE, LWPOLYLINE and
// POLYLINE (with bulges: arcs), ARC, CIRCLE, ELLIPSE, SPLINE (which
// OpenSCAD does not read) and INSERT (blocks, nested) are joined end to
// end into closed outlines, filled by the even-odd rule as OpenSCAD fills
// them. Arcs, circles and ellipses stay exact arcs unless `fragments` asks
// for OpenSCAD's polygons; splines stay exact Bézier curves. Annotations
// (DIMENSION, TEXT, MTEXT, POINT, HATCH, ...) are left out.
//
// The format: Autodesk, "DXF Reference" (AutoCAD 2012), group codes and the
// ENTITIES and BLOCKS sections.
#pragma once

#include <functional>
#include <string>

#include "profile/region.h"

namespace csgray::detail {

struct DxfOptions {
  std::string layer;  // the one layer read; empty: all
  // Each point p of the drawing becomes (p − origin) · scale, as in
  // OpenSCAD's import(origin=, scale=).
  dvec2 origin{0.0};
  double scale = 1.0;
  // The sides of a whole circle of radius r (in the scaled units) when arcs
  // are to be polygons as OpenSCAD makes them (an arc of angle a gets
  // ceil(sides · a / 360°)); 0 or no function keeps arcs exact.
  std::function<int(double r)> fragments;
};

// The region the drawing's text draws; fileName is used in messages.
// Throws std::invalid_argument "file:line: what" for text that is not DXF,
// a value that is not a number, a truncated section, an unknown block, an
// entity that draws shapes csgray cannot read (3DFACE, a rational SPLINE,
// ...), and a layer that draws nothing.
RegionPtr readDxf(const std::string& text, const std::string& fileName, const DxfOptions& options);

}  // namespace csgray::detail
