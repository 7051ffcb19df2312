#include "raytrace/section_plane.h"

#include "engine/boolean.h"
#include "primitives/half_space.h"
#include "scene/color_names.h"

namespace csgray::detail {

dvec3 sectionColor() { return srgbToLinear(dvec3(0.86, 0.35, 0.27)); }

const MaterialPtr& sectionMaterial() {
  static const MaterialPtr material = [] {
    auto m = std::make_shared<Material>();
    m->color = sectionColor();
    return m;
  }();
  return material;
}

Scene sectioned(const Scene& scene, const SectionPlane& plane) {
  // One half-space for all the solids: a cut face names it, whatever it cuts.
  const SolidPtr keep =
      Primitive::create<HalfSpace>(plane.normal, plane.offset)->withMaterial(sectionMaterial());
  // Each solid as rays walk it (Solid::forRays: nested unions as one,
  // made once per solid), since the cut is made again for every frame.
  Scene cut = scene;
  for (auto* solids : {&cut.objects, &cut.ghosts, &cut.highlights})
    for (SolidPtr& solid : *solids) solid = intersectionOf({solid->forRays(), keep});
  return cut;
}

}  // namespace csgray::detail
