#include "io/png_file.h"

#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>

namespace csgray::detail {

namespace {

void putBigEndian(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xFF));
}

std::uint32_t crcOf(std::uint32_t crc, const std::string& bytes) {
  return std::uint32_t(
      ::crc32(crc, reinterpret_cast<const Bytef*>(bytes.data()), uInt(bytes.size())));
}

// A chunk: length, type, data and the CRC-32 of type and data (PNG 5.3).
void putChunk(std::string& out, const char* type, const std::string& data) {
  putBigEndian(out, std::uint32_t(data.size()));
  std::string typed = std::string(type, 4) + data;
  out += typed;
  putBigEndian(out, crcOf(0, typed));
}

}  // namespace

PngEncoder::PngEncoder(int width, int height) : width_(width), height_(height) {
  const std::size_t filteredRow = std::size_t(width) * 3 + 1;
  std::size_t total = 0;
  for (int first = 0; first < height; first += kBandRows) {
    Band band;
    band.first = first;
    band.last = std::min(height, first + kBandRows);
    band.offset = total;
    // zlib's bound for any settings, and a few bytes for the full flush
    // that ends a band.
    band.capacity = deflateBound(nullptr, uLong(filteredRow * (band.last - band.first))) + 16;
    total += band.capacity;
    bands_.push_back(band);
  }
  out_.reset(new std::uint8_t[total]);
}

void PngEncoder::encodeBand(int index, const PngRowSource& rows) {
  Band& band = bands_[index];
  band.encoded = true;
  const bool final = index == bands() - 1;
  // Raw deflate (negative window bits). A band that is not the last ends
  // with a full flush: byte-aligned, and no later band refers back into
  // it, so the bands' streams can be joined as they are.
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_SPEED, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return;
  std::uint8_t* out = out_.get() + band.offset;
  z.next_out = out;
  z.avail_out = uInt(band.capacity);
  // Each row starts with its filter type. The "Sub" filter (PNG 9.2: each
  // byte minus the one a pixel to the left) makes smooth shading compress
  // well at zlib's fastest level. Rows go to zlib one at a time.
  const std::size_t stride = std::size_t(width_) * 3;
  std::vector<std::uint8_t> row(stride), filtered(stride + 1);
  filtered[0] = 1;  // Sub
  uLong adler = 1;
  bool ok = true;
  for (int y = band.first; y < band.last && ok; ++y) {
    rows(y, row.data());
    for (std::size_t i = 0; i < stride; ++i)
      filtered[i + 1] = std::uint8_t(row[i] - (i >= 3 ? row[i - 3] : 0));
    adler = adler32(adler, filtered.data(), uInt(filtered.size()));
    z.next_in = filtered.data();
    z.avail_in = uInt(filtered.size());
    ok = deflate(&z, Z_NO_FLUSH) == Z_OK && z.avail_in == 0;
  }
  int status = ok ? deflate(&z, final ? Z_FINISH : Z_FULL_FLUSH) : Z_STREAM_ERROR;
  band.size = z.total_out;
  band.length = z.total_in;
  band.adler = std::uint32_t(adler);
  band.crc = std::uint32_t(::crc32(0L, out, uInt(band.size)));
  band.ok = final ? status == Z_STREAM_END : status == Z_OK && z.avail_out > 0;
  deflateEnd(&z);
}

std::string PngEncoder::finish(const PngRowSource& rows, int threads) {
  std::vector<int> left;
  for (int i = 0; i < bands(); ++i)
    if (!bands_[i].encoded) left.push_back(i);
  std::atomic<std::size_t> next = 0;
  auto work = [&] {
    for (std::size_t i; (i = next++) < left.size();) encodeBand(left[i], rows);
  };
  std::vector<std::thread> workers;
  for (int i = 1; i < std::min(threads, int(left.size())); ++i) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();

  std::string header;
  putBigEndian(header, std::uint32_t(width_));
  putBigEndian(header, std::uint32_t(height_));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, filters, no interlace
  std::string png("\x89PNG\r\n\x1a\n", 8);
  putChunk(png, "IHDR", header);
  putChunk(png, "sRGB", std::string(1, '\0'));  // perceptual rendering intent

  // IDAT holds the zlib stream (RFC 1950): header, the bands' deflate data
  // and the Adler-32 of everything. Its checksums are combined from the
  // bands', so the join only copies.
  std::size_t deflated = 0;
  for (const Band& band : bands_) {
    if (!band.ok) throw std::runtime_error("PNG compression failed");
    deflated += band.size;
  }
  png.reserve(png.size() + deflated + 64);
  const std::string start("IDAT\x78\x01", 6);
  putBigEndian(png, std::uint32_t(2 + deflated + 4));
  png += start;
  std::uint32_t crc = crcOf(0, start);
  uLong adler = 1;
  for (const Band& band : bands_) {
    png.append(reinterpret_cast<const char*>(out_.get() + band.offset), band.size);
    crc = std::uint32_t(crc32_combine(crc, band.crc, z_off_t(band.size)));
    adler = adler32_combine(adler, band.adler, z_off_t(band.length));
  }
  std::string trailer;
  putBigEndian(trailer, std::uint32_t(adler));
  png += trailer;
  putBigEndian(png, crcOf(crc, trailer));
  putChunk(png, "IEND", "");
  return png;
}

std::string encodePng(int width, int height, const PngRowSource& rows, int threads) {
  return PngEncoder(width, height).finish(rows, threads);
}

}  // namespace csgray::detail
