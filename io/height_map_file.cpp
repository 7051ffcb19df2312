#include "io/height_map_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "engine/printable_token.h"
#include "io/input_file.h"
#include "io/png_reader.h"
#include "io/srgb.h"

namespace csgray::detail {

namespace {

constexpr std::size_t kMaxFileBytes = std::size_t{256} << 20;
constexpr std::size_t kMaxRows = std::size_t{1} << 16;

HeightMap heightMapOfImage(const TextureImage& image, bool invert) {
  HeightMap map;
  map.rows = std::size_t(image.height);
  map.columns = std::size_t(image.width);
  map.heights.resize(map.rows * map.columns);
  // The image's 8-bit codes again (readTextureImage decodes sRGB).
  static const SrgbEncoder encode;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const dvec3 rgb = image.at(x, y);
      const double luminance = 0.2126 * encode(float(rgb.r)) + 0.7152 * encode(float(rgb.g)) +
                               0.0722 * encode(float(rgb.b));
      map.heights[std::size_t(image.height - 1 - y) * map.columns + std::size_t(x)] =
          100.0 / 255.0 * (invert ? 1.0 - luminance : luminance);
    }
  return map;
}

}  // namespace

HeightMap heightMapOfText(const std::string& text, const std::string& name) {
  std::vector<std::vector<double>> rows;
  std::size_t at = 0;
  int line = 0;
  std::size_t count = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    const std::string_view row = std::string_view(text).substr(at, end - at);
    at = end + 1;
    ++line;
    std::vector<double> values;
    std::size_t i = 0;
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (i < row.size() && blank(row[i])) ++i;
    if (i == row.size() || row[i] == '#') continue;
    while (i < row.size()) {
      std::size_t j = i;
      while (j < row.size() && !blank(row[j])) ++j;
      std::string_view token = row.substr(i, j - i);
      if (!token.empty() && token.front() == '+') token.remove_prefix(1);
      double v = 0.0;
      auto [stop, error] = std::from_chars(token.data(), token.data() + token.size(), v);
      if (error != std::errc() || stop != token.data() + token.size() || token.empty() ||
          !std::isfinite(v))
        throw std::invalid_argument(name + ":" + std::to_string(line) + ": '" +
                                    printableToken(row.substr(i, j - i), 40) + "' is not a number");
      values.push_back(v);
      i = j;
      while (i < row.size() && blank(row[i])) ++i;
    }
    count += values.size();
    if (count > kMaxHeightMapPoints || rows.size() >= kMaxRows)
      throw std::invalid_argument(name + ":" + std::to_string(line) + ": more than " +
                                  std::to_string(kMaxHeightMapPoints) + " heights or " +
                                  std::to_string(kMaxRows) + " rows");
    rows.push_back(std::move(values));
  }
  HeightMap map;
  map.rows = rows.size();
  for (const auto& r : rows) map.columns = std::max(map.columns, r.size());
  if (map.rows * map.columns > kMaxHeightMapPoints)
    throw std::invalid_argument(name + ": more than " + std::to_string(kMaxHeightMapPoints) +
                                " heights");
  map.heights.assign(map.rows * map.columns, 0.0);
  for (std::size_t r = 0; r < map.rows; ++r)
    std::copy(rows[r].begin(), rows[r].end(), map.heights.begin() + r * map.columns);
  return map;
}

HeightMap readHeightMap(const std::string& path, const std::string& name, bool invert,
                        const std::function<TextureImage(const std::string&)>& loadImage) {
  // A PNG is told by its first bytes and left to loadImage, which reads it
  // itself (read here too, the file was held twice while it was decoded).
  if (!hasPngSignature(readInputFileStart(path, name, 8)))
    return heightMapOfText(readInputFile(path, name, kMaxFileBytes), name);
  if (!loadImage) throw std::invalid_argument(name + ": this program cannot read images");
  try {
    return heightMapOfImage(loadImage(path), invert);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
}

}  // namespace csgray::detail
