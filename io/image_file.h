// Image files through OpenImageIO, format by extension.
#pragma once

#include <string>

#include "modeler/texture.h"

namespace csgray {

// Can an image be written to this path: a known format, an existing
// writable folder? Returns an empty string if so, else why not; checked
// before a render so that a long render is not lost at the end.
std::string imageOutputProblem(const std::string& path);

// What the floats of an image are: colours in linear light, or values
// (depth, normals) that 8-bit formats store as they are, clamped to [0, 1].
enum class ImageData { LinearColor, Values };

// Writes RGB floats (row-major, top row first) atomically. Float formats
// (EXR, HDR) keep the values; others store colours sRGB-encoded. PNG files
// are encoded on up to `threads` threads. Throws std::runtime_error naming
// the file.
void writeImage(const std::string& path, int width, int height, const float* rgb,
                ImageData data = ImageData::LinearColor, int threads = 1);

// Reads an image for a texture as linear RGB floats: grey is replicated,
// alpha dropped; 8- and 16-bit integer formats are sRGB-decoded, float
// formats (EXR, HDR) kept. Throws std::runtime_error naming the file if it
// is missing, unreadable, not an image, empty or over 16384 pixels a side.
TextureImage readTextureImage(const std::string& path);

}  // namespace csgray
