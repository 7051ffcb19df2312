// The occluder cache of shadow rays (raytrace/shadow_cache.h): recording
// answers as the solid's own meetsWindow does, a remembered occluder says
// "blocked" only where the whole solid is met, and a render that asks the
// cache gives the image of the same rays traced one by one without it.
#include "raytrace/shadow_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/sphere.h"
#include "raytrace/renderer.h"

namespace csgray::detail {
namespace {

// A part whose every stretch is its own: a ball less a box through it.
SolidPtr part() {
  SolidPtr hole = Primitive::create<Box>(dvec3(0.6, 0.6, 4))
                      ->transformed(Affine::translation({-0.3, -0.3, -2}));
  return differenceOf({Primitive::create<Sphere>(1.0), hole});
}

// A field of turned parts in rows, nested: a union of rows (instances of
// one union of parts), as a script's loops and transforms make it.
SolidPtr field() {
  std::vector<SolidPtr> row;
  for (int i = 0; i < 6; ++i)
    row.push_back(part()->transformed(Affine::rotation(0.4 * i, glm::normalize(dvec3(1, 2, 3)))
                                          .then(Affine::translation({2.5 * i, 0, 1}))));
  const SolidPtr rowUnion = unionOf(row);
  std::vector<SolidPtr> rows;
  for (int j = 0; j < 5; ++j)
    rows.push_back(rowUnion->transformed(Affine::translation({0.7 * j, 2.5 * j, 0})));
  return unionOf(rows);
}

// Segments from points near the floor towards a light above, their ends
// jittered: neighbours, as the shadow rays of neighbouring pixels are.
struct Segments {
  std::mt19937 rng{7};
  std::uniform_real_distribution<double> x{-2.0, 17.0}, y{-2.0, 13.0}, jitter{-0.05, 0.05};
  Ray next(const dvec3& light) {
    const dvec3 from(x(rng), y(rng), 0.0);
    return Ray(from, light - from, 0.0, 1.0);
  }
  Ray near(const Ray& ray) {
    const dvec3 from = ray.origin + dvec3(jitter(rng), jitter(rng), 0.0);
    return Ray(from, ray.at(1.0) - from, 0.0, 1.0);
  }
};

TEST(ShadowCache, RecordingAnswersAsTheSolidDoes) {
  const SolidPtr solid = field();
  solid->prepare();
  Segments segments;
  SpanList a, b;
  int met = 0;
  for (int i = 0; i < 4000; ++i) {
    const Ray ray = segments.next(dvec3(7, 5, 20));
    Occluder occluder;
    const bool recorded = occluder.record(*solid, ray, a);
    ASSERT_EQ(recorded, solid->meetsWindow(ray, b)) << i;
    EXPECT_EQ(occluder.empty(), !recorded) << i;
    // What it remembers meets the very ray it was found by.
    if (recorded) EXPECT_TRUE(occluder.stillMeets(ray, a)) << i;
    met += recorded;
  }
  EXPECT_GT(met, 400);  // the field blocks a good share of the segments
  EXPECT_LT(met, 3600);
}

TEST(ShadowCache, ARememberedOccluderBlocksOnlyWhereTheSolidDoes) {
  const SolidPtr solid = field();
  solid->prepare();
  Segments segments;
  SpanList a, b;
  int hits = 0, misses = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray first = segments.next(dvec3(-4, 3, 15));
    Occluder occluder;
    if (!occluder.record(*solid, first, a)) continue;
    for (int k = 0; k < 10; ++k) {
      const Ray ray = segments.near(first);
      if (occluder.stillMeets(ray, a)) {
        ++hits;
        ASSERT_TRUE(solid->meetsWindow(ray, b)) << i << " " << k;
      } else {
        ++misses;
      }
    }
  }
  // Neighbouring segments mostly meet the same part, not always.
  EXPECT_GT(hits, 1000);
  EXPECT_GT(misses, 10);
}

TEST(ShadowCache, RenderIsTheImageOfRaysTracedOneByOne) {
  Scene scene;
  auto matte = std::make_shared<Material>();
  matte->color = dvec3(0.6, 0.7, 0.8);
  matte->ambient = 0.1;
  matte->diffuse = 0.9;
  matte->specular = 0.3;
  scene.objects.push_back(field()->withDefaultMaterial(matte));
  scene.surfaces.push_back(Surface::plane(dvec3(0), dvec3(0, 0, 1))->withMaterial(matte));
  scene.lights.push_back(Light{Light::Kind::Point, dvec3(20, -10, 30)});
  scene.lights.push_back(Light{Light::Kind::Point, dvec3(-10, -5, 15)});
  scene.camera = CameraSpec{dvec3(7, -14, 16), dvec3(7, 6, 0), dvec3(0, 0, 1), 60.0};
  const int w = 96, h = 72;
  const Renderer renderer(scene, {w, h, 1});
  const RenderResult rendered = renderer.renderAll();
  // Pixel by pixel through the public trace(), which keeps no cache.
  const Camera camera(renderer.camera(), w, h);
  Image oneByOne(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) oneByOne.set(x, y, renderer.trace(camera.ray(x + 0.5, y + 0.5)));
  EXPECT_EQ(rendered.color.rgb, oneByOne.rgb);
  // Enough shadow to test: pixels hidden from both lights show the ambient
  // term alone.
  int shadowed = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) shadowed += rendered.color.at(x, y).x < 0.07;
  EXPECT_GT(shadowed, w * h / 100);
}

}  // namespace
}  // namespace csgray::detail
