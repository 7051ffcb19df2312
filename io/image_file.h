// Image files through OpenImageIO, format by extension.
#pragma once

#include <string>

namespace csgray {

// Can an image be written to this path: a known format, an existing
// writable folder? Returns an empty string if so, else why not; checked
// before a render so that a long render is not lost at the end.
std::string imageOutputProblem(const std::string& path);

// Writes linear-light RGB floats (row-major, top row first) atomically.
// Float formats (EXR, HDR) keep linear values; others are sRGB-encoded.
// Throws std::runtime_error naming the file.
void writeImage(const std::string& path, int width, int height, const float* linearRgb);

}  // namespace csgray
