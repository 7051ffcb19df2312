#include "scene/region_surface.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace csgray::detail {

SurfacePtr regionSurface(RegionPtr region, const std::string& kind) {
  if (!region) throw std::invalid_argument(kind + ": no region");
  return std::make_shared<Surface>(std::move(region), Affine(), kind);
}

std::optional<Affine2> planarMap(const Affine& frame) {
  const glm::dmat4& m = frame.worldFromObject();  // m[column][row]
  // The size of the map's x and y columns, against which rounding is told
  // from a real tilt.
  double scale = 0.0;
  for (int c = 0; c < 2; ++c)
    for (int r = 0; r < 3; ++r) scale = std::max(scale, std::abs(m[c][r]));
  if (std::abs(m[0][2]) > 1e-12 * scale || std::abs(m[1][2]) > 1e-12 * scale) return std::nullopt;
  if (m[3][2] != 0.0) return std::nullopt;  // moved off the plane
  Affine2 map;
  map.linear = dmat2(m[0][0], m[0][1], m[1][0], m[1][1]);
  map.offset = dvec2(m[3][0], m[3][1]);
  return map;
}

RegionPtr regionInPlane(const Surface& surface) {
  if (surface.shape() != Surface::Shape::Region) return nullptr;
  const std::optional<Affine2> map = planarMap(surface.frame());
  if (!map) return nullptr;
  return surface.region()->transformed(*map);
}

}  // namespace csgray::detail
