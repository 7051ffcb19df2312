// Points on a straight crease between two flat sides are dropped, and
// nothing else is: the surface, its volume, its validity and its
// materials stay as they were.
#include "export/collinear_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "export/cgal/mesh_validity.h"

namespace csgray::detail {
namespace {

// A mesh from polygons, each made a fan from its first corner; tags per
// polygon.
struct Polygons {
  TriangleMesh mesh;
  std::vector<std::uint32_t> tags;

  std::uint32_t point(const dvec3& p) {
    for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
      if (mesh.points[v] == p) return v;
    mesh.points.push_back(p);
    return std::uint32_t(mesh.points.size() - 1);
  }
  void add(const std::vector<dvec3>& corners, std::uint32_t tag = 0) {
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      mesh.triangles.push_back({point(corners[0]), point(corners[k]), point(corners[k + 1])});
      tags.push_back(tag);
    }
  }
};

// The unit cube, with a point m on its edge from (0, 0, 0) to (1, 0, 0)
// that the two faces along that edge are fanned from (m moved off the
// edge by `off` along −y, so into the bottom face's plane, and out of
// the front face's); `frontTag` the front face's material.
Polygons cubeWithEdgePoint(double off = 0.0, std::uint32_t frontTag = 0) {
  const dvec3 m(0.5, -off, 0.0);
  const dvec3 p000(0, 0, 0), p100(1, 0, 0), p110(1, 1, 0), p010(0, 1, 0);
  const dvec3 p001(0, 0, 1), p101(1, 0, 1), p111(1, 1, 1), p011(0, 1, 1);
  Polygons cube;
  cube.add({m, p100, p101, p001, p000}, frontTag);  // y = 0, facing −y
  cube.add({m, p000, p010, p110, p100});            // z = 0, facing −z
  cube.add({p001, p101, p111, p011});               // z = 1
  cube.add({p010, p011, p111, p110});               // y = 1
  cube.add({p000, p001, p011, p010});               // x = 0
  cube.add({p100, p110, p111, p101});               // x = 1
  return cube;
}

TEST(CollinearPoints, APointOnACubesEdgeIsDropped) {
  Polygons cube = cubeWithEdgePoint();
  ASSERT_EQ(cube.mesh.points.size(), 9u);
  ASSERT_EQ(cube.mesh.triangles.size(), 14u);
  ASSERT_TRUE(meshDefect(cube.mesh).valid());

  EXPECT_EQ(dropCollinearPoints(cube.mesh, cube.tags, 1e-9), 1u);
  EXPECT_EQ(cube.mesh.points.size(), 8u);
  EXPECT_EQ(cube.mesh.triangles.size(), 12u);
  EXPECT_EQ(cube.tags.size(), 12u);
  EXPECT_NEAR(cube.mesh.volume(), 1.0, 1e-15);
  EXPECT_NEAR(cube.mesh.area(), 6.0, 1e-15);
  EXPECT_TRUE(meshDefect(cube.mesh).valid()) << meshDefect(cube.mesh).text;
  for (const dvec3& p : cube.mesh.points) EXPECT_NE(p, dvec3(0.5, 0.0, 0.0));
}

TEST(CollinearPoints, ACornerOfThreePlanesStays) {
  Polygons cube = cubeWithEdgePoint();
  dropCollinearPoints(cube.mesh, cube.tags, 1e-9);
  const TriangleMesh before = cube.mesh;
  EXPECT_EQ(dropCollinearPoints(cube.mesh, cube.tags, 1e-9), 0u);
  EXPECT_EQ(cube.mesh.points, before.points);
  EXPECT_EQ(cube.mesh.triangles, before.triangles);
}

TEST(CollinearPoints, APointOffTheCreaseByMoreThanTheReachStays) {
  // Within the reach it goes (the bottom face's plane holds it, the front
  // face's is off by 1e-10); beyond it, it is a corner of the shape.
  Polygons near = cubeWithEdgePoint(1e-10);
  EXPECT_EQ(dropCollinearPoints(near.mesh, near.tags, 1e-9), 1u);
  EXPECT_TRUE(meshDefect(near.mesh).valid());

  Polygons far = cubeWithEdgePoint(1e-6);
  EXPECT_EQ(dropCollinearPoints(far.mesh, far.tags, 1e-9), 0u);
  EXPECT_EQ(far.mesh.triangles.size(), 14u);
}

TEST(CollinearPoints, ASideOfTwoMaterialsKeepsItsPoint) {
  // The front face split in two materials at m: its fan from m holds both.
  Polygons cube = cubeWithEdgePoint();
  cube.tags[0] = 7;  // the front face's first triangle only
  EXPECT_EQ(dropCollinearPoints(cube.mesh, cube.tags, 1e-9), 0u);

  // A whole side of one other material is fine, and keeps it.
  Polygons tagged = cubeWithEdgePoint(0.0, 5);
  EXPECT_EQ(dropCollinearPoints(tagged.mesh, tagged.tags, 1e-9), 1u);
  std::size_t fives = 0;
  for (std::uint32_t tag : tagged.tags) fives += tag == 5;
  EXPECT_EQ(fives, 2u);  // the front face, now two triangles
}

TEST(CollinearPoints, ARowOfPointsOnOneCreaseAllGo) {
  // Nine points along the edge, fanned from the far corners: all drop,
  // over several passes, and the cube is left.
  Polygons cube;
  const dvec3 p000(0, 0, 0), p100(1, 0, 0), p110(1, 1, 0), p010(0, 1, 0);
  const dvec3 p001(0, 0, 1), p101(1, 0, 1), p111(1, 1, 1), p011(0, 1, 1);
  std::vector<dvec3> front{p101, p001, p000}, bottom{p110, p100};
  for (int i = 1; i <= 9; ++i) front.push_back(dvec3(i / 10.0, 0.0, 0.0));
  front.push_back(p100);
  for (int i = 9; i >= 1; --i) bottom.push_back(dvec3(i / 10.0, 0.0, 0.0));
  bottom.push_back(p000), bottom.push_back(p010);
  cube.add(front);
  cube.add(bottom);
  cube.add({p001, p101, p111, p011});
  cube.add({p010, p011, p111, p110});
  cube.add({p000, p001, p011, p010});
  cube.add({p100, p110, p111, p101});
  ASSERT_TRUE(meshDefect(cube.mesh).valid()) << meshDefect(cube.mesh).text;
  const double volume = cube.mesh.volume();

  EXPECT_EQ(dropCollinearPoints(cube.mesh, cube.tags, 1e-9), 9u);
  EXPECT_EQ(cube.mesh.points.size(), 8u);
  EXPECT_EQ(cube.mesh.triangles.size(), 12u);
  EXPECT_NEAR(cube.mesh.volume(), volume, 1e-15);
  EXPECT_TRUE(meshDefect(cube.mesh).valid()) << meshDefect(cube.mesh).text;
}

}  // namespace
}  // namespace csgray::detail
