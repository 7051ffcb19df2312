#include "profile/region_operations.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/degrees.h"
#include "profile/region_evaluation.h"
#include "profile/shapes.h"

namespace csgray::detail {

RegionPtr mappedRegion(const Region& region, const Affine2& map, const char* function) {
  const double det = map.linear[0][0] * map.linear[1][1] - map.linear[1][0] * map.linear[0][1];
  double size = 0.0;
  for (int c = 0; c < 2; ++c)
    for (int r = 0; r < 2; ++r) size = std::max(size, std::abs(map.linear[c][r]));
  if (!std::isfinite(det) || !(std::abs(det) > 1e-12 * size * size))
    throw std::invalid_argument(std::string(function) +
                                ": the map squashes the plane (it is singular)");
  RegionPtr mapped = region.transformed(map);
  const ProfileBounds& b = mapped->bounds();
  if (!b.empty() && !(std::max({std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.hi.x),
                                std::abs(b.hi.y)}) <= kLargestCoordinate))
    throw std::invalid_argument(std::string(function) +
                                ": the region's coordinates would pass 1e150");
  return mapped;
}

Affine2 turnMap(double degrees) {
  if (!std::isfinite(degrees)) throw std::invalid_argument("rotate: the angle must be finite");
  const dvec2 cs = unitCircleDegrees(degrees);
  Affine2 map;
  map.linear = dmat2(cs.x, cs.y, -cs.y, cs.x);
  return map;
}

Affine2 scaleMap(const dvec2& factors, const char* function) {
  if (factors.x == 0.0 || factors.y == 0.0)
    throw std::invalid_argument(std::string(function) + ": a factor of 0 squashes the region flat");
  Affine2 map;
  map.linear = dmat2(factors.x, 0.0, 0.0, factors.y);
  return map;
}

Affine2 mirrorMap(const dvec2& normal, const char* function) {
  const double length2 = normal.x * normal.x + normal.y * normal.y;
  if (!(length2 > 0.0) || !std::isfinite(length2))
    throw std::invalid_argument(std::string(function) + ": the normal must not be zero");
  // I − 2 n nᵀ / |n|² (a Householder reflection).
  Affine2 map;
  map.linear =
      dmat2(1.0 - 2.0 * normal.x * normal.x / length2, -2.0 * normal.x * normal.y / length2,
            -2.0 * normal.x * normal.y / length2, 1.0 - 2.0 * normal.y * normal.y / length2);
  return map;
}

RegionPtr offsetRegion(const Region& region, std::optional<double> r, std::optional<double> delta,
                       std::optional<bool> chamfer) {
  if (r && delta) throw std::invalid_argument("offset: give r or delta, not both");
  if (!r && !delta)
    throw std::invalid_argument("offset: needs r= (rounded) or delta= (with chamfer=true or not)");
  if (r && chamfer)
    throw std::invalid_argument("offset: chamfer goes with delta=, not with r= (which rounds)");
  if (const double by = r ? *r : *delta; std::isfinite(by) && std::abs(by) > kLargestCoordinate)
    throw std::invalid_argument(std::string("offset: ") + (r ? "r" : "delta") +
                                " is too large (at most 1e150 either way)");
  const double tolerance = evaluationTolerance(region);
  return Region::leaf(r ? offsetRounded(region, *r, tolerance)
                        : offsetDelta(region, *delta, chamfer.value_or(false), tolerance));
}

RegionPtr hullOfRegions(const std::vector<RegionPtr>& regions) {
  if (regions.empty()) throw std::invalid_argument("hull: needs at least one region");
  double tolerance = 1e300;
  for (const RegionPtr& r : regions) tolerance = std::min(tolerance, evaluationTolerance(*r));
  return Region::leaf(hull(regions, tolerance));
}

RegionPtr minkowskiOfRegions(const std::vector<RegionPtr>& regions) {
  if (regions.empty()) throw std::invalid_argument("minkowski: needs at least one region");
  RegionPtr sum = regions[0];
  for (std::size_t i = 1; i < regions.size(); ++i) {
    const double tolerance = std::min(evaluationTolerance(*sum), evaluationTolerance(*regions[i]));
    try {
      sum = Region::leaf(minkowskiSum(sum, regions[i], tolerance));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("minkowski: ") + e.what());
    }
  }
  return sum;
}

double regionArea(const Region& region) {
  return area(evaluate(region, evaluationTolerance(region)));
}

}  // namespace csgray::detail
