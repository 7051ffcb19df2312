// Rays allocate nothing: camera and shadow rays through a plate with
// spheres and holes (bench/plate.lua), which go through a union's BVH, a
// difference's first-boundary cuts and the scene's BVH, and through the
// Sierpinski tetrahedron (bench/parts/sierpinski.lua), whose levels are
// instances of one another, once the first ray has run (operator new
// counted by allocation_counter.h).
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "allocation_counter.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "script/script.h"

namespace csgray::detail {
namespace {

TEST(Rays, TracingThePlateAndTheSierpinskiTetrahedronAllocatesNothing) {
  const std::string plate = std::string(CSGRAY_SOURCE_DIR) + "/bench/plate.lua";
  const std::string sierpinski = std::string(CSGRAY_SOURCE_DIR) + "/bench/parts/sierpinski.lua";
  for (const auto& [file, define, n] : {std::tuple{plate, "n", "8"}, std::tuple{plate, "n", "64"},
                                        std::tuple{sierpinski, "level", "5"}}) {
    ScriptOptions options;
    options.defines = {{define, n}};
    Scene scene = runScriptFile(file, options);
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
    EXPECT_EQ(test::allocations(), before) << file << " " << n;
    EXPECT_GT(hits, w * h / 3) << file << " " << n;  // the rays did meet the part
  }
}

}  // namespace
}  // namespace csgray::detail
