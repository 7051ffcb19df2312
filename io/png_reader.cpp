#include "io/png_reader.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace csgray::detail {

namespace {

// The fuzzer's build (fuzz/fuzz_png.cpp) leaves the CRC check out.
#ifdef CSGRAY_PNG_SKIP_CRC
constexpr bool kCheckCrc = false;
#else
constexpr bool kCheckCrc = true;
#endif

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t bigEndian(const unsigned char* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// The image header (IHDR): colour types 0 grey, 2 RGB, 3 palette, 4 grey
// and alpha, 6 RGBA.
struct Header {
  std::uint32_t width = 0, height = 0;
  int depth = 0, colorType = 0;
  bool interlaced = false;

  int samples() const {
    static constexpr int kSamples[7] = {1, 0, 3, 1, 2, 0, 4};
    return kSamples[colorType];
  }
  int bitsPerPixel() const { return samples() * depth; }
  // The byte distance the filters look back (the spec's bpp): at least 1.
  int filterStride() const { return (bitsPerPixel() + 7) / 8; }
};

Header parseHeader(const unsigned char* data, std::uint32_t length) {
  if (length != 13)
    throw std::runtime_error("its IHDR chunk is " + std::to_string(length) + " bytes long, not 13");
  Header h;
  h.width = bigEndian(data);
  h.height = bigEndian(data + 4);
  h.depth = data[8];
  h.colorType = data[9];
  if (h.width == 0 || h.height == 0) throw std::runtime_error("the image is empty");
  // The allowed pairs of colour type and bit depth (the spec's table 11.1).
  const int d = h.depth;
  const bool lowDepth = d == 1 || d == 2 || d == 4 || d == 8;
  const bool allowed = h.colorType == 0   ? lowDepth || d == 16
                       : h.colorType == 3 ? lowDepth
                       : h.colorType == 2 || h.colorType == 4 || h.colorType == 6
                           ? d == 8 || d == 16
                           : false;
  if (!allowed)
    throw std::runtime_error("colour type " + std::to_string(h.colorType) + " with " +
                             std::to_string(d) + "-bit samples is not a PNG image kind");
  if (data[10] != 0 || data[11] != 0)
    throw std::runtime_error("unknown compression or filter method");
  if (data[12] > 1) throw std::runtime_error("unknown interlace method");
  h.interlaced = data[12] == 1;
  return h;
}

// A pass of the image's pixels: every pixel, or one of Adam7's seven.
struct Pass {
  std::uint32_t x0, y0, dx, dy;
  std::uint32_t columns(std::uint32_t width) const {
    return width > x0 ? (width - x0 + dx - 1) / dx : 0;
  }
  std::uint32_t rows(std::uint32_t height) const {
    return height > y0 ? (height - y0 + dy - 1) / dy : 0;
  }
};
constexpr Pass kWhole[1] = {{0, 0, 1, 1}};
constexpr Pass kAdam7[7] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                            {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};

std::size_t rowBytes(const Header& h, std::uint32_t columns) {
  return (std::size_t(columns) * h.bitsPerPixel() + 7) / 8;
}

// Paeth's predictor (the spec's section 9.4): of the left, upper and upper
// left bytes, the one nearest to left + upper − upper left.
int paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// Undoes a row's filter in place (the spec's section 9.2); prior is the
// row above in the same pass, all zeros for its first row.
void unfilter(int filter, unsigned char* row, const unsigned char* prior, std::size_t bytes,
              std::size_t stride) {
  auto add = [&](std::size_t i, int predicted) {
    row[i] = static_cast<unsigned char>(row[i] + predicted);
  };
  const std::size_t head = std::min(stride, bytes);  // bytes with none to their left
  switch (filter) {
    case 0:
      break;
    case 1:
      for (std::size_t i = stride; i < bytes; ++i) add(i, row[i - stride]);
      break;
    case 2:
      for (std::size_t i = 0; i < bytes; ++i) add(i, prior[i]);
      break;
    case 3:
      for (std::size_t i = 0; i < head; ++i) add(i, prior[i] / 2);
      for (std::size_t i = stride; i < bytes; ++i) add(i, (row[i - stride] + prior[i]) / 2);
      break;
    case 4:
      for (std::size_t i = 0; i < head; ++i) add(i, prior[i]);
      for (std::size_t i = stride; i < bytes; ++i)
        add(i, paeth(row[i - stride], prior[i], prior[i - stride]));
      break;
    default:
      throw std::runtime_error("unknown row filter " + std::to_string(filter));
  }
}

// Sample s (counted across the row) of an unfiltered row.
unsigned sampleAt(const unsigned char* row, std::size_t s, int depth) {
  if (depth == 8) return row[s];
  if (depth == 16) return unsigned(row[2 * s]) << 8 | row[2 * s + 1];
  const std::size_t bit = s * depth;  // samples fill bytes from the high bit
  return (row[bit / 8] >> (8 - depth - bit % 8)) & ((1u << depth) - 1);
}

// The zlib stream of the IDAT chunks, inflated to exactly `size` bytes.
std::string inflateAll(const std::string& compressed, std::size_t size) {
  std::string out(size, '\0');
  z_stream z{};
  if (inflateInit(&z) != Z_OK) throw std::runtime_error("cannot start zlib");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  z.avail_in = uInt(compressed.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(size);
  const int status = inflate(&z, Z_FINISH);
  const std::size_t made = z.total_out;
  const std::string why = z.msg ? z.msg : "";
  inflateEnd(&z);
  if (status == Z_DATA_ERROR || status == Z_NEED_DICT)
    throw std::runtime_error("its image data are corrupt (" + why + ")");
  // More data than the image needs are left unread, as libpng does.
  if (made < size) throw std::runtime_error("its image data end early");
  return out;
}

}  // namespace

bool hasPngSignature(const std::string& bytes) {
  return bytes.size() >= sizeof kSignature &&
         std::memcmp(bytes.data(), kSignature, sizeof kSignature) == 0;
}

PngPixels decodePng(const std::string& bytes, long maxPixels) {
  if (!hasPngSignature(bytes)) throw std::runtime_error("not a PNG file");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  Header header;
  bool seenHeader = false;
  std::vector<std::array<unsigned char, 3>> palette;
  std::string compressed;
  // Chunks: length, type, data, CRC of type and data (the spec's 5.3).
  for (std::size_t at = sizeof kSignature; at < bytes.size();) {
    if (bytes.size() - at < 12) throw std::runtime_error("the file ends inside a chunk");
    const std::uint32_t length = bigEndian(data + at);
    const std::string type(bytes, at + 4, 4);
    if (!std::all_of(type.begin(), type.end(),
                     [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }))
      throw std::runtime_error("a chunk's type is not four letters");
    if (length > bytes.size() - at - 12)
      throw std::runtime_error("the file ends inside its " + type + " chunk");
    const unsigned char* body = data + at + 8;
    // Bit 5 of a type's first letter clear (upper case): a critical chunk,
    // one a decoder must understand; others may be passed over.
    const bool critical = !(data[at + 4] & 0x20);
    const bool crcOk =
        !kCheckCrc || crc32(0, data + at + 4, length + 4) == bigEndian(body + length);
    at += std::size_t(length) + 12;
    if (!crcOk) {
      if (critical) throw std::runtime_error("CRC error in its " + type + " chunk");
      continue;  // a damaged ancillary chunk is dropped, as libpng does
    }
    if (!seenHeader && type != "IHDR") throw std::runtime_error("it does not begin with IHDR");
    if (type == "IHDR") {
      if (seenHeader) throw std::runtime_error("it has two IHDR chunks");
      header = parseHeader(body, length);
      seenHeader = true;
      if (long(header.width) > maxPixels / long(header.height))
        throw std::runtime_error(std::to_string(header.width) + "x" +
                                 std::to_string(header.height) + " pixels, more than the " +
                                 std::to_string(maxPixels) + " allowed");
    } else if (type == "PLTE") {
      if (length == 0 || length % 3 != 0 || length > 3 * 256)
        throw std::runtime_error("its PLTE chunk is " + std::to_string(length) + " bytes long");
      palette.resize(length / 3);
      for (std::size_t i = 0; i < palette.size(); ++i)
        std::memcpy(palette[i].data(), body + 3 * i, 3);
    } else if (type == "IDAT") {
      compressed.append(reinterpret_cast<const char*>(body), length);
    } else if (type == "IEND") {
      break;
    } else if (critical) {
      throw std::runtime_error("it has a critical chunk csgray does not know, " + type);
    }
  }
  if (!seenHeader) throw std::runtime_error("it has no IHDR chunk");
  if (header.colorType == 3 && palette.empty())
    throw std::runtime_error("a palette image without a PLTE chunk");
  if (compressed.empty()) throw std::runtime_error("it has no image data");

  const Pass* passes = header.interlaced ? kAdam7 : kWhole;
  const int passCount = header.interlaced ? 7 : 1;
  std::size_t filtered = 0;  // each row: a filter byte and its bytes
  for (int p = 0; p < passCount; ++p) {
    const std::uint32_t columns = passes[p].columns(header.width);
    if (columns > 0) filtered += passes[p].rows(header.height) * (1 + rowBytes(header, columns));
  }
  std::string raw = inflateAll(compressed, filtered);

  PngPixels image;
  image.width = int(header.width);
  image.height = int(header.height);
  image.grey = header.colorType == 0 || header.colorType == 4;
  const int channels = image.grey ? 1 : 3;
  image.values.resize(std::size_t(header.width) * header.height * channels);
  // Codes as floats the way OpenImageIO (libpng's data through
  // OIIO::convert_type) makes them: an 8- or 16-bit code times the
  // reciprocal of its largest code; samples of 1, 2 or 4 bits first spread
  // to 8 bits (× 255, 85 or 17), as libpng's expansion does.
  const float scale = header.depth == 16 ? 1.0f / 65535.0f : 1.0f / 255.0f;
  const unsigned spread = header.depth < 8 ? 255u / ((1u << header.depth) - 1) : 1u;
  const int samples = header.samples();
  const std::size_t stride = std::size_t(header.filterStride());
  unsigned char* next = reinterpret_cast<unsigned char*>(raw.data());
  for (int p = 0; p < passCount; ++p) {
    const Pass& pass = passes[p];
    const std::uint32_t columns = pass.columns(header.width), rows = pass.rows(header.height);
    if (columns == 0) continue;
    const std::size_t bytes = rowBytes(header, columns);
    const std::vector<unsigned char> zeros(bytes, 0);
    const unsigned char* prior = zeros.data();
    for (std::uint32_t r = 0; r < rows; ++r) {
      unsigned char* row = next + 1;
      unfilter(next[0], row, prior, bytes, stride);
      const std::size_t y = pass.y0 + std::size_t(r) * pass.dy;
      for (std::uint32_t c = 0; c < columns; ++c) {
        float* out =
            &image.values[(y * header.width + pass.x0 + std::size_t(c) * pass.dx) * channels];
        const std::size_t first = std::size_t(c) * samples;
        if (header.colorType == 3) {
          const unsigned index = sampleAt(row, first, header.depth);
          if (index >= palette.size())
            throw std::runtime_error("a pixel's palette index " + std::to_string(index) +
                                     " is past the palette's " + std::to_string(palette.size()) +
                                     " colours");
          for (int k = 0; k < 3; ++k) out[k] = float(palette[index][k]) * scale;
        } else {
          for (int k = 0; k < channels; ++k)
            out[k] = float(sampleAt(row, first + k, header.depth) * spread) * scale;
        }
      }
      prior = row;
      next += 1 + bytes;
    }
  }
  return image;
}

}  // namespace csgray::detail
