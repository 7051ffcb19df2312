#include "meshio/mesh_import.h"

#include <filesystem>
#include <stdexcept>

#include "export/cgal/mesh_repair.h"
#include "export/cgal/mesh_validity.h"
#include "meshio/mesh_reader.h"

namespace csgray::detail {

TriangleMesh importMesh(const std::string& path, bool repair, std::string& repairReport) {
  return importedMesh(readMeshFile(path), path, repair, repairReport);
}

TriangleMesh importedMesh(TriangleMesh mesh, const std::string& path, bool repair,
                          std::string& repairReport) {
  repairReport.clear();
  if (repair) mesh = repairMesh(mesh, repairReport);
  const MeshDefect defect = meshDefect(mesh);
  if (defect.valid()) return mesh;
  const std::string name = std::filesystem::path(path).filename().string();
  // Repairs cannot fill holes or resolve crossing faces.
  const bool repairable =
      defect.kind != MeshDefect::Kind::SelfIntersecting && defect.kind != MeshDefect::Kind::Open;
  std::string hint =
      !repair && repairable ? " (repair=true may fix this)"
      : repair ? " (after repair" + (repairReport.empty() ? "" : ": " + repairReport) + ")"
               : "";
  throw std::invalid_argument(name + ": " + defect.text + hint);
}

}  // namespace csgray::detail
