// meshDefect's test for self-intersections against CGAL's own
// (PMP::does_self_intersect) on meshes that fold and cross in every way:
// faces apart, faces that share a corner, faces that share an edge.
#include "export/cgal/mesh_validity.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include <random>

#include "primitives/sphere.h"

namespace csgray::detail {
namespace {

bool cgalSaysItCrosses(const TriangleMesh& mesh) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  for (const dvec3& p : mesh.points) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::array<std::size_t, 3>> faces;
  for (const auto& t : mesh.triangles) faces.push_back({t[0], t[1], t[2]});
  CGAL::Surface_mesh<Point> surface;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, surface);
  return CGAL::Polygon_mesh_processing::does_self_intersect(surface);
}

bool crosses(const TriangleMesh& mesh) {
  const MeshDefect defect = meshDefect(mesh);
  const bool crossing = defect.kind == MeshDefect::Kind::SelfIntersecting;
  EXPECT_EQ(crossing, defect.text.starts_with("self-intersecting")) << defect.text;
  return crossing;
}

// The octahedron with corners ±x, ±y, ±z.
TriangleMesh octahedron() {
  TriangleMesh m;
  m.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// (Faces that share nothing and cross: the random test below, and two
// overlapping cubes in mesh_reader_test.)
TEST(MeshValidity, AnOctahedronIsValidAndItsTopFoldedOntoItsBottomIsNot) {
  TriangleMesh m = octahedron();
  EXPECT_EQ(meshDefect(m).text, "");
  // The top corner pushed down inside: a dent, still a valid solid.
  m.points[4] = {0, 0, -0.5};
  EXPECT_EQ(meshDefect(m).text, "");
  EXPECT_FALSE(cgalSaysItCrosses(m));
  // Onto the bottom corner: each upper face lies on the lower face that
  // shares its equator edge (folded, in one plane, on one side).
  m.points[4] = {0, 0, -1};
  EXPECT_TRUE(crosses(m)) << meshDefect(m).text;
  EXPECT_TRUE(cgalSaysItCrosses(m));
  // Past it: the upper faces now wrap the lower ones, meeting them only
  // along the equator, and face inwards.
  m.points[4] = {0, 0, -2};
  EXPECT_FALSE(cgalSaysItCrosses(m));
  EXPECT_EQ(meshDefect(m).kind, MeshDefect::Kind::InsideOut) << meshDefect(m).text;
  EXPECT_TRUE(meshDefect(m).text.starts_with("inside out")) << meshDefect(m).text;
}

TEST(MeshValidity, CrossingsAgreeWithCgalOnRandomlyCrumpledSpheres) {
  // A coarse geodesic sphere (80 faces) with its vertices moved at random:
  // small moves keep it valid, large ones fold faces over their
  // neighbours (sharing a corner or an edge) and through far faces.
  const TriangleMesh sphere = Primitive::create<Sphere>(1.0)->tessellate(0.2, Bounds::everything());
  ASSERT_LT(sphere.triangles.size(), 200u);
  std::mt19937 random(20261123);
  int crossing = 0, clean = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double amplitude = 0.05 + 0.6 * (trial % 20) / 20.0;
    std::uniform_real_distribution<double> move(-amplitude, amplitude);
    TriangleMesh m = sphere;
    for (dvec3& p : m.points) p += dvec3(move(random), move(random), move(random));
    const bool expected = cgalSaysItCrosses(m);
    ASSERT_EQ(crosses(m), expected) << "trial " << trial << ": " << meshDefect(m).text;
    (expected ? crossing : clean)++;
  }
  // Both outcomes were tried, many times.
  EXPECT_GT(crossing, 50);
  EXPECT_GT(clean, 50);
}

TEST(MeshValidity, CrossingsAgreeWithCgalOnAFineSphereWithAFewVerticesMoved) {
  // Enough faces that the search for pairs of boxes splits them (more
  // than a few thousand, box_pairs.cpp); a few vertices moved far enough
  // to fold faces over or through others, or not quite.
  const TriangleMesh sphere =
      Primitive::create<Sphere>(1.0)->tessellate(0.0005, Bounds::everything());
  ASSERT_GT(sphere.triangles.size(), 5000u);
  EXPECT_EQ(meshDefect(sphere).text, "");
  std::mt19937 random(20261126);
  int crossing = 0, clean = 0;
  for (int trial = 0; trial < 24; ++trial) {
    TriangleMesh m = sphere;
    std::uniform_int_distribution<std::size_t> vertex(0, m.points.size() - 1);
    const double amplitude = trial % 2 ? 0.05 : 2.0;
    std::uniform_real_distribution<double> move(-amplitude, amplitude);
    for (int k = 0; k < 3; ++k)
      m.points[vertex(random)] += dvec3(move(random), move(random), move(random));
    const bool expected = cgalSaysItCrosses(m);
    ASSERT_EQ(crosses(m), expected) << "trial " << trial << ": " << meshDefect(m).text;
    (expected ? crossing : clean)++;
  }
  EXPECT_GT(crossing, 3);
  EXPECT_GT(clean, 3);
}

}  // namespace
}  // namespace csgray::detail
