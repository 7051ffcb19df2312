#include "export/sweeps_apart.h"

#include <vector>

#include "engine/boolean.h"
#include "engine/primitive.h"
#include "primitives/profile_sweep.h"

namespace csgray::detail {

namespace {

SolidPtr apart(const RegionSweep& sweep, const RegionPtr& region) {
  if (region->op() == Region::Op::Leaf) return sweep.sweepOf(region);
  std::vector<SolidPtr> operands;
  for (const RegionPtr& operand : region->operands()) operands.push_back(apart(sweep, operand));
  switch (region->op()) {
    case Region::Op::Union:
      return unionOf(std::move(operands));
    case Region::Op::Intersection:
      return intersectionOf(std::move(operands));
    case Region::Op::Difference:
    case Region::Op::Leaf:
      break;
  }
  return differenceOf(std::move(operands));
}

}  // namespace

SolidPtr sweepsTakenApart(const SolidPtr& part) {
  bool any = false;
  SolidPtr mapped = part->mapPrimitives([&](const Primitive& primitive) -> SolidPtr {
    auto* sweep = dynamic_cast<const RegionSweep*>(&primitive);
    if (sweep == nullptr || sweep->sweptRegion()->op() == Region::Op::Leaf)
      return primitive.shared_from_this();
    any = true;
    return apart(*sweep, sweep->sweptRegion());
  });
  return any ? mapped : part;
}

}  // namespace csgray::detail
