#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>
#include <unordered_set>

#include "cli/commands.h"
#include "cli/watchdog.h"
#include "engine/primitive.h"
#include "engine/solid.h"
#include "scene/material.h"
#include "scene/scene.h"

namespace csgray::detail {

namespace {

std::string formatPoint(const dvec3& p) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "[%g, %g, %g]", p.x, p.y, p.z);
  return buffer;
}

// The stored primitives whose material has bumps (a subtree placed by
// several instances counted once): a bumped face costs a render several
// times what a plain one does.
std::size_t bumpedPrimitives(const Solid& solid, std::unordered_set<const Solid*>& seen) {
  if (!seen.insert(&solid).second) return 0;
  if (const auto* primitive = dynamic_cast<const Primitive*>(&solid))
    return primitive->material() && primitive->material()->bumps ? 1 : 0;
  std::size_t count = 0;
  for (const SolidPtr& child : solid.children()) count += bumpedPrimitives(*child, seen);
  return count;
}

void printInfo(const std::string& script, const Scene& scene) {
  TreeStats stats;
  for (const SolidPtr& object : scene.objects) {
    TreeStats s = treeStats(*object);
    stats.primitives += s.primitives;
    stats.booleans += s.booleans;
    stats.storedPrimitives += s.storedPrimitives;
  }
  // The part's box (its ghosts are no part of it); a scene of open
  // surfaces alone, theirs.
  bool metNothing = false;
  const Bounds b = scene.objects.empty() ? scene.bounds() : scene.partBounds(&metNothing);
  std::cout << script << "\n";
  if (b.empty()) {
    std::cout << "  bounds:        empty\n";
  } else if (metNothing) {
    // (A part all of whose pieces are narrower than the rays' spacing, a
    // 64th of the box, would be missed too: hence the box.)
    std::cout << "  bounds:        empty (no ray through " << formatPoint(b.lo) << " .. "
              << formatPoint(b.hi) << " meets the part)\n";
  } else {
    std::cout << "  bounds:        " << formatPoint(b.lo) << " .. " << formatPoint(b.hi) << "\n";
    if (b.finite()) std::cout << "  size:          " << formatPoint(b.size()) << "\n";
  }
  std::cout << "  objects:       " << scene.objects.size() << "\n"
            << "  primitives:    " << stats.primitives;
  // A part placed many times by instances is stored once (engine/instance.h).
  if (stats.storedPrimitives != stats.primitives)
    std::cout << " (" << stats.storedPrimitives << " distinct, the rest placed again by instances)";
  std::cout << "\n"
            << "  boolean nodes: " << stats.booleans << "\n"
            << "  surfaces:      " << scene.surfaces.size() << "\n"
            << "  lights:        " << scene.lights.size()
            << (scene.lights.empty() && scene.defaultLight ? " (default)" : "") << "\n"
            << "  camera:        " << (scene.camera ? "set" : "framed from bounds");
  // Focal blur multiplies a render's rays: say by how much.
  if (scene.camera && scene.camera->blurs())
    std::cout << " (focal blur: aperture " << scene.camera->aperture << ", at least "
              << scene.camera->blurSamples << " rays a pixel)";
  std::cout << "\n";
  std::unordered_set<const Solid*> seen;
  std::size_t bumped = 0;
  for (const SolidPtr& object : scene.objects) bumped += bumpedPrimitives(*object, seen);
  for (const SurfacePtr& surface : scene.surfaces)
    bumped += surface->material() && surface->material()->bumps ? 1 : 0;
  if (bumped > 0) std::cout << "  bumps:         on " << bumped << " primitives and surfaces\n";
  if (scene.sky) std::cout << "  background:    a texture by direction (a sky)\n";
  if (scene.fog.distance > 0.0) {
    std::cout << "  fog:           distance " << scene.fog.distance;
    if (scene.fog.ground())
      std::cout << ", ground fog up to z = " << scene.fog.offset << ", thinning over "
                << scene.fog.altitude;
    std::cout << "\n";
  }
}

}  // namespace

Command infoCommand(CLI::App& app, ScriptArguments& script) {
  CLI::App* info =
      addScriptCommand(app, "info", "Print the bounds and tree size of a part script", script);
  addScriptOptions(*info, script);
  return {info, [](const PartScript& part) {
            const Scene scene = part.run();
            // The bounds by rays of a large part take long (400 letters:
            // 20 s): --timeout covers them too.
            const Watchdog limit(part.timeLeft(), part.timedOut());
            printInfo(part.path(), scene);
            return 0;
          }};
}

}  // namespace csgray::detail
