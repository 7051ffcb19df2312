// The bound of the rays a render traces (raytrace/ray_estimate.h): its
// factors for known scenes, and a render never tracing more than it says.
#include "raytrace/ray_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "primitives/sphere.h"
#include "raytrace/renderer.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

Scene sphereWith(MaterialPtr material) {
  Scene scene;
  SolidPtr sphere = Primitive::create<Sphere>(1.0);
  scene.objects.push_back(material ? solidWithMaterial(sphere, material) : sphere);
  scene.camera = CameraSpec{dvec3(0, -5, 0), dvec3(0), dvec3(0, 0, 1), 30.0};
  return scene;
}

MaterialPtr material(double reflection, double transparency) {
  auto m = std::make_shared<Material>();
  m->reflection = reflection;
  m->transparency = transparency;
  m->ior = 1.5;
  return m;
}

Light sphereLight(int samples) {
  LightParams p;
  p.kind = Light::Kind::Sphere;
  p.position = dvec3(2, -2, 5);
  p.samples = samples;
  return makeLight(p);
}

// 2000 area lights of 1024 samples over a matte sphere, a three-line script,
// at the default 800x600 is 480 000 camera rays, each shaded once with
// 2 048 000 shadow rays: 9.8e11 rays.
TEST(RayEstimate, ManyAreaLights) {
  Scene scene = sphereWith(nullptr);
  scene.lights.assign(2000, sphereLight(1024));
  const RayEstimate e = estimateRays(scene, RenderOptions(800, 600));
  EXPECT_EQ(e.cameraRays, 480000.0);
  EXPECT_EQ(e.raysPerCameraRay, 1.0);
  EXPECT_EQ(e.shadowRaysPerHit, 2048000.0);
  EXPECT_EQ(e.lights, 2000u);
  EXPECT_EQ(e.total(), 480000.0 * 2048001.0);
  EXPECT_EQ(e.factors(),
            "480000 camera rays × up to 1 ray each × (1 + 2048000 shadow rays from 2000 lights)");
}

// Without lights the scene has the default one, a point light: one shadow
// ray per hit. Samples multiply the camera rays; --adaptive adds its first
// pass of one ray per pixel.
TEST(RayEstimate, SamplesAndTheDefaultLight) {
  Scene scene = sphereWith(nullptr);
  RenderOptions options(40, 30);
  options.samples = 9;
  RayEstimate e = estimateRays(scene, options);
  EXPECT_EQ(e.cameraRays, 40.0 * 30.0 * 9.0);
  EXPECT_EQ(e.shadowRaysPerHit, 1.0);
  EXPECT_EQ(e.lights, 1u);
  options.adaptive = true;
  EXPECT_EQ(estimateRays(scene, options).cameraRays, 40.0 * 30.0 * 10.0);
}

// A scene that names no lights (lights={}) has none: no shadow rays.
TEST(RayEstimate, NoLightsNoShadowRays) {
  Scene scene = sphereWith(nullptr);
  scene.defaultLight = false;
  const RayEstimate e = estimateRays(scene, RenderOptions(40, 30));
  EXPECT_EQ(e.shadowRaysPerHit, 0.0);
  EXPECT_EQ(e.lights, 0u);
}

// An area light's samples are rounded to a square (Light::sampleCount).
TEST(RayEstimate, AreaLightSamplesAreRoundedToASquare) {
  Scene scene = sphereWith(nullptr);
  scene.lights = {sphereLight(10), sphereLight(16)};
  EXPECT_EQ(estimateRays(scene, RenderOptions(8, 8)).shadowRaysPerHit, 9.0 + 16.0);
}

// A mirror makes a chain: a ray's weight halves at each bounce, and the
// tenth, 1/1024 of the pixel, is below minWeight 1/512: 9 rays under
// maxDepth 12; maxDepth 3 allows 4.
TEST(RayEstimate, MirrorsMakeAChain) {
  Scene scene = sphereWith(material(0.5, 0.0));
  scene.limits.maxDepth = 12;
  EXPECT_EQ(estimateRays(scene, RenderOptions(8, 8)).raysPerCameraRay, 10.0);
  scene.limits.maxDepth = 3;
  EXPECT_EQ(estimateRays(scene, RenderOptions(8, 8)).raysPerCameraRay, 4.0);
}

// Glass branches at every hit: 2^(d+1) − 1 rays to depth d, here the
// default 8 (reflection + transparency 1: the weight does not bound it),
// and at depth 64 the renderer's own bound.
TEST(RayEstimate, GlassMakesATree) {
  Scene scene = sphereWith(material(0.1, 0.9));
  EXPECT_EQ(estimateRays(scene, RenderOptions(8, 8)).raysPerCameraRay, 511.0);
  scene.limits.maxDepth = 64;
  EXPECT_EQ(estimateRays(scene, RenderOptions(8, 8)).raysPerCameraRay,
            double(Renderer::kRaysPerCameraRay));
}

// The bound holds: a render of glass and a mirror under an area light
// traces no more rays than it says.
TEST(RayEstimate, BoundsTheRaysTraced) {
  Scene scene = sphereWith(material(0.2, 0.7));
  scene.surfaces.push_back(
      Surface::plane(dvec3(0, 0, -1), dvec3(0, 0, 1))->withMaterial(material(0.5, 0.0)));
  scene.lights = {sphereLight(4)};
  RenderOptions options(24, 18);
  options.samples = 2;
  const RayCounts rays = Renderer(scene, options).renderAll().rays;
  const double traced = double(rays.primary + rays.shadow + rays.secondary);
  EXPECT_GT(rays.secondary, 0u);
  EXPECT_LE(traced, estimateRays(scene, options).total());
}

// With indirect light, the paths' rays (a bound of their mean length: the
// sure bounces and ten for the roulette) keep the estimate above what is
// traced, and ambient occlusion's rays count as shadow rays.
TEST(RayEstimate, IndirectLightAndOcclusionStayWithinTheEstimate) {
  Scene scene;
  scene.objects.push_back(Primitive::create<Sphere>(2.0));
  scene.surfaces.push_back(Surface::plane(dvec3(0, 0, -2), dvec3(0, 0, 1)));
  scene.indirect = IndirectLight{8, 2};
  scene.ambientOcclusion = AmbientOcclusion{4, 1.0};
  RenderOptions options(24, 18);
  options.samples = 1;
  const RayCounts rays = Renderer(scene, options).renderAll().rays;
  const double traced = double(rays.primary + rays.shadow + rays.secondary);
  EXPECT_GT(rays.secondary, 24u * 18u);
  EXPECT_LE(traced, estimateRays(scene, options).total());
}

// The default limit of csgray render (cli/render_command.cpp, 1e11 rays)
// leaves every example a wide margin: at 1024x768 with 4 samples a pixel,
// the most the docs use, each is under a tenth of it.
TEST(RayEstimate, ExamplesAreFarBelowTheDefaultLimit) {
  RenderOptions options(1024, 768);
  options.samples = 4;
  for (const std::string& path : test::exampleScripts()) {
    const Scene scene = runScriptFile(path, test::exampleOptions());
    EXPECT_LT(estimateRays(scene, options).total(), 1e10) << path;
  }
}

}  // namespace
}  // namespace csgray::detail
