#include "io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "io/file_kind.h"

namespace csgray::detail {

namespace {

std::string openProblem(int error) {
  return error == ENOENT ? "no such file" : std::strerror(error);
}

}  // namespace

InputFile::InputFile(const std::string& path, bool devicesToo) {
  // O_NONBLOCK: open() of a FIFO returns at once instead of waiting for a
  // writer; the FIFO is then refused below.
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    problem_ = openProblem(errno);
    return;
  }
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    problem_ = std::strerror(errno);
  } else if (S_ISREG(info.st_mode)) {
    size_ = std::uint64_t(info.st_size);
  } else if (!(devicesToo && (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode)))) {
    problem_ = notRegularFile(info.st_mode);
  }
  // Reads wait for data as usual: a regular file or a device has it.
  if (problem_.empty() && ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK) != 0)
    problem_ = std::strerror(errno);
  if (!problem_.empty()) {
    ::close(fd_);
    fd_ = -1;
  }
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

bool InputFile::readUpTo(std::string& bytes, std::size_t limit) {
  if (fd_ < 0) return false;
  char block[1 << 16];
  while (bytes.size() < limit) {
    ssize_t n = ::read(fd_, block, std::min(sizeof block, limit - bytes.size()));
    if (n == 0) return true;
    if (n < 0) {
      if (errno == EINTR) continue;
      problem_ = std::strerror(errno);
      return false;
    }
    bytes.append(block, std::size_t(n));
  }
  return true;
}

std::string inputFileProblem(const std::string& path) { return InputFile(path).problem(); }

std::string readInputFile(const std::string& path, const std::string& name, std::size_t maxBytes) {
  std::string bytes = readInputFileStart(path, name, maxBytes + 1);
  if (bytes.size() > maxBytes)
    throw std::invalid_argument(name + ": the file is larger than " +
                                std::to_string(maxBytes >> 20) + " MiB");
  return bytes;
}

std::string readInputFileStart(const std::string& path, const std::string& name,
                               std::size_t count) {
  InputFile file(path);
  if (!file.problem().empty())
    throw std::invalid_argument(name + ": cannot open: " + file.problem());
  std::string bytes;
  if (!file.readUpTo(bytes, count))
    throw std::invalid_argument(name + ": cannot read: " + file.problem());
  return bytes;
}

}  // namespace csgray::detail
