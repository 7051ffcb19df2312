// A 2D region as a scene object: flat in the plane z = 0, shaded on both
// sides like the other open surfaces (docs/script.md, "2D regions"), as
// OpenSCAD shows 2D shapes. It encloses no volume, so it is no part of an
// export; its outline can be written as SVG or DXF instead
// (meshio/outline_writer.h).
#pragma once

#include <optional>
#include <string>

#include "engine/affine.h"
#include "profile/region.h"
#include "scene/surface.h"

namespace csgray::detail {

// The region in the plane z = 0; kind names it ("square", "region").
SurfacePtr regionSurface(RegionPtr region, const std::string& kind);

// The map of the plane z = 0 that the frame makes when it takes that plane
// onto itself, the image of (x, y, 0) being (map(x, y), 0); nullopt when
// it moves the plane elsewhere or tilts it. The frame's z row is compared
// with (0, 0, ·, 0) to a relative 1e-12, so that rotate(0, 180, 0) keeps
// the plane in spite of the rounding of sin 180°.
std::optional<Affine2> planarMap(const Affine& frame);

// The region a surface shows, in the world's (x, y), when the surface is a
// region lying in the plane z = 0; null otherwise.
RegionPtr regionInPlane(const Surface& surface);

}  // namespace csgray::detail
