// Every script in examples/ runs and renders: a small image that is not
// all background and has only finite, non-negative colours. Its part
// passes csgray check: the export agrees with the exact model; a scene of
// open surfaces alone has no part, and the export says so.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "check_support.h"
#include "engine/boolean.h"
#include "export/printed_part.h"
#include "raytrace/renderer.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

class Example : public ::testing::TestWithParam<std::string> {};

Scene runExample(const std::string& path) { return runScriptFile(path, test::exampleOptions()); }

TEST_P(Example, Renders) {
  Scene scene = runExample(GetParam());
  ASSERT_FALSE(scene.objects.empty() && scene.surfaces.empty());
  RenderOptions options(160, 120, 0);
  options.depthAov = true;
  RenderResult result = Renderer(scene, options).renderAll();
  const Image& image = result.color;
  int notBackground = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      dvec3 c = image.at(x, y);
      ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) << x << "," << y;
      ASSERT_TRUE(c.x >= 0 && c.y >= 0 && c.z >= 0) << x << "," << y;
      // Something is hit (the background of a bare solid is not one colour).
      notBackground += std::isfinite(result.depth.at(x, y).x);
    }
  }
  // The part fills a good share of the frame.
  EXPECT_GT(notBackground, image.width * image.height / 10);
}

TEST_P(Example, PassesTheCheck) {
  Scene scene = runExample(GetParam());
  if (scene.objects.empty()) {
    ASSERT_FALSE(scene.surfaces.empty());
    EXPECT_THROW(printedPart(scene, "example.lua", "export", [](const std::string&) {}),
                 std::runtime_error);
    return;
  }
  EXPECT_TRUE(test::checksOut(*unionOf(scene.objects)));
}

INSTANTIATE_TEST_SUITE_P(Examples, Example, ::testing::ValuesIn(test::exampleScripts()),
                         [](const auto& info) { return test::exampleName(info.param); });

TEST(Examples, ShowcaseIsAmongThem) {
  auto scripts = test::exampleScripts();
  EXPECT_NE(std::find_if(scripts.begin(), scripts.end(),
                         [](const std::string& p) { return p.ends_with("/showcase.lua"); }),
            scripts.end());
}

}  // namespace
}  // namespace csgray::detail
