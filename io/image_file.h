// Image files: PNG written and read by csgray itself (png_file.h,
// png_reader.h), other formats through OpenImageIO (image_formats.h).
#pragma once

#include <string>

#include "io/atomic_file.h"
#include "io/png_file.h"
#include "scene/texture.h"

namespace csgray::detail {

// Can an image be written to this path: a known format, an existing
// writable folder? Returns an empty string if so, else why not; checked
// before a render so that a long render is not lost at the end.
std::string imageOutputProblem(const std::string& path);
// The format's half of that: does the extension name a format csgray can
// write? Empty if so, else why not.
std::string imageFormatProblem(const std::string& path);

// Is the file at path a PNG file (by its extension, in any case)? csgray
// writes those itself, without OpenImageIO.
bool isPngFile(const std::string& path);

// Does the format of path (.exr, .hdr, .pfm) keep floats as they are,
// rather than as 8-bit codes?
bool keepsFloatValues(const std::string& path);

// What the floats of an image are: colours in linear light, or values
// (depth, normals) that 8-bit formats store as they are, clamped to [0, 1].
enum class ImageData { LinearColor, Values };

// The rows of an image of RGB floats as the 8-bit codes a PNG file holds.
PngRowSource pngRows(const float* rgb, int width, ImageData data);

// Writes RGB floats (row-major, top row first) atomically. Float formats
// (EXR, HDR) keep the values; others store colours sRGB-encoded. PNG files
// are encoded on up to `threads` threads; `started`, if given, is a PNG
// encoder of this image that may hold bands encoded already (from
// pngRows of the same floats). Throws std::runtime_error naming the file.
void writeImage(const std::string& path, int width, int height, const float* rgb,
                ImageData data = ImageData::LinearColor, int threads = 1,
                PngEncoder* started = nullptr);

// As writeImage, into file's temporary (file is of path), which the caller
// commits: images that land together, or not at all.
void writeImageUncommitted(AtomicFile& file, const std::string& path, int width, int height,
                           const float* rgb, ImageData data = ImageData::LinearColor,
                           int threads = 1, PngEncoder* started = nullptr);

// Reads an image for a texture as linear RGB floats: grey is replicated,
// alpha dropped; 8- and 16-bit integer formats are sRGB-decoded, float
// formats (EXR, HDR) kept. A file that begins with the PNG signature is
// read as PNG, whatever its name, without OpenImageIO. Throws
// std::runtime_error naming the file if it is missing, unreadable, not an
// image, empty or of more pixels than kMaxTexturePixels.
TextureImage readTextureImage(const std::string& path);

}  // namespace csgray::detail
