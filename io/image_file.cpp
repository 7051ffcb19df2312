#include "io/image_file.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"

namespace csgray {

namespace {

// The sRGB transfer function (IEC 61966-2-1).
float encodeSrgb(float linear) {
  float v = std::clamp(linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

bool keepsFloat(const std::string& formatName) {
  return formatName == "openexr" || formatName == "hdr" || formatName == "pfm";
}

}  // namespace

std::string imageOutputProblem(const std::string& path) {
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    return "folder " + folder.string() + " does not exist";
  if (::access(folder.c_str(), W_OK) != 0) return "folder " + folder.string() + " is not writable";
  if (std::filesystem::is_directory(path, error)) return "it is a folder";
  std::string ext = std::filesystem::path(path).extension().string();
  if (ext.empty()) return "no file extension to tell the image format (use .png, .exr, ...)";
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    (void)OIIO::geterror();
    return "unknown image format '" + ext + "'";
  }
  return "";
}

void writeImage(const std::string& path, int width, int height, const float* linearRgb) {
  AtomicFile file(path);
  auto out = OIIO::ImageOutput::create(file.tempPath());
  if (!out) throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
  bool linear = keepsFloat(out->format_name());
  OIIO::ImageSpec spec(width, height, 3, linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", linear ? "linear" : "sRGB");
  std::vector<float> pixels(linearRgb, linearRgb + static_cast<size_t>(width) * height * 3);
  if (!linear)
    for (float& v : pixels) v = encodeSrgb(v);
  if (!out->open(file.tempPath(), spec) ||
      !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close()) {
    std::string why = out->geterror();
    throw std::runtime_error("cannot write " + path + ": " + (why.empty() ? "write failed" : why));
  }
  file.commit();
}

}  // namespace csgray
