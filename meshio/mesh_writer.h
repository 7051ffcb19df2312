// Mesh files out: binary STL directly (binary_stl_writer.h), ASCII STL,
// OBJ, OFF and PLY through OpenMesh, and 3MF through lib3mf with each
// triangle's colour from its material. Every write is atomic
// (io/atomic_file.h).
#pragma once

#include <string>

#include "export/part_mesh.h"

namespace csgray::detail {

enum class MeshFormat { Stl, Obj, Off, Ply, ThreeMf };

// The format a file name asks for by its extension (any case). Throws
// std::invalid_argument naming the extensions there are.
MeshFormat meshFormatFor(const std::string& path);

// A coordinate as the file will hold it: a 32-bit float (OpenMesh writes
// floats in every format), or for 3MF (as lib3mf 1.8 writes it) the float
// of a number with six decimals. The exporter rounds the mesh this way
// before it checks it, so that the check is of what is written.
StoredCoordinate storedCoordinate(MeshFormat format, bool ascii);

// Writes the part; ascii asks for text STL and PLY (OBJ and OFF are always
// text, 3MF never). Text formats print 17 significant digits, so doubles
// read back unchanged. Throws std::runtime_error naming the path; a failed
// write leaves any old file as it was.
void writeMeshFile(const std::string& path, const PartMesh& part, bool ascii);

}  // namespace csgray::detail
