// The occluder cache of shadow rays: the solid that blocked a light's last
// shadow ray is asked first about the next one. Neighbouring pixels send
// shadow rays that run side by side, so the part that hides one from a
// light usually hides the next too; when it does, the answer (the light is
// blocked) is exact and the walk of the scene's and the unions' BVHs is
// skipped. This is the shadow cache of the ray-tracing literature (the
// last occluder kept per light: Arvo and Kirk, "A Survey of Ray Tracing
// Acceleration Techniques", in Glassner (ed.), "An Introduction to Ray
// Tracing", 1989; a cousin of Haines and Greenberg's light buffer, IEEE
// CG&A 6(9), 1986), which POV-Ray uses too; the code is csgray's own.
//
// What is remembered is not the whole top-level solid (a union of 200
// parts would cost as much as the walk) but the deepest operand found
// meeting the ray through unions and instances: the chain of instances
// that leads to it, whose frames take the ray into its frame, and the
// operand itself. A union contains each of its operands and an instance
// is its child moved, so that operand meeting the segment means the
// top-level solid does: the light is blocked, whatever else lies there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/instance.h"
#include "engine/solid.h"

namespace csgray::detail {

// The operand of an opaque top-level solid that met a shadow ray, and the
// way to it from the top.
class Occluder {
 public:
  // Instances deeper than this on the way are not remembered.
  static constexpr int kMaxInstances = 16;

  bool empty() const { return leaf_ == nullptr; }
  void clear() { leaf_ = nullptr; }

  // Does the solid meet the ray's open window (Solid::meetsWindow's answer,
  // with the same walk through unions and instances)? If it does, this
  // remembers the operand that met it.
  bool record(const Solid& solid, const Ray& ray, SpanList& scratch);
  // Does the remembered operand meet the ray's window? True only if the
  // solid given to record() does too (a false answer says nothing).
  bool stillMeets(const Ray& ray, SpanList& scratch) const;

 private:
  bool walk(const Solid& solid, const Ray& ray, SpanList& scratch);

  const Solid* leaf_ = nullptr;
  int instances_ = 0;  // on the way to leaf_, outermost first
  const Instance* chain_[kMaxInstances];
};

// One occluder per light, for one render thread: what blocked each light's
// last shadow ray. Which top-level object it belongs to is kept with it,
// and for an open surface (scene.surfaces) the surface's index alone.
struct ShadowCacheEntry {
  static constexpr std::uint32_t kNone = ~std::uint32_t(0);
  std::uint32_t item = kNone;  // index into the renderer's BVH items
  Occluder occluder;           // for a solid
};

class ShadowCache {
 public:
  explicit ShadowCache(std::size_t lights) : entries_(lights) {}
  ShadowCacheEntry* forLight(std::size_t light) {
    return light < entries_.size() ? &entries_[light] : nullptr;
  }

 private:
  std::vector<ShadowCacheEntry> entries_;
};

}  // namespace csgray::detail
