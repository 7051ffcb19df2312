// The mesh tools: the work of the export and check commands, check() in
// scripts and the mesh files that scripts import, in a module loaded on
// first use: CGAL's number types, OpenMesh and lib3MF (with libzip and
// libcrypto) made every run of csgray, renders included, spend 12 ms in
// the dynamic loader before main. The module and csgray are built
// together, so C++ types and exceptions cross between them.
#pragma once

#include <functional>
#include <string>

#include "cli/check_scene.h"
#include "cli/export_scene.h"
#include "profile/profile.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

struct MeshTools {
  // As declared in cli/export_scene.h, cli/check_scene.h,
  // meshio/mesh_import.h and check/part_check.h.
  void (*checkExportOutput)(const ExportOptions& options);
  void (*exportScene)(const Scene& scene, const ExportOptions& options, double scriptSeconds);
  int (*checkScene)(const Scene& scene, const CheckCommandOptions& options);
  TriangleMesh (*importMesh)(const std::string& path, bool repair, std::string& repairReport);
  CheckReport (*checkPart)(const Solid& solid, const CheckOptions& options);
  // As declared in export/solid_projection.h.
  Profile (*solidProjection)(const SolidPtr& solid, bool cut);
  // As declared in meshio/part_file_bytes.h and check/part_check.h (the
  // page of csgray view).
  std::string (*partFileBytes)(const Scene& scene, const std::string& script,
                               const std::string& extension, double tolerance,
                               const std::function<void(const std::string& stage)>& stage,
                               const std::function<void(const std::string& message)>& warn);
  CheckReport (*checkPrintedPart)(const Scene& scene, const std::string& script,
                                  const CheckOptions& options,
                                  const std::function<void(const std::string& message)>& warn);
};

// The module's table, loaded on the first call (thread-safe). Throws
// std::runtime_error if it cannot be loaded.
const MeshTools& meshTools();

}  // namespace csgray::detail

extern "C" const csgray::detail::MeshTools* csgray_mesh_tools();
