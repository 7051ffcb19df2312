// Writing bytes made in memory to a file, with the system's reason when it
// fails ("No space left on device"). Header-only: the image formats module
// (image_formats_module.cpp), which links nothing of csgray's, uses it too.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace csgray::detail {

// Writes size bytes to path, created or truncated. Throws
// std::runtime_error "cannot write <name>: <reason>": name is the file the
// user asked for, path may be its temporary.
inline void writeFileBytes(const std::string& path, const std::string& name, const void* data,
                           std::size_t size) {
  auto fail = [&](int error) {
    return std::runtime_error("cannot write " + name + ": " + std::strerror(error));
  };
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw fail(errno);
  const char* next = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, next, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      const int error = written < 0 ? errno : EIO;
      ::close(fd);
      throw fail(error);
    }
    next += written;
    size -= std::size_t(written);
  }
  if (::close(fd) != 0) throw fail(errno);
}

}  // namespace csgray::detail
