// The boolean in doubles (export/cgal/double_boolean.h): on operands in
// general position its result is closed, 2-manifold, outward and free of
// self-intersections, with the volume of CGAL's exact corefinement and,
// within the tessellation's tolerance, the analytic one; on operands that
// are not (coplanar faces, a corner on a face) it declines, and the
// export still succeeds through CGAL.
#include "export/cgal/double_boolean.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "engine/boolean.h"
#include "engine/cancellation.h"
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

DoubleMesh tagged(TriangleMesh triangles) {
  DoubleMesh mesh;
  mesh.tags.assign(triangles.size(), 0);
  mesh.mesh = std::move(triangles);
  return mesh;
}

// The mesh of a script's primitive, tessellated at kTolerance.
DoubleMesh meshOf(const std::string& source) {
  const SolidPtr solid = part(source);
  auto* primitive = dynamic_cast<const Primitive*>(solid.get());
  EXPECT_NE(primitive, nullptr) << source;
  return tagged(primitive->tessellate(kTolerance, solid->bounds()));
}

// a op b in doubles, expected to be made and valid, with CGAL's volume to
// 1e-9 relative; returns its volume.
double madeInDoubles(const DoubleMesh& a, const DoubleMesh& b, Op op) {
  const std::optional<DoubleMesh> made = doubleBoolean(a, b, op);
  EXPECT_TRUE(made.has_value()) << "declined";
  if (!made) return 0.0;
  const TriangleMesh& mesh = made->mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  ExactMesh exactA = exactOf(a), exactB = exactOf(b);
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
  const DoubleMesh a = meshOf("return sphere{r=10}");
  const DoubleMesh b = meshOf("return sphere{r=10}:translate(12, 0, 0)");
  EXPECT_NEAR(madeInDoubles(a, b, Op::Union), 2 * ball - lens, slack);
  EXPECT_NEAR(madeInDoubles(a, b, Op::Intersection), lens, slack);
  EXPECT_NEAR(madeInDoubles(a, b, Op::Difference), ball - lens, slack);
}

TEST(DoubleBoolean, BoxMinusCylinder) {
  const DoubleMesh box = meshOf("return box(20)");
  const DoubleMesh hole = meshOf("return cylinder{r=5, h=40}:translate(10, 10, -10)");
  EXPECT_NEAR(madeInDoubles(box, hole, Op::Difference), 8000 - kPi * 25 * 20,
              kTolerance * 2 * kPi * 5 * 20);
}

TEST(DoubleBoolean, BoxUnitedWithAGridOfSpheres) {
  // Nine balls of radius 4 centred on the box's top face, apart: each
  // adds half of itself.
  DoubleMesh spheres;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      spheres.append(meshOf("return sphere{r=4}:translate(" + std::to_string(6 + 12 * i) + ", " +
                            std::to_string(6 + 12 * j) + ", 10)"));
  const DoubleMesh box = meshOf("return box{size={36, 36, 10}}");
  const double half = 2.0 / 3.0 * kPi * 64;
  EXPECT_NEAR(madeInDoubles(spheres, box, Op::Union), 36 * 36 * 10 + 9 * half,
              kTolerance * 9 * 4 * kPi * 16);
}

TEST(DoubleBoolean, TwoTurnedBoxesIntersected) {
  // Polytopes: the tessellation is exact, and so is CGAL's volume.
  const DoubleMesh a = meshOf("return box(10):translate(-5, -5, -5):rotate(17, 23, 31)");
  const DoubleMesh b = meshOf("return box(10):translate(-5, -5, -5):rotate(-41, 13, 7)");
  const double volume = madeInDoubles(a, b, Op::Intersection);
  EXPECT_GT(volume, 0.0);
  EXPECT_LT(volume, 1000.0);
}

TEST(DoubleBoolean, DeclinesCoplanarFaces) {
  // Boxes side by side on one floor: their bottoms lie in one plane.
  const DoubleMesh a = meshOf("return box(10)");
  const DoubleMesh b = meshOf("return box(10):translate(5, 5, 0)");
  EXPECT_FALSE(doubleBoolean(a, b, Op::Union).has_value());
  // In a part, the second box less high (of one height, the two would be
  // one extrusion, export/prism_booleans.h): 1000 + 700 − 5 · 5 · 7.
  MeshBooleanStats stats;
  const PartMesh made =
      meshOfSolid(*part("return box(10) + box{size = {10, 10, 7}}:translate(5, 5, 0)"), kTolerance,
                  nullptr, &stats);
  EXPECT_EQ(meshDefect(made.mesh).text, "");
  EXPECT_NEAR(made.mesh.volume(), 1525.0, 1e-9);
  EXPECT_EQ(stats.corefinements, 1u);
  EXPECT_EQ(stats.inDoubles, 0u);
}

TEST(DoubleBoolean, SaysWhyItDeclines) {
  // Coplanar faces: not in general position, which a move may put right.
  const DoubleMesh a = meshOf("return box(10)");
  DoubleDecline why = DoubleDecline::NotInDoubles;
  EXPECT_FALSE(doubleBoolean(a, meshOf("return box(10):translate(5, 5, 0)"), Op::Union, &why));
  EXPECT_EQ(why, DoubleDecline::NotInGeneralPosition);
  // A point of CGAL's that is no double (a ball's faces cut by a box's):
  // no operand in doubles, and so none it can take.
  ExactMesh box = exactOf(a), ball = exactOf(meshOf("return sphere(4):translate(10, 10, 10)"));
  ASSERT_TRUE(exactBoolean(box, ball, Op::Union));
  EXPECT_FALSE(doublesOf(box).has_value());
}

// The corefinement reads the caller's cancel at its steps: with the flag
// set, CGAL stops inside its first stage (exactBoolean itself reads no
// flag), and the same meshes are combined once the flag is clear.
TEST(ExactBoolean, StopsInsideCgalsCorefinementWhenCancelled) {
  const DoubleMesh box = meshOf("return box(10)");
  const DoubleMesh ball = meshOf("return sphere(4):translate(10, 10, 10)");
  ExactMesh a = exactOf(box), b = exactOf(ball);
  std::atomic<bool> cancel = true;
  {
    const CancelScope scope(&cancel);
    EXPECT_THROW(exactBoolean(a, b, Op::Union), Cancelled);
  }
  ExactMesh c = exactOf(box), d = exactOf(ball);
  const CancelScope scope(&cancel);
  cancel = false;
  ASSERT_TRUE(exactBoolean(c, d, Op::Union));
  // The box and the ball's overlapping eighth: 1000 + (1 − 1/8) of the
  // ball, within the tessellation's tolerance times the ball's area.
  const double ball8 = 4.0 / 3.0 * kPi * 64;
  EXPECT_NEAR(trianglesOf(c).volume(), 1000 + 7.0 / 8.0 * ball8, kTolerance * 4 * kPi * 16);
}

// The boolean in doubles reads the caller's cancel as it finds the
// crossings and cuts the faces: set, it stops; clear, it is made.
TEST(DoubleBoolean, StopsWhenCancelled) {
  const DoubleMesh a = meshOf("return sphere{r=10}");
  const DoubleMesh b = meshOf("return sphere{r=10}:translate(12, 0, 0)");
  std::atomic<bool> cancel = true;
  const CancelScope scope(&cancel);
  EXPECT_THROW(doubleBoolean(a, b, Op::Union), Cancelled);
  cancel = false;
  EXPECT_TRUE(doubleBoolean(a, b, Op::Union).has_value());
}

TEST(DoubleBoolean, TopologyCountsShellsAndHandles) {
  // Two balls apart: two spheres (χ = 2 each). A box less a rod through
  // it: a torus (χ = 0).
  DoubleMesh two = meshOf("return sphere(2)");
  two.append(meshOf("return sphere(2):translate(10, 0, 0)"));
  EXPECT_EQ(topologyOf(two), (MeshTopology{2, 4}));
  const std::optional<DoubleMesh> ring =
      doubleBoolean(meshOf("return box(10)"),
                    meshOf("return cylinder{r=2, h=20}:translate(4, 5.5, -5)"), Op::Difference);
  ASSERT_TRUE(ring.has_value());
  EXPECT_EQ(topologyOf(*ring), (MeshTopology{1, 0}));
}

TEST(DoubleBoolean, DeclinesACornerOnAFace) {
  // A pyramid whose apex touches the box's top face from above, inside
  // it; then pushed into the box, its apex strictly inside: made.
  auto pyramid = [](double apex) {
    TriangleMesh t;
    t.points = {{5, 5, apex}, {2, 2, 15}, {8, 2, 15}, {8, 8, 15}, {2, 8, 15}};
    t.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4}, {1, 2, 3}, {1, 3, 4}};
    return tagged(t);
  };
  const DoubleMesh box = meshOf("return box(10)");
  EXPECT_GT(pyramid(10).mesh.volume(), 0.0);
  EXPECT_FALSE(doubleBoolean(box, pyramid(10), Op::Union).has_value());
  madeInDoubles(box, pyramid(9), Op::Union);
}

// A tetrahedron, outward: the smallest closed 2-manifold.
TriangleMesh tetrahedron(const dvec3& at) {
  TriangleMesh t;
  t.points = {at, at + dvec3(1, 0, 0), at + dvec3(0, 1, 0), at + dvec3(0, 0, 1)};
  t.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return t;
}

TEST(DoubleMesh, ClosedManifoldAsCgalBuildsIt) {
  TriangleMesh t = tetrahedron(dvec3(0));
  EXPECT_TRUE(closedManifold(t));
  TriangleMesh open = t;
  open.triangles.pop_back();  // a hole
  EXPECT_FALSE(closedManifold(open));
  TriangleMesh flipped = t;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);  // each edge twice one way
  EXPECT_FALSE(closedManifold(flipped));
  TriangleMesh twice = t;
  twice.triangles[0] = {0, 0, 1};  // a corner twice
  EXPECT_FALSE(closedManifold(twice));
  // Two tetrahedra that share a corner: each edge fine, the corner two fans.
  TriangleMesh pinched = t;
  TriangleMesh other = tetrahedron(dvec3(0, 0, 1));
  pinched.append(other);
  for (auto& tri : pinched.triangles)
    for (auto& v : tri)
      if (v == 4) v = 3;  // other's first point is t's last
  EXPECT_FALSE(closedManifold(pinched));
  // Apart, they are two closed shells.
  TriangleMesh two = t;
  two.append(tetrahedron(dvec3(5, 0, 0)));
  EXPECT_TRUE(closedManifold(two));
}

TEST(DoubleMesh, ExactAndBackKeepTheOrder) {
  // Vertices and faces keep their numbers both ways, and a face its
  // corners in the order add_face was given them.
  DoubleMesh mesh = tagged(tetrahedron(dvec3(1, 2, 3)));
  mesh.tags = {4, 5, 6, 7};
  const ExactMesh exact = exactOf(mesh);
  EXPECT_EQ(trianglesOf(exact).triangles, mesh.mesh.triangles);
  const std::optional<DoubleMesh> back = doublesOf(exact);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->mesh.points, mesh.mesh.points);
  EXPECT_EQ(back->mesh.triangles, mesh.mesh.triangles);
  EXPECT_EQ(back->tags, mesh.tags);
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
