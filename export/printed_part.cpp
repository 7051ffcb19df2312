#include "export/printed_part.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "engine/boolean.h"
#include "scene/surface.h"

namespace csgray::detail {

SolidPtr printedPart(const Scene& scene, const std::string& script, const char* verb,
                     const std::function<void(const std::string& message)>& warn) {
  if (scene.objects.empty()) {
    for (const SurfacePtr& surface : scene.surfaces)
      if (surface->shape() == Surface::Shape::Region)
        throw std::runtime_error(
            script + ": the 2D region" +
            (surface->kind() == "region" ? "" : " (a " + surface->kind() + ")") +
            " is not a solid, so it has no mesh: extrude it (linear_extrude, rotate_extrude) or "
            "export its outline to .svg or .dxf");
    throw std::runtime_error(script + ": there is no solid to " + verb +
                             " (open surfaces cannot be printed)");
  }
  if (const std::size_t surfaces = scene.surfaces.size(); surfaces > 0)
    warn(script + ": " + std::to_string(surfaces) + " open surface" +
         (surfaces == 1 ? " is" : "s are") + " not " + verb + "ed: only solids are");
  return scene.objects.size() == 1 ? scene.objects[0] : unionOf(scene.objects);
}

std::string floatPrecisionProblem(const Solid& part, double tolerance) {
  // Far from the origin a 32-bit float (every format here stores floats)
  // cannot hold the tolerance: half its spacing at |x| is |x|·2⁻²⁴.
  const Bounds box = part.bounds();
  if (!box.finite()) return "";
  double reach = 0.0;
  for (int a = 0; a < 3; ++a) reach = std::max({reach, std::abs(box.lo[a]), std::abs(box.hi[a])});
  const double precision = std::ldexp(reach, -24);
  if (precision <= 0.5 * tolerance) return "";
  char text[300];
  std::snprintf(text, sizeof text,
                "the part reaches %g from the origin, where the file's 32-bit floats are good to "
                "%.2g only, more than half the tolerance (%g); move it nearer the origin or give "
                "a larger tolerance",
                reach, precision, 0.5 * tolerance);
  return text;
}

void checkFloatPrecision(const Solid& part, double tolerance, const std::string& script) {
  if (std::string problem = floatPrecisionProblem(part, tolerance); !problem.empty())
    throw std::runtime_error(script + ": " + problem);
}

}  // namespace csgray::detail
