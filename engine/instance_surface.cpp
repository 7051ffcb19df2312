#include "engine/instance_surface.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "engine/primitive.h"

namespace csgray::detail {

namespace {

// The use key one instance further out (BoundarySurface::use).
std::uintptr_t useThrough(std::uintptr_t use, const Instance& instance) {
  return use * 1000003u ^ reinterpret_cast<std::uintptr_t>(&instance);
}

BoundarySurface surfaceOf(const Primitive& primitive, const dvec3& point, const Boundary& b,
                          bool texture) {
  BoundarySurface s;
  s.normal = primitive.normal(point, int(b.face));
  if (texture) {
    s.texturePoint = primitive.texturePoint(point);
    s.textureNormal = primitive.textureNormal(point, int(b.face));
    s.textureFromWorld = primitive.textureFromWorld();
  }
  return s;
}

// The surface s, found in an instance's child, in the instance's frame
// (its texture's derivative too, when asked for).
void bringOut(BoundarySurface& s, const Instance& instance, bool texture) {
  s.normal = instance.frame().normalToWorld(s.normal);
  if (texture)
    s.textureFromWorld = s.textureFromWorld * glm::dmat3(instance.frame().objectFromWorld());
  s.use = useThrough(s.use, instance);
}

// The search for the use of b.primitive that the ray met: the candidate
// whose boundary on the same face lies nearest b.t, stopping at one within
// rounding of it.
class UseSearch {
 public:
  UseSearch(const Boundary& b, bool texture)
      : b_(b), texture_(texture), closeEnough_(1e-9 * (1.0 + std::abs(b.t))) {}

  bool found() const { return distance_ < kInfinity; }
  const BoundarySurface& surface() const { return best_; }
  // The instances on the way to the best use, outermost first; false if
  // there were more than a hint holds.
  bool wayToBest(UseHint& hint) const {
    if (bestDepth_ > UseHint::kMaxInstances) return false;
    hint.instances = bestDepth_;
    std::copy(bestWay_, bestWay_ + bestDepth_, hint.chain);
    return true;
  }

  // Looks in node, the ray given in node's frame; true when done.
  bool visit(const Solid& node, const Ray& ray) {
    if (&node == b_.primitive) return offer(static_cast<const Primitive&>(node), ray);
    if (!near(node.bounds(), ray.at(b_.t))) return false;
    if (const Instance* instance = node.asInstance()) {
      const double before = distance_;
      if (depth_ < UseHint::kMaxInstances) way_[depth_] = instance;
      ++depth_;
      const bool done = visit(*instance->child(), instance->rayToChild(ray));
      --depth_;
      // A better use below this instance: its normal into this frame.
      if (distance_ < before) bringOut(best_, *instance, texture_);
      return done;
    }
    if (const Boolean* boolean = node.asBoolean()) {
      // The operands whose boxes the ray meets about b.t, through the
      // node's BVH: a wide union is not searched operand by operand.
      Ray near = ray;
      const double slack = 1e-9 * (1.0 + std::abs(b_.t));
      near.tMin = b_.t - slack;
      near.tMax = b_.t + slack;
      bool done = false;
      boolean->forEachOperandHitBy(near, [&](const Solid& operand) {
        done = visit(operand, ray);
        return !done;
      });
      return done;
    }
    for (const SolidPtr& child : node.children())
      if (visit(*child, ray)) return true;
    return false;
  }

  // Offers b's primitive, the ray given in its frame (the last step of a
  // visit); true if it has a boundary on b's face within rounding of b.t.
  bool offer(const Primitive& primitive, const Ray& ray) {
    Ray line = ray;
    line.tMin = -kInfinity;
    line.tMax = kInfinity;
    primitive.spans(line, spans_);
    for (const Span& s : spans_)
      for (const Boundary* end : {&s.in, &s.out}) {
        const double d = std::abs(end->t - b_.t);
        if (end->face != b_.face || !(d < distance_)) continue;
        distance_ = d;
        best_ = surfaceOf(primitive, ray.at(b_.t), b_, texture_);
        bestDepth_ = depth_;
        std::copy(way_, way_ + std::min(depth_, UseHint::kMaxInstances), bestWay_);
      }
    return distance_ <= closeEnough_;
  }

 private:
  // Boxes hold their solids' surfaces up to rounding of the point.
  static bool near(const Bounds& box, const dvec3& p) {
    const double margin = 1e-9 * (1.0 + std::abs(p.x) + std::abs(p.y) + std::abs(p.z));
    return p.x >= box.lo.x - margin && p.x <= box.hi.x + margin && p.y >= box.lo.y - margin &&
           p.y <= box.hi.y + margin && p.z >= box.lo.z - margin && p.z <= box.hi.z + margin;
  }

  const Boundary& b_;
  const bool texture_;
  const double closeEnough_;
  double distance_ = kInfinity;
  BoundarySurface best_{};
  SpanList spans_;
  // The instances on the way to the node visited, and to the best use.
  int depth_ = 0, bestDepth_ = 0;
  const Instance* way_[UseHint::kMaxInstances];
  const Instance* bestWay_[UseHint::kMaxInstances];
};

// The surface at the use the hint names, if that use has a boundary on b's
// face within rounding of b.t: the search's answer there, with the same
// steps (the ray taken down the instances, the primitive offered, the
// normal brought up through the same frames innermost first).
std::optional<BoundarySurface> hintedSurface(const UseHint& hint, const Solid& root, const Ray& ray,
                                             const Boundary& b, bool texture) {
  if (hint.root != &root || !hint.knows(hint.wayEnd(), b.primitive)) return std::nullopt;
  Ray local = ray;
  for (int i = 0; i < hint.instances; ++i) local = hint.chain[i]->rayToChild(local);
  UseSearch search(b, texture);
  if (!search.offer(*b.primitive, local)) return std::nullopt;
  BoundarySurface s = search.surface();
  for (int i = hint.instances - 1; i >= 0; --i) bringOut(s, *hint.chain[i], texture);
  return s;
}

// The surface when node is a chain of instances over a tree without any (a
// boolean moved as a whole, as a script's transform of it makes): b's
// primitive has one use there, under the chain's frames, and it is the
// one the search would find, with no boxes to walk and no spans to
// recompute (12 % of the glass scene's render). Empty for other nodes.
std::optional<BoundarySurface> underInstanceChain(const Solid& node, const Ray& ray,
                                                  const Boundary& b, bool texture) {
  if (!node.hasInstances()) return surfaceOf(*b.primitive, ray.at(b.t), b, texture);
  const Instance* instance = node.asInstance();
  if (!instance) return std::nullopt;
  std::optional<BoundarySurface> s =
      underInstanceChain(*instance->child(), instance->rayToChild(ray), b, texture);
  if (s) bringOut(*s, *instance, texture);
  return s;
}

}  // namespace

const Solid* UseHint::wayEnd() const {
  return instances ? chain[instances - 1]->child().get() : root;
}

bool UseHint::knows(const Solid* subtree, const Primitive* primitive) const {
  for (const Reach& r : known)
    if (r.subtree == subtree && r.primitive == primitive) return true;
  return false;
}

void UseHint::learn(const Solid* subtree, const Primitive* primitive) {
  if (knows(subtree, primitive)) return;
  known[nextKnown] = {subtree, primitive};
  nextKnown = (nextKnown + 1) % kKnown;
}

BoundarySurface boundarySurface(const Solid& root, const Ray& ray, const Boundary& b, bool texture,
                                UseHint* hint) {
  const dvec3 point = ray.at(b.t);
  if (!root.hasInstances()) return surfaceOf(*b.primitive, point, b, texture);
  if (std::optional<BoundarySurface> s = underInstanceChain(root, ray, b, texture)) return *s;
  if (hint) {
    if (std::optional<BoundarySurface> s = hintedSurface(*hint, root, ray, b, texture)) return *s;
    hint->root = nullptr;
  }
  UseSearch search(b, texture);
  search.visit(root, ray);
  // Not found only if rounding put the point outside every box that holds
  // the primitive: its frame is then the best guess there is.
  if (!search.found()) return surfaceOf(*b.primitive, point, b, texture);
  if (hint && search.wayToBest(*hint)) {
    hint->root = &root;
    hint->learn(hint->wayEnd(), b.primitive);
  }
  return search.surface();
}

}  // namespace csgray::detail
