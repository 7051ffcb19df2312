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

// Why a mesh file's 32-bit floats cannot hold the part to half the
// tolerance (it reaches too far from the origin), or "".
std::string floatPrecisionProblem(const Solid& part, double tolerance);

// Throws std::runtime_error, naming the script, for floatPrecisionProblem.
void checkFloatPrecision(const Solid& part, double tolerance, const std::string& script);

}  // namespace csgray::detail
