// The exact volume of a solid as `csgray check` measures it: the lengths
// inside it along three grids of rays, one along each axis, each ray at a
// random point of its cell (stratified sampling: unbiased, and no aliasing
// with a regular pattern of holes), the three volumes averaged. The check
// traces the same rays for more than their lengths (check/ray_grids.h);
// the library's Solid::volume() asks only for the volume.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/bounds.h"
#include "engine/solid.h"

namespace csgray::detail {

// The n × n rays along one axis over a box, whole lines, one at a random
// point of each cell; the seed places them, the same on any threads.
class RayGrid {
 public:
  RayGrid(const Bounds& box, int axis, int n, std::uint64_t seed);

  // The ray of cell (i, j), i across the next axis and j the one after.
  Ray ray(int i, int j) const;

  // The grid's volume from its rays' lengths inside the solid (ray (i, j)
  // at i·n + j), and the standard deviation of that estimate: at least one
  // cell's column through the box, since a part thinner than a cell (a
  // crescent 10⁻⁵ wide) may fall between all the rays of one grid and
  // across many of another's.
  struct Volume {
    double volume = 0.0;
    double sigma = 0.0;
  };
  Volume volume(const std::vector<double>& lengths) const;

 private:
  dvec3 lo_, along_{0.0};
  int axis_, u_, v_;  // along axis_, across u_ and v_
  double du_, dv_;    // the cells' sides
  double length_;     // the box's along axis_
  std::uint64_t seed_;
};

// The mean of the three grids' volumes over the solid's box, grid × grid
// rays each, placed as the check places them with its default seed. 0 for
// an empty solid; the solid must not be unbounded.
double exactVolume(const Solid& solid, int grid);

}  // namespace csgray::detail
