// The work of csgray export, in the mesh tools module (cli/mesh_tools.h):
// a scene's solids as a closed, printable mesh file.
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace csgray::detail {

struct ExportOptions {
  std::string script;       // for messages
  std::string output;       // its extension picks the format
  double tolerance = 0.01;  // also that of ellipses in an outline
  bool ascii = false;       // text STL and PLY
  bool stats = false;       // stage times on stderr
  // Called when the mesh is made, before it is written: the command's
  // time limit ends there, so that the file is whole or not there.
  std::function<void()> meshed;
};

// Throws std::runtime_error when the output cannot be written (checked
// before the script runs, so that a typo costs no time).
void checkExportOutput(const ExportOptions& options);

// Evaluates the scene's solids (their union, when there are several) on
// meshes, checks the result with CGAL and writes it. For an output of .svg
// or .dxf, writes the outline of the scene's 2D regions (their union)
// instead (meshio/outline_writer.h); a scene of regions alone has no mesh. Prints one line on
// success; throws std::exception with a one-line message otherwise, and
// leaves any old output file as it was.
void exportScene(const Scene& scene, const ExportOptions& options, double scriptSeconds);

}  // namespace csgray::detail
