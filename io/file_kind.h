// What a path names, in the words of a message that refuses it: csgray
// reads and writes regular files only (io/input_file.h, io/atomic_file.h).
#pragma once

#include <sys/stat.h>

#include <string>

namespace csgray::detail {

// "a folder", "a FIFO", "a socket", "a character device", "a block
// device"; "" for a regular file.
std::string specialFileKind(mode_t mode);

// "it is a folder", "it is a FIFO, not a regular file", ...; "" for a
// regular file.
std::string notRegularFile(mode_t mode);

}  // namespace csgray::detail
