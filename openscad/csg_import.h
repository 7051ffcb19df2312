// Makes solids and 2D regions of an OpenSCAD .csg file (csg_parser.h), so
// that `csgray render part.csg` and import_csg{file=} take OpenSCAD's
// models (docs/openscad.md, "Opening .csg files"). Curved primitives are
// exact unless asked for OpenSCAD's own polygons (CsgFacets::OpenScad);
// a low explicit $fn is a shape, not a quality, and is kept either way.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/solid.h"
#include "openscad/csg_parser.h"
#include "profile/region.h"
#include "scene/texture.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

enum class CsgFacets {
  Exact,    // circles, spheres, cylinders exact ($fn from 3 to kShapeFacets kept)
  OpenScad  // the polygons OpenSCAD makes from $fn, $fa and $fs
};

// A $fn from 3 to this is a polygon the model means (a hexagon's nut, a
// square's peg), made as such also when curves are exact.
inline constexpr int kShapeFacets = 12;

struct CsgImportOptions {
  CsgFacets facets = CsgFacets::Exact;
  // The path of a file a node names (import(file=...)), relative to the
  // .csg file's folder, checked against what may be read; throws
  // std::invalid_argument. Without it, import() is an error.
  std::function<std::string(const std::string& name)> resolveFile;
  // Reads a triangle mesh (STL, OFF, OBJ, PLY) as a solid's; throws
  // std::invalid_argument. Without it, import() of a mesh is an error.
  std::function<TriangleMesh(const std::string& path)> loadMesh;
  // Reads an image (surface(file="x.png")); throws std::runtime_error.
  // Without it, surface() of an image is an error.
  std::function<TextureImage(const std::string& path)> loadImage;
  // The section by z = 0 (cut) or the shadow on it of a solid, for
  // projection(); throws std::exception with a one-line message. Without
  // it, projection() is an error. (solidProjection of
  // export/solid_projection.h fits.)
  std::function<Profile(const SolidPtr& solid, bool cut)> project;
  // Told of a parameter no node here reads ("part.csg:3: cube: parameter
  // 'foo' is not known here and was left out"): a newer OpenSCAD's, or a
  // typo in a file written by hand. Without it, such parameters are quiet.
  std::function<void(const std::string& message)> warn;
};

// What a file holds: solids (3D) and regions (2D) at the top level, each
// top-level node's own.
struct CsgModel {
  std::vector<SolidPtr> solids;
  std::vector<RegionPtr> regions;
};

// The model of the text; fileName is used in messages. Throws CsgError
// "file:line: what" for a node that cannot be made (an unknown node, bad
// arguments, a node that is not supported).
CsgModel importCsg(const std::string& text, const std::string& fileName,
                   const CsgImportOptions& options);
// The same, read from the file at path (at most 256 MiB). Throws CsgError.
CsgModel importCsgFile(const std::string& path, const CsgImportOptions& options);

// OpenSCAD's number of segments of a circle of radius r (its
// get_fragments_from_r): max($fn, 3) for $fn > 0, else
// ceil(max(min(360/$fa, 2πr/$fs), 5)). Throws std::invalid_argument when
// that is more than kMaxOpenScadFragments (a $fa or $fs near 0 asks for
// billions).
int openscadFragments(double r, double fn, double fa, double fs);
constexpr int kMaxOpenScadFragments = 1'000'000;

}  // namespace csgray::detail
