// PNG files read by csgray itself (io/png_reader.h): every colour type and
// bit depth, interlaced or not, with every row filter, decodes to the
// samples it was made of, and to the same floats as OpenImageIO (libpng)
// reads from the same file; damaged files are refused in one line.
#include "io/png_reader.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/image_file.h"
#include "io/srgb.h"

namespace csgray::detail {
namespace {

// A PNG image to encode: its samples (each below 2^depth), row-major, so
// many a pixel as its colour type has.
struct TestImage {
  int width = 0, height = 0, colorType = 0, depth = 8;
  bool interlaced = false;
  std::vector<unsigned> samples;
  std::vector<std::array<std::uint8_t, 3>> palette;

  int samplesPerPixel() const {
    return colorType == 2 ? 3 : colorType == 4 ? 2 : colorType == 6 ? 4 : 1;
  }
};

void putBigEndian(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xff);
}

void putChunk(std::string& out, const std::string& type, const std::string& data) {
  putBigEndian(out, std::uint32_t(data.size()));
  const std::string body = type + data;
  out += body;
  putBigEndian(
      out, std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
}

// The PNG signature and an IHDR chunk.
std::string signatureAndHeader(int width, int height, int depth = 8, int colorType = 0,
                               bool interlaced = false) {
  std::string png = "\x89PNG\r\n\x1a\n";
  std::string header;
  putBigEndian(header, std::uint32_t(width));
  putBigEndian(header, std::uint32_t(height));
  header += char(depth);
  header += char(colorType);
  header += std::string(2, '\0');  // compression and filter method 0
  header += char(interlaced ? 1 : 0);
  putChunk(png, "IHDR", header);
  return png;
}

std::string zlibOf(const std::string& bytes) {
  uLongf size = compressBound(uLong(bytes.size()));
  std::string zlib(size, '\0');
  EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(zlib.data()), &size,
                      reinterpret_cast<const Bytef*>(bytes.data()), uLong(bytes.size()), 9),
            Z_OK);
  zlib.resize(size);
  return zlib;
}

// Adam7 as the PNG specification draws it: the pass of each pixel of an
// 8 × 8 tile (an encoder's view, unlike the decoder's table of steps).
constexpr int kAdam7Tile[8][8] = {{1, 6, 4, 6, 2, 6, 4, 6}, {7, 7, 7, 7, 7, 7, 7, 7},
                                  {5, 6, 5, 6, 5, 6, 5, 6}, {7, 7, 7, 7, 7, 7, 7, 7},
                                  {3, 6, 4, 6, 3, 6, 4, 6}, {7, 7, 7, 7, 7, 7, 7, 7},
                                  {5, 6, 5, 6, 5, 6, 5, 6}, {7, 7, 7, 7, 7, 7, 7, 7}};

int predictPaeth(int left, int up, int upLeft) {
  const int estimate = left + up - upLeft;
  const int dl = std::abs(estimate - left), du = std::abs(estimate - up),
            dc = std::abs(estimate - upLeft);
  if (dl <= du && dl <= dc) return left;
  return du <= dc ? up : upLeft;
}

// The image as a PNG file: each scanline filtered with the filter given
// by its index (all five in turn), the zlib stream cut into IDAT chunks of
// idatPiece bytes; `extra` chunks go before the first IDAT.
std::string encode(const TestImage& image, std::size_t idatPiece = 1000,
                   const std::string& extra = "") {
  const int spp = image.samplesPerPixel(), bits = spp * image.depth;
  const int stride = (bits + 7) / 8;
  std::string filtered;
  int scanline = 0;
  for (int pass = 1; pass <= (image.interlaced ? 7 : 1); ++pass) {
    std::vector<std::uint8_t> prior;
    for (int y = 0; y < image.height; ++y) {
      std::vector<int> xs;
      for (int x = 0; x < image.width; ++x)
        if (!image.interlaced || kAdam7Tile[y % 8][x % 8] == pass) xs.push_back(x);
      if (xs.empty()) continue;
      std::vector<std::uint8_t> row((xs.size() * bits + 7) / 8, 0);
      std::size_t s = 0;
      for (int x : xs)
        for (int k = 0; k < spp; ++k, ++s) {
          const unsigned v = image.samples[(std::size_t(y) * image.width + x) * spp + k];
          if (image.depth == 16) {
            row[2 * s] = std::uint8_t(v >> 8);
            row[2 * s + 1] = std::uint8_t(v);
          } else {
            const std::size_t bit = s * image.depth;
            row[bit / 8] |= std::uint8_t(v << (8 - image.depth - bit % 8));
          }
        }
      if (prior.empty()) prior.assign(row.size(), 0);
      const int filter = scanline++ % 5;
      filtered += char(filter);
      for (std::size_t i = 0; i < row.size(); ++i) {
        const int left = i >= std::size_t(stride) ? row[i - stride] : 0;
        const int upLeft = i >= std::size_t(stride) ? prior[i - stride] : 0;
        const int predicted = filter == 1   ? left
                              : filter == 2 ? prior[i]
                              : filter == 3 ? (left + prior[i]) / 2
                              : filter == 4 ? predictPaeth(left, prior[i], upLeft)
                                            : 0;
        filtered += char(std::uint8_t(row[i] - predicted));
      }
      prior = row;
    }
  }
  const std::string zlib = zlibOf(filtered);
  std::string png =
      signatureAndHeader(image.width, image.height, image.depth, image.colorType, image.interlaced);
  if (!image.palette.empty()) {
    std::string entries;
    for (const auto& rgb : image.palette) entries.append(rgb.begin(), rgb.end());
    putChunk(png, "PLTE", entries);
  }
  png += extra;
  for (std::size_t at = 0; at < zlib.size(); at += idatPiece)
    putChunk(png, "IDAT", zlib.substr(at, idatPiece));
  putChunk(png, "IEND", "");
  return png;
}

TestImage randomImage(int width, int height, int colorType, int depth, bool interlaced,
                      unsigned seed) {
  TestImage image{width, height, colorType, depth, interlaced, {}, {}};
  std::mt19937 rng(seed);
  const unsigned top = (1u << depth) - 1;
  if (colorType == 3) {
    image.palette.resize(std::size_t(top) + 1);
    for (auto& rgb : image.palette)
      for (auto& c : rgb) c = std::uint8_t(rng());
  }
  image.samples.resize(std::size_t(width) * height * image.samplesPerPixel());
  for (unsigned& v : image.samples) v = rng() % (top + 1);
  // The extremes too, where a scale that is a little off shows.
  image.samples.front() = 0;
  image.samples.back() = top;
  return image;
}

// What each pixel's value must be: the code over the largest code, with
// codes of 1, 2 and 4 bits spread to 8 first and palette indices looked up.
float expectedValue(const TestImage& image, std::size_t pixel, int channel) {
  const int spp = image.samplesPerPixel();
  const unsigned v = image.samples[pixel * spp + (image.colorType == 3 ? 0 : channel)];
  if (image.colorType == 3) return float(image.palette[v][channel]) * (1.0f / 255.0f);
  if (image.depth == 16) return float(v) * (1.0f / 65535.0f);
  return float(v * (255u / ((1u << image.depth) - 1))) * (1.0f / 255.0f);
}

struct Kind {
  int colorType, depth;
};
const std::vector<Kind> kEveryKind = {{0, 1}, {0, 2},  {0, 4},  {0, 8}, {0, 16},
                                      {2, 8}, {2, 16}, {3, 1},  {3, 2}, {3, 4},
                                      {3, 8}, {4, 8},  {4, 16}, {6, 8}, {6, 16}};

TEST(PngReader, EveryKindDecodesToTheSamplesItWasMadeOf) {
  unsigned seed = 1;
  for (const Kind& kind : kEveryKind)
    for (bool interlaced : {false, true})
      // Sizes with empty Adam7 passes (1 × 1, 3 × 2) and with partial tiles.
      for (auto [w, h] : {std::pair{1, 1}, {3, 2}, {13, 11}, {40, 9}}) {
        const TestImage image = randomImage(w, h, kind.colorType, kind.depth, interlaced, seed++);
        const PngPixels png = decodePng(encode(image, 7), 1L << 24);
        const std::string what = "colour type " + std::to_string(kind.colorType) + ", " +
                                 std::to_string(kind.depth) + " bits, " +
                                 (interlaced ? "interlaced, " : "") + std::to_string(w) + "x" +
                                 std::to_string(h);
        ASSERT_EQ(png.width, w) << what;
        ASSERT_EQ(png.height, h) << what;
        const bool grey = kind.colorType == 0 || kind.colorType == 4;
        ASSERT_EQ(png.grey, grey) << what;
        const int channels = grey ? 1 : 3;
        ASSERT_EQ(png.values.size(), std::size_t(w) * h * channels) << what;
        for (std::size_t p = 0; p < std::size_t(w) * h; ++p)
          for (int c = 0; c < channels; ++c)
            ASSERT_EQ(png.values[p * channels + c], expectedValue(image, p, c))
                << what << ", pixel " << p << ", channel " << c;
      }
}

class PngTextures : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("csgray_png_reader_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  std::string write(const std::string& name, const std::string& bytes) {
    const std::string path = (folder_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  std::string errorOf(const std::string& path) {
    try {
      readTextureImage(path);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "(read)";
  }

  std::filesystem::path folder_;
};

// The same file through OpenImageIO, as csgray read textures before it
// read PNG itself: channels 0 to 2 (or grey), sRGB-decoded.
std::vector<float> throughOpenImageIo(const std::string& path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  const int channels = in->spec().nchannels >= 3 ? 3 : 1;
  std::vector<float> values(std::size_t(in->spec().width) * in->spec().height * channels);
  EXPECT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, values.data()));
  std::vector<float> rgb;
  for (std::size_t i = 0; i < values.size(); i += channels)
    for (int c = 0; c < 3; ++c) rgb.push_back(decodeSrgb(values[i + (channels == 3 ? c : 0)]));
  return rgb;
}

TEST_F(PngTextures, AgreeWithOpenImageIoBitForBit) {
  unsigned seed = 100;
  for (const Kind& kind : kEveryKind)
    for (bool interlaced : {false, true}) {
      const TestImage image = randomImage(19, 14, kind.colorType, kind.depth, interlaced, seed++);
      const std::string path = write("kind.png", encode(image));
      const TextureImage ours = readTextureImage(path);
      EXPECT_EQ(ours.rgb, throughOpenImageIo(path))
          << "colour type " << kind.colorType << ", " << kind.depth << " bits"
          << (interlaced ? ", interlaced" : "");
    }
}

// Alpha, from a channel or a tRNS chunk, is left out, and chunks csgray
// does not know are passed over if they are ancillary.
TEST_F(PngTextures, AlphaAndAncillaryChunksAreLeftOut) {
  TestImage image = randomImage(5, 4, 3, 8, false, 7);
  std::string extra;
  putChunk(extra, "tRNS", std::string(3, '\x10'));
  putChunk(extra, "tEXt", std::string("Comment\0made by a test", 22));
  std::string damaged;  // an ancillary chunk with a wrong CRC is dropped
  putChunk(damaged, "zzZz", "abc");
  damaged[damaged.size() - 1] ^= 1;
  const PngPixels plain = decodePng(encode(image), 1L << 24);
  const PngPixels withChunks = decodePng(encode(image, 1000, extra + damaged), 1L << 24);
  EXPECT_EQ(plain.values, withChunks.values);
  EXPECT_FALSE(plain.grey);
}

// A PNG file is told by its first bytes, not its name.
TEST_F(PngTextures, APngNamedOtherwiseIsReadAsPng) {
  const TestImage image = randomImage(6, 3, 2, 8, false, 9);
  const TextureImage a = readTextureImage(write("texture.png", encode(image)));
  const TextureImage b = readTextureImage(write("texture.jpg", encode(image)));
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(b.width, 6);
}

// Every one-byte change inside a critical chunk (IHDR, PLTE, IDAT, IEND:
// length, type, data or CRC) is refused, by its CRC if nothing else; a
// file cut short anywhere is refused or, cut after the image data, gives
// the same pixels. Each error is one line naming the file.
TEST_F(PngTextures, DamagedFilesAreRefusedInOneLine) {
  const TestImage image = randomImage(9, 7, 3, 4, true, 11);
  const std::string good = encode(image, 20);
  const PngPixels whole = decodePng(good, 1L << 24);
  for (std::size_t at = 8; at < good.size(); ++at) {
    std::string bad = good;
    bad[at] = char(bad[at] ^ 0x5a);
    const std::string path = write("damaged.png", bad);
    const std::string message = errorOf(path);
    ASSERT_EQ(message.rfind("cannot read texture image " + path + ": ", 0), 0u)
        << "byte " << at << ": " << message;
    ASSERT_EQ(message.find('\n'), std::string::npos) << message;
  }
  for (std::size_t length = 0; length < good.size(); ++length) {
    try {
      EXPECT_EQ(decodePng(good.substr(0, length), 1L << 24).values, whole.values) << length;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()), "") << length;
    }
  }
}

TEST(PngReader, SaysWhatIsWrong) {
  auto errorOf = [](const std::string& bytes) -> std::string {
    try {
      decodePng(bytes, 1L << 24);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "(decoded)";
  };
  const TestImage grey = randomImage(4, 4, 0, 8, false, 3);
  std::string png = encode(grey);
  EXPECT_EQ(errorOf("GIF89a"), "not a PNG file");
  EXPECT_EQ(errorOf(png.substr(0, 20)), "the file ends inside its IHDR chunk");
  std::string crc = png;
  crc[16] ^= 1;  // the width
  EXPECT_EQ(errorOf(crc), "CRC error in its IHDR chunk");

  // A header that asks for more pixels than allowed is refused before any
  // data are inflated.
  EXPECT_EQ(errorOf(signatureAndHeader(5000, 5000)),
            "5000x5000 pixels, more than the 16777216 allowed");

  TestImage rgb4 = grey;
  rgb4.colorType = 2;
  rgb4.depth = 4;
  rgb4.samples.assign(48, 1);
  EXPECT_EQ(errorOf(encode(rgb4)), "colour type 2 with 4-bit samples is not a PNG image kind");

  TestImage indexed = randomImage(4, 4, 3, 2, false, 5);
  indexed.palette.resize(2);  // indices 2 and 3 point past it
  std::fill(indexed.samples.begin(), indexed.samples.end(), 1);
  indexed.samples.back() = 3;
  EXPECT_EQ(errorOf(encode(indexed)), "a pixel's palette index 3 is past the palette's 2 colours");
  indexed.palette.clear();
  EXPECT_EQ(errorOf(encode(indexed)), "a palette image without a PLTE chunk");

  // An IDAT stream that holds fewer rows than the header promises.
  std::string cut = encode(grey);
  const std::string tallHeader = signatureAndHeader(4, 5);
  cut.replace(0, tallHeader.size(), tallHeader);
  EXPECT_EQ(errorOf(cut), "its image data end early");

  // A one-pixel image whose only row names filter 7 (there are five).
  std::string unknownFilter = signatureAndHeader(1, 1);
  putChunk(unknownFilter, "IDAT", zlibOf(std::string("\x07\x80", 2)));
  putChunk(unknownFilter, "IEND", "");
  EXPECT_EQ(errorOf(unknownFilter), "unknown row filter 7");
}

}  // namespace
}  // namespace csgray::detail
