// PNG files written by csgray itself: the bands compressed on several
// threads join into one valid stream, and the pixels read back (through
// OpenImageIO, an independent decoder) are the ones written.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>
#include <vector>

#include "io/image_file.h"
#include "io/png_file.h"
#include "io/srgb.h"

namespace csgray::detail {
namespace {

std::vector<std::uint8_t> readBack(const std::string& path, int& w, int& h) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  w = in->spec().width;
  h = in->spec().height;
  EXPECT_EQ(in->spec().nchannels, 3);
  std::vector<std::uint8_t> pixels(std::size_t(w) * h * 3);
  EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
  return pixels;
}

TEST(Png, BandsOnSeveralThreadsDecodeToTheSamePixels) {
  const int w = 97, h = 301;  // odd sizes: bands of unequal height
  std::mt19937 rng(1);
  std::vector<std::uint8_t> pixels(std::size_t(w) * h * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i)  // smooth areas and noise
    pixels[i] = i % 7 == 0 ? std::uint8_t(rng()) : std::uint8_t(i / 300);
  auto rows = [&](int y, std::uint8_t* out) {
    std::copy_n(&pixels[std::size_t(y) * w * 3], w * 3, out);
  };
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "csgray_png_test";
  std::filesystem::create_directories(dir);
  for (int threads : {1, 2, 3, 8}) {
    std::string path = (dir / ("bands" + std::to_string(threads) + ".png")).string();
    std::ofstream(path, std::ios::binary) << encodePng(w, h, rows, threads);
    int rw = 0, rh = 0;
    std::vector<std::uint8_t> back = readBack(path, rw, rh);
    ASSERT_EQ(rw, w);
    ASSERT_EQ(rh, h);
    EXPECT_EQ(back, pixels) << threads << " threads";
  }
  std::filesystem::remove_all(dir);
}

// The renderer hands bands over in whatever order its threads finish
// them; the file does not depend on it, nor on who encodes the rest.
TEST(Png, BandsEncodedInAnyOrderGiveTheSameFile) {
  const int w = 50, h = 4 * PngEncoder::kBandRows + 7;
  std::mt19937 rng(3);
  std::vector<std::uint8_t> pixels(std::size_t(w) * h * 3);
  for (std::uint8_t& p : pixels) p = std::uint8_t(rng() % 5 * 60);
  auto rows = [&](int y, std::uint8_t* out) {
    std::copy_n(&pixels[std::size_t(y) * w * 3], w * 3, out);
  };
  const std::string whole = encodePng(w, h, rows, 1);
  PngEncoder encoder(w, h);
  ASSERT_EQ(encoder.bands(), 5);
  std::thread a([&] { encoder.encodeBand(4, rows); });
  std::thread b([&] { encoder.encodeBand(1, rows); });
  encoder.encodeBand(2, rows);
  a.join();
  b.join();
  EXPECT_EQ(encoder.finish(rows, 2), whole);  // bands 0 and 3 encoded here
}

TEST(Png, SrgbCodesAreTheRoundedTransferFunction) {
  SrgbEncoder encode;
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 200000; ++i) {
    float v = i % 2 ? u(rng) : u(rng) * 0.01f;  // also the dark, linear segment
    float exact = 255.0f * encodeSrgb(v);
    int code = encode(v);
    // Equal to the rounding, except within float error of a midpoint.
    if (std::abs(exact - std::floor(exact) - 0.5f) > 1e-3f) {
      ASSERT_EQ(code, int(std::lround(exact))) << v;
    } else {
      ASSERT_NEAR(code, exact, 0.51f) << v;
    }
  }
  EXPECT_EQ(encode(0.0f), 0);
  EXPECT_EQ(encode(-1.0f), 0);
  EXPECT_EQ(encode(std::nanf("")), 0);
  EXPECT_EQ(encode(1.0f), 255);
  EXPECT_EQ(encode(7.0f), 255);
}

TEST(Png, WriteImageEncodesLinearColoursAsSrgb) {
  const int w = 64, h = 130;
  std::vector<float> rgb(std::size_t(w) * h * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = float(i % 1000) / 999.0f;
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "csgray_png_test2";
  std::filesystem::create_directories(dir);
  std::string path = (dir / "linear.png").string();
  writeImage(path, w, h, rgb.data(), ImageData::LinearColor, 2);
  int rw = 0, rh = 0;
  std::vector<std::uint8_t> back = readBack(path, rw, rh);
  ASSERT_EQ(back.size(), rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i)
    ASSERT_NEAR(back[i], 255.0f * encodeSrgb(rgb[i]), 0.51f) << i;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace csgray::detail
