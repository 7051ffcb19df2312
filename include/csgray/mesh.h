// Printable meshes: a solid exported as a closed triangle mesh within a
// tolerance of its exact surface (docs/cli.md, export), and mesh files.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "csgray/material.h"
#include "csgray/solid.h"
#include "csgray/types.h"

namespace csgray {

struct Mesh {
  std::vector<Vec3> vertices;
  // Vertex indices, counter-clockwise seen from outside.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // Per triangle, an index into materials (empty: none); a triangle takes
  // the material of the primitive whose surface it lies on.
  std::vector<std::uint32_t> triangleMaterial;
  std::vector<std::optional<Material>> materials;  // none: the primitive had no material

  // The enclosed volume, by the divergence theorem.
  CSGRAY_API double volume() const;
};

enum class MeshFormat { Stl, Obj, Off, Ply, ThreeMf };

struct ExportOptions {
  // The largest distance of the mesh from the exact surface: 1e-6 to 1000.
  double tolerance = 0.01;
  // The file format the mesh will be written in: coordinates are rounded as
  // it stores them before the mesh is checked, so that the file holds a
  // valid mesh. None: plain doubles.
  std::optional<MeshFormat> format = MeshFormat::Stl;
  bool ascii = false;  // text STL or PLY (give writeMesh the same)
  // Set by another thread, stops the export: exportMesh throws Error with
  // ErrorCode::Cancelled at its next step: a primitive's mesh, a step of a
  // boolean, a step of the final test of the mesh (docs/library.md: within
  // a fraction of a second on large parts).
  const std::atomic<bool>* cancel = nullptr;
};

// The closed, 2-manifold, outward, self-intersection-free mesh of the
// solid, as `csgray export` makes it. Error NotPrintable when there is none
// (an unbounded or empty solid, solids that touch where CGAL cannot cut).
CSGRAY_API Mesh exportMesh(const Solid& solid, const ExportOptions& options = {});

// Writes the mesh; the extension picks the format (.stl, .obj, .off, .ply,
// .3mf, the last with each triangle's colour). ascii: text STL or PLY.
// Atomic, as writeImage. A mesh without triangles is refused
// (InvalidArgument): no file of it would read back.
CSGRAY_API void writeMesh(const Mesh& mesh, const std::string& path, bool ascii = false);
// Reads a mesh file (STL, OBJ, OFF, PLY or 3MF): polygons are split into
// triangles and equal vertices merged; it is not checked (see meshDefect).
CSGRAY_API Mesh readMesh(const std::string& path);

// The first problem that keeps a mesh from bounding a solid, if any.
struct MeshDefect {
  enum class Kind {
    None,                     // closed, 2-manifold, outward, no self-intersections
    Empty,                    // no triangles
    NotFinite,                // a vertex has a NaN or infinite coordinate
    BadIndex,                 // a triangle names a vertex the mesh does not have
    Degenerate,               // a triangle uses a vertex twice or has no area
    Open,                     // an edge has one triangle: a hole
    NonManifold,              // an edge has more than two triangles, or a vertex joins two fans
    InconsistentOrientation,  // two triangles run the same way along their edge
    SelfIntersecting,         // two triangles cross
    InsideOut,                // the triangles face inward
  };
  Kind kind = Kind::None;
  std::string text;  // one line: what and where; empty for None
};
CSGRAY_API MeshDefect meshDefect(const Mesh& mesh);

}  // namespace csgray
