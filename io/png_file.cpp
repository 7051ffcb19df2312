#include "io/png_file.h"

#include <zlib.h>

#include <stdexcept>
#include <vector>

namespace csgray {

namespace {

void putBigEndian(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xFF));
}

// A chunk: length, type, data and the CRC-32 of type and data (PNG 5.3).
void putChunk(std::string& out, const char* type, const std::string& data) {
  putBigEndian(out, std::uint32_t(data.size()));
  std::string typed = std::string(type, 4) + data;
  out += typed;
  putBigEndian(out, std::uint32_t(::crc32(0L, reinterpret_cast<const Bytef*>(typed.data()),
                                          uInt(typed.size()))));
}

}  // namespace

std::string encodePng(int width, int height, const std::uint8_t* rgb) {
  // Each row starts with its filter type. The "Sub" filter (PNG 9.2: each
  // byte minus the one a pixel to the left) makes smooth shading compress
  // well at zlib's fastest level.
  const std::size_t stride = std::size_t(width) * 3;
  std::vector<std::uint8_t> filtered((stride + 1) * height);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = rgb + y * stride;
    std::uint8_t* out = &filtered[y * (stride + 1)];
    out[0] = 1;  // Sub
    for (std::size_t i = 0; i < stride; ++i)
      out[i + 1] = std::uint8_t(row[i] - (i >= 3 ? row[i - 3] : 0));
  }
  // zlib's fastest level: a render's PNG is written once and viewed, so
  // time matters more than the last few percent of size.
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_SPEED, Z_DEFLATED, 15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("PNG compression failed");
  std::string compressed(deflateBound(&z, uLong(filtered.size())), '\0');
  z.next_in = filtered.data();
  z.avail_in = uInt(filtered.size());
  z.next_out = reinterpret_cast<Bytef*>(compressed.data());
  z.avail_out = uInt(compressed.size());
  int status = deflate(&z, Z_FINISH);
  compressed.resize(z.total_out);
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw std::runtime_error("PNG compression failed");

  std::string header;
  putBigEndian(header, std::uint32_t(width));
  putBigEndian(header, std::uint32_t(height));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, filters, no interlace
  std::string png("\x89PNG\r\n\x1a\n", 8);
  putChunk(png, "IHDR", header);
  putChunk(png, "sRGB", std::string(1, '\0'));  // perceptual rendering intent
  putChunk(png, "IDAT", compressed);
  putChunk(png, "IEND", "");
  return png;
}

}  // namespace csgray
