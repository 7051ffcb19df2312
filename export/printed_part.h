// What of a scene is printed, and whether a mesh file can hold it: the
// checks an export (and the check of one) makes before any boolean.
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace csgray::detail {

// The scene's solids as one part: their union when there are several.
// Open surfaces bound no volume and are left out, which `warn` is told.
// Throws std::runtime_error when there is no solid. Messages start with
// the script's name and say that `verb` ("export", "check") is what was
// to be done.
SolidPtr printedPart(const Scene& scene, const std::string& script, const char* verb,
                     const std::function<void(const std::string& message)>& warn);

// Throws std::runtime_error, naming the script, when the part reaches so
// far from the origin that a mesh file's 32-bit floats cannot hold it to
// half the tolerance.
void checkFloatPrecision(const Solid& part, double tolerance, const std::string& script);

}  // namespace csgray::detail
