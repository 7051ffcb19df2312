// Rays allocate nothing: camera and shadow rays through a plate with
// spheres and holes (bench/plate.lua), which go through a union's BVH, a
// difference's first-boundary cuts and the scene's BVH, once the first ray
// has run (operator new counted by allocation_counter.h).
#include <gtest/gtest.h>

#include <string>

#include "allocation_counter.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "script/script.h"

namespace csgray::detail {
namespace {

TEST(Rays, TracingThePlateAllocatesNothing) {
  for (const char* n : {"8", "64"}) {
    ScriptOptions options;
    options.defines = {{"n", n}};
    Scene scene = runScriptFile(std::string(CSGRAY_SOURCE_DIR) + "/bench/plate.lua", options);
    const int w = 64, h = 48;
    Renderer renderer(scene, RenderOptions(w, h, 1));
    Camera camera(*scene.camera, w, h);
    renderer.trace(camera.ray(w / 2.0, h / 2.0));
    const long before = test::allocations();
    int hits = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        Ray ray = camera.ray(x + 0.5, y + 0.5);
        renderer.trace(ray);  // with its shadow rays to both lights
        hits += renderer.firstHit(ray).has_value();
      }
    EXPECT_EQ(test::allocations(), before) << "plate(" << n << ")";
    EXPECT_GT(hits, w * h / 3) << "plate(" << n << ")";  // the rays did meet the part
  }
}

}  // namespace
}  // namespace csgray::detail
