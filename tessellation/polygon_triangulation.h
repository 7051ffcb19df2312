// Splits a planar polygon of a mesh (a face of a polyhedron, an n-gon of an
// OBJ, OFF or PLY file) into triangles with its orientation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

#include "engine/ray.h"

namespace csgray::detail {

// Polygons with more corners than this are not ear clipped: they are cut as
// if convex (triangulatePolygon).
inline constexpr std::size_t kMaxEarClippedCorners = 20'000;

// Calls triangle(a, b, c) n − 2 times for the polygon's n corners (indices
// into points, in the order that is to face out). A triangle is passed on
// as it is; convex polygons become zig-zag strips, others are cut by ear
// clipping in the plane of the polygon's Newell normal, and what is left
// convex of them is a strip too, as is a polygon of more than
// kMaxEarClippedCorners. A polygon that is not simple is cut anyway, so
// that a closed mesh stays closed and its validity check can say what is
// wrong. Returns false, and calls nothing, if a polygon of more than three
// corners has a zero normal (its corners are collinear, or it has no area).
bool triangulatePolygon(
    std::span<const dvec3> points, std::span<const std::uint32_t> polygon,
    const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& triangle);

}  // namespace csgray::detail
