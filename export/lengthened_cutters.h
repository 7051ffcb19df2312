// Cylinders and turns cut away, made a little longer, where their ends
// are flush with slanted faces.
//
// A tube turned by an angle that is not a quarter (a pipe's branch at
// 37.5°, an elbow's leg) with a bore of its length: the bore's ends and
// the tube's lie in one slanted plane only to rounding, each placed by
// its own frame, and the difference of the meshes keeps slivers between
// the two faces a hair apart, which the rounding to the file's precision
// folds over (the export fails as self-intersecting). A cutter that goes
// on past the face cuts the same tube and meets no face at a sliver's
// angle. Lengthening a cutter by less than the tolerance changes the part
// by less than the tolerance wherever it ends, so the export takes it as
// a last try, where the part as given fails.
#pragma once

#include <functional>

#include "engine/solid.h"

namespace csgray::detail {

// The part with every cylinder and cone in a difference's cutters that
// `which` takes made longer by `by` (in the world's lengths) past each end
// that crosses the surface of what it cuts (the point 2·by before its
// centre inside, the point 2·by past it outside: the end is flush with a
// face of it), or that ends in another of its cutters; a cone's end widened or
// narrowed along its side, an end at a cone's tip left where it is. Every
// rotate_extrude through part of a turn that it takes is turned on so past
// each end face that crosses it so, by the angle that moves its
// farthest point by `by` (a hollow bend's bore, of the bend's angle). The
// part itself when it makes none so.
SolidPtr cuttersLengthened(const SolidPtr& part, double by,
                           const std::function<bool(const Primitive&)>& which);

}  // namespace csgray::detail
