#include "export/opened_pinches.h"

#include "engine/primitive.h"
#include "primitives/profile_sweep.h"
#include "profile/pinch_points.h"
#include "profile/region_evaluation.h"

namespace csgray::detail {

SolidPtr pinchesOpened(const SolidPtr& part, double by) {
  bool any = false;
  SolidPtr mapped = part->mapPrimitives([&](const Primitive& primitive) -> SolidPtr {
    auto* sweep = dynamic_cast<const RegionSweep*>(&primitive);
    if (sweep == nullptr) return primitive.shared_from_this();
    const Region& region = *sweep->sweptRegion();
    const double tolerance = evaluationTolerance(region);
    if (!touchesItself(evaluate(region, tolerance))) return primitive.shared_from_this();
    const Profile opened = offsetDelta(region, -by, false, tolerance);
    if (opened.loops.empty()) return primitive.shared_from_this();
    any = true;
    return sweep->sweepOf(Region::leaf(opened));
  });
  return any ? mapped : part;
}

}  // namespace csgray::detail
