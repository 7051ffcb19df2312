// Writing a file so that readers see the old file or the complete new one,
// never a partial one: write to a temporary file in the same folder, fsync,
// then rename over the target. A failed write leaves no temporary behind.
#pragma once

#include <string>

namespace csgray::detail {

// Why a file cannot be written at path (its folder is missing or not
// writable; the path names a folder, a FIFO, a device or anything else
// that is not a regular file; its name is longer than the file system
// takes), or "" when it can: checked before the work that makes the file,
// so that a typo costs no time.
std::string outputPathProblem(const std::string& path);

class AtomicFile {
 public:
  // The temporary's name keeps the target's extension, for writers that
  // choose a format by extension, and is no longer than a file name may be.
  explicit AtomicFile(std::string target);
  ~AtomicFile();  // removes the temporary unless committed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& tempPath() const { return temp_; }
  // Flushes the temporary to disk and renames it over the target, unless
  // the target has become something other than a regular file. Throws
  // std::runtime_error naming the target.
  void commit();

 private:
  std::string target_, temp_;
  bool committed_ = false;
};

}  // namespace csgray::detail
