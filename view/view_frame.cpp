#include "view/view_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <regex>
#include <stdexcept>
#include <vector>

#include "scene/camera.h"

namespace csgray::detail {

namespace {

constexpr int kMaxSide = 4096;

// The one value of a parameter, or nothing; twice is an error.
std::optional<std::string> single(const std::multimap<std::string, std::string>& query,
                                  const std::string& key) {
  auto [first, last] = query.equal_range(key);
  if (first == last) return std::nullopt;
  if (std::next(first) != last) throw std::invalid_argument(key + " is given twice");
  return first->second;
}

double finiteNumber(const std::string& text, const std::string& key) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
    throw std::invalid_argument(key + " must be a finite number");
  return value;
}

// Numbers separated by commas, as many as count.
std::vector<double> numberList(const std::string& text, const std::string& key, std::size_t count,
                               const std::string& what) {
  std::vector<double> numbers;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    numbers.push_back(finiteNumber(text.substr(start, comma - start), key));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (numbers.size() != count) throw std::invalid_argument(key + " must be " + what);
  return numbers;
}

// A switch: 0 or 1.
bool flag(const std::string& text, const std::string& key) {
  if (text != "0" && text != "1") throw std::invalid_argument(key + " must be 0 or 1");
  return text == "1";
}

}  // namespace

int FrameRequest::passWidth() const { return pass == 0 ? (width + 3) / 4 : width; }
int FrameRequest::passHeight() const { return pass == 0 ? (height + 3) / 4 : height; }

void FrameRequest::applyTo(Scene& scene) const {
  if (camera) scene.camera = camera;
  if (!ghosts) scene.ghosts.clear();
  if (!highlights) scene.highlights.clear();
}

FrameRequest parseFrameRequest(const std::multimap<std::string, std::string>& query) {
  FrameRequest request;
  if (auto size = single(query, "size")) {
    std::smatch m;
    if (!std::regex_match(*size, m, std::regex(R"((\d{1,5})x(\d{1,5}))")))
      throw std::invalid_argument("size must be WIDTHxHEIGHT, e.g. 800x600");
    request.width = std::stoi(m[1]);
    request.height = std::stoi(m[2]);
    if (request.width < 1 || request.height < 1 || request.width > kMaxSide ||
        request.height > kMaxSide)
      throw std::invalid_argument("size must be 1 to " + std::to_string(kMaxSide) + " per side");
  }
  if (auto pass = single(query, "pass")) {
    if (*pass != "0" && *pass != "1" && *pass != "2")
      throw std::invalid_argument("pass must be 0, 1 or 2");
    request.pass = (*pass)[0] - '0';
  }
  const auto fov = single(query, "fov"), ortho = single(query, "ortho");
  if (fov && ortho) throw std::invalid_argument("give fov or ortho, not both");
  if (auto camera = single(query, "camera")) {
    const std::vector<double> numbers =
        numberList(*camera, "camera", 9, "9 numbers: eye, target and up");
    CameraSpec spec;
    spec.eye = {numbers[0], numbers[1], numbers[2]};
    spec.lookAt = {numbers[3], numbers[4], numbers[5]};
    spec.up = {numbers[6], numbers[7], numbers[8]};
    std::optional<double> width;
    if (fov) {
      spec.fovDegrees = finiteNumber(*fov, "fov");
      if (!(spec.fovDegrees > 0.0 && spec.fovDegrees < 180.0))
        throw std::invalid_argument("fov must be between 0 and 180 degrees");
    }
    if (ortho) {
      spec.orthographic = true;
      width = finiteNumber(*ortho, "ortho");
      if (!(*width > 0.0)) throw std::invalid_argument("ortho must be a width above 0");
    }
    request.camera = checkedCamera(spec, width);  // throws for a degenerate camera
  } else if (fov || ortho) {
    throw std::invalid_argument("fov and ortho need a camera");
  }
  if (auto ghosts = single(query, "ghosts")) request.ghosts = flag(*ghosts, "ghosts");
  if (auto highlights = single(query, "highlights"))
    request.highlights = flag(*highlights, "highlights");
  if (auto section = single(query, "section")) {
    const std::vector<double> n =
        numberList(*section, "section", 4, "4 numbers: the plane's normal and offset");
    // Scaled by its largest entry first, so that the length of a normal
    // of 1e308s does not overflow.
    const double largest = std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
    if (!(largest > 0.0)) throw std::invalid_argument("section's normal must not be zero");
    const dvec3 normal = dvec3(n[0], n[1], n[2]) / largest;
    const double length = glm::length(normal);
    request.section = SectionPlane{normal / length, n[3] / largest / length};
  }
  return request;
}

}  // namespace csgray::detail
