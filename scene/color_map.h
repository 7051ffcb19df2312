// A colour map: the colours a pattern blends as its value t goes from 0 to
// 1, given at stops (POV-Ray's color_map): linear between neighbouring
// stops, the first colour below the first stop and the last above the
// last. Two stops at one place make a sharp edge there.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "engine/ray.h"

namespace csgray::detail {

struct ColorStop {
  double at;  // in [0, 1]
  dvec3 color;
};

class ColorMap {
 public:
  static constexpr std::size_t kMaxStops = 256;

  // a at 0, b at 1.
  ColorMap(const dvec3& a, const dvec3& b) : stops_{{0.0, a}, {1.0, b}} {}
  ColorMap(const std::pair<dvec3, dvec3>& ab) : ColorMap(ab.first, ab.second) {}  // NOLINT
  // Checked as the script checks it, under `function`'s name ("gradient:
  // colors ..."): 2 to kMaxStops stops, their places in [0, 1] and in
  // order, their colours finite and >= 0. Throws std::invalid_argument.
  ColorMap(std::vector<ColorStop> stops, const std::string& function);
  // Colours spaced evenly from 0 to 1 (at least two).
  static ColorMap evenly(const std::vector<dvec3>& colors, const std::string& function);

  dvec3 at(double t) const;
  const std::vector<ColorStop>& stops() const { return stops_; }

 private:
  std::vector<ColorStop> stops_;
};

}  // namespace csgray::detail
