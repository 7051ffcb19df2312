// The outline of a 2D region out, for laser cutters and drawing programs:
// SVG (one path of lines and arc commands, filled by the even-odd rule)
// or DXF R12 text (LINE, ARC and CIRCLE entities; AutoCAD's DXF reference
// describes the group codes). Both keep circular arcs as arcs, with
// coordinates printed to 17 significant digits, so that doubles read back
// unchanged. Every write is atomic (io/atomic_file.h).
#pragma once

#include <optional>
#include <string>

#include "profile/profile.h"

namespace csgray::detail {

enum class OutlineFormat { Svg, Dxf };

// The outline format a file name asks for by its extension (.svg, .dxf,
// any case), or nullopt for any other.
std::optional<OutlineFormat> outlineFormatFor(const std::string& path);

// The file's text for an evaluated profile (region_evaluation.h: loops that
// do not cross). SVG's y axis points down: the outline is mirrored into it,
// so that it shows as the region does in the plane, in millimetres, one
// model unit a millimetre. An arc of an ellipse that is not a circle is an
// elliptic arc in SVG, and in DXF R12, which has no ellipses, lines within
// `tolerance` of it.
std::string svgOutline(const Profile& evaluated);
std::string dxfOutline(const Profile& evaluated, double tolerance);

// Writes the outline in the format the path's extension names. Throws
// std::runtime_error naming the path; a failed write leaves any old file
// as it was.
void writeOutlineFile(const std::string& path, const Profile& evaluated, double tolerance);

}  // namespace csgray::detail
