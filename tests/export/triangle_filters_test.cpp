// The validity check's filters in doubles never contradict CGAL's exact
// predicates: on triangles with corners on a coarse grid (flat caps,
// shared planes, touching corners and edges: the cases rounding gets
// wrong) and on the same corners moved by a few ulps, whenever a filter
// says "certainly", the exact test agrees. And the filters do answer the
// plain cases, which is what they are for.
#include "export/triangle_filters.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace csgray::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point point(const dvec3& p) { return {p.x, p.y, p.z}; }
Kernel::Triangle_3 triangle(const dvec3 t[3]) { return {point(t[0]), point(t[1]), point(t[2])}; }
bool collinear(const dvec3 t[3]) { return CGAL::collinear(point(t[0]), point(t[1]), point(t[2])); }

struct Corners {
  std::mt19937_64 random{20261125};
  bool nudge = false;
  dvec3 next() {
    std::uniform_int_distribution<int> grid(0, 3);
    dvec3 p(grid(random), grid(random), grid(random) == 0 ? 0 : grid(random));
    if (nudge)
      for (int k = 0; k < 3; ++k)
        p[k] = std::nextafter(p[k] + 0.5, random() % 2 ? 10.0 : -10.0) * 0.37;
    return p;
  }
};

TEST(TriangleFilters, NeverContradictTheExactTests) {
  int answered[3] = {0, 0, 0}, asked[3] = {0, 0, 0};
  for (bool nudge : {false, true}) {
    Corners corners;
    corners.nudge = nudge;
    for (int trial = 0; trial < 40000; ++trial) {
      dvec3 a[3], b[3];
      for (int k = 0; k < 3; ++k) a[k] = corners.next(), b[k] = corners.next();
      if (collinear(a) || collinear(b)) continue;
      // No corner shared.
      ++asked[0];
      if (certainlyApart(a, b)) {
        ++answered[0];
        ASSERT_FALSE(CGAL::do_intersect(triangle(a), triangle(b))) << trial;
      }
      // A corner shared: b[0] = a[0].
      b[0] = a[0];
      if (!collinear(b)) {
        ++asked[1];
        if (certainlyMeetOnlyAtCorner(a, b)) {
          ++answered[1];
          const Kernel::Segment_3 aFar(point(a[1]), point(a[2])), bFar(point(b[1]), point(b[2]));
          ASSERT_FALSE(CGAL::do_intersect(aFar, triangle(b))) << trial;
          ASSERT_FALSE(CGAL::do_intersect(bFar, triangle(a))) << trial;
        }
      }
      // An edge shared, run the other way: a = (u, w, p), b = (w, u, q).
      b[0] = a[1], b[1] = a[0];
      if (!collinear(b)) {
        ++asked[2];
        if (certainlyNotFolded(a, b)) {
          ++answered[2];
          const bool folded = CGAL::coplanar(point(a[0]), point(a[1]), point(a[2]), point(b[2])) &&
                              CGAL::coplanar_orientation(point(a[0]), point(a[1]), point(a[2]),
                                                         point(b[2])) == CGAL::POSITIVE;
          ASSERT_FALSE(folded) << trial;
        }
      }
    }
  }
  // Most random pairs are plainly apart or plainly unfolded.
  for (int k = 0; k < 3; ++k) EXPECT_GT(answered[k], asked[k] / 4) << k;
}

TEST(TriangleFilters, FlatFacesOfOneCapAreApartByTheirShadows) {
  // Two triangles in the plane z = 1 side by side: no plane separates
  // them, their shadows do.
  const dvec3 a[3] = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, b[3] = {{2, 0, 1}, {3, 0, 1}, {2, 1, 1}};
  EXPECT_TRUE(certainlyApart(a, b));
  // Touching at a point: not apart.
  const dvec3 c[3] = {{1, 0, 1}, {2, 0, 1}, {2, 1, 1}};
  EXPECT_FALSE(certainlyApart(a, c));
}

TEST(TriangleFilters, FoldedFacesAreNeverCertainlyUnfolded) {
  // a = (u, w, p), b = (w, u, q) with q on p's side, in one plane.
  const dvec3 a[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, b[3] = {{1, 0, 0}, {0, 0, 0}, {1, 1, 0}};
  EXPECT_FALSE(certainlyNotFolded(a, b));
  // Unfolded: q on the other side.
  const dvec3 c[3] = {{1, 0, 0}, {0, 0, 0}, {1, -1, 0}};
  EXPECT_TRUE(certainlyNotFolded(a, c));
}

}  // namespace
}  // namespace csgray::detail
