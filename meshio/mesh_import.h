// A mesh file as a solid for mesh{file=...} in a script: read, repaired
// when asked, and refused unless it is the boundary of a solid.
#pragma once

#include <string>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// Reads the mesh file at path (STL, OBJ, OFF or PLY by its extension);
// with repair, makes the repairs of repairMesh and puts what they did in
// repairReport (empty when nothing). Throws std::invalid_argument naming
// the file and what is wrong where (meshDefect) when the result is not a
// closed, manifold, outward-facing mesh without self-intersections. Fits
// ScriptOptions::loadMesh.
TriangleMesh importMesh(const std::string& path, bool repair, std::string& repairReport);
// The same for a mesh already read from the file at path (messages begin
// with its file name): what importMesh does after reading.
TriangleMesh importedMesh(TriangleMesh mesh, const std::string& path, bool repair,
                          std::string& repairReport);

}  // namespace csgray::detail
