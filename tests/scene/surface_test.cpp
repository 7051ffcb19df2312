// Planar surfaces against an independent reference (Winkler, "Raytracing", 17.3.2):
// λ = −n·w / n·r for the supporting plane, ‖s − m‖ ≤ r for the circle and
// the linear factors (ϑ, φ) solved from two of the three equations
// s = t + ϑ·u + φ·v for triangles and parallelograms. Random and aimed
// rays (also within 1e-6 of every edge), parallel rays, hits behind the
// origin, tMin/tMax, normals, bounds, transforms, kinds, refused inputs and
// texture space.
#include "scene/surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectVecNear;
using test::randomDirection;
using test::randomPoint;
using Shape = Surface::Shape;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ------------------------------------------------------------ the reference

// A planar shape as the seed describes it: base corner t (the centre for a
// disc) and spanning vectors u, v. A disc with circleRadius > 0 is tested by
// ‖s − m‖ ≤ r (17.3.2.2); without, it is the ellipse t + ϑ·u + φ·v with
// ϑ² + φ² ≤ 1 (a disc after a non-uniform scale).
struct Reference {
  Shape shape;
  dvec3 t, u, v;
  double circleRadius = 0.0;

  dvec3 normal() const { return glm::cross(u, v); }  // 17.3.2.1: n = u × v
  dvec3 at(double theta, double phi) const { return t + theta * u + phi * v; }
};

// The same shape moved by an affine map: corners map to corners, edges by
// the linear part (an affine map keeps the linear factors of every point).
Reference movedBy(const Reference& ref, const Affine& a) {
  auto linear = [&](const dvec3& x) { return dvec3(a.worldFromObject() * glm::dvec4(x, 0.0)); };
  return Reference{ref.shape, a.pointToWorld(ref.t), linear(ref.u), linear(ref.v), 0.0};
}

// Linear factors (ϑ, φ) of a point p of the plane, 17.3.2.3: solve two of
// the equations p_i = t_i + ϑ·u_i + φ·v_i. Of the pairs of coordinates the
// one with the largest determinant u_i·v_j − u_j·v_i is the most suitable.
// (The seed prints the denominator as u_x·v_y + u_y·v_x; eliminating ϑ
// from 17.1 and 17.2 gives u_x·v_y − u_y·v_x, used here.)
void linearFactors(const Reference& ref, const dvec3& p, double& theta, double& phi) {
  const dvec3 &u = ref.u, &v = ref.v;
  dvec3 q = p - ref.t;
  int bi = 0, bj = 1;
  double best = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (i == j) continue;
      double det = u[i] * v[j] - u[j] * v[i];
      if (std::abs(det) > best) best = std::abs(det), bi = i, bj = j;
    }
  double det = u[bi] * v[bj] - u[bj] * v[bi];
  theta = (q[bi] * v[bj] - q[bj] * v[bi]) / det;
  phi = (u[bi] * q[bj] - u[bj] * q[bi]) / det;
}

struct RefHit {
  double lambda;  // ray parameter of the hit with the supporting plane
  dvec3 point;
  double margin;  // > 0 inside the shape, < 0 outside, in units of its size
  double cosine;  // |cos| of the angle between ray and normal
};

// The reference's intersection with the supporting plane and the area check, or
// nothing when the ray is parallel to the plane.
std::optional<RefHit> reference(const Reference& ref, const Ray& ray) {
  dvec3 n = ref.normal();
  dvec3 w = ray.origin - ref.t;  // w = e − t
  double nr = glm::dot(n, ray.dir);
  if (nr == 0.0) return std::nullopt;
  RefHit h{};
  h.lambda = -glm::dot(n, w) / nr;  // λ = −n·w / n·r
  h.point = ray.origin + h.lambda * ray.dir;
  h.cosine = std::abs(nr) / (glm::length(n) * glm::length(ray.dir));
  double theta, phi;
  switch (ref.shape) {
    case Shape::Plane:
      h.margin = 1.0;
      break;
    case Shape::Disc:
      if (ref.circleRadius > 0.0) {
        h.margin = (ref.circleRadius - glm::length(h.point - ref.t)) / ref.circleRadius;
      } else {
        linearFactors(ref, h.point, theta, phi);
        h.margin = 1.0 - std::sqrt(theta * theta + phi * phi);
      }
      break;
    case Shape::Triangle:
      linearFactors(ref, h.point, theta, phi);
      h.margin = std::min({theta, phi, 1.0 - theta - phi});
      break;
    case Shape::Parallelogram:
      linearFactors(ref, h.point, theta, phi);
      h.margin = std::min({theta, phi, 1.0 - theta, 1.0 - phi});
      break;
    case Shape::Region:
    case Shape::Mesh:  // not figures of the seed's kind: no reference here
      ADD_FAILURE() << "no reference hit for this shape";
      return std::nullopt;
  }
  return h;
}

// How many comparisons were decided each way, so that a test cannot pass
// by skipping everything.
struct Tally {
  int hits = 0, misses = 0;
};

// Surface::hit must agree with the reference wherever the reference is
// clear of the boundary by more than the rounding of either computation.
void expectAgrees(const Surface& s, const Reference& ref, const Ray& ray, Tally& tally) {
  std::optional<double> got = s.hit(ray);
  std::optional<RefHit> want = reference(ref, ray);
  if (!want) {
    EXPECT_FALSE(got) << "a ray parallel to the plane hit at " << *got;
    ++tally.misses;
    return;
  }
  if (want->cosine < 1e-3) return;  // grazing: the factors are ill-conditioned
  double scale = 1.0 + std::abs(want->lambda);
  bool inRange = want->lambda > ray.tMin + 1e-9 * scale && want->lambda < ray.tMax - 1e-9 * scale;
  bool outRange = want->lambda < ray.tMin - 1e-9 * scale || want->lambda > ray.tMax + 1e-9 * scale;
  if (inRange && want->margin > 1e-9) {
    ASSERT_TRUE(got) << "missed a hit at λ=" << want->lambda << " margin " << want->margin;
    EXPECT_NEAR(*got, want->lambda, 1e-9 * scale);
    ++tally.hits;
  } else if (outRange || want->margin < -1e-9) {
    EXPECT_FALSE(got) << "hit at " << *got << " where the reference has λ=" << want->lambda
                      << " margin " << want->margin;
    ++tally.misses;
  }
}

// The world box around the reference shape's corners (or its circle).
Bounds boxAround(const Reference& ref) {
  Bounds b;
  if (ref.shape == Shape::Disc) {
    for (int i = 0; i < 64; ++i) {
      double a = 2.0 * std::numbers::pi * i / 64;
      b.include(ref.at(std::cos(a), std::sin(a)));
    }
  } else {
    b.include(ref.at(0, 0));
    b.include(ref.at(1, 0));
    b.include(ref.at(0, 1));
    if (ref.shape != Shape::Triangle) b.include(ref.at(1, 1));
  }
  return b;
}

// A random direction that is not nearly parallel to the plane of normal n.
dvec3 directionAcross(std::mt19937_64& rng, const dvec3& n) {
  dvec3 d;
  do d = randomDirection(rng);
  while (std::abs(glm::dot(d, glm::normalize(n))) < 0.05);
  return d;
}

// A ray that meets the plane at p after travelling the parameter lambda,
// with a direction of random length (dir need not be unit).
Ray rayTowards(std::mt19937_64& rng, const dvec3& p, const dvec3& n, double lambda) {
  std::uniform_real_distribution<double> len(0.3, 3.0);
  dvec3 d = len(rng) * directionAcross(rng, n);
  return Ray(p - lambda * d, d);
}

// Random rays through the box around the shape, and rays aimed at random
// linear factors around the shape, compared with the reference.
void expectAgreesOnRandomRays(const Surface& s, const Reference& ref, unsigned seed) {
  std::mt19937_64 rng(seed);
  Tally tally;
  Bounds box = boxAround(ref);
  Bounds around{box.lo - dvec3(2.0), box.hi + dvec3(2.0)};
  for (int i = 0; i < 2000; ++i) {
    expectAgrees(s, ref, Ray(randomPoint(rng, around), randomDirection(rng)), tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  double lo = ref.shape == Shape::Disc ? -1.3 : -0.3;
  std::uniform_real_distribution<double> factor(lo, 1.3), lambda(0.1, 20.0);
  for (int i = 0; i < 2000; ++i) {
    dvec3 p = ref.at(factor(rng), factor(rng));
    expectAgrees(s, ref, rayTowards(rng, p, ref.normal(), lambda(rng)), tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(tally.hits, 200);
  EXPECT_GT(tally.misses, 200);
}

// Rays aimed at points 1e-6 (in linear factors, or relative radius) inside
// and outside every edge: the inside ones hit, the outside ones miss.
void expectEdgesExact(const Surface& s, const Reference& ref, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> along(0.05, 0.95), lambda(0.5, 20.0),
      angle(0.0, 2 * std::numbers::pi);
  const double d = 1e-6;
  for (int i = 0; i < 300; ++i) {
    // (inside, outside) pairs of linear factors next to one edge.
    std::vector<std::pair<dvec3, dvec3>> pairs;
    double a = along(rng);
    switch (ref.shape) {
      case Shape::Plane:
        return;
      case Shape::Disc: {
        double c = std::cos(angle(rng)), sn = std::sin(angle(rng));
        double r = std::hypot(c, sn);
        c /= r, sn /= r;
        pairs.push_back({dvec3((1 - d) * c, (1 - d) * sn, 0), dvec3((1 + d) * c, (1 + d) * sn, 0)});
        break;
      }
      case Shape::Triangle:
        pairs.push_back({dvec3(a, d, 0), dvec3(a, -d, 0)});                             // φ = 0
        pairs.push_back({dvec3(d, a, 0), dvec3(-d, a, 0)});                             // ϑ = 0
        pairs.push_back({dvec3(a, 1 - a, 0) * (1 - d), dvec3(a, 1 - a, 0) * (1 + d)});  // ϑ+φ = 1
        break;
      case Shape::Parallelogram:
        pairs.push_back({dvec3(a, d, 0), dvec3(a, -d, 0)});         // φ = 0
        pairs.push_back({dvec3(d, a, 0), dvec3(-d, a, 0)});         // ϑ = 0
        pairs.push_back({dvec3(1 - d, a, 0), dvec3(1 + d, a, 0)});  // ϑ = 1
        pairs.push_back({dvec3(a, 1 - d, 0), dvec3(a, 1 + d, 0)});  // φ = 1
        break;
      case Shape::Region:
      case Shape::Mesh:
        FAIL() << "no edges of the seed's kind for this shape";
    }
    for (const auto& [in, out] : pairs) {
      double l = lambda(rng);
      Ray toIn = rayTowards(rng, ref.at(in.x, in.y), ref.normal(), l);
      Ray toOut = rayTowards(rng, ref.at(out.x, out.y), ref.normal(), l);
      std::optional<double> hitIn = s.hit(toIn), hitOut = s.hit(toOut);
      ASSERT_TRUE(hitIn) << "missed (ϑ, φ) = (" << in.x << ", " << in.y << ")";
      EXPECT_NEAR(*hitIn, l, 1e-9 * l);
      EXPECT_FALSE(hitOut) << "hit (ϑ, φ) = (" << out.x << ", " << out.y << ") at " << *hitOut;
    }
  }
}

// ---------------------------------------------------------- random shapes

dvec3 randomIn(std::mt19937_64& rng, double r) {
  return randomPoint(rng, Bounds{dvec3(-r), dvec3(r)});
}

// An orthonormal pair spanning the plane of the unit normal n, built here
// independently of the surface's own choice.
void testBasis(const dvec3& n, dvec3& a, dvec3& b) {
  dvec3 helper = std::abs(n.z) < 0.5 ? dvec3(0, 0, 1) : dvec3(1, 0, 0);
  a = glm::normalize(helper - glm::dot(helper, n) * n);
  b = glm::cross(n, a);
}

struct Case {
  SurfacePtr surface;
  Reference ref;
};

Case randomTriangle(std::mt19937_64& rng) {
  dvec3 a = randomIn(rng, 5), b = randomIn(rng, 5), c = randomIn(rng, 5);
  return {Surface::triangle(a, b, c), Reference{Shape::Triangle, a, b - a, c - a}};
}

Case randomParallelogram(std::mt19937_64& rng) {
  dvec3 o = randomIn(rng, 5), u = randomIn(rng, 3), v = randomIn(rng, 3);
  return {Surface::parallelogram(o, u, v), Reference{Shape::Parallelogram, o, u, v}};
}

Case randomDisc(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> radius(0.1, 3.0);
  dvec3 m = randomIn(rng, 5), n = randomDirection(rng);
  double r = radius(rng);
  dvec3 a, b;
  testBasis(n, a, b);
  // The normal passed in need not be unit.
  return {Surface::disc(m, 2.5 * n, r), Reference{Shape::Disc, m, r * a, r * b, r}};
}

Case randomPlane(std::mt19937_64& rng) {
  dvec3 p = randomIn(rng, 5), n = randomDirection(rng);
  dvec3 a, b;
  testBasis(n, a, b);
  return {Surface::plane(p, 0.4 * n), Reference{Shape::Plane, p, a, b}};
}

std::vector<Case> randomCases(unsigned seed, int each = 6) {
  std::mt19937_64 rng(seed);
  std::vector<Case> cases;
  for (int i = 0; i < each; ++i) {
    cases.push_back(randomTriangle(rng));
    cases.push_back(randomParallelogram(rng));
    cases.push_back(randomDisc(rng));
    cases.push_back(randomPlane(rng));
  }
  return cases;
}

// A non-uniform scale, a rotation about an oblique axis and a translation.
Affine someTransform() {
  return Affine::scaling(dvec3(2.0, 0.5, 1.5))
      .then(Affine::rotation(0.7, glm::normalize(dvec3(1, 2, 3))))
      .then(Affine::translation(dvec3(1.0, -2.0, 3.0)));
}

// --------------------------------------------------------------- hit tests

TEST(Surface, AgreesWithTheSeedOnRandomRays) {
  unsigned seed = 10;
  for (const Case& c : randomCases(1)) {
    SCOPED_TRACE(c.surface->kind());
    expectAgreesOnRandomRays(*c.surface, c.ref, ++seed);
    if (HasFatalFailure()) return;
  }
}

TEST(Surface, EdgesDecideWithinAMillionth) {
  unsigned seed = 100;
  for (const Case& c : randomCases(2)) {
    SCOPED_TRACE(c.surface->kind());
    expectEdgesExact(*c.surface, c.ref, ++seed);
    if (HasFatalFailure()) return;
  }
}

// Boundaries are inclusive: points exactly on an edge hit where the
// arithmetic is exact (axis-aligned shapes with small integer coordinates).
TEST(Surface, BoundariesAreInclusive) {
  dvec3 down(0, 0, -1);
  auto tri = Surface::triangle(dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0));
  EXPECT_TRUE(tri->hit(Ray(dvec3(0.5, 0.5, 1), down)));  // ϑ + φ = 1
  EXPECT_TRUE(tri->hit(Ray(dvec3(0.25, 0, 1), down)));   // φ = 0
  EXPECT_TRUE(tri->hit(Ray(dvec3(0, 0, 1), down)));      // the base corner
  EXPECT_TRUE(tri->hit(Ray(dvec3(1, 0, 1), down)));
  EXPECT_FALSE(tri->hit(Ray(dvec3(0.5, 0.5 + 1e-15, 1), down)));
  auto square = Surface::parallelogram(dvec3(0), dvec3(2, 0, 0), dvec3(0, 2, 0), "square");
  EXPECT_TRUE(square->hit(Ray(dvec3(2, 2, 1), down)));
  EXPECT_TRUE(square->hit(Ray(dvec3(2, 1, 1), down)));
  EXPECT_FALSE(square->hit(Ray(dvec3(2, 2.0000001, 1), down)));
  auto disc = Surface::disc(dvec3(0), dvec3(0, 0, 1), 1.0);
  EXPECT_TRUE(disc->hit(Ray(dvec3(1, 0, 1), down)));
  EXPECT_TRUE(disc->hit(Ray(dvec3(0, -1, 1), down)));
  EXPECT_FALSE(disc->hit(Ray(dvec3(1.0000001, 0, 1), down)));
}

// 17.3.2.1: a ray parallel to the plane misses, whether it runs beside the
// plane or inside it. Exact parallelism needs an axis-aligned plane.
TEST(Surface, ParallelRaysMiss) {
  std::vector<SurfacePtr> surfaces = {
      Surface::plane(dvec3(0, 0, 2), dvec3(0, 0, 1)),
      Surface::disc(dvec3(0, 0, 2), dvec3(0, 0, -3), 1.5),
      Surface::triangle(dvec3(0, 0, 2), dvec3(1, 0, 2), dvec3(0, 1, 2)),
      Surface::parallelogram(dvec3(0, 0, 2), dvec3(1, 0, 0), dvec3(0, 1, 0)),
  };
  for (const SurfacePtr& s : surfaces) {
    SCOPED_TRACE(s->kind());
    for (double z : {2.0, 2.5, 1.0}) {
      for (dvec3 d : {dvec3(1, 0, 0), dvec3(-0.3, 0.7, 0), dvec3(0, -1, 0)}) {
        Ray ray(dvec3(0.2, 0.2, z) - 3.0 * d, d, -kInfinity, kInfinity);
        EXPECT_FALSE(s->hit(ray)) << "z=" << z;
      }
    }
    // The same surface is hit by a slightly tilted ray.
    EXPECT_TRUE(s->hit(Ray(dvec3(0.2, 0.2, 2.5), dvec3(0.01, 0, -1))));
  }
  // In a general orientation, a ray parallel to a finite shape misses it
  // (the rounding of the direction is harmless: λ becomes huge).
  std::mt19937_64 rng(5);
  for (const Case& c : randomCases(3)) {
    if (c.ref.shape == Shape::Plane) continue;
    dvec3 n = glm::normalize(c.ref.normal());
    for (int i = 0; i < 50; ++i) {
      dvec3 d = glm::normalize(glm::cross(n, randomDirection(rng)));
      dvec3 centre = c.ref.shape == Shape::Disc ? c.ref.t : c.ref.at(0.3, 0.3);
      Ray ray(centre + 0.5 * n - 10.0 * d, d, -kInfinity, kInfinity);
      EXPECT_FALSE(c.surface->hit(ray)) << c.surface->kind();
    }
  }
}

// 17.3.2.1: λ < 0 lies behind the eye. tMin and tMax bound the hit strictly.
TEST(Surface, HitsOutsideTMinTMaxAreRefused) {
  std::mt19937_64 rng(6);
  for (const Case& c : randomCases(4)) {
    SCOPED_TRACE(c.surface->kind());
    dvec3 p = c.ref.shape == Shape::Disc ? c.ref.at(0.2, -0.3) : c.ref.at(0.25, 0.25);
    dvec3 d = directionAcross(rng, c.ref.normal());
    Ray ahead(p - 5.0 * d, d);
    ASSERT_TRUE(c.surface->hit(ahead));
    EXPECT_NEAR(*c.surface->hit(ahead), 5.0, 1e-9);
    // Behind the origin: refused with the default tMin = 0, found with -inf.
    Ray behind(p + 5.0 * d, d);
    EXPECT_FALSE(c.surface->hit(behind));
    behind.tMin = -kInfinity;
    ASSERT_TRUE(c.surface->hit(behind));
    EXPECT_NEAR(*c.surface->hit(behind), -5.0, 1e-9);
    EXPECT_FALSE(c.surface->hit(Ray(p - 5.0 * d, d, 0.0, 4.999)));
    EXPECT_TRUE(c.surface->hit(Ray(p - 5.0 * d, d, 0.0, 5.001)));
    EXPECT_FALSE(c.surface->hit(Ray(p - 5.0 * d, d, 5.001, kInfinity)));
    EXPECT_TRUE(c.surface->hit(Ray(p - 5.0 * d, d, 4.999, kInfinity)));
    // A ray leaving from the hit point does not meet the surface again
    // past a small tMin (shadow rays).
    Ray fromSurface(ahead.at(*c.surface->hit(ahead)), d, 1e-9, kInfinity);
    EXPECT_FALSE(c.surface->hit(fromSurface));
  }
}

// Hit points lie on the plane and in the surface's bounds, also for
// axis-aligned shapes whose box has no thickness: the computed hit point
// rounds off the plane, which the box must allow for.
TEST(Surface, HitPointsLieOnThePlane) {
  std::mt19937_64 rng(7);
  std::vector<Case> cases = randomCases(5);
  dvec3 a(0.1, 0.2, 0.3), x(0.7, 0, 0), y(0, 1.3, 0), z(0, 0, 0.9);
  cases.push_back({Surface::triangle(a, a + x, a + y), Reference{Shape::Triangle, a, x, y}});
  cases.push_back({Surface::triangle(a, a + z, a + y), Reference{Shape::Triangle, a, z, y}});
  cases.push_back(
      {Surface::parallelogram(a, z, x, "rectangle"), Reference{Shape::Parallelogram, a, z, x}});
  cases.push_back({Surface::disc(a, dvec3(0, 1, 0), 0.7),
                   Reference{Shape::Disc, a, dvec3(0, 0, 0.7), dvec3(0.7, 0, 0), 0.7}});
  for (const Case& c : cases) {
    SCOPED_TRACE(c.surface->kind());
    dvec3 n = glm::normalize(c.ref.normal());
    int hits = 0;
    double lo = c.ref.shape == Shape::Disc ? -1.2 : -0.2;
    std::uniform_real_distribution<double> factor(lo, 1.2), lambda(0.1, 30.0);
    for (int i = 0; i < 500; ++i) {
      Ray ray = rayTowards(rng, c.ref.at(factor(rng), factor(rng)), c.ref.normal(), lambda(rng));
      std::optional<double> t = c.surface->hit(ray);
      if (!t) continue;
      ++hits;
      dvec3 p = ray.at(*t);
      EXPECT_NEAR(glm::dot(n, p - c.ref.t), 0.0, 1e-9 * (1.0 + std::abs(*t)));
      EXPECT_TRUE(c.surface->bounds().contains(p));
      // The object frame puts the hit in z = 0.
      EXPECT_NEAR(c.surface->frame().pointToObject(p).z, 0.0, 1e-9 * (1.0 + std::abs(*t)));
    }
    EXPECT_GT(hits, 100);
  }
}

// ------------------------------------------------------- normals and bounds

TEST(Surface, NormalIsUnitAndPerpendicularToTheEdges) {
  for (const Case& c : randomCases(6)) {
    SCOPED_TRACE(c.surface->kind());
    const dvec3& n = c.surface->normal();
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(n, glm::normalize(c.ref.u)), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(n, glm::normalize(c.ref.v)), 0.0, 1e-12);
    // Same side as u × v: for triangles the order of the corners, for discs
    // and planes the normal given (the reference spans them that way).
    EXPECT_GT(glm::dot(n, c.ref.normal()), 0.0);
  }
  auto tri = Surface::triangle(dvec3(0), dvec3(0, 1, 0), dvec3(1, 0, 0));
  expectVecNear(tri->normal(), dvec3(0, 0, -1), 1e-15);
  auto plane = Surface::plane(dvec3(1, 2, 3), dvec3(0, 3, 4));
  expectVecNear(plane->normal(), dvec3(0, 0.6, 0.8), 1e-15);
}

TEST(Surface, BoundsHoldTheShape) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const Case& c : randomCases(7)) {
    SCOPED_TRACE(c.surface->kind());
    const Bounds& b = c.surface->bounds();
    if (c.ref.shape == Shape::Plane) {
      EXPECT_FALSE(b.finite());
      EXPECT_TRUE(b.contains(dvec3(1e300, -1e300, 0)));
      continue;
    }
    ASSERT_TRUE(b.finite());
    Bounds sampled;
    for (int i = 0; i < 2000; ++i) {
      double theta = unit(rng), phi = unit(rng);
      if (c.ref.shape == Shape::Triangle && theta + phi > 1) theta = 1 - theta, phi = 1 - phi;
      if (c.ref.shape == Shape::Disc) {
        double a = 2 * std::numbers::pi * theta, r = std::sqrt(phi);
        theta = r * std::cos(a), phi = r * std::sin(a);
      }
      dvec3 p = c.ref.at(theta, phi);
      EXPECT_TRUE(b.contains(p));
      sampled.include(p);
    }
    // Tight: the box of the corners (triangles, parallelograms) and for the
    // disc r·√(1 − n_i²) about the centre on each axis.
    Bounds want;
    if (c.ref.shape == Shape::Disc) {
      dvec3 n = glm::normalize(c.ref.normal());
      dvec3 half;
      for (int i = 0; i < 3; ++i) half[i] = c.ref.circleRadius * std::sqrt(1 - n[i] * n[i]);
      want = Bounds{c.ref.t - half, c.ref.t + half};
    } else {
      want = boxAround(c.ref);
    }
    expectVecNear(b.lo, want.lo, 1e-7);
    expectVecNear(b.hi, want.hi, 1e-7);
    // And nearly reached by the sampled points.
    expectVecNear(sampled.lo, want.lo, 0.1 * glm::length(want.size()));
    expectVecNear(sampled.hi, want.hi, 0.1 * glm::length(want.size()));
  }
}

// ------------------------------------------------------------- transforms

TEST(Surface, TransformedSurfacesHitWhereTheMovedShapeIs) {
  Affine a = someTransform();
  unsigned seed = 200;
  for (const Case& c : randomCases(8, 3)) {
    SCOPED_TRACE(c.surface->kind());
    SurfacePtr moved = c.surface->transformed(a);
    // The disc becomes an ellipse: compare by linear factors.
    Reference ref = movedBy(c.ref, a);
    expectAgreesOnRandomRays(*moved, ref, ++seed);
    expectEdgesExact(*moved, ref, ++seed);
    if (HasFatalFailure()) return;
    // The normal follows the inverse transpose: still perpendicular to the
    // moved edges, on the side of their cross product (det > 0 here).
    EXPECT_NEAR(glm::length(moved->normal()), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(moved->normal(), glm::normalize(ref.u)), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(moved->normal(), glm::normalize(ref.v)), 0.0, 1e-12);
    EXPECT_GT(glm::dot(moved->normal(), ref.normal()), 0.0);
    EXPECT_EQ(moved->kind(), c.surface->kind());
    EXPECT_EQ(moved->shape(), c.surface->shape());
    // The original is unchanged.
    expectVecNear(c.surface->normal(), glm::normalize(c.ref.normal()), 1e-12);
  }
}

// The box of an ellipse (a disc under non-uniform scale) is exact: along
// axis i it reaches √(u_i² + v_i²) for any pair of conjugate semi-axes u, v.
TEST(Surface, TransformedDiscBoundsAreTheEllipsesBox) {
  std::mt19937_64 rng(9);
  Affine a = someTransform();
  for (int k = 0; k < 10; ++k) {
    Case c = randomDisc(rng);
    Reference ref = movedBy(c.ref, a);
    SurfacePtr moved = c.surface->transformed(a);
    const Bounds& b = moved->bounds();
    dvec3 half;
    for (int i = 0; i < 3; ++i) half[i] = std::hypot(ref.u[i], ref.v[i]);
    expectVecNear(b.lo, ref.t - half, 1e-7);
    expectVecNear(b.hi, ref.t + half, 1e-7);
  }
}

TEST(Surface, ConstructorTakesAnyInvertibleFrame) {
  // The unit square z = 0 sheared and stretched by a general frame.
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(2, 0, 0, 0);
  m[1] = glm::dvec4(1, 3, 0, 0);
  m[2] = glm::dvec4(0, 1, 5, 0);
  m[3] = glm::dvec4(1, 1, 1, 1);
  Surface s(Shape::Parallelogram, Affine::fromMatrix(m), "panel");
  EXPECT_EQ(s.kind(), "panel");
  Reference ref{Shape::Parallelogram, dvec3(1, 1, 1), dvec3(2, 0, 0), dvec3(1, 3, 0)};
  expectAgreesOnRandomRays(s, ref, 300);
  expectVecNear(s.normal(), dvec3(0, 0, 1), 1e-15);
}

// ------------------------------------------------------- kinds and checks

TEST(Surface, KindsAndShapes) {
  auto plane = Surface::plane(dvec3(0), dvec3(0, 0, 1));
  auto disc = Surface::disc(dvec3(0), dvec3(0, 0, 1), 2.0);
  auto tri = Surface::triangle(dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0));
  auto para = Surface::parallelogram(dvec3(0), dvec3(1, 0, 0), dvec3(1, 1, 0));
  auto rect = Surface::parallelogram(dvec3(0), dvec3(2, 0, 0), dvec3(0, 1, 0), "rectangle");
  auto square = Surface::parallelogram(dvec3(0), dvec3(0, 0, 1), dvec3(0, 1, 0), "square");
  EXPECT_EQ(plane->shape(), Shape::Plane);
  EXPECT_EQ(plane->kind(), "plane");
  EXPECT_EQ(disc->shape(), Shape::Disc);
  EXPECT_EQ(disc->kind(), "disc");
  EXPECT_EQ(tri->shape(), Shape::Triangle);
  EXPECT_EQ(tri->kind(), "triangle");
  EXPECT_EQ(para->shape(), Shape::Parallelogram);
  EXPECT_EQ(para->kind(), "parallelogram");
  EXPECT_EQ(rect->shape(), Shape::Parallelogram);
  EXPECT_EQ(rect->kind(), "rectangle");
  EXPECT_EQ(square->shape(), Shape::Parallelogram);
  EXPECT_EQ(square->kind(), "square");
  // The rectangle covers its 2 × 1 area and nothing beyond.
  EXPECT_TRUE(rect->hit(Ray(dvec3(1.9, 0.9, 1), dvec3(0, 0, -1))));
  EXPECT_FALSE(rect->hit(Ray(dvec3(0.9, 1.1, 1), dvec3(0, 0, -1))));
  EXPECT_FALSE(rect->hit(Ray(dvec3(2.1, 0.5, 1), dvec3(0, 0, -1))));
  // The square lies in x = 0, with u × v pointing to -x.
  expectVecNear(square->normal(), dvec3(-1, 0, 0), 1e-15);
  EXPECT_TRUE(square->hit(Ray(dvec3(3, 0.5, 0.5), dvec3(-1, 0, 0))));
  EXPECT_FALSE(square->hit(Ray(dvec3(3, 0.5, 1.5), dvec3(-1, 0, 0))));
  EXPECT_EQ(plane->material(), nullptr);
}

// Expects std::invalid_argument whose message names the shape.
// With why, the message must also contain that word.
template <class F>
void expectRefused(F make, const std::string& shape, const std::string& why = "") {
  try {
    make();
    ADD_FAILURE() << shape << ": no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(shape), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
  }
}

TEST(Surface, DegenerateInputsAreRefused) {
  dvec3 o(0), x(1, 0, 0), y(0, 1, 0);
  for (dvec3 bad : {dvec3(kNaN, 0, 0), dvec3(0, kInfinity, 0), dvec3(0, 0, -kInfinity)}) {
    expectRefused([&] { return Surface::plane(bad, y); }, "plane");
    expectRefused([&] { return Surface::plane(o, bad); }, "plane");
    expectRefused([&] { return Surface::disc(bad, y, 1.0); }, "disc");
    expectRefused([&] { return Surface::disc(o, bad, 1.0); }, "disc");
    expectRefused([&] { return Surface::triangle(bad, x, y); }, "triangle");
    expectRefused([&] { return Surface::triangle(o, bad, y); }, "triangle");
    expectRefused([&] { return Surface::triangle(o, x, bad); }, "triangle");
    expectRefused([&] { return Surface::parallelogram(bad, x, y); }, "parallelogram");
    expectRefused([&] { return Surface::parallelogram(o, bad, y); }, "parallelogram");
    expectRefused([&] { return Surface::parallelogram(o, x, bad, "square"); }, "square");
  }
  // Zero normals and radii that are not positive and finite.
  expectRefused([&] { return Surface::plane(o, dvec3(0)); }, "plane", "normal");
  expectRefused([&] { return Surface::disc(o, dvec3(0), 1.0); }, "disc", "normal");
  for (double r : {0.0, -1.0, kNaN, kInfinity})
    expectRefused([&] { return Surface::disc(o, y, r); }, "disc", "radius");
  // Triangles without area: coincident, collinear, nearly collinear.
  expectRefused([&] { return Surface::triangle(o, o, y); }, "triangle", "coincide");
  expectRefused([&] { return Surface::triangle(o, x, x); }, "triangle", "coincide");
  expectRefused([&] { return Surface::triangle(o, x, 3.0 * x); }, "triangle", "collinear");
  expectRefused([&] { return Surface::triangle(x, 2.0 * x, -5.0 * x); }, "triangle", "collinear");
  expectRefused([&] { return Surface::triangle(o, dvec3(1, 1, 1), dvec3(2, 2, 2 + 1e-14)); },
                "triangle", "collinear");
  // Overflowing coordinates.
  expectRefused([&] { return Surface::triangle(o, dvec3(1e300, 0, 0), dvec3(0, 1e300, 0)); },
                "triangle");
  // Parallelograms with a zero edge or parallel edges.
  expectRefused([&] { return Surface::parallelogram(o, dvec3(0), y); }, "parallelogram", "zero");
  expectRefused([&] { return Surface::parallelogram(o, x, dvec3(0), "rectangle"); }, "rectangle",
                "zero");
  expectRefused([&] { return Surface::parallelogram(o, x, -2.0 * x); }, "parallelogram",
                "parallel");
  expectRefused([&] { return Surface::parallelogram(o, x, dvec3(1, 1e-14, 0), "square"); },
                "square", "parallel");
  // Small but proper shapes are accepted.
  EXPECT_NO_THROW(Surface::triangle(o, 1e-6 * x, 1e-6 * y));
  EXPECT_NO_THROW(Surface::triangle(o, x, dvec3(1, 1e-9, 0)));
  EXPECT_NO_THROW(Surface::disc(o, y, 1e-9));
  EXPECT_NO_THROW(Surface::parallelogram(dvec3(1e6), 1e-3 * x, 1e-3 * y));
}

// ---------------------------------------------------------- texture space

// Texture space is the world when the material was given: a texture point
// stays on the same spot of the surface when the surface moves later.
TEST(Surface, TextureStaysOnTheSurfaceWhenMoved) {
  auto material = std::make_shared<Material>();
  std::mt19937_64 rng(11);
  Affine a = someTransform();
  for (const Case& c : randomCases(12, 2)) {
    SCOPED_TRACE(c.surface->kind());
    SurfacePtr painted = c.surface->withMaterial(material);
    EXPECT_EQ(painted->material(), material);
    EXPECT_EQ(c.surface->material(), nullptr);  // the original keeps none
    SurfacePtr moved = painted->transformed(a);
    EXPECT_EQ(moved->material(), material);
    for (int i = 0; i < 20; ++i) {
      dvec3 p = c.ref.at(0.3 + 0.01 * i, 0.2);
      // Right after painting, texture space is the world.
      expectVecNear(painted->texturePoint(p), p, 1e-9);
      // Aim at the same spot on the moved surface.
      dvec3 q = a.pointToWorld(p);
      Ray ray = rayTowards(rng, q, moved->normal(), 4.0);
      std::optional<double> t = moved->hit(ray);
      ASSERT_TRUE(t);
      expectVecNear(moved->texturePoint(ray.at(*t)), p, 1e-8);
    }
    // The texture normal is the normal when painted, not the moved one.
    expectVecNear(painted->textureNormal(), painted->normal(), 1e-12);
    expectVecNear(moved->textureNormal(), painted->normal(), 1e-12);
    EXPECT_GT(glm::length(moved->normal() - painted->normal()), 1e-3);
    // Painting after the move makes the moved world the texture space.
    SurfacePtr paintedLater = c.surface->transformed(a)->withMaterial(material);
    dvec3 q = a.pointToWorld(c.ref.at(0.3, 0.2));
    expectVecNear(paintedLater->texturePoint(q), q, 1e-8);
    expectVecNear(paintedLater->textureNormal(), paintedLater->normal(), 1e-12);
  }
}

}  // namespace
}  // namespace csgray::detail
