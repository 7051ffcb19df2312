#include "io/png_file.h"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>
#include <thread>
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

// One band of rows, filtered and deflated on its own.
struct Band {
  int first = 0, last = 0;  // rows [first, last)
  std::string deflated;     // raw deflate data (no zlib header or trailer)
  uLong adler = 1;          // Adler-32 of the band's filtered bytes
  std::size_t length = 0;   // number of filtered bytes
  bool ok = false;
};

void encodeBand(Band& band, int width, const PngRowSource& rows, bool final) {
  // Each row starts with its filter type. The "Sub" filter (PNG 9.2: each
  // byte minus the one a pixel to the left) makes smooth shading compress
  // well at zlib's fastest level.
  const std::size_t stride = std::size_t(width) * 3;
  std::vector<std::uint8_t> row(stride);
  std::vector<std::uint8_t> filtered((stride + 1) * std::size_t(band.last - band.first));
  for (int y = band.first; y < band.last; ++y) {
    rows(y, row.data());
    std::uint8_t* out = &filtered[std::size_t(y - band.first) * (stride + 1)];
    out[0] = 1;  // Sub
    for (std::size_t i = 0; i < stride; ++i)
      out[i + 1] = std::uint8_t(row[i] - (i >= 3 ? row[i - 3] : 0));
  }
  band.length = filtered.size();
  band.adler = adler32(1L, filtered.data(), uInt(filtered.size()));
  // Raw deflate (negative window bits). A band that is not the last ends
  // with a full flush: byte-aligned, and no later band refers back into
  // it, so the bands' streams can be joined as they are.
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_SPEED, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return;
  band.deflated.assign(deflateBound(&z, uLong(filtered.size())) + 16, '\0');
  z.next_in = filtered.data();
  z.avail_in = uInt(filtered.size());
  z.next_out = reinterpret_cast<Bytef*>(band.deflated.data());
  z.avail_out = uInt(band.deflated.size());
  int status = deflate(&z, final ? Z_FINISH : Z_FULL_FLUSH);
  band.deflated.resize(z.total_out);
  deflateEnd(&z);
  band.ok = final ? status == Z_STREAM_END : status == Z_OK && z.avail_in == 0;
}

}  // namespace

std::string encodePng(int width, int height, const PngRowSource& rows, int threads) {
  // Bands of at least 64 rows, one per thread.
  int count = std::clamp(std::min(threads, height / 64), 1, 64);
  std::vector<Band> bands(count);
  for (int i = 0; i < count; ++i) {
    bands[i].first = int(std::int64_t(height) * i / count);
    bands[i].last = int(std::int64_t(height) * (i + 1) / count);
  }
  std::vector<std::thread> workers;
  for (int i = 1; i < count; ++i)
    workers.emplace_back([&, i] { encodeBand(bands[i], width, rows, i == count - 1); });
  encodeBand(bands[0], width, rows, count == 1);
  for (std::thread& w : workers) w.join();

  // The zlib stream (RFC 1950): header, the bands' deflate data, and the
  // Adler-32 of everything, combined from the bands'.
  std::string compressed("\x78\x01", 2);
  uLong adler = 1;
  for (const Band& band : bands) {
    if (!band.ok) throw std::runtime_error("PNG compression failed");
    compressed += band.deflated;
    adler = adler32_combine(adler, band.adler, z_off_t(band.length));
  }
  putBigEndian(compressed, std::uint32_t(adler));

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
