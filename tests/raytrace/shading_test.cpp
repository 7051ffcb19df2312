// The renderer's shading checked against geometry and the shading rules,
// not against golden images: lateral shifts through glass slabs, total
// internal reflection in a prism, the media stack of hollow and nested
// solids, mirror images, textures, light falloff, spot cones, transparent
// and soft shadows, recursion limits, sampling and the AOVs, and the
// orthographic camera. Targets are flat (ambient 1, diffuse 0), so the
// colour a ray sees tells exactly which target it reached.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/half_space.h"
#include "primitives/sphere.h"
#include "raytrace/renderer.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;
double radians(double degrees) { return degrees * kPi / 180.0; }

const dvec3 kBlack(0.0), kRed(1, 0, 0), kGreen(0, 1, 0), kBlue(0, 0, 1), kYellow(1, 1, 0);

// A self-coloured material: the colour seen is exactly its colour.
MaterialPtr flat(const dvec3& color) {
  auto m = std::make_shared<Material>();
  m->color = color;
  m->ambient = 1.0;
  m->diffuse = 0.0;
  return m;
}

// Clear glass: no surface colour, all light passes, refracted by Snell's law.
MaterialPtr glass(double ior) {
  auto m = std::make_shared<Material>();
  m->ambient = 0.0;
  m->diffuse = 0.0;
  m->transparency = 1.0;
  m->ior = ior;
  return m;
}

// A lit, matte material.
MaterialPtr matte(const dvec3& color, double ambient, double diffuse) {
  auto m = std::make_shared<Material>();
  m->color = color;
  m->ambient = ambient;
  m->diffuse = diffuse;
  return m;
}

// An axis-aligned box from lo to hi.
SolidPtr boxFromTo(const dvec3& lo, const dvec3& hi) {
  return Primitive::create<Box>(hi - lo)->transformed(Affine::translation(lo));
}

SolidPtr sphereAt(const dvec3& centre, double radius) {
  return Primitive::create<Sphere>(radius)->transformed(Affine::translation(centre));
}

// A camera far off that the single traced rays do not depend on.
CameraSpec farCamera() { return CameraSpec{dvec3(0, -30, 0), dvec3(0), dvec3(0, 0, 1), 45.0}; }

// A camera looking straight down at (cx, cy) with parallel rays.
CameraSpec topDown(double cx, double cy, double width, double height = 10.0) {
  CameraSpec c{dvec3(cx, cy, height), dvec3(cx, cy, 0.0), dvec3(0, 1, 0), 45.0};
  c.orthographic = true;
  c.orthoWidth = width;
  return c;
}

// The world (x, y) of pixel (i, j)'s centre for a topDown camera, from the
// camera model (square pixels, orthoWidth wide, +x right, +y up).
glm::dvec2 topDownPoint(const CameraSpec& c, int w, int h, int i, int j) {
  double pixel = c.orthoWidth / w;
  return {c.eye.x + (i + 0.5 - 0.5 * w) * pixel, c.eye.y + (0.5 * h - j - 0.5) * pixel};
}

// ------------------------------------------------------------- refraction

// A target that is red for x < 0 and green for x > 0 on the plane z = depth:
// two flat half-planes (rectangles wider than the rays' reach) meeting at
// x = 0. Kept small: the renderer offsets continued rays by a share of the
// scene's size, which sets the precision of a shift.
void addHalfRedHalfGreen(Scene& scene, double depth) {
  scene.surfaces.push_back(
      Surface::parallelogram(dvec3(-10, -10, depth), dvec3(10, 0, 0), dvec3(0, 20, 0))
          ->withMaterial(flat(kRed)));
  scene.surfaces.push_back(
      Surface::parallelogram(dvec3(0, -10, depth), dvec3(10, 0, 0), dvec3(0, 20, 0))
          ->withMaterial(flat(kGreen)));
}

// The x where the colour seen by rays straight down (along −z, at y = 0.5)
// changes from red to green, by bisection.
double colourEdge(const Renderer& renderer) {
  auto green = [&](double x) {
    dvec3 c = renderer.trace(Ray(dvec3(x, 0.5, 10.0), dvec3(0, 0, -1)));
    EXPECT_TRUE(c == kRed || c == kGreen) << "x = " << x << ": " << c.x << " " << c.y << " " << c.z;
    return c == kGreen;
  };
  double lo = -1.0, hi = 1.0;
  EXPECT_FALSE(green(lo));
  EXPECT_TRUE(green(hi));
  for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
    double mid = 0.5 * (lo + hi);
    (green(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// A slab of glass 6 × 6 wide and `thickness` thick about the origin,
// tilted by theta about the y axis.
Affine tilt(double theta) { return Affine::rotation(theta, dvec3(0, 1, 0)); }
SolidPtr slab(double thickness, double theta, double ior) {
  return boxFromTo(dvec3(-3, -3, -0.5 * thickness), dvec3(3, 3, 0.5 * thickness))
      ->transformed(tilt(theta))
      ->withDefaultMaterial(glass(ior));
}

// The lateral shift of a ray through a plane-parallel slab of thickness d
// at incidence theta: d·sin(θ − θr)/cos θr with sin θr = sin θ / n.
double lateralShift(double d, double theta, double n) {
  double thetaR = std::asin(std::sin(theta) / n);
  return d * std::sin(theta - thetaR) / std::cos(thetaR);
}

// The x a vertical ray must start at to land on x = 0 beyond a tilted slab
// (it is shifted towards −x by the shift when the slab's normal leans +x).
double expectedEdge(double d, double theta, double n) {
  dvec3 normal = tilt(theta).normalToWorld(dvec3(0, 0, 1));
  return (normal.x > 0 ? 1.0 : -1.0) * std::abs(lateralShift(d, theta, n));
}

Scene refractionScene(double targetDepth) {
  Scene scene;
  addHalfRedHalfGreen(scene, targetDepth);
  scene.camera = farCamera();
  scene.background = kBlack;
  return scene;
}

TEST(Shading, GlassSlabShiftsRaysSidewaysAndLeavesThemParallel) {
  for (double n : {1.5, 1.33, 2.0}) {
    for (double degrees : {10.0, 30.0, 45.0, -25.0}) {
      double theta = radians(degrees), d = 0.8;
      double edges[2];
      for (int k = 0; k < 2; ++k) {
        Scene scene = refractionScene(k == 0 ? -5.0 : -20.0);
        scene.objects.push_back(slab(d, theta, n));
        edges[k] = colourEdge(Renderer(scene, {8, 8, 1}));
        EXPECT_NEAR(edges[k], expectedEdge(d, theta, n), 1e-6) << "n " << n << " θ " << degrees;
      }
      // The ray leaves parallel to itself: the same shift at both depths
      // (15 apart; up to the continued rays' offsets, which scale with the
      // scene's size and so differ slightly between the two scenes).
      EXPECT_NEAR(edges[0], edges[1], 1e-7) << "n " << n << " θ " << degrees;
      ASSERT_GT(std::abs(edges[0]), 0.03);  // a shift that could be missed
    }
  }
  // Without glass, or with a slab of index 1, there is no shift.
  Scene scene = refractionScene(-5.0);
  EXPECT_NEAR(colourEdge(Renderer(scene, {8, 8, 1})), 0.0, 1e-9);
  scene.objects.push_back(slab(0.8, radians(30), 1.0));
  // (Up to the offset of the continued rays off each face, 1e-9 of the
  // scene's size along the tilted normal.)
  EXPECT_NEAR(colourEdge(Renderer(scene, {8, 8, 1})), 0.0, 1e-7);
}

TEST(Shading, OpenSurfacesNeverBendRays) {
  // A tilted sheet of "glass" encloses nothing: rays pass it unbent.
  Scene scene = refractionScene(-5.0);
  scene.surfaces.push_back(Surface::parallelogram(dvec3(-3, -3, 0), dvec3(6, 0, 3), dvec3(0, 6, 0))
                               ->withMaterial(glass(1.5)));
  EXPECT_NEAR(colourEdge(Renderer(scene, {8, 8, 1})), 0.0, 1e-7);
}

// A horizontal slab of glass with Fresnel reflection over a flat target,
// seen straight down against a black sky: each face reflects R = 0.04 and
// passes 1 − R, so what comes through is T·(1 − R)·Σ (1 − R)·R^(2i) =
// T·(1 − R)/(1 + R) with all the reflections inside the slab, and T·(1 − R)²
// when the weight limit stops the rays that were reflected twice.
TEST(Shading, FresnelSlabPassesOneMinusROverOnePlusR) {
  const double n = 1.5, r = std::pow((n - 1) / (n + 1), 2.0);
  ASSERT_NEAR(r, 0.04, 1e-15);
  const dvec3 target(0.3, 0.6, 0.9);
  Scene scene;
  auto m = std::make_shared<Material>(*glass(n));
  m->fresnel = true;
  scene.objects.push_back(boxFromTo(dvec3(-3, -3, -0.5), dvec3(3, 3, 0.5))->withDefaultMaterial(m));
  scene.surfaces.push_back(
      Surface::plane(dvec3(0, 0, -5), dvec3(0, 0, 1))->withMaterial(flat(target)));
  scene.camera = farCamera();
  scene.background = kBlack;
  const Ray down(dvec3(0.2, 0.1, 5), dvec3(0, 0, -1));
  // Default limits: after two reflections a ray's weight is below 1/512.
  ASSERT_LT((1 - r) * r * r, scene.limits.minWeight);
  dvec3 once = Renderer(scene, {8, 8, 1}).trace(down);
  scene.limits.minWeight = 0.0;
  scene.limits.maxDepth = 60;
  dvec3 all = Renderer(scene, {8, 8, 1}).trace(down);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(once[c], target[c] * (1 - r) * (1 - r), 1e-12) << c;
    EXPECT_NEAR(all[c], target[c] * (1 - r) / (1 + r), 1e-12) << c;
  }
  // The light reflected off the top face shows what is above it.
  scene.background = dvec3(1.0);
  scene.limits = TraceLimits{};
  dvec3 sky = Renderer(scene, {8, 8, 1}).trace(down);
  EXPECT_NEAR(sky.x, once.x + r + (1 - r) * r * (1 - r), 1e-12);
}

// A right-angle prism: the cube [-1, 1]³ cut to z >= x. A ray straight
// down enters the top face head-on and meets the hypotenuse at 45°.
Scene prismScene(double ior) {
  Scene scene;
  SolidPtr prism = intersectionOf(
      {boxFromTo(dvec3(-1), dvec3(1)), Primitive::create<HalfSpace>(dvec3(1, 0, -1), 0.0)});
  scene.objects.push_back(prism->withDefaultMaterial(glass(ior)));
  // At the side (−x), a red strip 0.15 <= z <= 0.25 in front of a yellow wall;
  // below, a blue floor.
  scene.surfaces.push_back(
      Surface::parallelogram(dvec3(-5, -2, 0.15), dvec3(0, 4, 0), dvec3(0, 0, 0.1))
          ->withMaterial(flat(kRed)));
  scene.surfaces.push_back(
      Surface::plane(dvec3(-6, 0, 0), dvec3(1, 0, 0))->withMaterial(flat(kYellow)));
  scene.surfaces.push_back(
      Surface::plane(dvec3(0, 0, -5), dvec3(0, 0, 1))->withMaterial(flat(kBlue)));
  scene.camera = farCamera();
  scene.background = kBlack;
  return scene;
}

TEST(Shading, PrismTotallyReflectsPastTheCriticalAngleOnly) {
  auto down = [](double x) { return Ray(dvec3(x, 0.1, 5.0), dvec3(0, 0, -1)); };
  {
    // n = 1.5: the critical angle asin(1/1.5) = 41.8° < 45°: the ray is
    // turned by 90° at the hypotenuse, at the height z = x where it meets
    // it, and leaves through the side face x = -1 towards −x.
    ASSERT_LT(std::asin(1.0 / 1.5), radians(45));
    Scene scene = prismScene(1.5);
    Renderer renderer(scene, {8, 8, 1});
    EXPECT_EQ(renderer.trace(down(0.2)), kRed);
    EXPECT_EQ(renderer.trace(down(0.16)), kRed);
    EXPECT_EQ(renderer.trace(down(0.24)), kRed);
    EXPECT_EQ(renderer.trace(down(0.5)), kYellow);   // turned above the strip
    EXPECT_EQ(renderer.trace(down(-0.5)), kYellow);  // turned below it
    EXPECT_EQ(renderer.trace(down(1.5)), kBlue);     // beside the prism
  }
  {
    // n = 1.3: the critical angle asin(1/1.3) = 50.3° > 45°: the ray passes
    // the hypotenuse, bent away from the normal, down to the floor.
    ASSERT_GT(std::asin(1.0 / 1.3), radians(45));
    Scene scene = prismScene(1.3);
    Renderer renderer(scene, {8, 8, 1});
    for (double x : {0.2, 0.16, 0.24, 0.5, -0.5}) EXPECT_EQ(renderer.trace(down(x)), kBlue) << x;
  }
}

TEST(Shading, HollowSlabShiftsLikeItsGlassAlone) {
  // A slab 1 thick with a gap 0.4 thick inside it (parallel faces): 0.6 of
  // glass along the normal, in two layers.
  for (double degrees : {20.0, 40.0}) {
    double theta = radians(degrees), n = 1.5;
    for (double depth : {-5.0, -20.0}) {
      Scene scene = refractionScene(depth);
      SolidPtr hollow = differenceOf({boxFromTo(dvec3(-3, -3, -0.5), dvec3(3, 3, 0.5)),
                                      boxFromTo(dvec3(-2, -2, -0.2), dvec3(2, 2, 0.2))});
      scene.objects.push_back(hollow->transformed(tilt(theta))->withDefaultMaterial(glass(n)));
      double edge = colourEdge(Renderer(scene, {8, 8, 1}));
      EXPECT_NEAR(edge, expectedEdge(0.6, theta, n), 1e-6) << degrees;
      // Not the shift of the full thickness.
      EXPECT_GT(std::abs(edge - expectedEdge(1.0, theta, n)), 0.03);
    }
  }
}

TEST(Shading, NestedSlabOfTheSameIndexShiftsLikeTheOuterSlabAlone) {
  for (double degrees : {20.0, 40.0}) {
    double theta = radians(degrees), n = 1.5;
    Scene scene = refractionScene(-5.0);
    scene.objects.push_back(slab(1.0, theta, n));
    // A thinner slab of the same glass inside it, a separate object.
    scene.objects.push_back(boxFromTo(dvec3(-2, -2, -0.2), dvec3(2, 2, 0.2))
                                ->transformed(tilt(theta))
                                ->withDefaultMaterial(glass(n)));
    double edge = colourEdge(Renderer(scene, {8, 8, 1}));
    EXPECT_NEAR(edge, expectedEdge(1.0, theta, n), 1e-6) << degrees;
    // A nested slab of another glass bends the ray at its faces: the shift
    // is then the sum of the layers' shifts, each by its own index (the
    // inner layer's relative to the outer glass).
    Scene other = refractionScene(-5.0);
    other.objects.push_back(slab(1.0, theta, n));
    other.objects.push_back(boxFromTo(dvec3(-2, -2, -0.2), dvec3(2, 2, 0.2))
                                ->transformed(tilt(theta))
                                ->withDefaultMaterial(glass(2.0)));
    // Each layer shifts the ray by its thickness at the incidence θ in air
    // and its own index (the ray in a layer runs at asin(sin θ / n_layer)
    // to the normal whatever the layers before it).
    double inner = lateralShift(0.4, theta, 2.0);
    double outer = lateralShift(0.6, theta, n);
    double sign = expectedEdge(1.0, theta, n) > 0 ? 1.0 : -1.0;
    EXPECT_NEAR(colourEdge(Renderer(other, {8, 8, 1})), sign * std::abs(outer + inner), 1e-6)
        << degrees;
  }
}

// ----------------------------------------------------------------- mirror

TEST(Shading, MirrorShowsTheSphereWhereGeometryPutsItsImage) {
  Scene scene;
  auto mirror = std::make_shared<Material>();
  mirror->ambient = 0.0;
  mirror->diffuse = 0.0;
  mirror->reflection = 1.0;
  scene.surfaces.push_back(Surface::plane(dvec3(0), dvec3(0, 0, 1))->withMaterial(mirror));
  const dvec3 centre(0.5, 1.0, 3.0), image(0.5, 1.0, -3.0);
  const double r = 1.0;
  scene.objects.push_back(sphereAt(centre, r)->withDefaultMaterial(flat(kRed)));
  scene.camera = farCamera();
  scene.background = kBlack;
  Renderer renderer(scene, {8, 8, 1});

  const dvec3 eye(0, -10, 4);
  dvec3 axis = glm::normalize(image - eye);
  double dist = glm::length(image - eye);
  double angularRadius = std::asin(r / dist);
  EXPECT_EQ(renderer.trace(Ray(eye, axis)), kRed);
  // Rays on a cone about the axis, just inside and just outside the image's
  // angular radius, all around.
  dvec3 a = glm::normalize(glm::cross(axis, dvec3(0, 0, 1)));
  dvec3 b = glm::cross(axis, a);
  for (int k = 0; k < 24; ++k) {
    double phi = 2 * kPi * k / 24;
    dvec3 side = std::cos(phi) * a + std::sin(phi) * b;
    for (double f : {0.5, 1.0 - 1e-6, 1.0 + 1e-6, 1.2}) {
      double g = f * angularRadius;
      dvec3 dir = std::cos(g) * axis + std::sin(g) * side;
      EXPECT_EQ(renderer.trace(Ray(eye, dir)), f < 1 ? kRed : kBlack) << "φ " << phi << " f " << f;
    }
  }
  // Without the mirror nothing is there.
  Scene bare = scene;
  bare.surfaces.clear();
  EXPECT_EQ(Renderer(bare, {8, 8, 1}).trace(Ray(eye, axis)), kBlack);
}

// Panes that mirror all light and pass all of it keep every ray's weight at
// 1, so min_weight never prunes: between two mirrors, the rays double at
// each pane, 2^64 of them at max_depth 64. The camera ray's budget bounds
// the tree, and the tree uses it.
TEST(Shading, ARayTreeThatNeverLosesWeightStaysWithinItsBudget) {
  Scene scene;
  auto mirror = std::make_shared<Material>(*flat(kBlack));
  mirror->reflection = 1.0;
  auto pane = std::make_shared<Material>(*flat(kRed));
  pane->reflection = 1.0;
  pane->transparency = 1.0;
  for (double z : {0.0, 8.0})
    scene.surfaces.push_back(Surface::plane(dvec3(0, 0, z), dvec3(0, 0, 1))->withMaterial(mirror));
  for (int z = 1; z < 8; ++z)
    scene.surfaces.push_back(Surface::plane(dvec3(0, 0, z), dvec3(0, 0, 1))->withMaterial(pane));
  scene.camera = CameraSpec{dvec3(0, 0, 4.5), dvec3(3, 1, 3.5), dvec3(0, 0, 1), 45.0};
  scene.limits.maxDepth = 64;
  scene.limits.minWeight = 0.0;
  const int w = 4, h = 3;
  RenderResult result = Renderer(scene, {w, h, 1}).renderAll();
  const std::uint64_t most = std::uint64_t(w * h) * (Renderer::kRaysPerCameraRay - 1);
  EXPECT_EQ(result.rays.primary, std::uint64_t(w * h));
  EXPECT_LE(result.rays.secondary, most);
  EXPECT_GE(result.rays.secondary, most / 2);
}

// ---------------------------------------------------------------- texture

TEST(Shading, CheckerboardPixelsShowTheSquareOfTheirCentre) {
  const dvec3 a(0.9, 0.2, 0.1), b(0.1, 0.3, 0.8);
  const double size = 0.7, z = -1.5;
  auto m = std::make_shared<Material>(*flat(kBlack));
  m->texture = checkerTexture(a, b, size);
  Scene scene;
  scene.surfaces.push_back(Surface::plane(dvec3(0, 0, z), dvec3(0, 0, 1))->withMaterial(m));
  scene.camera = topDown(0.31, -0.17, 6.0);
  const int w = 64, h = 48;
  Image image = Renderer(scene, {w, h, 2}).render();
  double nearest = kInfinity;  // the closest any pixel centre comes to a square's edge
  int countA = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      glm::dvec2 p = topDownPoint(*scene.camera, w, h, i, j);
      for (double c : {p.x, p.y})
        nearest = std::min(nearest, std::abs(c / size - std::round(c / size)));
      long parity =
          std::lround(std::floor(p.x / size) + std::floor(p.y / size) + std::floor(z / size));
      dvec3 expected = parity % 2 == 0 ? a : b;
      countA += parity % 2 == 0;
      dvec3 seen = image.at(i, j);
      ASSERT_NEAR(seen.x, expected.x, 1e-6) << i << " " << j;
      ASSERT_NEAR(seen.y, expected.y, 1e-6) << i << " " << j;
      ASSERT_NEAR(seen.z, expected.z, 1e-6) << i << " " << j;
    }
  // No pixel centre sits on (or within a ten-thousandth of) an edge, where
  // rounding, or the texture's rule for points on a cell boundary, could
  // pick either side; and both colours are there.
  EXPECT_GT(nearest * size, 1e-4);
  EXPECT_GT(countA, w * h / 4);
  EXPECT_LT(countA, 3 * w * h / 4);
}

// ----------------------------------------------------------------- lights

// The colour seen at a point of the floor z = 0, from a ray from above.
dvec3 floorColour(const Renderer& renderer, const dvec3& p) {
  dvec3 from = p + dvec3(0.1, -0.3, 2.0);
  return renderer.trace(Ray(from, glm::normalize(p - from)));
}

Scene floorScene(const MaterialPtr& floor) {
  Scene scene;
  scene.surfaces.push_back(Surface::plane(dvec3(0), dvec3(0, 0, 1))->withMaterial(floor));
  scene.camera = topDown(0, 0, 4.0);
  scene.background = kBlack;
  return scene;
}

TEST(Shading, PointLightFallsOffAsCosineOverDistanceSquared) {
  Scene scene = floorScene(matte(dvec3(1.0), 0.0, 1.0));
  Light light{Light::Kind::Point, dvec3(0.3, -0.2, 3.0)};
  light.intensity = 7.0;
  light.inverseSquare = true;
  scene.lights.push_back(light);
  Renderer renderer(scene, {8, 8, 1});
  auto expected = [&](const dvec3& p) {
    dvec3 toLight = light.position - p;
    double d = glm::length(toLight);
    return light.intensity * (toLight.z / d) / (d * d);  // cos α / d²
  };
  const dvec3 points[] = {dvec3(0.3, -0.2, 0), dvec3(2, 1, 0), dvec3(-4, 3, 0), dvec3(6, -5, 0)};
  double c0 = floorColour(renderer, points[0]).x;
  EXPECT_NEAR(c0, light.intensity / 9.0, 1e-12);
  for (const dvec3& p : points) {
    double c = floorColour(renderer, p).x;
    EXPECT_NEAR(c, expected(p), 1e-12);
    EXPECT_NEAR(c / c0, expected(p) / expected(points[0]), 1e-12);
  }
  // Without the falloff only the cosine is left.
  scene.lights[0].inverseSquare = false;
  Renderer plain(scene, {8, 8, 1});
  for (const dvec3& p : points) {
    dvec3 toLight = light.position - p;
    EXPECT_NEAR(floorColour(plain, p).x, light.intensity * toLight.z / glm::length(toLight), 1e-12);
  }
}

TEST(Shading, SpotLightLightsADiscOfRadiusHeightTimesTanConeWithCosineFalloff) {
  const double h = 4.0, cone = 20.0, exponent = 3.0;
  const dvec3 foot(0.13, -0.07, 0.0);
  Scene scene = floorScene(matte(dvec3(1.0), 0.0, 1.0));
  Light spot{Light::Kind::Spot, foot + dvec3(0, 0, h)};
  spot.direction = dvec3(0, 0, -1);
  spot.coneDegrees = cone;
  spot.exponent = exponent;
  scene.lights.push_back(spot);
  scene.camera = topDown(foot.x, foot.y, 4.0);
  const int w = 100, hgt = 100;
  Image image = Renderer(scene, {w, hgt, 2}).render();
  const double radius = h * std::tan(radians(cone));
  const double pixel = scene.camera->orthoWidth / w;
  ASSERT_LT(radius, 0.5 * scene.camera->orthoWidth);  // the whole disc is in view
  int lit = 0;
  double nearest = kInfinity;
  for (int j = 0; j < hgt; ++j)
    for (int i = 0; i < w; ++i) {
      glm::dvec2 p = topDownPoint(*scene.camera, w, hgt, i, j);
      double rho = glm::length(p - glm::dvec2(foot.x, foot.y));
      nearest = std::min(nearest, std::abs(rho - radius));
      bool inside = rho < radius;
      lit += image.at(i, j).x > 0.0;
      EXPECT_EQ(image.at(i, j).x > 0.0, inside) << i << " " << j << " ρ " << rho;
    }
  EXPECT_GT(nearest, 1e-6);
  // The lit disc's radius from its area, within a pixel.
  EXPECT_NEAR(std::sqrt(lit / kPi) * pixel, radius, pixel);

  // cosⁿ ψ of the angle off the axis, times Lambert's cos α (= cos ψ here,
  // the floor facing the light straight up).
  Renderer renderer(scene, {8, 8, 1});
  for (double rho : {0.0, 0.3, 0.8, 1.2, 0.99 * radius}) {
    dvec3 p = foot + dvec3(rho * 0.6, rho * 0.8, 0.0);
    double cosPsi = h / std::sqrt(h * h + rho * rho);
    EXPECT_NEAR(floorColour(renderer, p).x, std::pow(cosPsi, exponent) * cosPsi, 1e-12) << rho;
  }
  EXPECT_EQ(floorColour(renderer, foot + dvec3(1.01 * radius, 0, 0)).x, 0.0);
}

TEST(Shading, TransparentSphereCastsALighterTintedShadow) {
  const dvec3 floorColourRgb(0.6, 0.7, 0.8);
  const double ambient = 0.2, diffuse = 0.8, k = 0.4;
  auto build = [&](double transparency, const dvec3& filter) {
    Scene scene = floorScene(matte(floorColourRgb, ambient, diffuse));
    scene.lights.push_back(Light{Light::Kind::Point, dvec3(0, 0, 10)});
    if (transparency >= 0.0) {
      auto m = std::make_shared<Material>(*matte(dvec3(0.5), 0.1, 0.9));
      m->transparency = transparency;
      m->filter = filter;
      scene.objects.push_back(sphereAt(dvec3(0, 0, 3), 1.0)->withDefaultMaterial(m));
    }
    return scene;
  };
  const dvec3 p(0.1, 0.2, 0.0);  // in the shadow's middle
  const dvec3 base = ambient * floorColourRgb;
  Scene noSphere = build(-1.0, dvec3(1.0));
  dvec3 lit = floorColour(Renderer(noSphere, {8, 8, 1}), p);
  Scene opaque = build(0.0, dvec3(1.0));
  dvec3 dark = floorColour(Renderer(opaque, {8, 8, 1}), p);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(dark[c], base[c], 1e-12);
    EXPECT_GT(lit[c], base[c] + 0.1);
  }
  Scene clear = build(k, dvec3(1.0));
  dvec3 light = floorColour(Renderer(clear, {8, 8, 1}), p);
  const dvec3 tint(1.0, 0.5, 0.2);
  Scene tinted = build(k, tint);
  dvec3 coloured = floorColour(Renderer(tinted, {8, 8, 1}), p);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR((light[c] - base[c]) / (lit[c] - base[c]), k, 1e-12) << c;
    EXPECT_NEAR((coloured[c] - base[c]) / (lit[c] - base[c]), k * tint[c], 1e-12) << c;
  }
}

// A surface with no diffuse and no highlight term takes nothing from the
// lights, so it asks them nothing: a pure mirror over which every
// reflected ray leaves the scene sends no shadow rays, and shows the
// background at its reflection; the same floor with a diffuse term sends
// one per pixel to the light above it.
TEST(Shading, APureMirrorSendsNoShadowRays) {
  const dvec3 sky(0.2, 0.3, 0.4);
  const int w = 6, h = 4;
  auto render = [&](double diffuse) {
    auto m = std::make_shared<Material>(*matte(dvec3(0.5), 0.0, diffuse));
    m->reflection = 0.75;
    Scene scene = floorScene(m);
    scene.background = sky;
    scene.lights.push_back(Light{Light::Kind::Point, dvec3(0.5, 0.5, 10)});
    return Renderer(scene, {w, h, 1}).renderAll();
  };
  const RenderResult mirror = render(0.0);
  EXPECT_EQ(mirror.rays.primary, std::uint64_t(w * h));
  EXPECT_EQ(mirror.rays.secondary, std::uint64_t(w * h));
  EXPECT_EQ(mirror.rays.shadow, 0u);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(mirror.color.at(x, y)[c], 0.75 * sky[c], 1e-6) << x << " " << y;
  EXPECT_EQ(render(0.5).rays.shadow, std::uint64_t(w * h));
}

// A ball of radius 1 about the origin, and the same ball hollowed to a
// radius of 0.5, both of material m.
std::pair<SolidPtr, SolidPtr> ballAndHollowBall(const MaterialPtr& m) {
  return {sphereAt(dvec3(0), 1.0)->withDefaultMaterial(m),
          differenceOf({sphereAt(dvec3(0), 1.0), sphereAt(dvec3(0), 0.5)})->withDefaultMaterial(m)};
}

// The solid over a flat target on the plane z = -5, black beyond.
Scene overFlatTarget(const SolidPtr& solid, const dvec3& target) {
  Scene scene;
  scene.objects.push_back(solid);
  scene.surfaces.push_back(
      Surface::plane(dvec3(0, 0, -5), dvec3(0, 0, 1))->withMaterial(flat(target)));
  scene.camera = farCamera();
  scene.background = kBlack;
  return scene;
}

// An eye ray through a transparent solid (index 1) sees the solid's own
// colour s by (1 − k) and what lies beyond by k·filter, once per stretch
// inside the solid: the face where it leaves a stretch is not shaded. The
// same for shadow rays: a hollow sphere, two stretches, passes (k·filter)².
TEST(Shading, TransparencyAndFilterApplyOncePerStretch) {
  const double k = 0.4;
  const dvec3 s(0.9, 0.8, 0.1), f(1.0, 0.5, 0.25), target(0.2, 0.6, 0.8);
  auto m = std::make_shared<Material>(*flat(s));
  m->transparency = k;
  m->filter = f;
  const auto [ball, hollow] = ballAndHollowBall(m);
  auto sceneWith = [&](const SolidPtr& solid) { return overFlatTarget(solid, target); };
  const Ray down(dvec3(0.1, 0.2, 5), dvec3(0, 0, -1));
  Scene one = sceneWith(ball), two = sceneWith(hollow);
  dvec3 through = Renderer(one, {8, 8, 1}).trace(down);
  dvec3 throughHollow = Renderer(two, {8, 8, 1}).trace(down);
  for (int c = 0; c < 3; ++c) {
    double single = (1 - k) * s[c] + k * f[c] * target[c];
    EXPECT_NEAR(through[c], single, 1e-12) << c;
    EXPECT_NEAR(throughHollow[c], (1 - k) * s[c] + k * f[c] * single, 1e-12) << c;
  }

  // Shadows on a lit floor below: the share of the light that passes.
  auto shadow = [&](const SolidPtr& solid) {
    Scene scene = floorScene(matte(dvec3(1.0), 0.0, 1.0));
    if (solid) scene.objects.push_back(solid->transformed(Affine::translation(dvec3(0, 0, 3))));
    scene.lights.push_back(Light{Light::Kind::Point, dvec3(0, 0, 10)});
    return floorColour(Renderer(scene, {8, 8, 1}), dvec3(0.05, -0.1, 0));
  };
  dvec3 lit = shadow(nullptr), pass1 = shadow(ball), pass2 = shadow(hollow);
  ASSERT_GT(lit.x, 0.5);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(pass1[c] / lit[c], k * f[c], 1e-12) << c;
    EXPECT_NEAR(pass2[c] / lit[c], std::pow(k * f[c], 2.0), 1e-12) << c;
  }
}

// With a filter distance D, a stretch of length d passes filter^(d / D)
// (Hall's transmissivity raised to the distance, the Beer-Lambert law):
// the eye ray through a ball sees what lies beyond by k·filter^(chord / D);
// through a hollow ball, by that for each of its two stretches; and a
// shadow ray through the ball passes k·filter^(chord / D) of the light,
// the chord of its own line.
TEST(Shading, FilterDistanceDimsEachStretchByItsLength) {
  const double k = 0.4, distance = 0.7;
  const dvec3 s(0.9, 0.8, 0.1), f(1.0, 0.5, 0.25), target(0.2, 0.6, 0.8);
  auto m = std::make_shared<Material>(*flat(s));
  m->transparency = k;
  m->filter = f;
  m->filterDistance = distance;
  const auto [ball, hollow] = ballAndHollowBall(m);
  auto sceneWith = [&](const SolidPtr& solid) { return overFlatTarget(solid, target); };
  // Down at x = 0.1, y = 0.2: 0.05 from the axis, squared.
  const Ray down(dvec3(0.1, 0.2, 5), dvec3(0, 0, -1));
  const double chord = 2.0 * std::sqrt(1.0 - 0.05);
  const double wall = std::sqrt(1.0 - 0.05) - std::sqrt(0.25 - 0.05);
  Scene one = sceneWith(ball), two = sceneWith(hollow);
  // (The way inside is the chord less the offsets rays start at, 10⁻⁹ of
  // the scene's size off each face: 10⁻⁷ covers them.)
  const dvec3 through = Renderer(one, {8, 8, 1}).trace(down);
  const dvec3 throughHollow = Renderer(two, {8, 8, 1}).trace(down);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(through[c], (1 - k) * s[c] + k * std::pow(f[c], chord / distance) * target[c], 1e-7)
        << c;
    const double inner = (1 - k) * s[c] + k * std::pow(f[c], wall / distance) * target[c];
    EXPECT_NEAR(throughHollow[c], (1 - k) * s[c] + k * std::pow(f[c], wall / distance) * inner,
                1e-7)
        << c;
  }
  // Thicker than the filter distance, darker than the filter once.
  EXPECT_LT(through.z, (1 - k) * s.z + k * f.z * target.z - 0.01);

  // The shadow of the ball, 3 above a floor lit from 10 above it.
  const dvec3 lamp(0, 0, 10), centre(0, 0, 3), floorPoint(0.05, -0.1, 0);
  auto shadow = [&](const SolidPtr& solid) {
    Scene scene = floorScene(matte(dvec3(1.0), 0.0, 1.0));
    if (solid) scene.objects.push_back(solid->transformed(Affine::translation(centre)));
    scene.lights.push_back(Light{Light::Kind::Point, lamp});
    return floorColour(Renderer(scene, {8, 8, 1}), floorPoint);
  };
  // The chord of the shadow ray's line: 2·√(1 − δ²), δ its distance from
  // the ball's centre.
  const dvec3 axis = glm::normalize(lamp - floorPoint);
  const double offAxis = glm::length(glm::cross(centre - floorPoint, axis));
  const double shadowChord = 2.0 * std::sqrt(1.0 - offAxis * offAxis);
  const dvec3 lit = shadow(nullptr), passed = shadow(ball);
  ASSERT_GT(lit.x, 0.5);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(passed[c] / lit[c], k * std::pow(f[c], shadowChord / distance), 1e-12) << c;
}

// Hall's transmitted highlight: a lamp under a slab of glass (index n, 2
// thick) shows, to parallel eye rays 40° off the slab's normal, where the
// eye's path through the slab ends pointing at it. The path bends into the
// slab at sin θt = sin 40° / n (Snell), crosses it, and leaves it parallel
// to the eye ray: the lamp, 5 under the slab, is seen from the top face's
// point 5·tan 40° + 2·tan θt before it in x. The highlight's brightest
// pixel is that point's, at n = 1.5 and at n = 1 (no bending). It is
// dimmed by the slab's transparency once; without transmitted_specular, or
// through an opaque slab, there is none.
TEST(Shading, TransmittedHighlightLiesWhereTheEyePathThroughAGlassSlabMeetsTheLamp) {
  const double theta = radians(40.0), thickness = 2.0, below = 5.0;
  const dvec3 lamp(0.0, 0.0, -thickness - below);
  const int w = 241, h = 3;
  const dvec3 view(std::sin(theta), 0.0, -std::cos(theta));
  CameraSpec camera{dvec3(-5.5, 0.0, 0.0) - 10.0 * view, dvec3(-5.5, 0.0, 0.0), dvec3(0, 1, 0),
                    45.0};
  camera.orthographic = true;
  camera.orthoWidth = 12.0;
  auto render = [&](double ior, double transmitted, double transparency) {
    auto m = std::make_shared<Material>(*glass(ior));
    m->transparency = transparency;
    m->transmittedSpecular = transmitted;
    m->shininess = 2000.0;
    Scene scene;
    scene.objects.push_back(
        boxFromTo(dvec3(-30, -30, -thickness), dvec3(30, 30, 0))->withDefaultMaterial(m));
    scene.lights.push_back(Light{Light::Kind::Point, lamp});
    scene.camera = camera;
    scene.background = kBlack;
    return Renderer(scene, {w, h, 1}).render();
  };
  const Camera rays(camera, w, h);
  for (const double ior : {1.5, 1.0}) {
    const Image image = render(ior, 1.0, 1.0);
    int brightest = 0;
    for (int x = 1; x < w; ++x)
      if (image.at(x, 1).x > image.at(brightest, 1).x) brightest = x;
    EXPECT_GT(image.at(brightest, 1).x, 0.8) << ior;
    // Where the brightest pixel's ray meets the pane's top, z = 0.
    const Ray ray = rays.ray(brightest + 0.5, 1.5);
    const double x = ray.origin.x - ray.origin.z / ray.dir.z * ray.dir.x;
    const double refracted = std::asin(std::sin(theta) / ior);
    const double expected = lamp.x - below * std::tan(theta) - thickness * std::tan(refracted);
    // Within a pixel, as it falls on the pane.
    EXPECT_NEAR(x, expected, camera.orthoWidth / w / std::cos(theta)) << ior;
  }
  // Dimmed once by the slab's transparency, where the eye ray enters it:
  // half as bright at every pixel at transparency 0.5.
  const Image clear = render(1.5, 1.0, 1.0), half = render(1.5, 1.0, 0.5);
  for (int x = 0; x < w; ++x) EXPECT_NEAR(half.at(x, 1).x, 0.5 * clear.at(x, 1).x, 1e-12) << x;
  for (const auto& [transmitted, transparency] : {std::pair{0.0, 1.0}, std::pair{1.0, 0.0}}) {
    const Image image = render(1.5, transmitted, transparency);
    for (int x = 0; x < w; ++x) EXPECT_EQ(image.at(x, 1).x, 0.0) << transmitted << " " << x;
  }
}

// A square light of side w at height 100 above the floor; an opaque
// half-plane x <= 0 at height 50 hides the part of the light with
// x_light <= −x_floor from a floor point (the crossing at half height is
// the midpoint). So the visible share of the light at floor x is
// (w/2 + x)/w, clamped to [0, 1].
TEST(Shading, AreaLightGivesUmbraPenumbraAndFullLight) {
  const double w = 2.0;
  const int k = 16;
  auto build = [&](bool occluder) {
    Scene scene = floorScene(matte(dvec3(1.0), 0.1, 0.9));
    Light area{Light::Kind::Rectangle, dvec3(0, 0, 100)};
    area.edgeU = dvec3(w, 0, 0);
    area.edgeV = dvec3(0, w, 0);
    area.samples = k * k;
    scene.lights.push_back(area);
    if (occluder)
      scene.surfaces.push_back(
          Surface::parallelogram(dvec3(-50, -50, 50), dvec3(50, 0, 0), dvec3(0, 100, 0))
              ->withMaterial(matte(dvec3(0.5), 0.1, 0.9)));
    return scene;
  };
  Scene shadowed = build(true), open = build(false);
  Renderer renderer(shadowed, {8, 8, 1}), reference(open, {8, 8, 1});
  ASSERT_EQ(renderer.lights()[0].sampleCount(), k * k);
  const double ambient = 0.1;
  auto share = [&](double x) {
    dvec3 p(x, 0.3, 0.0);
    return (floorColour(renderer, p).x - ambient) / (floorColour(reference, p).x - ambient);
  };
  // Umbra and full light.
  for (double x : {-3.0, -1.5, -1.01}) EXPECT_NEAR(share(x), 0.0, 1e-12) << x;
  for (double x : {1.01, 1.5, 3.0}) EXPECT_NEAR(share(x), 1.0, 1e-12) << x;
  // The penumbra: in between, rising across it, the analytic share within 1/k.
  double previous = 0.0;
  for (double x = -0.95; x < 0.96; x += 0.05) {
    double s = share(x);
    double analytic = std::clamp((0.5 * w + x) / w, 0.0, 1.0);
    EXPECT_NEAR(s, analytic, 1.0 / k) << x;
    EXPECT_GT(s, 0.0) << x;
    EXPECT_LT(s, 1.0) << x;
    // Each sample is lit with a nearly equal weight (the light is far), so
    // the share only grows: no more than the slight change of the cosines.
    EXPECT_GE(s, previous - 1e-3) << x;
    previous = std::max(previous, s);
  }
  EXPECT_GT(share(0.5) - share(-0.5), 0.5 - 2.0 / k);
}

// ------------------------------------------------------------- recursion

// Two mirrors z = 0 and z = 1 facing each other, reflection rho, seen with
// their own colour c (ambient 1): a ray between them sees c·Σ rho^i over the
// mirrors it reaches, one per level of recursion allowed.
Scene mirrorsScene(double rho) {
  auto m = std::make_shared<Material>(*flat(dvec3(0.1, 0.05, 0.02)));
  m->reflection = rho;
  Scene scene;
  scene.surfaces.push_back(Surface::plane(dvec3(0), dvec3(0, 0, 1))->withMaterial(m));
  scene.surfaces.push_back(Surface::plane(dvec3(0, 0, 1), dvec3(0, 0, -1))->withMaterial(m));
  scene.camera = CameraSpec{dvec3(0, 0, 0.5), dvec3(10, 0, 0.5), dvec3(0, 0, 1), 60.0};
  scene.background = kBlack;
  return scene;
}

double seriesOfMirrors(double rho, int reflections) {
  double sum = 0.0;
  for (int i = 0; i <= reflections; ++i) sum += std::pow(rho, i);
  return sum * 0.1;
}

TEST(Shading, FacingMirrorsStopAtTheDepthAndWeightLimits) {
  const Ray up(dvec3(0, 0, 0.5), dvec3(0, 0, 1));
  {
    Scene scene = mirrorsScene(1.0);
    ASSERT_EQ(scene.limits.maxDepth, 8);
    Image image = Renderer(scene, {40, 30, 2}).render();
    // Every ray bounces between the mirrors until the depth limit: the
    // mirror's colour once per mirror met, 1 + maxDepth times.
    for (int j = 0; j < image.height; ++j)
      for (int i = 0; i < image.width; ++i)
        ASSERT_NEAR(image.at(i, j).x, seriesOfMirrors(1.0, 8), 1e-6) << i << " " << j;
    EXPECT_NEAR(Renderer(scene, {8, 8, 1}).trace(up).x, seriesOfMirrors(1.0, 8), 1e-12);
    scene.limits.maxDepth = 3;
    EXPECT_NEAR(Renderer(scene, {8, 8, 1}).trace(up).x, seriesOfMirrors(1.0, 3), 1e-12);
    scene.limits.maxDepth = 0;
    EXPECT_NEAR(Renderer(scene, {8, 8, 1}).trace(up).x, 0.1, 1e-15);  // no reflection at all
  }
  {
    // Reflection 0.5, minWeight 0.1: rays of weight 0.5, 0.25, 0.125 are
    // traced, 0.0625 is not.
    Scene scene = mirrorsScene(0.5);
    scene.limits.minWeight = 0.1;
    EXPECT_NEAR(Renderer(scene, {8, 8, 1}).trace(up).x, seriesOfMirrors(0.5, 3), 1e-12);
    // Above the mirror's reflection nothing is mirrored.
    scene.limits.minWeight = 0.51;
    EXPECT_NEAR(Renderer(scene, {8, 8, 1}).trace(up).x, 0.1, 1e-15);
    // The default minWeight 1/512 lets 0.5^9 through, but the depth limit 8 stops it.
    scene.limits = TraceLimits{};
    EXPECT_NEAR(Renderer(scene, {8, 8, 1}).trace(up).x, seriesOfMirrors(0.5, 8), 1e-12);
  }
}

// ---------------------------------------------------- sampling and AOVs

// A white disc (a flat sphere) of radius 0.95 on black, seen from above with
// parallel rays: pixels 0.1 wide, the pixel [0.9, 1] × [0, 0.1] is about
// half covered and its centre (0.95, 0.05) is just outside.
Scene silhouetteScene() {
  Scene scene;
  scene.objects.push_back(sphereAt(dvec3(0), 0.95)->withDefaultMaterial(flat(dvec3(1.0))));
  scene.camera = topDown(0, 0, 4.0);
  scene.background = kBlack;
  return scene;
}

TEST(Shading, SupersamplingGivesSilhouettePixelsIntermediateValues) {
  Scene scene = silhouetteScene();
  const int w = 40, px = 29, py = 19;
  glm::dvec2 centre = topDownPoint(*scene.camera, w, w, px, py);
  ASSERT_NEAR(centre.x, 0.95, 1e-12);
  ASSERT_NEAR(centre.y, 0.05, 1e-12);
  // The covered share of the pixel, by the midpoint rule on a fine grid.
  double covered = 0.0;
  const int n = 400;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      double x = 0.9 + 0.1 * (a + 0.5) / n, y = 0.1 * (b + 0.5) / n;
      covered += x * x + y * y <= 0.95 * 0.95;
    }
  covered /= double(n) * n;
  ASSERT_GT(covered, 0.3);
  ASSERT_LT(covered, 0.7);

  RenderOptions one(w, w, 2);
  EXPECT_EQ(Renderer(scene, one).render().at(px, py).x, 0.0);
  RenderOptions sixteen(w, w, 2);
  sixteen.samples = 16;
  double v = Renderer(scene, sixteen).render().at(px, py).x;
  EXPECT_GT(v, 0.0);
  EXPECT_LT(v, 1.0);
  EXPECT_NEAR(v, covered, 0.25);          // 16 stratified samples
  EXPECT_EQ(v * 16, std::round(v * 16));  // a count of 16 samples
}

TEST(Shading, RendersAreTheSameOnOneAndTwoThreads) {
  Scene scene = silhouetteScene();
  scene.objects[0] = sphereAt(dvec3(0), 0.95)->withDefaultMaterial(matte(dvec3(0.8), 0.1, 0.9));
  scene.surfaces.push_back(
      Surface::plane(dvec3(0, 0, -1.5), dvec3(0, 0, 1))->withMaterial(matte(dvec3(0.5), 0.1, 0.9)));
  Light area{Light::Kind::Rectangle, dvec3(1, 1, 5)};
  area.samples = 9;
  scene.lights.push_back(area);
  for (bool adaptive : {false, true}) {
    RenderOptions a(32, 32, 1), b(32, 32, 2);
    a.samples = b.samples = 4;
    a.adaptive = b.adaptive = adaptive;
    EXPECT_EQ(Renderer(scene, a).render().rgb, Renderer(scene, b).render().rgb) << adaptive;
  }
}

TEST(Shading, AdaptiveSamplingRefinesEdgesOnly) {
  const int w = 40;
  {
    // The half-covered pixel of silhouetteScene is an edge: refined to an
    // in-between value.
    Scene scene = silhouetteScene();
    RenderOptions options(w, w, 2);
    options.samples = 16;
    options.adaptive = true;
    double v = Renderer(scene, options).render().at(29, 19).x;
    EXPECT_GT(v, 0.0);
    EXPECT_LT(v, 1.0);
  }
  // A shaded sphere over a floor lit by a near light: smooth gradients,
  // where more samples would change a pixel slightly, and edges.
  Scene scene = silhouetteScene();
  scene.objects[0] = sphereAt(dvec3(0), 0.95)->withDefaultMaterial(matte(dvec3(0.8), 0.1, 0.9));
  scene.surfaces.push_back(
      Surface::plane(dvec3(0, 0, -1.5), dvec3(0, 0, 1))->withMaterial(matte(dvec3(0.5), 0.1, 0.9)));
  Light light{Light::Kind::Point, dvec3(2, 1, 3)};
  light.inverseSquare = true;
  light.intensity = 12.0;
  scene.lights.push_back(light);
  RenderOptions base(w, w, 2);
  Image first = Renderer(scene, base).render();
  RenderOptions fullOptions(w, w, 2);
  fullOptions.samples = 16;
  Image full = Renderer(scene, fullOptions).render();
  RenderOptions adaptiveOptions = fullOptions;
  adaptiveOptions.adaptive = true;
  Image adaptive = Renderer(scene, adaptiveOptions).render();
  // An edge pixel: one of its eight neighbours differs from it by more than
  // the threshold in some channel (colours clamped to 1) in the 1-spp image.
  auto isEdge = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= w) continue;
        dvec3 d = glm::abs(glm::min(first.at(nx, ny), 1.0) - glm::min(first.at(x, y), 1.0));
        if (std::max({d.x, d.y, d.z}) > adaptiveOptions.adaptiveThreshold) return true;
      }
    return false;
  };
  int flatPixels = 0, flatButSampledDiffers = 0, edgePixels = 0, changed = 0;
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      if (!isEdge(x, y)) {
        ++flatPixels;
        flatButSampledDiffers += full.at(x, y) != first.at(x, y);
        EXPECT_EQ(adaptive.at(x, y), first.at(x, y)) << x << " " << y;
      } else {
        ++edgePixels;
        changed += adaptive.at(x, y) != first.at(x, y);
      }
    }
  EXPECT_GT(flatPixels, w * w / 2);
  EXPECT_GT(edgePixels, 40);
  // Supersampling would have changed most flat pixels too: keeping them is
  // the adaptive choice, not a property of the scene.
  EXPECT_GT(flatButSampledDiffers, flatPixels / 2);
  EXPECT_GT(changed, edgePixels * 3 / 4);
  // With one sample, adaptive changes nothing.
  RenderOptions single(w, w, 2);
  single.adaptive = true;
  EXPECT_EQ(Renderer(scene, single).render().rgb, first.rgb);
}

TEST(Shading, DepthAndNormalAovsOfPlanesFacingTheCamera) {
  // Seen from eye = (0.37, 0, 0) looking along +y: an open rectangle in the
  // plane y = 4 over x <= 0, and the face y = 6 of a box over x >= 0.37
  // (its side face x = 0.37 is edge-on to the eye). The depth along the
  // view direction is 4 or 6 wherever they are met, +inf elsewhere.
  Scene scene;
  scene.surfaces.push_back(
      Surface::parallelogram(dvec3(-10, 4, -10), dvec3(0, 0, 20), dvec3(10, 0, 0)));
  scene.objects.push_back(boxFromTo(dvec3(0.37, 6, -10), dvec3(10, 7, 10)));
  scene.camera = CameraSpec{dvec3(0.37, 0, 0), dvec3(0.37, 1, 0), dvec3(0, 0, 1), 60.0};
  const int w = 30, h = 20;
  RenderOptions options(w, h, 2);
  options.depthAov = options.normalAov = true;
  RenderResult result = Renderer(scene, options).renderAll();
  ASSERT_EQ(result.depth.width, w);
  ASSERT_EQ(result.normal.height, h);
  int onPlane = 0, onBox = 0, onSky = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      // The pixel's ray is forward + u·right + v·up; it reaches y = D at
      // x = 0.37 + D·u.
      double u = (i + 0.5 - 0.5 * w) * 2.0 * std::tan(radians(30)) / w;
      double depth = 0.37 + 4.0 * u <= 0.0 ? 4.0 : u > 0.0 ? 6.0 : kInfinity;
      onPlane += depth == 4.0, onBox += depth == 6.0, onSky += depth == kInfinity;
      dvec3 d = result.depth.at(i, j), n = result.normal.at(i, j);
      if (depth == kInfinity) {
        EXPECT_EQ(d.x, kInfinity) << i << " " << j;
        EXPECT_EQ(n, dvec3(0.0)) << i << " " << j;
      } else {
        EXPECT_NEAR(d.x, depth, 1e-5) << i << " " << j;
        EXPECT_NEAR(n.x, 0.0, 1e-7) << i << " " << j;
        EXPECT_NEAR(n.y, -1.0, 1e-7) << i << " " << j;
        EXPECT_NEAR(n.z, 0.0, 1e-7) << i << " " << j;
      }
    }
  EXPECT_GT(onPlane, 100);
  EXPECT_GT(onBox, 100);
  EXPECT_GE(onSky, 2 * h);
}

// ------------------------------------------------------------- cameras

// A block 0.01 × 0.01 × 0.005 on a slab, lit from above at a slant, seen
// from above: its
// shadow, a strip as long as the cube is tall times the light's slope,
// covers the same pixels at the origin and 10⁶ away. Rays left the surface
// a billionth of the distance from the origin off it (10⁻³ there), beyond
// such a cube, and its shadow was lost.
TEST(Shading, ASmallPartFarFromTheOriginCastsTheSameShadow) {
  const int w = 80, h = 80;
  std::vector<bool> shadowed[2];
  for (int k = 0; k < 2; ++k) {
    const dvec3 at = k == 0 ? dvec3(0.0) : dvec3(1e6, -2e6, 5e5);
    Scene scene;
    scene.objects.push_back(boxFromTo(at + dvec3(-0.05, -0.05, -0.01), at + dvec3(0.05, 0.05, 0.0))
                                ->withDefaultMaterial(matte(dvec3(1.0), 0.0, 1.0)));
    scene.objects.push_back(boxFromTo(at + dvec3(-0.005, -0.005, 0.0), at + dvec3(0.005))
                                ->withDefaultMaterial(matte(dvec3(1.0), 0.0, 1.0)));
    scene.lights.push_back(Light{Light::Kind::Point, at + dvec3(-1.0, 0.0, 1.0)});
    scene.camera = CameraSpec{at + dvec3(0, 0, 1), at, dvec3(0, 1, 0), 45.0, true, 0.04};
    scene.background = kBlack;
    const Image image = Renderer(scene, {w, h, 1}).render();
    int count = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool dark = image.at(x, y).x < 0.01;
        shadowed[k].push_back(dark);
        count += dark;
      }
    // The strip beside the cube: 0.005 long (its height times the
    // light's slope, 1), 0.01 wide: 10 × 20 pixels of 0.0005.
    EXPECT_NEAR(count, 200, 25) << k;
  }
  int differ = 0;
  for (std::size_t i = 0; i < shadowed[0].size(); ++i) differ += shadowed[0][i] != shadowed[1][i];
  EXPECT_LE(differ, 2);
}

TEST(Shading, OrthographicSilhouetteDoesNotDependOnDistance) {
  const double r = 1.3, orthoWidth = 5.0;
  const int w = 80, h = 60;
  std::vector<bool> masks[2];
  for (int k = 0; k < 2; ++k) {
    Scene scene;
    scene.objects.push_back(sphereAt(dvec3(0.0), r)->withDefaultMaterial(flat(dvec3(1.0))));
    double distance = k == 0 ? 4.0 : 60.0;
    scene.camera =
        CameraSpec{dvec3(0, -distance, 0), dvec3(0), dvec3(0, 0, 1), 45.0, true, orthoWidth};
    scene.background = kBlack;
    Image image = Renderer(scene, {w, h, 2}).render();
    int covered = 0, widest = 0;
    for (int y = 0; y < h; ++y) {
      int row = 0;
      for (int x = 0; x < w; ++x) {
        bool in = image.at(x, y).x > 0.0;
        masks[k].push_back(in);
        row += in;
      }
      covered += row;
      widest = std::max(widest, row);
    }
    double expected = r * w / orthoWidth;
    EXPECT_NEAR(std::sqrt(covered / kPi), expected, 1.0) << distance;
    EXPECT_NEAR(widest / 2.0, expected, 1.0) << distance;
  }
  EXPECT_EQ(masks[0], masks[1]);
}

// ------------------------------------------------------- open surfaces

TEST(Shading, DiscAndTriangleRenderWhereTheirFormulasSay) {
  const dvec3 discCentre(-1.0, 0.4, 0.5), discNormal = glm::normalize(dvec3(0.3, 0.1, 1.0));
  const double discRadius = 0.8;
  const dvec3 ta(0.4, -1.2, 1.0), tb(1.9, -0.6, 1.3), tc(0.8, 1.5, 0.9);
  Scene scene;
  scene.surfaces.push_back(
      Surface::disc(discCentre, discNormal, discRadius)->withMaterial(flat(kRed)));
  scene.surfaces.push_back(Surface::triangle(ta, tb, tc)->withMaterial(flat(kGreen)));
  scene.camera = topDown(0.1037, 0.0519, 4.4);
  scene.background = kBlack;
  const int w = 88, h = 72;
  Image image = Renderer(scene, {w, h, 2}).render();

  int red = 0, green = 0;
  double nearest = kInfinity;  // closest approach of a pixel centre to an edge
  dvec3 tn = glm::cross(tb - ta, tc - ta);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      glm::dvec2 q = topDownPoint(*scene.camera, w, h, i, j);
      // The disc: the vertical line's point on its plane, within the radius.
      double zd = discCentre.z -
                  (discNormal.x * (q.x - discCentre.x) + discNormal.y * (q.y - discCentre.y)) /
                      discNormal.z;
      double rho = glm::length(dvec3(q.x, q.y, zd) - discCentre);
      bool inDisc = rho <= discRadius;
      nearest = std::min(nearest, std::abs(rho - discRadius));
      // The triangle: the signs of the projected edge functions agree.
      auto edge = [&](const dvec3& p0, const dvec3& p1) {
        return (p1.x - p0.x) * (q.y - p0.y) - (p1.y - p0.y) * (q.x - p0.x);
      };
      double e0 = edge(ta, tb), e1 = edge(tb, tc), e2 = edge(tc, ta);
      double s = tn.z > 0 ? 1.0 : -1.0;
      bool inTriangle = s * e0 >= 0 && s * e1 >= 0 && s * e2 >= 0;
      nearest = std::min({nearest, std::abs(e0) / glm::length(glm::dvec2(tb - ta)),
                          std::abs(e1) / glm::length(glm::dvec2(tc - tb)),
                          std::abs(e2) / glm::length(glm::dvec2(ta - tc))});
      ASSERT_FALSE(inDisc && inTriangle);  // they do not overlap in view
      dvec3 expected = inDisc ? kRed : inTriangle ? kGreen : kBlack;
      EXPECT_EQ(image.at(i, j), expected) << i << " " << j;
      red += inDisc;
      green += inTriangle;
    }
  EXPECT_GT(nearest, 1e-6);
  // Both shapes cover their projected areas: the disc an ellipse of area
  // πr²·cos tilt, the triangle half the cross product's z.
  double pixelArea = std::pow(scene.camera->orthoWidth / w, 2.0);
  EXPECT_NEAR(red * pixelArea, kPi * discRadius * discRadius * discNormal.z, 0.05);
  EXPECT_NEAR(green * pixelArea, 0.5 * std::abs(tn.z), 0.05);
}

// ------------------------------------------------------------- inside a solid

// A room made as one opaque box with the camera and the light inside it:
// its inner walls are lit (a wall casts a shadow, the solid's inside does
// not), the ball on the floor shadows the floor under it, and a light
// outside the room is stopped by its walls.
TEST(Shading, ALightInsideAnOpaqueSolidLightsItsInnerWalls) {
  auto renderOf = [](const dvec3& light) {
    Scene scene;
    scene.objects = {
        boxFromTo(dvec3(-5), dvec3(5))->withDefaultMaterial(matte(dvec3(1), 0.1, 0.9)),
        sphereAt(dvec3(0, 0, -4), 0.5)->withDefaultMaterial(matte(dvec3(1), 0.1, 0.9))};
    scene.camera = CameraSpec{dvec3(0, -3, 0), dvec3(0, 0, -2), dvec3(0, 0, 1), 60.0};
    Light l;
    l.position = light;
    scene.lights = {l};
    return scene;
  };
  const dvec3 eye(0, -3, 0);
  auto toward = [&](const dvec3& p) { return Ray(eye, p - eye); };
  const Scene inside = renderOf(dvec3(0, 0, 3));
  const Renderer renderer(inside, {8, 8, 1});
  // Lambert at the floor point (2, 0, −5): ambient + diffuse · cos α.
  const double cosAlpha = 8.0 / std::sqrt(68.0);
  EXPECT_NEAR(renderer.trace(toward(dvec3(2, 0, -5))).x, 0.1 + 0.9 * cosAlpha, 1e-9);
  // Under the ball (on the camera's side of it), in its shadow: ambient alone.
  EXPECT_NEAR(renderer.trace(toward(dvec3(0, -0.4, -5))).x, 0.1, 1e-9);
  // A light above the room: its ceiling is between.
  const Scene outside = renderOf(dvec3(0, 0, 8));
  EXPECT_NEAR(Renderer(outside, {8, 8, 1}).trace(toward(dvec3(2, 0, -5))).x, 0.1, 1e-9);
}

}  // namespace
}  // namespace csgray::detail
