// PNG files written without OpenImageIO: 8-bit RGB, the format of every
// preview, kept off the path that loads OpenImageIO's many libraries.
#pragma once

#include <cstdint>
#include <string>

namespace csgray {

// The bytes of a PNG file (ISO/IEC 15948) of width × height pixels of
// 8-bit RGB, rows from the top. Throws std::runtime_error if compression
// fails.
std::string encodePng(int width, int height, const std::uint8_t* rgb);

}  // namespace csgray
