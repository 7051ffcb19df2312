#include "scene/color_map.h"

#include <cmath>
#include <stdexcept>

#include "scene/value_checks.h"

namespace csgray::detail {

ColorMap::ColorMap(std::vector<ColorStop> stops, const std::string& function)
    : stops_(std::move(stops)) {
  if (stops_.size() < 2 || stops_.size() > kMaxStops)
    throw std::invalid_argument(function + ": colors must be from 2 to " +
                                std::to_string(kMaxStops) + " colours, not " +
                                std::to_string(stops_.size()));
  for (std::size_t i = 0; i < stops_.size(); ++i) {
    const ColorStop& s = stops_[i];
    if (!(s.at >= 0.0 && s.at <= 1.0))
      throw std::invalid_argument(function + ": colors[" + std::to_string(i + 1) +
                                  "]: a stop's place must be in [0, 1]");
    if (i > 0 && s.at < stops_[i - 1].at)
      throw std::invalid_argument(function + ": colors[" + std::to_string(i + 1) +
                                  "]: stops must be in order of their places");
    checkColor(function, "colors", s.color);
  }
}

ColorMap ColorMap::evenly(const std::vector<dvec3>& colors, const std::string& function) {
  std::vector<ColorStop> stops;
  for (std::size_t i = 0; i < colors.size(); ++i)
    stops.push_back({colors.size() > 1 ? double(i) / double(colors.size() - 1) : 0.0, colors[i]});
  return ColorMap(std::move(stops), function);
}

dvec3 ColorMap::at(double t) const {
  if (!(t > stops_.front().at)) return stops_.front().color;  // NaN too
  if (t >= stops_.back().at) return stops_.back().color;
  // The segment [a, b) that holds t: few stops, so a walk.
  std::size_t i = 1;
  while (stops_[i].at <= t) ++i;
  const ColorStop &a = stops_[i - 1], &b = stops_[i];
  const double s = (t - a.at) / (b.at - a.at);
  return a.color + (b.color - a.color) * s;
}

}  // namespace csgray::detail
