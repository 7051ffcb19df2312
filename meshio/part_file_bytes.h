// A part's mesh file made in memory rather than in the user's folder, for
// `csgray view` to offer as a download: the scene's printed part (its
// solids' union), meshed and written as a file of the format, whose bytes
// are returned. The file passes through a folder of its own in the system's
// temporary folder, removed before this returns.
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace csgray::detail {

// extension: "stl" or "3mf" (any mesh format of meshio/mesh_writer.h);
// stage is told "mesh", then "write"; warn gets the warnings of an export
// (an open surface left out). Throws std::exception with a one-line message
// that starts with the script's name when the part cannot be exported.
std::string partFileBytes(const Scene& scene, const std::string& script,
                          const std::string& extension, double tolerance,
                          const std::function<void(const std::string& stage)>& stage,
                          const std::function<void(const std::string& message)>& warn);

}  // namespace csgray::detail
