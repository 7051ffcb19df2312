// Unions nested under transforms, as one union of their leaves, for rays.
//
// A fractal's levels and an assembly's groups are unions of moved uses of
// a shared union (engine/instance.h): stored once, but a ray walks a BVH
// per level, is taken into each use's frame on the way down, and the
// renderer searches down the uses for the surface of the boundary it
// shades. flatUnion gives the same point set as one union of the leaves
// of that nesting, each moved into place: a primitive copied with its
// composed frame, any other node (an intersection, a difference) a use of
// it there. A ray then walks one BVH, and a primitive's boundary names its
// own surface in the world. This spends the memory the sharing saves (a
// primitive's copy, with its two frames and its share of the BVH, is about
// a kilobyte; the large data of meshes and sweeps stays shared), so past
// kMaxFlatLeaves uses a solid is kept as it is.
#pragma once

#include <cstddef>
#include <mutex>

#include "engine/solid.h"

namespace csgray::detail {

// Uses of primitives beyond which a nesting is not flattened: about
// 100 MB of copies at most, and a BVH built in a few tenths of a second.
inline constexpr std::size_t kMaxFlatLeaves = 100'000;

// Does the solid nest a union under a transform: is it a union with such
// an operand (at any depth of unions), or a use of a union?
bool nestsMovedUnions(const Solid& solid);

// The union of the nesting's leaves, each moved into place, when the solid
// nests moved unions and uses at most maxLeaves primitives; else the solid.
SolidPtr flatUnion(const SolidPtr& solid, std::size_t maxLeaves = kMaxFlatLeaves);

// Solid::forRays() of a node that keeps its flat union: made once (under
// `made`) and kept in `kept` when it is not the node itself, which the
// node cannot hold.
SolidPtr keptFlatUnion(const Solid& node, std::once_flag& made, SolidPtr& kept);

}  // namespace csgray::detail
