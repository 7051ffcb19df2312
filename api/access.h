// How the library reaches the internal value behind a public one, and
// makes a public value of an internal one. The public classes hold their
// internals privately and name Access their friend, so that users see
// neither.
#pragma once

#include <utility>

#include "csgray/region.h"
#include "csgray/scene.h"
#include "profile/region.h"
#include "scene/scene.h"

// The state of a public Scene: the internal scene, and the count of its
// objects' primitives that the script's scene{} keeps as it adds them.
struct csgray::Scene::Impl {
  detail::Scene scene;
  detail::ObjectTally tally;
};

namespace csgray::detail {

struct Access {
  static const SolidPtr& of(const csgray::Solid& s) { return s.impl_.pointer(); }
  static csgray::Solid solid(SolidPtr p) { return csgray::Solid(std::move(p)); }

  static const RegionPtr& of(const csgray::Region& r) { return r.impl_.pointer(); }
  static csgray::Region region(RegionPtr p) { return csgray::Region(std::move(p)); }

  static const TexturePtr& of(const csgray::Texture& t) { return t.impl_.pointer(); }
  static csgray::Texture texture(TexturePtr p) { return csgray::Texture(std::move(p)); }

  static const SurfacePtr& of(const csgray::Surface& s) { return s.impl_.pointer(); }
  static csgray::Surface surface(SurfacePtr p) { return csgray::Surface(std::move(p)); }

  static const Scene& of(const csgray::Scene& s) { return s.impl_->scene; }
  // A scene made elsewhere (by a script), within the limits already.
  static csgray::Scene scene(Scene s) {
    csgray::Scene made;
    for (const SolidPtr& object : s.objects) made.impl_->tally.add(object->primitiveCount(), "");
    made.impl_->tally.add(s.surfaces.size(), "");
    made.impl_->scene = std::move(s);
    return made;
  }
};

}  // namespace csgray::detail
