#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace csgray::detail {

namespace {
std::atomic<unsigned> counter{0};

std::runtime_error failure(const std::string& target, const std::string& what) {
  return std::runtime_error("cannot write " + target + ": " + what);
}
}  // namespace

std::string outputPathProblem(const std::string& path) {
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    return "folder " + folder.string() + " does not exist";
  if (::access(folder.c_str(), W_OK) != 0) return "folder " + folder.string() + " is not writable";
  if (std::filesystem::is_directory(path, error)) return "it is a folder";
  return "";
}

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  std::filesystem::path path(target_);
  // Hidden, unique per process and call: ".name.tmp<pid>-<n>.ext".
  std::string name(".");
  name += path.stem().string();
  name += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  name += path.extension().string();
  temp_ = (path.parent_path() / name).string();
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicFile::commit() {
  int fd = ::open(temp_.c_str(), O_RDONLY);
  if (fd < 0) throw failure(target_, std::strerror(errno));
  bool synced = ::fsync(fd) == 0;
  int syncError = errno;
  ::close(fd);
  if (!synced) throw failure(target_, std::strerror(syncError));
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
