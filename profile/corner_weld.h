// Corners of polygons placed side by side in doubles meet only to
// rounding: a honeycomb's cells have corners at 2·cos 60° =
// 1.0000000000000002 from one centre and at 3 − 2 = 1 from the next.
// Their exact union keeps slivers that wide between the cells, and a
// sweep of it has walls a hair apart that pinch. A CornerWeld moves the
// corners between two straight edges that lie within a hair of another
// such corner onto one of them, so that shared edges coincide exactly;
// a corner that meets no other, and every end of an arc, stays where it
// is (a sweep's circles keep the cylinders' polygons they were given).
#pragma once

#include <map>
#include <utility>

#include "profile/region.h"

namespace csgray::detail {

class CornerWeld {
 public:
  // The corners of every leaf of the region, its Bézier curves flattened
  // within ellipseTolerance as the evaluation flattens them.
  CornerWeld(const Region& region, double ellipseTolerance);

  // The corner p is welded to, or p.
  dvec2 operator()(const dvec2& p) const;
  bool empty() const { return moved_.empty(); }

 private:
  std::map<std::pair<double, double>, dvec2> moved_;
};

}  // namespace csgray::detail
