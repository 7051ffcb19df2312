#include "io/image_file.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/file_bytes.h"
#include "io/image_formats.h"
#include "io/input_file.h"
#include "io/png_file.h"
#include "io/png_reader.h"
#include "io/srgb.h"

namespace csgray::detail {

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

bool isPngFile(const std::string& path) { return lowerExtension(path) == ".png"; }

bool keepsFloatValues(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".exr" || ext == ".hdr" || ext == ".pfm";
}

SrgbEncoder::SrgbEncoder() {
  // The step from code k to k + 1 is the decoding of the midpoint
  // (k + 0.5) / 255 between the two codes.
  for (int k = 0; k < 255; ++k) steps_[k] = decodeSrgb((float(k) + 0.5f) / 255.0f);
  steps_[255] = 2.0f;  // above every clamped value
  // The code at each bucket's start: the number of steps at or below it,
  // found in one sweep since both rise together.
  int code = 0;
  for (int i = 0; i < kBuckets; ++i) {
    float v = float(i) / float(kBuckets - 1);
    while (v > steps_[code]) ++code;
    start_[i] = std::uint8_t(code);
  }
}

std::string imageFormatProblem(const std::string& path) {
  if (std::filesystem::path(path).extension().empty())
    return "no file extension to tell the image format (use .png, .exr, ...)";
  if (isPngFile(path)) return "";
  return imageFormats().outputProblem(path);
}

std::string imageOutputProblem(const std::string& path) {
  if (std::string problem = outputPathProblem(path); !problem.empty()) return problem;
  return imageFormatProblem(path);
}

PngRowSource pngRows(const float* rgb, int width, ImageData data) {
  static const SrgbEncoder srgb;
  const std::size_t stride = std::size_t(width) * 3;
  return [rgb, stride, data](int y, std::uint8_t* out) {
    const float* in = rgb + std::size_t(y) * stride;
    for (std::size_t i = 0; i < stride; ++i)
      out[i] = data == ImageData::LinearColor
                   ? srgb(in[i])
                   : std::uint8_t(std::lround(255.0f * std::clamp(in[i], 0.0f, 1.0f)));
  };
}

void writeImage(const std::string& path, int width, int height, const float* rgb, ImageData data,
                int threads, PngEncoder* started) {
  AtomicFile file(path);
  writeImageUncommitted(file, path, width, height, rgb, data, threads, started);
  file.commit();
}

void writeImageUncommitted(AtomicFile& file, const std::string& path, int width, int height,
                           const float* rgb, ImageData data, int threads, PngEncoder* started) {
  if (!isPngFile(path)) {
    imageFormats().write(file.tempPath(), path, width, height, rgb, data);
    return;
  }
  std::optional<PngEncoder> own;
  PngEncoder& encoder = started ? *started : own.emplace(width, height);
  std::string png = encoder.finish(pngRows(rgb, width, data), threads);
  writeFileBytes(file.tempPath(), path, png.data(), png.size());
}

TextureImage readTextureImage(const std::string& path) {
  auto fail = [&](const std::string& why) {
    return std::runtime_error("cannot read texture image " + path + ": " + why);
  };
  // Opened here, not in OpenImageIO, which would wait for ever on a FIFO.
  InputFile file(path);
  if (!file.problem().empty()) throw fail(file.problem());
  // PNG files by their signature, whatever their name, without loading
  // OpenImageIO (io/png_reader.h); the first bytes say which.
  std::string bytes;
  if (!file.readUpTo(bytes, 8)) throw fail(file.problem());
  if (!hasPngSignature(bytes)) return imageFormats().read(path);
  constexpr std::size_t kMaxPngBytes = std::size_t{256} << 20;
  if (file.size() > kMaxPngBytes) throw fail("the file is larger than 256 MiB");
  if (!file.readUpTo(bytes, std::size_t(file.size()))) throw fail(file.problem());
  PngPixels png;
  try {
    png = decodePng(bytes, kMaxTexturePixels);
  } catch (const std::runtime_error& e) {
    throw fail(e.what());
  }
  TextureImage image;
  image.width = png.width;
  image.height = png.height;
  image.rgb.resize(std::size_t(png.width) * png.height * 3);
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = decodeSrgb(png.values[png.grey ? i / 3 : i]);
  return image;
}

}  // namespace csgray::detail
