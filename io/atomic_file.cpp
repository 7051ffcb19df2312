#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "io/file_kind.h"

namespace csgray::detail {

namespace {
std::atomic<unsigned> counter{0};

std::runtime_error failure(const std::string& target, const std::string& what) {
  return std::runtime_error("cannot write " + target + ": " + what);
}

// The longest file name the folder's file system takes (255 bytes on the
// common ones).
std::size_t nameLimit(const std::filesystem::path& folder) {
  long limit = ::pathconf(folder.empty() ? "." : folder.c_str(), _PC_NAME_MAX);
  return limit > 0 ? std::size_t(limit) : 255;
}

// Why an existing target may not be replaced: a rename would put the file
// in the place of a FIFO or a device (/dev/full), and whoever reads that
// would get nothing. "" for a regular file or none.
std::string targetProblem(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 ? notRegularFile(info.st_mode) : "";
}
}  // namespace

std::string outputPathProblem(const std::string& path) {
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    return "folder " + folder.string() + " does not exist";
  if (::access(folder.c_str(), W_OK) != 0) return "folder " + folder.string() + " is not writable";
  if (std::string problem = targetProblem(path); !problem.empty()) return problem;
  const std::size_t limit = nameLimit(folder);
  if (std::filesystem::path(path).filename().string().size() > limit)
    return "the file name is longer than " + std::to_string(limit) + " bytes";
  return "";
}

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  std::filesystem::path path(target_);
  // Hidden, unique per process and call: ".name.tmp<pid>-<n>.ext". The
  // name is cut short where the whole would be longer than a file name may
  // be, so that an output whose name is near the limit can be written.
  const std::string unique = ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  std::string stem = path.stem().string(), ext = path.extension().string();
  const std::size_t limit = nameLimit(path.parent_path());
  if (1 + unique.size() + ext.size() > limit) ext.clear();  // no format has such an extension
  const std::size_t used = 1 + unique.size() + ext.size();
  std::size_t keep = std::min(stem.size(), used < limit ? limit - used : 0);
  while (keep > 0 && keep < stem.size() && (stem[keep] & 0xC0) == 0x80) --keep;  // whole UTF-8
  temp_ = (path.parent_path() / ("." + stem.substr(0, keep) + unique + ext)).string();
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicFile::commit() {
  int fd = ::open(temp_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw failure(target_, std::strerror(errno));
  bool synced = ::fsync(fd) == 0;
  int syncError = errno;
  if (::close(fd) != 0 && synced) {
    synced = false;
    syncError = errno;
  }
  if (!synced) throw failure(target_, std::strerror(syncError));
  // Checked before the work too (outputPathProblem); again here, for the
  // library's callers and for a FIFO made meanwhile.
  if (std::string problem = targetProblem(target_); !problem.empty())
    throw failure(target_, problem);
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw failure(target_, std::strerror(errno));
  committed_ = true;
  // Make the rename itself durable.
  std::filesystem::path folder = std::filesystem::path(target_).parent_path();
  int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace csgray::detail
