#include "raytrace/shadow_cache.h"

#include "engine/boolean.h"

namespace csgray::detail {

bool Occluder::record(const Solid& solid, const Ray& ray, SpanList& scratch) {
  leaf_ = nullptr;
  instances_ = 0;
  return walk(solid, ray, scratch);
}

// The walk of Instance::meetsWindow and of a union's Boolean::meetsWindow,
// step for step (the same rays, the same operands in the same order), so
// that its answer is theirs; it only notes the way down as it goes.
bool Occluder::walk(const Solid& solid, const Ray& ray, SpanList& scratch) {
  if (const Instance* instance = solid.asInstance()) {
    const int depth = instances_++;
    if (depth < kMaxInstances) chain_[depth] = instance;
    if (walk(*instance->child(), instance->rayToChild(ray), scratch)) return true;
    --instances_;
    return false;
  }
  const Boolean* boolean = solid.asBoolean();
  if (boolean && boolean->op() == Boolean::Op::Union) {
    bool met = false;
    boolean->forEachOperandHitBy(ray, [&](const Solid& operand) {
      met = walk(operand, ray, scratch);
      return !met;
    });
    return met;
  }
  if (!solid.meetsWindow(ray, scratch)) return false;
  // Too deep a chain to take the ray down again: nothing is remembered.
  if (instances_ <= kMaxInstances) leaf_ = &solid;
  return true;
}

bool Occluder::stillMeets(const Ray& ray, SpanList& scratch) const {
  if (!leaf_) return false;
  Ray local = ray;
  for (int i = 0; i < instances_; ++i) local = chain_[i]->rayToChild(local);
  // The box first, as the union's walk tests it: a ray that has moved off
  // the operand is turned away in a few comparisons.
  return leaf_->bounds().hitBy(local) && leaf_->meetsWindow(local, scratch);
}

}  // namespace csgray::detail
