// A region from an SVG drawing: OpenSCAD's import() of a .svg file, and
// import_svg{} in scripts (docs/script.md, "SVG drawings";
// docs/openscad.md for how it compares with OpenSCAD's). The shapes
// <path>, <rect> (with rounded corners), <circle>, <ellipse> and
// <polygon>, in <g>, nested <svg> and <use> of what <defs> holds, under
// their transforms, each filled by its fill-rule (even-odd where none is
// given, as OpenSCAD fills) and united; <line>, <polyline> and open paths
// as the outlines of their strokes, as OpenSCAD makes them (svg_stroke.h).
// Curves stay exact: segments, quadratic and cubic Bézier curves and arcs
// of ellipses.
//
// Units follow OpenSCAD: the page's width and height in mm, cm, in, pt, pc,
// px (96 to the inch) or none (the dpi given, 72 unless told); the viewBox
// maps onto the page by preserveAspectRatio; without a viewBox a user unit
// is a millimetre. SVG's y axis points down: the page is mirrored so that
// its bottom left corner is the origin.
//
// The format: W3C, "Scalable Vector Graphics (SVG) 1.1", 2nd ed., 2011
// (https://www.w3.org/TR/SVG11/): 7 (coordinate systems, transforms,
// viewBox, preserveAspectRatio), 8 (paths), 9 (basic shapes), 5.6 (use),
// 11.3 (fill-rule).
#pragma once

#include <string>
#include <string_view>

#include "profile/region.h"

namespace csgray::detail {

struct SvgOptions {
  // Dots per inch of lengths without a unit (OpenSCAD's dpi= of import()).
  double dpi = 72.0;
  // Centre the drawing's bounds on the origin (OpenSCAD's center=).
  bool center = false;
  // Only the element with this id and what it holds; empty: the whole drawing.
  std::string id;
  // Curves as the polygons OpenSCAD 2021.01 draws of them (svg_reader.cpp)
  // rather than exact.
  bool openscadPolygons = false;
};

// The region the drawing fills; fileName is used in messages. Throws
// std::invalid_argument "file:line: what" for text that is not XML, a
// root that is not <svg>, path data that cannot be read, a length in a
// unit csgray does not know (em, ex), a transform it cannot read, a
// stroke-width that is not a number, an id no element has, and a drawing
// that fills nothing.
RegionPtr readSvg(std::string_view text, const std::string& fileName, const SvgOptions& options);

}  // namespace csgray::detail
