#include "meshio/part_file_bytes.h"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "export/cgal/mesh_boolean.h"
#include "export/printed_part.h"
#include "meshio/mesh_writer.h"

namespace csgray::detail {

namespace {

namespace fs = std::filesystem;

// A folder only this process can write to (mkdtemp: a name no one else
// has), removed with what is in it when this goes out of scope.
class PrivateFolder {
 public:
  PrivateFolder() {
    std::string pattern = (fs::temp_directory_path() / "csgray_part_XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw std::runtime_error("cannot make a temporary folder in " +
                               fs::temp_directory_path().string());
    path_ = pattern;
  }
  ~PrivateFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

std::string partFileBytes(const Scene& scene, const std::string& script,
                          const std::string& extension, double tolerance,
                          const std::function<void(const std::string& stage)>& stage,
                          const std::function<void(const std::string& message)>& warn) {
  const std::string name = "part." + extension;
  const MeshFormat format = meshFormatFor(name);  // throws for an unknown format
  stage("mesh");
  const SolidPtr part = printedPart(scene, script, "export", warn);
  checkFloatPrecision(*part, tolerance, script);
  PartMesh mesh;
  try {
    mesh = meshOfSolid(*part, tolerance, storedCoordinate(format, false));
  } catch (const std::exception& e) {
    throw std::runtime_error(script + ": " + e.what());
  }
  if (mesh.mesh.empty()) throw std::runtime_error(script + ": the part is empty");
  stage("write");
  const PrivateFolder folder;
  const fs::path file = folder.path() / name;
  writeMeshFile(file.string(), mesh, false);
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) throw std::runtime_error("cannot read back the " + extension + " file just written");
  return std::move(bytes).str();
}

}  // namespace csgray::detail
