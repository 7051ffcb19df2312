// PNG files written without OpenImageIO: 8-bit RGB, the format of every
// preview, kept off the path that loads OpenImageIO's many libraries.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace csgray {

// Writes the 8-bit RGB bytes of image row y (width · 3 of them) to out.
using PngRowSource = std::function<void(int y, std::uint8_t* out)>;

// The bytes of a PNG file (ISO/IEC 15948) of width × height pixels of
// 8-bit RGB, rows from the top. Bands of rows are filtered and compressed
// on up to `threads` threads, each band an independent deflate stream
// joined into one (as pigz does). Throws std::runtime_error if
// compression fails.
std::string encodePng(int width, int height, const PngRowSource& rows, int threads = 1);

}  // namespace csgray
