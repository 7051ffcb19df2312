// Open triangle meshes as surfaces: rays meet them from both sides where
// the triangles are, none slips through the seams between triangles (rays
// aimed at the grid's edges and corners), the nearest of several sheets
// comes first, the window tMin < t < tMax holds, transforms place the
// mesh, and the shading normal is the points' normals interpolated (the
// analytic normal of a cylinder), turned to the side of the triangle.
#include "scene/surface_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_support.h"

namespace csgray::detail {
namespace {

using Faces = std::vector<std::vector<std::int64_t>>;

// The square [0, n]² at height z as n × n cells of two triangles each,
// their diagonals alternating so that the triangles around a point run
// both ways round.
SurfacePtr grid(int n, double z) {
  std::vector<dvec3> points;
  Faces faces;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) points.push_back(dvec3(i, j, z));
  auto at = [&](int i, int j) { return std::int64_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      faces.push_back({at(i, j + 1), at(i + 1, j + 1), at(i, j)});  // the other way round
    }
  return meshSurfaceOf(points, faces, {}, true);
}

TEST(SurfaceMesh, RaysMeetItFromBothSidesAndNeverThroughASeam) {
  const SurfacePtr sheet = grid(4, 1.0);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> in(0.0, 4.0);
  // Vertical rays at random points, and exactly at every inner edge and
  // corner of the grid: each meets the sheet once, at z = 1. (On its
  // border a ray may pass on either side.)
  std::vector<dvec2> aims;
  for (int k = 0; k < 200; ++k) aims.push_back(dvec2(in(rng), in(rng)));
  for (int j = 1; j < 8; ++j)
    for (int i = 1; i < 8; ++i) aims.push_back(dvec2(i / 2.0, j / 2.0));
  for (const dvec2& a : aims) {
    for (double dir : {-1.0, 1.0}) {
      const Ray ray(dvec3(a.x, a.y, 1.0 - 3.0 * dir), dvec3(0, 0, dir));
      int face = -1;
      const std::optional<double> t = sheet->hit(ray, &face);
      ASSERT_TRUE(t) << a.x << ", " << a.y << " from " << (dir > 0 ? "below" : "above");
      EXPECT_NEAR(*t, 3.0, 1e-12);
      EXPECT_GE(face, 0);
      EXPECT_LT(face, 32);
      // Flat: every normal is the sheet's, up to its side.
      EXPECT_NEAR(std::abs(sheet->normalAt(ray.at(*t), face).z), 1.0, 1e-12);
    }
  }
  // Beside the square: nothing.
  EXPECT_FALSE(sheet->hit(Ray(dvec3(4.001, 2, 5), dvec3(0, 0, -1))));
  EXPECT_FALSE(sheet->hit(Ray(dvec3(-0.001, 2, 5), dvec3(0, 0, -1))));
  // Along the sheet's plane: nothing (it has no thickness).
  EXPECT_FALSE(sheet->hit(Ray(dvec3(-1, 2.5, 1), dvec3(1, 0, 0))));
}

TEST(SurfaceMesh, TheNearestSheetWithinTheWindowIsHit) {
  // Two sheets in one mesh, at z = 0 and z = 2.
  std::vector<dvec3> points = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 2}, {4, 0, 2}, {0, 4, 2}};
  const SurfacePtr two = meshSurfaceOf(points, {{0, 1, 2}, {3, 4, 5}}, {}, true);
  const dvec3 down(0, 0, -1);
  EXPECT_NEAR(*two->hit(Ray(dvec3(1, 1, 5), down)), 3.0, 1e-12);
  EXPECT_NEAR(*two->hit(Ray(dvec3(1, 1, -5), -down)), 5.0, 1e-12);
  // Past the first sheet: the second; before it: nothing.
  EXPECT_NEAR(*two->hit(Ray(dvec3(1, 1, 5), down, 3.5, kInfinity)), 5.0, 1e-12);
  EXPECT_FALSE(two->hit(Ray(dvec3(1, 1, 5), down, 0.0, 2.5)));
  // A ray that starts on a sheet does not meet it again there.
  EXPECT_NEAR(*two->hit(Ray(dvec3(1, 1, 2), down, 1e-9, kInfinity)), 2.0, 1e-12);
}

TEST(SurfaceMesh, TransformsPlaceItAndItsNormals) {
  const SurfacePtr sheet = grid(2, 0.0);
  // Turned upright (the sheet in the xz plane) and moved by 10 in y.
  const SurfacePtr wall = sheet->transformed(Affine::rotation(std::numbers::pi / 2, dvec3(1, 0, 0))
                                                 .then(Affine::translation(dvec3(0, 10, 0))));
  int face = -1;
  const Ray ray(dvec3(1, 0, 1), dvec3(0, 1, 0));
  const std::optional<double> t = wall->hit(ray, &face);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 10.0, 1e-12);
  EXPECT_NEAR(std::abs(wall->normalAt(ray.at(*t), face).y), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(wall->faceNormal(face).y), 1.0, 1e-12);
  EXPECT_NEAR(wall->bounds().lo.y, 10.0, 1e-6);
  EXPECT_NEAR(wall->bounds().hi.z, 2.0, 1e-6);
  EXPECT_NEAR(wall->bounds().lo.z, 0.0, 1e-6);
  // Beside it (z > 2): nothing.
  EXPECT_FALSE(wall->hit(Ray(dvec3(1, 0, 2.01), dvec3(0, 1, 0))));
  EXPECT_EQ(wall->kind(), "mesh surface");
}

// A quarter of the cylinder x² + z² = 1 (x, z ≥ 0) from y = 0 to 1, as
// strips of `n` triangles pairs round it, with the cylinder's normals at
// the points or without.
SurfacePtr cylinderPatch(int n, bool normals, bool smooth = true) {
  std::vector<dvec3> points, given;
  Faces faces;
  for (int i = 0; i <= n; ++i) {
    const double a = std::numbers::pi / 2 * i / n;
    for (double y : {0.0, 1.0}) {
      points.push_back(dvec3(std::cos(a), y, std::sin(a)));
      given.push_back(dvec3(std::cos(a), 0, std::sin(a)));
    }
  }
  for (int i = 0; i < n; ++i) {
    const std::int64_t a = 2 * i, b = a + 1, c = a + 2, d = a + 3;
    faces.push_back({a, c, d});
    faces.push_back({d, b, a});
  }
  return meshSurfaceOf(points, faces, normals ? given : std::vector<dvec3>{}, smooth);
}

TEST(SurfaceMesh, SmoothNormalsFollowTheCurvedSurface) {
  // Rays towards the axis meet the chords; the interpolated normal is
  // within a small angle of the radial direction there, whether the
  // normals are given or averaged from the triangles, while each
  // triangle's own is up to half a step (45°/8) off.
  const int n = 8;
  const double step = std::numbers::pi / 2 / n;
  for (bool given : {true, false}) {
    const SurfacePtr patch = cylinderPatch(n, given);
    const SurfacePtr flat = cylinderPatch(n, given, false);
    double worst = 0.0, worstFlat = 0.0;
    for (int k = 1; k < 100; ++k) {
      const double a = std::numbers::pi / 2 * k / 100.0;
      const dvec3 radial(std::cos(a), 0, std::sin(a));
      const Ray ray(dvec3(0, 0.5, 0) + 2.0 * radial, -radial);
      int face = -1;
      const std::optional<double> t = patch->hit(ray, &face);
      ASSERT_TRUE(t);
      // On a chord: between cos(step/2) and 1 from the axis.
      EXPECT_GE(2.0 - *t, std::cos(step / 2) - 1e-12);
      EXPECT_LE(2.0 - *t, 1.0 + 1e-12);
      const dvec3 n = patch->normalAt(ray.at(*t), face);
      EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
      worst = std::max(worst, std::acos(std::min(1.0, std::abs(glm::dot(n, radial)))));
      const dvec3 f = flat->normalAt(ray.at(*t), face);
      worstFlat = std::max(worstFlat, std::acos(std::min(1.0, std::abs(glm::dot(f, radial)))));
      // On the triangle's side.
      EXPECT_GT(glm::dot(n, patch->faceNormal(face)), 0.0);
    }
    // Linear interpolation of unit normals a step apart: off by far less
    // than the step (the averaged normals at the two ends of the patch
    // lean a little, within half a step).
    EXPECT_LT(worst, given ? 0.01 * step : 0.5 * step) << given;
    EXPECT_GT(worstFlat, 0.4 * step);
  }
}

TEST(SurfaceMesh, AOneSidedStripIsShadedSmoothAcrossItsTwist) {
  // A Möbius strip: its triangles cannot all face one way, so averaged
  // normals must not cancel where the ends meet turned over.
  const int n = 48;
  std::vector<dvec3> points;
  Faces faces;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * std::numbers::pi * i / n;
    for (double v : {-0.3, 0.3})
      points.push_back(dvec3((1 + v * std::cos(u / 2)) * std::cos(u),
                             (1 + v * std::cos(u / 2)) * std::sin(u), v * std::sin(u / 2)));
  }
  for (int i = 0; i < n; ++i) {
    // The last strip joins the first turned over: point v of u = 2π is −v of u = 0.
    const std::int64_t a = 2 * i, b = a + 1;
    const std::int64_t c = i + 1 < n ? a + 2 : 1, d = i + 1 < n ? a + 3 : 0;
    faces.push_back({a, c, d});
    faces.push_back({d, b, a});
  }
  const SurfacePtr strip = meshSurfaceOf(points, faces, {}, true);
  // Every point's normal is a direction, about perpendicular to the strip
  // along u (its tangent).
  const auto& normals = strip->mesh()->pointNormals();
  for (std::size_t i = 0; i < normals.size(); ++i) {
    EXPECT_NEAR(glm::length(normals[i]), 1.0, 1e-12) << i;
    const double u = 2 * std::numbers::pi * double(i / 2) / n;
    // (The strip's edges lean: their tangent is 0.21 off the middle line's.)
    EXPECT_LT(std::abs(glm::dot(normals[i], dvec3(-std::sin(u), std::cos(u), 0))), 0.3) << i;
  }
}

TEST(SurfaceMesh, BadMeshesAreRefusedByName) {
  const std::vector<dvec3> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  auto message = [&](const std::vector<dvec3>& points, const Faces& faces,
                     const std::vector<dvec3>& normals = {}) {
    try {
      meshSurfaceOf(points, faces, normals, true);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(message(three, {{0, 1, 3}}),
            "mesh_surface: face 0: point index 3 is out of range (there are 3 points, numbered "
            "from 0)");
  EXPECT_EQ(message(three, {{0, 1, 2, 0}}),
            "mesh_surface: face 0 has 4 points; the faces of a surface are triangles of 3");
  EXPECT_EQ(message(three, {{0, 1, 2}}, {{0, 0, 1}}),
            "mesh_surface: normals must give one normal per point (3 points, 1 normals)");
  EXPECT_EQ(message({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}),
            "mesh_surface: no face has an area (every face's points lie on one line)");
  EXPECT_EQ(message(three, {}), "mesh_surface: needs at least one face");
  EXPECT_EQ(message({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}, {{0, 1, 2}})
                .rfind("mesh_surface: point 2 has a coordinate that is not finite (0, ", 0),
            0u);
  // A face with no area among others is left out; the rest stands.
  EXPECT_EQ(message({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}}, {{0, 1, 3}, {0, 1, 2}}),
            "(no error)");
}

}  // namespace
}  // namespace csgray::detail
