#include "engine/instance.h"

#include <stdexcept>
#include <string>

#include "engine/boolean.h"
#include "engine/flat_union.h"
#include "engine/moved_box.h"
#include "engine/parts_box.h"
#include "engine/primitive.h"

namespace csgray::detail {

namespace {

// Nodes of the child visited for its box, each a box moved by a frame
// (about 60 ns): a part turned at each step of a loop is a chain of three
// or four nodes a step, so the deepest chain a tree may hold (two levels
// a step, Boolean::kMaxDepth) is walked whole; a part shared through
// levels of instances (2^k uses at k levels) is walked as far as this goes.
constexpr std::size_t kPartsVisits = 2048;

// Does the map take each axis onto an axis (the box's moved corners are
// then the moved box itself)?
bool keepsAxes(const Affine& map) {
  const glm::dmat4& m = map.worldFromObject();
  for (int column = 0; column < 3; ++column) {
    int nonzero = 0;
    for (int row = 0; row < 3; ++row) nonzero += m[column][row] != 0.0;
    if (nonzero > 1) return false;
  }
  return true;
}

}  // namespace

Instance::Instance(SolidPtr child, const Affine& worldFromChild)
    : child_(std::move(child)), worldFromChild_(worldFromChild) {
  primitives_ = child_->primitiveCount();
  booleans_ = child_->booleanCount();
  depth_ = child_->depth() + 1;
  if (depth_ > Boolean::kMaxDepth)
    throw std::invalid_argument(kind() + ": tree deeper than " +
                                std::to_string(Boolean::kMaxDepth) + " levels");
  insideBeyondWindow_ = child_->insideBeyondWindow();
  instances_ = true;
  const Bounds& local = child_->bounds();
  if (local.empty()) return;
  // An unbounded child may reach anywhere once moved.
  bounds_ = local.finite() ? movedBox(local, worldFromChild_) : Bounds::everything();
  // A turn boxes the child's box again (partsBox says why that grows);
  // a move, a stretch along the axes or a quarter turn keeps it exact.
  if (local.finite() && !keepsAxes(worldFromChild_)) {
    std::size_t budget = kPartsVisits;
    bounds_ = bounds_.intersected(partsBox(*child_, worldFromChild_, budget));
  }
  // A turned child's box made from its parts where they are few
  // (Solid::boundsUnder): a ray that misses it meets no part, so the
  // union's BVH above leaves it out without taking the ray into the
  // child's frame.
  rayBox_ = local.finite() ? child_->boundsUnder(worldFromChild_).intersected(bounds_) : bounds_;
}

Bounds Instance::boundsUnder(const Affine& outer) const {
  if (outer.isTranslation() || !bounds_.finite()) return Solid::boundsUnder(outer);
  return child_->boundsUnder(worldFromChild_.then(outer));
}

SolidPtr Instance::forRays() const { return keptFlatUnion(*this, flatMade_, flat_); }

Ray Instance::rayToChild(const Ray& ray) const {
  Ray r = worldFromChild_.rayToObject(ray);
  // A translation leaves the direction, and so 1/dir, as it was: three
  // divisions saved at each instance a ray goes through.
  r.invDir = r.dir == ray.dir ? ray.invDir : 1.0 / r.dir;
  return r;
}

// (Whoever asks has tested this instance's box, and the child tests its
// own, tighter one: no box test here.)
void Instance::spans(const Ray& ray, SpanList& out) const { child_->spans(rayToChild(ray), out); }

void Instance::spansToFirstBoundary(const Ray& ray, SpanList& out) const {
  child_->spansToFirstBoundary(rayToChild(ray), out);
}

bool Instance::meetsWindow(const Ray& ray, SpanList& scratch) const {
  return child_->meetsWindow(rayToChild(ray), scratch);
}

bool Instance::contains(const dvec3& p) const {
  return bounds_.contains(p) && child_->contains(worldFromChild_.pointToObject(p));
}

SolidPtr Instance::mapPrimitives(const PrimitiveMap& f) const {
  return child_->mapPrimitives([&](const Primitive& p) {
    const SolidPtr moved = p.withFrame(p.frame().then(worldFromChild_));
    return f(static_cast<const Primitive&>(*moved));
  });
}

SolidPtr Instance::mapSharedPrimitives(const PrimitiveMap& f, SharedMap& done) const {
  auto mapped = std::make_shared<Instance>(child_->mapSharedPrimitives(f, done), worldFromChild_);
  mapped->setOrigin(origin());
  return mapped;
}

SolidPtr flattened(const SolidPtr& solid) {
  if (!solid->hasInstances()) return solid;
  return solid->mapPrimitives([](const Primitive& p) { return p.shared_from_this(); });
}

}  // namespace csgray::detail
