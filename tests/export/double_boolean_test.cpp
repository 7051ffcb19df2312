// The boolean in doubles (export/cgal/double_boolean.h): on operands in
// general position its result is closed, 2-manifold, outward and free of
// self-intersections, with the volume of CGAL's exact corefinement and,
// within the tessellation's tolerance, the analytic one; on operands that
// are not (coplanar faces, a corner on a face) it declines, and the
// export still succeeds through CGAL.
#include "export/cgal/double_boolean.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "engine/boolean.h"
#include "engine/primitive.h"
#include "export/cgal/exact_boolean.h"
#include "export/cgal/mesh_boolean.h"
#include "export/cgal/mesh_validity.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTolerance = 0.01;
using Op = Boolean::Op;

SolidPtr part(const std::string& source) {
  const Scene scene = runScript(source, "part.lua", test::exampleOptions());
  return scene.objects.size() == 1 ? scene.objects[0] : unionOf(scene.objects);
}

ExactMesh exactOf(const TriangleMesh& triangles) {
  ExactMesh mesh;
  for (const dvec3& p : triangles.points) mesh.add_vertex(CGAL::Epeck::Point_3(p.x, p.y, p.z));
  tagsOf(mesh);
  for (const auto& t : triangles.triangles)
    mesh.add_face(ExactMesh::Vertex_index(t[0]), ExactMesh::Vertex_index(t[1]),
                  ExactMesh::Vertex_index(t[2]));
  return mesh;
}

// The exact mesh of a script's primitive, tessellated at kTolerance.
ExactMesh meshOf(const std::string& source) {
  const SolidPtr solid = part(source);
  auto* primitive = dynamic_cast<const Primitive*>(solid.get());
  EXPECT_NE(primitive, nullptr) << source;
  return exactOf(primitive->tessellate(kTolerance, solid->bounds()));
}

// a op b in doubles, expected to be made and valid, with CGAL's volume to
// 1e-9 relative; returns its volume.
double madeInDoubles(const ExactMesh& a, const ExactMesh& b, Op op) {
  const std::optional<ExactMesh> made = doubleBoolean(a, b, op);
  EXPECT_TRUE(made.has_value()) << "declined";
  if (!made) return 0.0;
  const TriangleMesh mesh = trianglesOf(*made);
  EXPECT_EQ(meshDefect(mesh).text, "");
  ExactMesh exactA = a, exactB = b;
  EXPECT_TRUE(exactBoolean(exactA, exactB, op));
  const double cgal = trianglesOf(exactA).volume();
  EXPECT_NEAR(mesh.volume(), cgal, 1e-9 * std::abs(cgal));
  return mesh.volume();
}

TEST(DoubleBoolean, TwoOverlappingSpheres) {
  // Two balls of radius r at distance d share a lens of volume
  // π(4r + d)(2r − d)²/12 (Weisstein, "Sphere-Sphere Intersection",
  // MathWorld). The geodesic meshes are within the tolerance of their
  // spheres: the volume within tolerance × area.
  const double r = 10, d = 12;
  const double ball = 4.0 / 3.0 * kPi * r * r * r;
  const double lens = kPi * (4 * r + d) * (2 * r - d) * (2 * r - d) / 12;
  const double slack = kTolerance * 2 * 4 * kPi * r * r;
  const ExactMesh a = meshOf("return sphere{r=10}");
  const ExactMesh b = meshOf("return sphere{r=10}:translate(12, 0, 0)");
  EXPECT_NEAR(madeInDoubles(a, b, Op::Union), 2 * ball - lens, slack);
  EXPECT_NEAR(madeInDoubles(a, b, Op::Intersection), lens, slack);
  EXPECT_NEAR(madeInDoubles(a, b, Op::Difference), ball - lens, slack);
}

TEST(DoubleBoolean, BoxMinusCylinder) {
  const ExactMesh box = meshOf("return box(20)");
  const ExactMesh hole = meshOf("return cylinder{r=5, h=40}:translate(10, 10, -10)");
  EXPECT_NEAR(madeInDoubles(box, hole, Op::Difference), 8000 - kPi * 25 * 20,
              kTolerance * 2 * kPi * 5 * 20);
}

TEST(DoubleBoolean, BoxUnitedWithAGridOfSpheres) {
  // Nine balls of radius 4 centred on the box's top face, apart: each
  // adds half of itself.
  ExactMesh spheres;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      ExactMesh ball = meshOf("return sphere{r=4}:translate(" + std::to_string(6 + 12 * i) + ", " +
                              std::to_string(6 + 12 * j) + ", 10)");
      tagsOf(ball);
      spheres.join(ball);
    }
  const ExactMesh box = meshOf("return box{size={36, 36, 10}}");
  const double half = 2.0 / 3.0 * kPi * 64;
  EXPECT_NEAR(madeInDoubles(spheres, box, Op::Union), 36 * 36 * 10 + 9 * half,
              kTolerance * 9 * 4 * kPi * 16);
}

TEST(DoubleBoolean, TwoTurnedBoxesIntersected) {
  // Polytopes: the tessellation is exact, and so is CGAL's volume.
  const ExactMesh a = meshOf("return box(10):translate(-5, -5, -5):rotate(17, 23, 31)");
  const ExactMesh b = meshOf("return box(10):translate(-5, -5, -5):rotate(-41, 13, 7)");
  const double volume = madeInDoubles(a, b, Op::Intersection);
  EXPECT_GT(volume, 0.0);
  EXPECT_LT(volume, 1000.0);
}

TEST(DoubleBoolean, DeclinesCoplanarFaces) {
  // Boxes side by side on one floor: their bottoms lie in one plane.
  const ExactMesh a = meshOf("return box(10)");
  const ExactMesh b = meshOf("return box(10):translate(5, 5, 0)");
  EXPECT_FALSE(doubleBoolean(a, b, Op::Union).has_value());
  MeshBooleanStats stats;
  const PartMesh made = meshOfSolid(*part("return box(10) + box(10):translate(5, 5, 0)"),
                                    kTolerance, nullptr, &stats);
  EXPECT_EQ(meshDefect(made.mesh).text, "");
  EXPECT_NEAR(made.mesh.volume(), 1750.0, 1e-9);
  EXPECT_EQ(stats.corefinements, 1u);
  EXPECT_EQ(stats.inDoubles, 0u);
}

TEST(DoubleBoolean, SaysWhyItDeclines) {
  // Coplanar faces: not in general position, which a move may put right.
  const ExactMesh a = meshOf("return box(10)");
  DoubleDecline why = DoubleDecline::NotInDoubles;
  EXPECT_FALSE(doubleBoolean(a, meshOf("return box(10):translate(5, 5, 0)"), Op::Union, &why));
  EXPECT_EQ(why, DoubleDecline::NotInGeneralPosition);
  // A point of CGAL's that is no double (a ball's faces cut by a box's):
  // an operand it cannot take.
  ExactMesh ball = meshOf("return sphere(4):translate(10, 10, 10)"), box = a;
  ASSERT_TRUE(exactBoolean(box, ball, Op::Union));
  why = DoubleDecline::NotInGeneralPosition;
  EXPECT_FALSE(doubleBoolean(box, meshOf("return sphere(1):translate(0, 0, 10)"), Op::Union, &why));
  EXPECT_EQ(why, DoubleDecline::NotInDoubles);
}

TEST(DoubleBoolean, TopologyCountsShellsAndHandles) {
  // Two balls apart: two spheres (χ = 2 each). A box less a rod through
  // it: a torus (χ = 0).
  const ExactMesh ball = meshOf("return sphere(2)");
  ExactMesh two = ball;
  two.join(meshOf("return sphere(2):translate(10, 0, 0)"));
  EXPECT_EQ(topologyOf(two), (MeshTopology{2, 4}));
  ExactMesh ring = meshOf("return box(10)"),
            rod = meshOf("return cylinder{r=2, h=20}:translate(5, 5, -5)");
  ASSERT_TRUE(exactBoolean(ring, rod, Op::Difference));
  EXPECT_EQ(topologyOf(ring), (MeshTopology{1, 0}));
}

TEST(DoubleBoolean, DeclinesACornerOnAFace) {
  // A pyramid whose apex touches the box's top face from above, inside
  // it; then pushed into the box, its apex strictly inside: made.
  auto pyramid = [](double apex) {
    TriangleMesh t;
    t.points = {{5, 5, apex}, {2, 2, 15}, {8, 2, 15}, {8, 8, 15}, {2, 8, 15}};
    t.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4}, {1, 2, 3}, {1, 3, 4}};
    return exactOf(t);
  };
  const ExactMesh box = meshOf("return box(10)");
  EXPECT_GT(trianglesOf(pyramid(10)).volume(), 0.0);
  EXPECT_FALSE(doubleBoolean(box, pyramid(10), Op::Union).has_value());
  madeInDoubles(box, pyramid(9), Op::Union);
}

// bench/plate.lua at n: a box united with an n × n grid of balls, less a
// grid of holes on the same centres.
SolidPtr plate(int n) {
  return part("local n, p = " + std::to_string(n) + ", 100 / " + std::to_string(n) + R"(
    local spheres, holes = {}, {}
    for i = 0, n - 1 do
      for j = 0, n - 1 do
        local x, y = p / 2 + i * p, p / 2 + j * p
        spheres[#spheres + 1] = sphere{r=0.32 * p}:translate(x, y, 10)
        holes[#holes + 1] = cylinder{r=0.2 * p, h=20}:translate(x, y, -1)
      end
    end
    return difference(union(box{size={100, 100, 10}}, union(spheres)), union(holes)))");
}

TEST(DoubleBoolean, SmallPlateExportsInDoublesWithCgalsVolume) {
  // plate(6): both booleans made in doubles.
  const SolidPtr solid = plate(6);
  MeshBooleanStats fast, exact;
  const PartMesh inDoubles = meshOfSolid(*solid, kTolerance, nullptr, &fast);
  const PartMesh byCgal = meshOfSolid(*solid, kTolerance, nullptr, &exact, false);
  EXPECT_EQ(fast.corefinements, 2u);
  EXPECT_EQ(fast.inDoubles, 2u);
  EXPECT_FALSE(fast.redoneByCgal);
  EXPECT_EQ(exact.inDoubles, 0u);
  EXPECT_EQ(meshDefect(inDoubles.mesh).text, "");
  EXPECT_NEAR(inDoubles.mesh.volume(), byCgal.mesh.volume(), 1e-9 * byCgal.mesh.volume());
}

TEST(DoubleBoolean, TheSameMeshOnOneThreadAndOnFour) {
  // The union's balls are tessellated on all threads, the pairs of faces
  // are found and tested on all threads, each operand is cut and
  // classified on a thread of its own, and the check's pairs of boxes are
  // shared out: the part must not depend on how many threads did it.
  // (plate(8): two booleans in doubles with hundreds of cut faces, and
  // enough faces that the check splits.)
  const SolidPtr solid = plate(8);
  auto meshOn = [&](int threads) {
    MeshBooleanStats stats;
    PartMesh part;
    tbb::task_arena(threads).execute(
        [&] { part = meshOfSolid(*solid, kTolerance, nullptr, &stats); });
    EXPECT_EQ(stats.inDoubles, 2u);
    return part;
  };
  const PartMesh one = meshOn(1), four = meshOn(4);
  ASSERT_GT(one.mesh.triangles.size(), 20000u);
  EXPECT_EQ(one.mesh.points, four.mesh.points);
  EXPECT_EQ(one.mesh.triangles, four.mesh.triangles);
  EXPECT_EQ(one.material, four.material);
}

}  // namespace
}  // namespace csgray::detail
