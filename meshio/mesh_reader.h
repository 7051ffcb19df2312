// Readers of triangle mesh files: STL (ASCII and binary), OBJ, OFF, PLY
// (ASCII and binary) and 3MF (through lib3mf). Our own rather than OpenMesh's, so that a bad file
// gets one line naming the file and the line (text) or byte (binary) where
// it goes wrong, and so that no declared count is trusted before it is
// checked against the file's size.
//
// Polygons are split into triangles (ear clipping); identical vertex
// positions are merged, so the mesh is indexed even from an STL file. The
// result is not checked for being a closed solid: see meshDefect.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

struct MeshReadLimits {
  std::uint64_t maxFileBytes = std::uint64_t{2} << 30;
  std::uint64_t maxTriangles = 50'000'000;
};

// Each parses a whole file held in memory; `name` is the file name that
// messages begin with. Throws std::invalid_argument.
TriangleMesh readStl(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits = {});
TriangleMesh readObj(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits = {});
TriangleMesh readOff(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits = {});
TriangleMesh readPly(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits = {});
// 3MF: the build's objects, placed (threemf_reader.cpp).
TriangleMesh read3mf(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits = {});

// Whether `name`'s extension is one of the formats read here (.stl, .obj,
// .off, .ply, .3mf, in any case).
bool isReadableMeshName(const std::string& name);
// The reader chosen by the extension of `name` (.stl, .obj, .off, .ply,
// .3mf, in any case).
TriangleMesh readMesh(std::string_view bytes, const std::string& name,
                      const MeshReadLimits& limits = {});
// Reads the file at path (refusing one larger than the limit before reading
// it); messages name the file by its file name.
TriangleMesh readMeshFile(const std::string& path, const MeshReadLimits& limits = {});

}  // namespace csgray::detail
