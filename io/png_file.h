// PNG files written without OpenImageIO: 8-bit RGB, the format of every
// preview, kept off the path that loads OpenImageIO's many libraries.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace csgray::detail {

// Writes the 8-bit RGB bytes of image row y (width · 3 of them) to out.
using PngRowSource = std::function<void(int y, std::uint8_t* out)>;

// A PNG file (ISO/IEC 15948) of width × height pixels of 8-bit RGB, rows
// from the top, encoded in bands of kBandRows rows. Each band is filtered
// and deflated on its own, an independent deflate stream, and the streams
// are joined into one (as pigz does): so bands can be compressed on
// several threads at once, and while later rows are still being rendered.
class PngEncoder {
 public:
  static constexpr int kBandRows = 32;

  PngEncoder(int width, int height);
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  int bands() const { return int(bands_.size()); }
  // Filters and compresses band i, rows [i · kBandRows, (i + 1) · kBandRows)
  // (fewer in the last band), read from `rows`. Each band once; different
  // bands may be encoded on different threads at the same time.
  void encodeBand(int band, const PngRowSource& rows);
  // The file's bytes: encodes the bands not encoded yet, on up to `threads`
  // threads, and joins them. Throws std::runtime_error if compression failed.
  std::string finish(const PngRowSource& rows, int threads);

 private:
  struct Band {
    int first = 0, last = 0;   // rows [first, last)
    std::size_t offset = 0;    // where its deflate data go in out_
    std::size_t capacity = 0;  // room for them there
    std::size_t size = 0;      // length of its deflate data
    std::uint32_t crc = 0;     // CRC-32 of its deflate data
    std::uint32_t adler = 1;   // Adler-32 of its filtered bytes
    std::size_t length = 0;    // number of filtered bytes
    bool encoded = false, ok = false;
  };

  int width_, height_;
  std::vector<Band> bands_;
  // The bands' raw deflate data, each in its slice; left uninitialised, so
  // that only the pages written are ever touched.
  std::unique_ptr<std::uint8_t[]> out_;
};

// The bytes of a PNG file of width × height pixels, bands compressed on up
// to `threads` threads. Throws std::runtime_error if compression fails.
std::string encodePng(int width, int height, const PngRowSource& rows, int threads = 1);

}  // namespace csgray::detail
