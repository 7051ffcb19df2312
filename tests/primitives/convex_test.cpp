// Convex polyhedra and the Platonic solids: analytic ray hits (a vertex at
// the circumradius, a face at the inradius), vertices on the boundary, unit
// outward normals with the face index of the plane hit, spans that agree
// with contains(), volumes along three axes, bounds (exact, conservative,
// infinite), general convex{} against box{} and half_space{}, the refusal
// of bad planes, and the script functions with their file:line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "primitives/box.h"
#include "primitives/convex_polyhedron.h"
#include "primitives/half_space.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectOutwardUnitNormals;
using test::expectSpansAgreeWithContainsOnRandomLines;
using test::expectVecNear;
using test::randomDirection;
using test::scriptError;
using test::spansOf;
using Plane = ConvexPolyhedron::Plane;

constexpr double kPi = std::numbers::pi;
const double kSqrt5 = std::sqrt(5.0);

constexpr Platonic kAll[] = {Platonic::Tetrahedron, Platonic::Hexahedron, Platonic::Octahedron,
                             Platonic::Dodecahedron, Platonic::Icosahedron};

// The edge a from the circumradius R, and the inradius r and volume from
// a: the formulas of the tables (independent of the code's ratios).
double edgeOf(Platonic s, double R) {
  switch (s) {
    case Platonic::Tetrahedron:
      return R * 4.0 / std::sqrt(6.0);
    case Platonic::Hexahedron:
      return 2.0 * R / std::sqrt(3.0);
    case Platonic::Octahedron:
      return std::sqrt(2.0) * R;
    case Platonic::Dodecahedron:
      return 4.0 * R / (std::sqrt(3.0) * (1.0 + kSqrt5));
    case Platonic::Icosahedron:
      return 4.0 * R / std::sqrt(10.0 + 2.0 * kSqrt5);
  }
  return 0.0;
}

double inradiusOf(Platonic s, double a) {
  switch (s) {
    case Platonic::Tetrahedron:
      return a * std::sqrt(6.0) / 12.0;
    case Platonic::Hexahedron:
      return a / 2.0;
    case Platonic::Octahedron:
      return a / std::sqrt(6.0);
    case Platonic::Dodecahedron:
      return a * std::sqrt(250.0 + 110.0 * kSqrt5) / 20.0;
    case Platonic::Icosahedron:
      return a * std::sqrt(3.0) * (3.0 + kSqrt5) / 12.0;
  }
  return 0.0;
}

double volumeOf(Platonic s, double a) {
  double a3 = a * a * a;
  switch (s) {
    case Platonic::Tetrahedron:
      return a3 / (6.0 * std::sqrt(2.0));
    case Platonic::Hexahedron:
      return a3;
    case Platonic::Octahedron:
      return std::sqrt(2.0) / 3.0 * a3;
    case Platonic::Dodecahedron:
      return (15.0 + 7.0 * kSqrt5) / 4.0 * a3;
    case Platonic::Icosahedron:
      return 5.0 * (3.0 + kSqrt5) / 12.0 * a3;
  }
  return 0.0;
}

std::string nameOf(Platonic s) { return platonicInfo(s).name; }

// The last boundary of the line from the centre along the unit direction:
// where it leaves the solid.
Boundary exitAlong(const Solid& solid, const dvec3& dir) {
  SpanList spans = spansOf(solid, Ray(dvec3(0.0), dir, -kInfinity, kInfinity));
  EXPECT_EQ(spans.size(), 1u);
  return spans.size() ? spans.back().out : Boundary{};
}

// ---------------------------------------------------------------- Platonic solids

TEST(Platonic, CountsRadiiAndEdges) {
  const double R = 2.5;
  for (Platonic s : kAll) {
    SCOPED_TRACE(nameOf(s));
    const PlatonicInfo& info = platonicInfo(s);
    std::vector<dvec3> v = platonicVertices(s, R);
    std::vector<Plane> planes = platonicPlanes(s, R);
    ASSERT_EQ(static_cast<int>(v.size()), info.vertices);
    ASSERT_EQ(static_cast<int>(planes.size()), info.faces);
    // Euler: V - E + F = 2, with E from the shortest distances.
    double a = edgeOf(s, R), shortest = kInfinity;
    int edges = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      EXPECT_NEAR(glm::length(v[i]), R, 1e-12 * R);
      for (std::size_t j = i + 1; j < v.size(); ++j) {
        double d = glm::distance(v[i], v[j]);
        shortest = std::min(shortest, d);
        edges += std::abs(d - a) < 1e-9 * R;
      }
    }
    EXPECT_NEAR(shortest, a, 1e-12 * R);
    EXPECT_NEAR(info.edge * R, a, 1e-12 * R);
    EXPECT_EQ(info.vertices - edges + info.faces, 2);
    EXPECT_NEAR(info.inradius * R, inradiusOf(s, a), 1e-12 * R);
    // Each face plane is unit, at distance r, and touches exactly the
    // vertices of one face (3, 4 or 5 of them).
    int perFace = 2 * edges / info.faces;
    for (const Plane& p : planes) {
      EXPECT_NEAR(glm::length(p.normal), 1.0, 1e-15);
      EXPECT_NEAR(p.offset, inradiusOf(s, a), 1e-12 * R);
      int touching = 0;
      for (const dvec3& q : v) {
        double h = glm::dot(p.normal, q) - p.offset;
        EXPECT_LE(h, 1e-12 * R);
        touching += std::abs(h) < 1e-12 * R;
      }
      EXPECT_EQ(touching, perFace);
    }
  }
}

TEST(Platonic, Orientation) {
  const double R = 3.0;
  auto tet = platonicSolid(Platonic::Tetrahedron, R);
  // A vertex at (0, 0, R), the opposite face on z = -R/3 facing down.
  Boundary top = exitAlong(*tet, {0, 0, 1});
  EXPECT_NEAR(top.t, R, 1e-12);
  Boundary bottom = exitAlong(*tet, {0, 0, -1});
  EXPECT_NEAR(bottom.t, R / 3.0, 1e-12);
  expectVecNear(tet->normal(dvec3(0, 0, -R / 3), bottom.face), {0, 0, -1}, 1e-15);
  EXPECT_NEAR(tet->bounds().lo.z, -R / 3.0, 1e-12);
  EXPECT_NEAR(tet->bounds().hi.z, R, 1e-12);
  // A base vertex on the xz plane at x > 0.
  EXPECT_NEAR(tet->bounds().hi.x, R * 2.0 * std::sqrt(2.0) / 3.0, 1e-12);

  // The cube by circumradius is box{} of edge 2R/√3, centred.
  double a = 2.0 * R / std::sqrt(3.0);
  auto cube = platonicSolid(Platonic::Hexahedron, R);
  SolidPtr box = Primitive::create<Box>(dvec3(a))->transformed(Affine::translation(dvec3(-a / 2)));
  std::mt19937_64 rng(5);
  for (int i = 0; i < 500; ++i) {
    Ray line(test::randomPoint(rng, {dvec3(-R), dvec3(R)}), randomDirection(rng), -kInfinity,
             kInfinity);
    SpanList p = spansOf(*cube, line), q = spansOf(*box, line);
    ASSERT_EQ(p.size(), q.size());
    for (std::uint32_t k = 0; k < p.size(); ++k) {
      EXPECT_NEAR(p[k].in.t, q[k].in.t, 1e-9);
      EXPECT_NEAR(p[k].out.t, q[k].out.t, 1e-9);
    }
  }

  // The octahedron has its vertices on the axes: |x| + |y| + |z| <= R.
  auto octa = platonicSolid(Platonic::Octahedron, R);
  for (int axis = 0; axis < 3; ++axis) {
    dvec3 e(0.0);
    e[axis] = 1.0;
    EXPECT_NEAR(exitAlong(*octa, e).t, R, 1e-12);
    EXPECT_NEAR(exitAlong(*octa, -e).t, R, 1e-12);
  }
  EXPECT_TRUE(octa->contains({0.3 * R, -0.3 * R, 0.39 * R}));
  EXPECT_FALSE(octa->contains({0.3 * R, -0.3 * R, 0.41 * R}));

  // Dodecahedron and icosahedron: the coordinate planes are mirror planes,
  // so the box is symmetric; the dodecahedron has the vertex (1, 1, 1)R/√3
  // and the icosahedron the vertex (0, 1, φ)R/√(1 + φ²).
  auto dodeca = platonicSolid(Platonic::Dodecahedron, R);
  EXPECT_NEAR(exitAlong(*dodeca, glm::normalize(dvec3(1, 1, 1))).t, R, 1e-12);
  double phi = std::numbers::phi;
  auto icosa = platonicSolid(Platonic::Icosahedron, R);
  EXPECT_NEAR(exitAlong(*icosa, glm::normalize(dvec3(0, 1, phi))).t, R, 1e-12);
  for (const auto& s : {dodeca, icosa}) {
    expectVecNear(s->bounds().lo, -s->bounds().hi, 1e-12);
    // Both reach φ/√3·R (dodecahedron) or φ/√(1 + φ²)·R (icosahedron) along z.
  }
  EXPECT_NEAR(dodeca->bounds().hi.z, R * phi / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(icosa->bounds().hi.z, R * phi / std::sqrt(1 + phi * phi), 1e-12);
}

// Along a vertex direction a line through the centre leaves at R; along a
// face normal at r, on the face of that plane, whose normal is the plane's.
TEST(Platonic, AnalyticRayHits) {
  const double R = 1.7;
  for (Platonic s : kAll) {
    SCOPED_TRACE(nameOf(s));
    auto solid = platonicSolid(s, R);
    for (const dvec3& v : platonicVertices(s, R)) {
      Boundary out = exitAlong(*solid, v / R);
      EXPECT_NEAR(out.t, R, 1e-12 * R);
      EXPECT_EQ(out.primitive, solid.get());
    }
    double r = inradiusOf(s, edgeOf(s, R));
    std::vector<Plane> planes = platonicPlanes(s, R);
    for (std::uint32_t i = 0; i < planes.size(); ++i) {
      Boundary out = exitAlong(*solid, planes[i].normal);
      EXPECT_NEAR(out.t, r, 1e-12 * R);
      EXPECT_EQ(out.face, i);
      expectVecNear(solid->normal(out.t * planes[i].normal, out.face), planes[i].normal, 1e-15);
      // The line from the other side enters through the same face.
      SpanList in = spansOf(*solid, Ray(2 * R * planes[i].normal, -planes[i].normal));
      ASSERT_EQ(in.size(), 1u);
      EXPECT_NEAR(in[0].in.t, 2 * R - r, 1e-12 * R);
      EXPECT_EQ(in[0].in.face, i);
    }
  }
}

TEST(Platonic, VerticesOnTheBoundary) {
  const double R = 4.0;
  for (Platonic s : kAll) {
    SCOPED_TRACE(nameOf(s));
    auto solid = platonicSolid(s, R);
    std::vector<dvec3> v = platonicVertices(s, R);
    for (const dvec3& p : v) {
      // On the surface up to rounding: in just inside, out 1e-9·R outside.
      EXPECT_TRUE(solid->contains(p * (1.0 - 1e-12)));
      EXPECT_FALSE(solid->contains(p * (1.0 + 1e-9)));
    }
    // The vertices the polyhedron finds from its planes are the same.
    ASSERT_EQ(solid->vertices().size(), v.size());
    for (const dvec3& p : solid->vertices()) {
      double nearest = kInfinity;
      for (const dvec3& q : v) nearest = std::min(nearest, glm::distance(p, q));
      EXPECT_LT(nearest, 1e-12 * R);
    }
    // The bounds are the box of the vertices.
    Bounds box;
    for (const dvec3& p : v) box.include(p);
    expectVecNear(solid->bounds().lo, box.lo, 1e-12 * R);
    expectVecNear(solid->bounds().hi, box.hi, 1e-12 * R);
  }
}

TEST(Platonic, NormalsAndSpansAgreeWithContains) {
  for (Platonic s : kAll) {
    SCOPED_TRACE(nameOf(s));
    auto solid = platonicSolid(s, 1.3);
    expectOutwardUnitNormals(*solid, 1e-12);
    expectSpansAgreeWithContainsOnRandomLines(*solid);
    // Moved and turned, too.
    SolidPtr moved = solid->transformed(Affine::rotation(0.7, glm::normalize(dvec3(1, 2, 3)))
                                            .then(Affine::translation({4, -2, 1})));
    expectSpansAgreeWithContainsOnRandomLines(*moved, 500, 2);
  }
}

// Volume from the spans of a grid of parallel rays (test_support.h), along
// z and, by turning the solid, along x and y: within 0.5% of the formula.
TEST(Platonic, Volumes) {
  constexpr int kGrid = 400;
  const double R = 2.0;
  for (Platonic s : kAll) {
    SCOPED_TRACE(nameOf(s));
    SolidPtr solid = platonicSolid(s, R);
    double exact = volumeOf(s, edgeOf(s, R));
    for (const SolidPtr& turned : {solid, solid->transformed(Affine::rotation(kPi / 2, {0, 1, 0})),
                                   solid->transformed(Affine::rotation(kPi / 2, {1, 0, 0}))}) {
      EXPECT_NEAR(test::gridVolume(*turned, turned->bounds(), kGrid), exact, 0.005 * exact);
    }
  }
}

TEST(Platonic, RefusesBadRadius) {
  for (double r : {0.0, -1.0, kInfinity, std::nan("")}) {
    try {
      platonicSolid(Platonic::Dodecahedron, r);
      ADD_FAILURE() << r;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("dodecahedron: r must be a positive finite number"),
                std::string::npos)
          << e.what();
    }
  }
}

// ---------------------------------------------------------------- general convex polyhedra

std::shared_ptr<ConvexPolyhedron> convex(const std::vector<Plane>& planes) {
  return Primitive::create<ConvexPolyhedron>(planes);
}

std::string errorOf(const std::vector<Plane>& planes) {
  try {
    convex(planes);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// A box from six planes with normals of any length is box{}: the same
// spans, and the normal of the face that bounds each end.
TEST(Convex, BoxFromSixPlanes) {
  dvec3 size(2, 3, 5);
  auto solid = convex({{{0, 0, -2}, 0},
                       {{0, 0, 0.5}, 2.5},
                       {{-1, 0, 0}, 0},
                       {{3, 0, 0}, 6},
                       {{0, -7, 0}, 0},
                       {{0, 1, 0}, 3}});
  auto box = Primitive::create<Box>(size);
  expectVecNear(solid->bounds().lo, dvec3(0.0), 1e-12);
  expectVecNear(solid->bounds().hi, size, 1e-12);
  EXPECT_EQ(solid->vertices().size(), 8u);
  std::mt19937_64 rng(11);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    Ray ray(test::randomPoint(rng, {dvec3(-2), dvec3(7)}), randomDirection(rng));
    SpanList p = spansOf(*solid, ray), q = spansOf(*box, ray);
    ASSERT_EQ(p.size(), q.size());
    for (std::uint32_t k = 0; k < p.size(); ++k) {
      ++hits;
      EXPECT_NEAR(p[k].in.t, q[k].in.t, 1e-9);
      EXPECT_NEAR(p[k].out.t, q[k].out.t, 1e-9);
      if (p[k].length() < 1e-9) continue;
      for (bool in : {true, false}) {
        const Boundary& a = in ? p[k].in : p[k].out;
        const Boundary& b = in ? q[k].in : q[k].out;
        dvec3 at = ray.at(a.t);
        expectVecNear(solid->normal(at, a.face), box->normal(at, b.face), 1e-12);
      }
    }
  }
  EXPECT_GT(hits, 100);
  expectSpansAgreeWithContainsOnRandomLines(*solid);
}

// Two planes meeting at an edge: unbounded, with ends at infinity that
// belong to no surface, bounds infinite along the edge and across.
TEST(Convex, UnboundedWedge) {
  // The roof z <= -|x|, along y.
  auto roof = convex({{{1, 0, 1}, 0}, {{-1, 0, 1}, 0}});
  Bounds b = roof->bounds();
  EXPECT_EQ(b.lo.x, -kInfinity);
  EXPECT_EQ(b.hi.x, kInfinity);
  EXPECT_EQ(b.lo.y, -kInfinity);
  EXPECT_EQ(b.hi.y, kInfinity);
  EXPECT_EQ(b.lo.z, -kInfinity);
  EXPECT_NEAR(b.hi.z, 0.0, 1e-12);
  EXPECT_TRUE(roof->vertices().empty());
  // Down the line x = 1: inside below z = -1, on face 0 (x + z <= 0).
  SpanList down = spansOf(*roof, Ray({1, 0, 5}, {0, 0, -1}));
  ASSERT_EQ(down.size(), 1u);
  EXPECT_NEAR(down[0].in.t, 6.0, 1e-12);
  EXPECT_EQ(down[0].in.face, 0u);
  EXPECT_EQ(down[0].out.t, kInfinity);
  EXPECT_EQ(down[0].out.primitive, nullptr);
  expectVecNear(roof->normal({1, 0, -1}, 0), glm::normalize(dvec3(1, 0, 1)), 1e-15);
  // Across, at z = -3: inside for |x| <= 3, entering and leaving on the two faces.
  SpanList across = spansOf(*roof, Ray({-10, 4, -3}, {1, 0, 0}));
  ASSERT_EQ(across.size(), 1u);
  EXPECT_NEAR(across[0].in.t, 7.0, 1e-12);
  EXPECT_EQ(across[0].in.face, 1u);
  EXPECT_NEAR(across[0].out.t, 13.0, 1e-12);
  EXPECT_EQ(across[0].out.face, 0u);
  // Parallel to the edge: all of the line, or none of it.
  SpanList along = spansOf(*roof, Ray({0.5, 0, -1}, {0, 1, 0}, -kInfinity, kInfinity));
  ASSERT_EQ(along.size(), 1u);
  EXPECT_EQ(along[0].in.t, -kInfinity);
  EXPECT_EQ(along[0].in.primitive, nullptr);
  EXPECT_EQ(along[0].out.t, kInfinity);
  EXPECT_TRUE(spansOf(*roof, Ray({0.5, 0, 1}, {0, 1, 0}, -kInfinity, kInfinity)).empty());
  expectSpansAgreeWithContainsOnRandomLines(*roof);
  expectOutwardUnitNormals(*roof, 1e-12);

  // A quadrant x <= 0, y <= 0: bounded above on x and y only.
  auto quadrant = convex({{{1, 0, 0}, 0}, {{0, 2, 0}, 0}});
  EXPECT_EQ(quadrant->bounds().hi.x, 0.0);
  EXPECT_EQ(quadrant->bounds().hi.y, 0.0);
  EXPECT_EQ(quadrant->bounds().lo.x, -kInfinity);
  EXPECT_EQ(quadrant->bounds().lo.y, -kInfinity);
  EXPECT_EQ(quadrant->bounds().lo.z, -kInfinity);
  EXPECT_EQ(quadrant->bounds().hi.z, kInfinity);
}

TEST(Convex, SlabsPrismsAndHalfSpaces) {
  // A slab 0 <= z <= 1: bounded along z only.
  auto slab = convex({{{0, 0, -1}, 0}, {{0, 0, 1}, 1}});
  EXPECT_EQ(slab->bounds().lo.z, 0.0);
  EXPECT_EQ(slab->bounds().hi.z, 1.0);
  EXPECT_EQ(slab->bounds().lo.x, -kInfinity);
  EXPECT_EQ(slab->bounds().hi.y, kInfinity);
  expectSpansAgreeWithContainsOnRandomLines(*slab);
  // A ray in the slab, parallel to it, is inside all along; above, nowhere.
  EXPECT_EQ(spansOf(*slab, Ray({0, 0, 0.5}, {1, 0, 0})).size(), 1u);
  EXPECT_TRUE(spansOf(*slab, Ray({0, 0, 1.5}, {1, 0, 0})).empty());

  // An infinite triangular prism along z: bounded across, not along.
  auto prism = convex({{{0, -1, 0}, 0}, {{1, 1, 0}, 1}, {{-1, 1, 0}, 1}});
  Bounds b = prism->bounds();
  expectVecNear(dvec3(b.lo.x, b.lo.y, 0), dvec3(-1, 0, 0), 1e-12);
  expectVecNear(dvec3(b.hi.x, b.hi.y, 0), dvec3(1, 1, 0), 1e-12);
  EXPECT_EQ(b.lo.z, -kInfinity);
  EXPECT_EQ(b.hi.z, kInfinity);
  expectSpansAgreeWithContainsOnRandomLines(*prism);
  expectOutwardUnitNormals(*prism, 1e-12);

  // A pyramid open at the bottom: bounded above only.
  auto cone = convex({{{1, 0, 1}, 1}, {{-1, 0, 1}, 1}, {{0, 1, 1}, 1}, {{0, -1, 1}, 1}});
  EXPECT_NEAR(cone->bounds().hi.z, 1.0, 1e-12);
  EXPECT_EQ(cone->bounds().lo.z, -kInfinity);
  EXPECT_EQ(cone->bounds().hi.x, kInfinity);
  expectSpansAgreeWithContainsOnRandomLines(*cone);

  // One plane is a half-space.
  dvec3 n(1, -2, 0.5);
  auto one = convex({{n, 3}});
  auto half = Primitive::create<HalfSpace>(n, 3.0);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 500; ++i) {
    Ray line(test::randomPoint(rng, {dvec3(-5), dvec3(5)}), randomDirection(rng), -kInfinity,
             kInfinity);
    SpanList p = spansOf(*one, line), q = spansOf(*half, line);
    ASSERT_EQ(p.size(), q.size());
    for (std::uint32_t k = 0; k < p.size(); ++k) {
      for (auto [a, b] : {std::pair(p[k].in.t, q[k].in.t), std::pair(p[k].out.t, q[k].out.t)}) {
        if (std::isinf(b))
          EXPECT_EQ(a, b);
        else
          EXPECT_NEAR(a, b, 1e-9 * (1 + std::abs(b)));
      }
    }
  }
  // Planes meeting at an angle of 1e-12: their meeting line (at x = 1e12
  // here) cannot be placed reliably, so the bounds claim nothing.
  auto thin = convex({{{0, 0, 1}, 1}, {{0, 0, -1}, 0}, {{1e-12, 0, 1}, 1}});
  EXPECT_EQ(thin->bounds().lo, Bounds::everything().lo);
  EXPECT_EQ(thin->bounds().hi, Bounds::everything().hi);
  EXPECT_TRUE(thin->contains({-5, 3, 0.5}));
  // A flat but not empty set (x = 0) is allowed; it has no volume.
  EXPECT_NO_THROW(convex({{{1, 0, 0}, 0}, {{-1, 0, 0}, 0}}));
}

TEST(Convex, WindowAndUnboundedEnds) {
  auto cube = platonicSolid(Platonic::Hexahedron, std::sqrt(3.0));  // [-1, 1]³
  // Spans before tMin or after tMax are left out.
  EXPECT_TRUE(spansOf(*cube, Ray({0, 0, 5}, {0, 0, 1})).empty());
  EXPECT_TRUE(spansOf(*cube, Ray({0, 0, -5}, {0, 0, 1}, 0.0, 3.0)).empty());
  EXPECT_EQ(spansOf(*cube, Ray({0, 0, -5}, {0, 0, 1}, 0.0, 4.5)).size(), 1u);
  // A ray along an edge of the cube, in the plane of two faces.
  SpanList edge = spansOf(*cube, Ray({1, 1, -5}, {0, 0, 1}));
  ASSERT_EQ(edge.size(), 1u);
  EXPECT_NEAR(edge[0].in.t, 4.0, 1e-12);
  EXPECT_NEAR(edge[0].out.t, 6.0, 1e-12);
}

// Many planes: the tangent planes of a sphere at points spread over it
// (a Fibonacci lattice). Face indices above 255 must survive the span
// lists, and the bounds (from a subset of the planes) must hold the solid.
TEST(Convex, ManyPlanes) {
  const int n = 2000;
  std::vector<Plane> planes;
  for (int i = 0; i < n; ++i) {
    double z = 1.0 - (2.0 * i + 1.0) / n, rho = std::sqrt(1.0 - z * z);
    double angle = i * kPi * (3.0 - kSqrt5);
    planes.push_back({{rho * std::cos(angle), rho * std::sin(angle), z}, 1.0});
  }
  auto solid = convex(planes);
  Bounds b = solid->bounds();
  ASSERT_TRUE(b.finite());
  // The solid lies between the sphere and the sphere of radius 1/cos(the
  // largest gap), so its box is at least [-1, 1]³ and, being from a few
  // planes, not very much more.
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(b.lo[a], -1.0);
    EXPECT_GE(b.hi[a], 1.0);
    EXPECT_LT(b.hi[a], 1.5);
    EXPECT_GT(b.lo[a], -1.5);
  }
  bool highFace = false;
  for (int i = 0; i < n; i += 97) {
    Boundary out = exitAlong(*solid, planes[i].normal);
    EXPECT_NEAR(out.t, 1.0, 1e-12);
    EXPECT_EQ(out.face, static_cast<std::uint32_t>(i));
    expectVecNear(solid->normal(planes[i].normal, out.face), planes[i].normal, 1e-15);
    highFace = highFace || out.face > 255;
  }
  EXPECT_TRUE(highFace);
  expectSpansAgreeWithContainsOnRandomLines(*solid, 300);
  // Volume close to the ball's (the polyhedron is a little larger).
  double ball = 4.0 / 3.0 * kPi;
  EXPECT_NEAR(test::gridVolume(*solid, b, 200), ball, 0.01 * ball);
}

TEST(Convex, RefusesBadPlanes) {
  double nan = std::nan("");
  EXPECT_NE(errorOf({}).find("convex: needs at least one plane"), std::string::npos);
  EXPECT_NE(errorOf({{{0, 0, 1}, 1}, {{0, 0, 0}, 1}})
                .find("convex: plane 2: normal must be a non-zero finite vector"),
            std::string::npos);
  EXPECT_NE(errorOf({{{nan, 0, 1}, 1}}).find("convex: plane 1: normal"), std::string::npos);
  EXPECT_NE(errorOf({{{0, 0, 1}, 1}, {{1, 0, 0}, 1}, {{0, kInfinity, 0}, 1}})
                .find("convex: plane 3: normal"),
            std::string::npos);
  EXPECT_NE(errorOf({{{0, 0, 1}, nan}}).find("convex: plane 1: offset must be finite"),
            std::string::npos);
  // Empty sets: bounded, a slab turned inside out, and half-spaces apart.
  EXPECT_NE(errorOf({{{0, 0, 1}, -1}, {{0, 0, -1}, -1}}).find("empty"), std::string::npos);
  std::vector<Plane> apart = platonicPlanes(Platonic::Octahedron, 1.0);
  apart.push_back({{1, 1, 1}, -1.5});  // x + y + z >= -1 in the octahedron
  EXPECT_NE(errorOf(apart).find("convex: the planes have no point in common"), std::string::npos);
  EXPECT_NE(errorOf({{{1, 0, 0}, 0}, {{-1, 0, 1}, 0}, {{0, 0, -1}, -1}}).find("empty"),
            std::string::npos);
  std::vector<Plane> tooMany(ConvexPolyhedron::kMaxPlanes + 1, Plane{{0, 0, 1}, 1});
  EXPECT_NE(errorOf(tooMany).find("at most 10000 planes"), std::string::npos);
  // At the limit it is accepted.
  tooMany.pop_back();
  EXPECT_EQ(errorOf(tooMany), "(no error)");
}

// ---------------------------------------------------------------- script API

Scene sceneOf(const std::string& source) { return runScript(source, "part.lua"); }

void expectScriptError(const std::string& source, const std::string& expected) {
  std::string e = scriptError(source);
  EXPECT_NE(e.find(expected), std::string::npos) << source << "\n  gave: " << e;
}

std::shared_ptr<const ConvexPolyhedron> polyhedronOf(const std::string& source) {
  Scene scene = sceneOf(source);
  EXPECT_EQ(scene.objects.size(), 1u);
  if (scene.objects.empty()) return nullptr;
  auto p = std::dynamic_pointer_cast<const ConvexPolyhedron>(scene.objects[0]);
  EXPECT_NE(p, nullptr) << source;
  return p;
}

TEST(ConvexScript, PlatonicFunctions) {
  for (Platonic s : kAll) {
    std::string name = nameOf(s);
    for (const std::string& call : {name + "{r=2}", name + "(2)"}) {
      auto p = polyhedronOf("return " + call);
      ASSERT_NE(p, nullptr);
      EXPECT_EQ(p->kind(), name);
      EXPECT_EQ(static_cast<int>(p->planes().size()), platonicInfo(s).faces);
      EXPECT_NEAR(exitAlong(*p, platonicVertices(s, 1.0)[0]).t, 2.0, 1e-12) << call;
    }
  }
  // The usual methods apply.
  Scene moved = sceneOf("return icosahedron{r=1}:translate(5, 0, 0):material{color={1, 0, 0}}");
  ASSERT_EQ(moved.objects.size(), 1u);
  EXPECT_TRUE(moved.objects[0]->contains({5, 0, 0}));
  EXPECT_FALSE(moved.objects[0]->contains({0, 0, 0}));
}

TEST(ConvexScript, GeneralConvex) {
  // Box from planes equals box{} on random rays.
  Scene scene = sceneOf(R"(
    local c = convex{planes={
      {normal={-1, 0, 0}, offset=0}, {normal={1, 0, 0}, offset=2},
      {normal={0, -1, 0}, offset=0}, {normal={0, 2, 0}, offset=6},
      {normal={0, 0, -1}}, {normal={0, 0, 1}, offset=5},
    }}
    return scene{objects={c, box{2, 3, 5}}}
  )");
  ASSERT_EQ(scene.objects.size(), 2u);
  std::mt19937_64 rng(17);
  for (int i = 0; i < 500; ++i) {
    Ray ray(test::randomPoint(rng, {dvec3(-2), dvec3(7)}), randomDirection(rng));
    SpanList p = spansOf(*scene.objects[0], ray), q = spansOf(*scene.objects[1], ray);
    ASSERT_EQ(p.size(), q.size());
    for (std::uint32_t k = 0; k < p.size(); ++k) {
      EXPECT_NEAR(p[k].in.t, q[k].in.t, 1e-9);
      EXPECT_NEAR(p[k].out.t, q[k].out.t, 1e-9);
    }
  }
  // A wedge is allowed and unbounded; its bounds() in the script say so.
  Scene wedge = sceneOf(R"(
    local w = convex{planes={{normal={1, 0, 1}, offset=0}, {normal={-1, 0, 1}, offset=0}}}
    local lo, hi = w:bounds()
    assert(lo[1] == -math.huge and hi[3] == 0)
    return w * box{size=4, center=true}
  )");
  EXPECT_TRUE(wedge.objects.at(0)->contains({0, 0, -1}));
  EXPECT_FALSE(wedge.objects.at(0)->contains({0, 0, 1}));
}

TEST(ConvexScript, ErrorsNameTheLineFunctionAndParameter) {
  expectScriptError("return tetrahedron{r=-1}",
                    "part.lua:1: tetrahedron: r must be a positive finite number (got -1)");
  expectScriptError("\nreturn hexahedron{r=0}", "part.lua:2: hexahedron: r must be a positive");
  expectScriptError("return octahedron{}", "part.lua:1: octahedron: needs r (circumradius)");
  expectScriptError("return dodecahedron{radius=1}",
                    "part.lua:1: dodecahedron: unknown parameter 'radius'");
  expectScriptError("return icosahedron{r=0/0}", "part.lua:1: icosahedron: r must be finite");
  expectScriptError("return icosahedron('big')",
                    "part.lua:1: icosahedron: expected a table of named parameters");
  expectScriptError("return convex{}", "part.lua:1: convex: needs planes=");
  expectScriptError("return convex{planes={}}", "part.lua:1: convex: planes must be a list");
  expectScriptError("return convex{planes={normal={0, 0, 1}, offset=1}}",
                    "part.lua:1: convex: planes must be a list");
  expectScriptError("return convex{planes={5}}", "part.lua:1: convex: plane 1 must be a table");
  expectScriptError("return convex{planes={{normal={0, 0, 1}}, {{0, 0, 1}, 1}}}",
                    "part.lua:1: convex: plane 2: unexpected value without a name");
  expectScriptError("return convex{planes={{normal={0, 0, 1}, offest=1}}}",
                    "part.lua:1: convex: plane 1: unknown parameter 'offest'");
  expectScriptError("return convex{planes={{offset=1}}}",
                    "part.lua:1: convex: plane 1: needs normal");
  expectScriptError("return convex{planes={{normal={0, 0, 1}}, {normal={0, 0, 0}, offset=1}}}",
                    "part.lua:1: convex: plane 2: normal must be a non-zero finite vector");
  expectScriptError("return convex{planes={{normal={0, 0/0, 1}}}}",
                    "part.lua:1: convex: plane 1: normal[2] must be finite");
  expectScriptError("return convex{planes={{normal={0, 0, 1}, offset=1/0}}}",
                    "part.lua:1: convex: plane 1: offset must be finite");
  expectScriptError("return convex{planes={{normal={0, 0, 1}, offset='x'}}}",
                    "part.lua:1: convex: plane 1: offset must be a number");
  expectScriptError(
      "local p = {}\n"
      "return convex{planes={{normal={0, 0, 1}, offset=-1}, {normal={0, 0, -1}, offset=-1}}}",
      "part.lua:2: convex: the planes have no point in common");
  expectScriptError("return convex{planes={{normal={0, 0, 1}}}, extra=1}",
                    "part.lua:1: convex: unknown parameter 'extra'");
}

}  // namespace
}  // namespace csgray::detail
