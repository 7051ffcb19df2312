#include "scene/value_checks.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <vector>

namespace csgray::detail {

namespace {

[[noreturn]] void refuse(const std::string& function, const char* key, const std::string& what) {
  throw std::invalid_argument(function + ": " + key + " " + what);
}

}  // namespace

void checkFinite(const std::string& function, const char* key, double value) {
  if (!std::isfinite(value)) refuse(function, key, "must be finite");
}

void checkFinite(const std::string& function, const char* key, const dvec3& vector) {
  if (!std::isfinite(vector.x) || !std::isfinite(vector.y) || !std::isfinite(vector.z))
    refuse(function, key, "must be finite");
}

void checkUnit(const std::string& function, const char* key, double value) {
  checkFinite(function, key, value);
  if (value < 0.0 || value > 1.0) refuse(function, key, "must be in [0, 1]");
}

void checkPositive(const std::string& function, const char* key, double value) {
  checkFinite(function, key, value);
  if (!(value > 0.0)) refuse(function, key, "must be > 0");
}

void checkNonNegative(const std::string& function, const char* key, double value) {
  checkFinite(function, key, value);
  if (!(value >= 0.0)) refuse(function, key, "must be >= 0");
}

void checkColor(const std::string& function, const char* key, const dvec3& color) {
  checkFinite(function, key, color);
  if (color.x < 0.0 || color.y < 0.0 || color.z < 0.0)
    refuse(function, key, "components must be >= 0");
}

void checkNonZero(const std::string& function, const char* key, const dvec3& vector) {
  checkFinite(function, key, vector);
  if (!(glm::length(vector) > 0.0)) refuse(function, key, "must not be the zero vector");
}

int checkWhole(const std::string& function, const char* key, double value, int lo, int hi) {
  checkFinite(function, key, value);
  if (value != std::floor(value) || value < lo || value > hi)
    refuse(function, key,
           "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return int(value);
}

std::string shownValue(std::string_view text, std::size_t length) {
  std::string shown;
  if (text.size() <= length) {
    shown = text;
  } else {
    // The cuts move off UTF-8 continuation bytes, not to split a character.
    auto continues = [&](std::size_t i) { return (text[i] & 0xC0) == 0x80; };
    std::size_t head = length * 2 / 3, tail = text.size() - (length - head - 3);
    while (head > 0 && continues(head)) --head;
    while (tail < text.size() && continues(tail)) ++tail;
    shown = std::string(text.substr(0, head)) + "..." + std::string(text.substr(tail));
  }
  // A message is an exception's text, a C string: a NUL would end it here.
  std::replace(shown.begin(), shown.end(), '\0', '?');
  return shown;
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace csgray::detail
