// Files that a user names as input (the script, meshes, texture images).
// open() of a FIFO waits for a writer, for ever if none comes, and a read
// from a socket or a terminal may wait as long: so an input is opened
// without waiting, and refused unless it is a regular file (or, where the
// caller allows it, a device such as /dev/zero, read up to its limit).
#pragma once

#include <cstdint>
#include <string>

namespace csgray::detail {

class InputFile {
 public:
  // Opens path for reading. problem() says why it cannot be read, in a few
  // words ("no such file", "it is a folder", "it is a FIFO, not a regular
  // file", ...), or is "" when it is open.
  explicit InputFile(const std::string& path, bool devicesToo = false);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& problem() const { return problem_; }
  // The size of a regular file (0 for a device).
  std::uint64_t size() const { return size_; }
  // Appends bytes until the end of the file or until `bytes` holds
  // `limit`. Returns false, with problem() set, if a read fails.
  bool readUpTo(std::string& bytes, std::size_t limit);

 private:
  int fd_ = -1;
  std::uint64_t size_ = 0;
  std::string problem_;
};

// Why path cannot be read as an input that must be a regular file, or "".
std::string inputFileProblem(const std::string& path);

// The whole of the regular file at path, at most maxBytes of it. Throws
// std::invalid_argument "name: cannot open: why", "name: cannot read: why"
// or "name: the file is larger than N MiB", name being how the user named
// the file.
std::string readInputFile(const std::string& path, const std::string& name, std::size_t maxBytes);
// The first `count` bytes of the regular file at path (fewer if it is
// shorter); throws as readInputFile does. For telling a file's kind before
// reading it whole, or handing it to a reader that opens it itself.
std::string readInputFileStart(const std::string& path, const std::string& name, std::size_t count);

}  // namespace csgray::detail
