// The primitives' tessellations: closed, outward, manifold meshes whose
// every point is within the tolerance of the exact surface, with the
// volume that implies, segment counts that follow the tolerance, and the
// refusals (too fine, unbounded, horn torus).
#include "tessellation/tessellation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>

#include "engine/affine.h"
#include "export/cgal/mesh_validity.h"
#include "primitives/box.h"
#include "primitives/convex_polyhedron.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/mesh_solid.h"
#include "primitives/sphere.h"
#include "primitives/torus.h"
#include "tessellation/mesh_shells.h"

namespace csgray::detail {
namespace {

using glm::dvec2;
constexpr double kPi = std::numbers::pi;

// ---- Invariants -------------------------------------------------------------------

// Closed, 2-manifold at its edges and consistently oriented: every directed
// edge is used once, and so is its opposite. No two vertices at one point,
// no triangle of zero area, no index out of range.
void expectValidMesh(const TriangleMesh& mesh) {
  ASSERT_FALSE(mesh.empty());
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  double longest = 0.0;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_LT(t[k], mesh.points.size());
      ++directed[{t[k], t[(k + 1) % 3]}];
      longest = std::max(longest, glm::length(mesh.points[t[k]] - mesh.points[t[(k + 1) % 3]]));
    }
  }
  int bad = 0;
  for (const auto& [edge, count] : directed) {
    auto opposite = directed.find({edge.second, edge.first});
    if (count != 1 || opposite == directed.end() || opposite->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0) << "directed edges without exactly one opposite";
  int degenerate = 0;
  for (const auto& t : mesh.triangles) {
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    if (!(glm::length(glm::cross(b - a, c - a)) > 1e-12 * longest * longest)) ++degenerate;
  }
  EXPECT_EQ(degenerate, 0) << "zero-area triangles";
  std::set<std::tuple<double, double, double>> seen;
  for (const dvec3& p : mesh.points) seen.insert({p.x, p.y, p.z});
  EXPECT_EQ(seen.size(), mesh.points.size()) << "duplicate vertices";
  // Every point used: a stray vertex would be a defect in an exported file.
  std::vector<bool> used(mesh.points.size(), false);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t i : t) used[i] = true;
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << "unused vertices";
  // And the exporter's own check, with exact predicates: no self-crossing.
  EXPECT_EQ(meshDefect(mesh).text, "");
}

// The largest distance from the exact surface (given as a function of an
// object-space point) of barycentric samples of every triangle, mapped back
// into the primitive's frame.
double maxSampleDistance(const TriangleMesh& mesh, const Primitive& primitive,
                         const std::function<double(const dvec3&)>& distance) {
  constexpr int kSteps = 4;
  double worst = 0.0;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j) {
        double a = double(i) / kSteps, b = double(j) / kSteps;
        dvec3 p = (1.0 - a - b) * mesh.points[t[0]] + a * mesh.points[t[1]] + b * mesh.points[t[2]];
        worst = std::max(worst, distance(primitive.frame().pointToObject(p)));
      }
  return worst;
}

// Distance in the (ρ, z) half-plane from q to the segment a–b.
double segmentDistance(dvec2 q, dvec2 a, dvec2 b) {
  dvec2 ab = b - a;
  double t = std::clamp(glm::dot(q - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(q - (a + t * ab));
}

// Distance from p to a surface of revolution about z given by its profile
// polyline: the nearest point is in the plane through the axis and p, on
// p's side or the opposite one.
double revolvedPolylineDistance(const dvec3& p, const std::vector<dvec2>& profile) {
  double rho = std::sqrt(p.x * p.x + p.y * p.y);
  double best = kInfinity;
  for (double side : {rho, -rho})
    for (std::size_t k = 0; k + 1 < profile.size(); ++k)
      best = std::min(best, segmentDistance({side, p.z}, profile[k], profile[k + 1]));
  return best;
}

// The tube's circle, centre (R, 0), radius r, for cos v >= -R/r when the
// torus is not a ring; distance from a (ρ, z) point on either side.
double torusDistance(const dvec3& p, double R, double r) {
  double rho = std::sqrt(p.x * p.x + p.y * p.y);
  double v0 = R > r ? kPi : std::acos(-R / r);
  double best = kInfinity;
  for (double side : {rho, -rho}) {
    dvec2 q(side - R, p.z);
    double v = std::atan2(q.y, q.x);
    if (std::abs(v) <= v0) {
      best = std::min(best, std::abs(glm::length(q) - r));
    } else {
      for (double end : {-v0, v0})
        best = std::min(best, glm::length(q - r * dvec2(std::cos(end), std::sin(end))));
    }
  }
  return best;
}

double boxDistance(const dvec3& p, const dvec3& size) {
  dvec3 outside = glm::max(glm::max(-p, p - size), dvec3(0.0));
  if (glm::length(outside) > 0.0) return glm::length(outside);
  double inside = kInfinity;
  for (int a = 0; a < 3; ++a) inside = std::min({inside, p[a], size[a] - p[a]});
  return inside;
}

// For a point of a convex polytope: the distance to its nearest face, or,
// outside it, how far it is outside (an upper bound that is 0 only inside).
double polytopeDistance(const dvec3& p, const std::vector<ConvexPolyhedron::Plane>& planes) {
  double deepest = kInfinity, outside = 0.0;
  for (const auto& q : planes) {
    double s = glm::dot(glm::normalize(q.normal), p) - q.offset / glm::length(q.normal);
    outside = std::max(outside, s);
    deepest = std::min(deepest, -s);
  }
  return outside > 0.0 ? outside : deepest;
}

// ---- The primitives and what is known of them --------------------------------------

struct Case {
  std::string name;
  std::shared_ptr<const Primitive> primitive;
  double volume, area;
  std::function<double(const dvec3&)> distance;
  // Vertices on a convex surface: the mesh lies inside the solid. (The
  // meshes of spheres, cylinders and cones straddle their surfaces
  // instead.)
  bool inscribed;
};

std::shared_ptr<Primitive> cone(double r1, double r2, double h) {
  return Primitive::create<Cylinder>(r1, r2, h);
}

Case cylinderCase(const std::string& name, double r1, double r2, double h) {
  double slant = std::hypot(r2 - r1, h);
  std::vector<dvec2> profile = {{0.0, 0.0}, {r1, 0.0}, {r2, h}, {0.0, h}};
  // πh(r1² + r1·r2 + r2²)/3, the frustum; lateral area π(r1 + r2)·slant.
  return {name,
          cone(r1, r2, h),
          kPi * h * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0,
          kPi * (r1 * r1 + r2 * r2) + kPi * (r1 + r2) * slant,
          [profile](const dvec3& p) { return revolvedPolylineDistance(p, profile); },
          false};
}

// Volume and area of a torus; R < r by the sections z = const, which are
// disks of radius R + w, w = √(r² − z²), for |z| < zd = √(r² − R²) (the
// lemon fills the middle) and annuli of area 4πRw beyond:
//   V = 2π²Rr² + π∫_{−zd}^{zd} (w − R)² dz,
// and the area of the outer arc turned about the axis (Pappus):
//   A = 2π∫_{−v0}^{v0} (R + r cos v)·r dv = 4πr(R·v0 + r·sin v0).
Case torusCase(const std::string& name, double R, double r) {
  double volume = 2.0 * kPi * kPi * R * r * r, area = 4.0 * kPi * kPi * R * r;
  if (R < r) {
    double zd = std::sqrt(r * r - R * R), v0 = std::acos(-R / r);
    // ∫(w − R)² = ∫(r² + R² − z²) − 2R∫w, ∫_{−zd}^{zd} w dz = zd·R + r²·asin(zd/r).
    double integral = 2.0 * zd * (r * r + R * R) - 2.0 * zd * zd * zd / 3.0 -
                      2.0 * R * (zd * R + r * r * std::asin(zd / r));
    volume += kPi * integral;
    area = 4.0 * kPi * r * (R * v0 + r * std::sin(v0));
  }
  return {name,
          Primitive::create<Torus>(R, r),
          volume,
          area,
          [R, r](const dvec3& p) { return torusDistance(p, R, r); },
          false};
}

// Volumes in the edge a (the standard formulas): tetrahedron a³/(6√2),
// cube a³, octahedron a³√2/3, dodecahedron a³(15 + 7√5)/4, icosahedron
// a³·5(3 + √5)/12; areas: √3a², 6a², 2√3a², 3√(25 + 10√5)a², 5√3a².
Case platonicCase(Platonic solid, double R) {
  const PlatonicInfo& info = platonicInfo(solid);
  double a = info.edge * R, a3 = a * a * a, a2 = a * a, s5 = std::sqrt(5.0);
  const double volumes[5] = {a3 / (6.0 * std::sqrt(2.0)), a3, a3 * std::sqrt(2.0) / 3.0,
                             a3 * (15.0 + 7.0 * s5) / 4.0, a3 * 5.0 * (3.0 + s5) / 12.0};
  const double areas[5] = {std::sqrt(3.0) * a2, 6.0 * a2, 2.0 * std::sqrt(3.0) * a2,
                           3.0 * std::sqrt(25.0 + 10.0 * s5) * a2, 5.0 * std::sqrt(3.0) * a2};
  auto planes = platonicPlanes(solid, R);
  int i = static_cast<int>(solid);
  return {info.name,
          platonicSolid(solid, R),
          volumes[i],
          areas[i],
          [planes](const dvec3& p) { return polytopeDistance(p, planes); },
          true};
}

// A unit cube from points and faces, clockwise from outside (OpenSCAD's).
std::shared_ptr<MeshSolid> cubeMesh() {
  std::vector<dvec3> points;
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  std::vector<std::vector<std::int64_t>> faces = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                                  {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  return Primitive::create<MeshSolid>(points, faces);
}

std::vector<Case> bounded() {
  std::vector<Case> cases;
  cases.push_back({"sphere", Primitive::create<Sphere>(2.5), 4.0 / 3.0 * kPi * std::pow(2.5, 3),
                   4.0 * kPi * 2.5 * 2.5,
                   [](const dvec3& p) { return std::abs(glm::length(p) - 2.5); }, false});
  cases.push_back({"box", Primitive::create<Box>(dvec3(1.0, 2.0, 3.0)), 6.0, 22.0,
                   [](const dvec3& p) {
                     return boxDistance(p, {1.0, 2.0, 3.0});
                   },
                   true});
  cases.push_back(cylinderCase("cylinder", 1.5, 1.5, 4.0));
  cases.push_back(cylinderCase("frustum", 2.0, 0.5, 3.0));
  cases.push_back(cylinderCase("cone up", 2.0, 0.0, 3.0));
  cases.push_back(cylinderCase("cone down", 0.0, 1.0, 2.0));
  cases.push_back(torusCase("ring torus", 3.0, 1.0));
  cases.push_back(torusCase("thin-holed torus", 1.05, 1.0));
  cases.push_back(torusCase("spindle torus", 0.5, 1.0));
  cases.push_back(torusCase("ball torus", 0.0, 1.5));
  for (Platonic s : {Platonic::Tetrahedron, Platonic::Hexahedron, Platonic::Octahedron,
                     Platonic::Dodecahedron, Platonic::Icosahedron})
    cases.push_back(platonicCase(s, 1.7));
  cases.push_back({"polyhedron cube", cubeMesh(), 1.0, 6.0,
                   [](const dvec3& p) { return boxDistance(p, dvec3(1.0)); }, true});
  return cases;
}

// The bound on the volume a tolerance implies: every point of the mesh is
// within tol of the surface, so the two differ by at most tol × area (to
// first order; the areas here are of the exact surface).
void expectMeshOf(const Case& c, const TriangleMesh& mesh, double tolerance, double volumeScale,
                  double objectTolerance) {
  SCOPED_TRACE(c.name);
  expectValidMesh(mesh);
  double volume = mesh.volume();
  EXPECT_GT(volume, 0.0) << "inside out";
  EXPECT_NEAR(volume, c.volume * volumeScale, tolerance * c.area * volumeScale * 1.01);
  if (c.inscribed) {
    EXPECT_LE(volume, c.volume * volumeScale * (1.0 + 1e-12));
  }
  EXPECT_LE(maxSampleDistance(mesh, *c.primitive, c.distance), objectTolerance * (1.0 + 1e-9));
}

// ---- Tests ------------------------------------------------------------------------------

// Two shells whose nearest points are a vertex of one and the middle of
// a face of the other: a pyramid's tip 10⁻⁴ over a box's top. Vertex to
// vertex they are 5 apart; the shells are 10⁻⁴ apart, and nearestShells
// (the check's "separate shells" warning) says so.
// Shells appended one by one (an export joins thousands of parts whose
// boxes are apart) keep their points and faces, renumbered, and the faces'
// storage grows geometrically: 10 000 appends move it a few dozen times,
// not at every append (which copied the whole mesh each time).
TEST(Tessellation, AppendedShellsKeepTheirFacesAndGrowGeometrically) {
  const TriangleMesh tetrahedron{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                 {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  TriangleMesh all;
  int moves = 0;
  for (int i = 0; i < 10000; ++i) {
    const auto* before = all.triangles.data();
    all.append(tetrahedron);
    moves += all.triangles.data() != before;
  }
  ASSERT_EQ(all.points.size(), 40000u);
  ASSERT_EQ(all.triangles.size(), 40000u);
  EXPECT_EQ(all.triangles[4 * 9999 + 3], (TriangleMesh::Triangle{39997, 39998, 39999}));
  EXPECT_NEAR(all.volume(), 10000.0 / 6.0, 1e-9);
  EXPECT_LE(moves, 40);
}

TEST(Tessellation, NearestShellsMeetVertexToFace) {
  TriangleMesh mesh = Primitive::create<Box>(dvec3(10.0))->tessellate(0.01, Bounds());
  const std::uint32_t base = std::uint32_t(mesh.points.size());
  const double z = 10.0 + 1e-4;
  for (const dvec3& p : {dvec3(5, 5, z), dvec3(3, 3, z + 2), dvec3(7, 3, z + 2), dvec3(7, 7, z + 2),
                         dvec3(3, 7, z + 2)})
    mesh.points.push_back(p);
  const std::uint32_t tip = base, ring[4] = {base + 1, base + 2, base + 3, base + 4};
  for (int k = 0; k < 4; ++k) mesh.triangles.push_back({tip, ring[(k + 1) % 4], ring[k]});
  mesh.triangles.push_back({ring[0], ring[1], ring[2]});
  mesh.triangles.push_back({ring[0], ring[2], ring[3]});
  const MeshShells shells = meshShells(mesh);
  ASSERT_EQ(shells.count, 2u);
  const ShellApproach near = nearestShells(mesh, shells);
  EXPECT_NEAR(near.distance, 1e-4, 1e-12);
  EXPECT_NEAR(glm::length(0.5 * (near.a + near.b) - dvec3(5, 5, 10)), 0.0, 2e-4);
}

TEST(Tessellation, EveryBoundedPrimitiveIsClosedOutwardAndWithinTolerance) {
  for (double tolerance : {0.05, 0.002}) {
    for (const Case& c : bounded()) {
      TriangleMesh mesh = c.primitive->tessellate(tolerance, Bounds::everything());
      expectMeshOf(c, mesh, tolerance, 1.0, tolerance);
    }
  }
}

TEST(Tessellation, ScaledAndMirroredFramesKeepTheMeshOutward) {
  // A non-uniform scale, then a mirror: the world volume is |det| times the
  // object's and must stay positive; the object tolerance is the world's
  // over the largest stretch, 3.
  const Affine scale = Affine::scaling({0.5, 3.0, 1.25});
  const Affine frames[2] = {scale, scale.then(Affine::mirror(glm::normalize(dvec3(1, 1, 0))))};
  const double tolerance = 0.01, det = 0.5 * 3.0 * 1.25;
  for (const Affine& frame : frames) {
    for (Case c : bounded()) {
      c.primitive = std::dynamic_pointer_cast<const Primitive>(c.primitive->transformed(frame));
      ASSERT_TRUE(c.primitive);
      TriangleMesh mesh = c.primitive->tessellate(tolerance, Bounds::everything());
      // The object mesh is within tol/3 of the object surface, so the
      // object volume within tol/3 × area, and the world's det times that.
      expectMeshOf(c, mesh, tolerance / 3.0, det, tolerance / 3.0);
    }
  }
}

TEST(Tessellation, SphereMeshStraddlesTheSurfaceByHalfTheError) {
  // Vertices outside and face centres inside, by the same distance: the
  // farthest points out and in are both close to the tolerance's limit,
  // and the volume is closer to the sphere's than an inscribed mesh's.
  const double r = 4.0, tolerance = 0.01;
  TriangleMesh mesh = Primitive::create<Sphere>(r)->tessellate(tolerance, Bounds::everything());
  double outside = 0.0, inside = 0.0;
  for (const dvec3& p : mesh.points) outside = std::max(outside, glm::length(p) - r);
  for (const auto& t : mesh.triangles) {
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    inside = std::max(inside, r - glm::dot(a, glm::normalize(glm::cross(b - a, c - a))));
  }
  EXPECT_LE(outside, tolerance);
  EXPECT_LE(inside, tolerance);
  EXPECT_NEAR(outside, inside, 1e-12);
  EXPECT_GT(outside, 0.5 * tolerance);
  const double volume = 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_LT(std::abs(mesh.volume() - volume), 0.5 * tolerance * 4.0 * kPi * r * r);
}

TEST(Tessellation, CylinderMeshStraddlesTheSurfaceWithFewerSegments) {
  // The rim's vertices lie outside the circle and its chords' midpoints
  // inside, by (nearly) the same distance within the tolerance; an
  // inscribed n-gon within tol needs π/acos(1 − tol/r) segments, √2 times
  // as many.
  const double r = 2.5, tolerance = 0.01;
  TriangleMesh mesh = cone(r, r, 20.0)->tessellate(tolerance, Bounds::everything());
  double outside = 0.0, inside = 0.0;
  std::size_t rim = 0;
  for (const dvec3& p : mesh.points) {
    if (p.z != 0.0 || (p.x == 0.0 && p.y == 0.0)) continue;
    ++rim;
    outside = std::max(outside, std::hypot(p.x, p.y) - r);
  }
  // The rim's own edges (the cap's strip also has chords across the disc).
  const double side = 2.0 * 1.01 * r * std::sin(kPi / double(rim));
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const dvec3 &a = mesh.points[t[k]], &b = mesh.points[t[(k + 1) % 3]];
      if (a.z != 0.0 || b.z != 0.0 || glm::length(a - b) > side) continue;
      inside = std::max(inside, r - glm::length(0.5 * (a + b)));
    }
  EXPECT_LE(outside, tolerance);
  EXPECT_LE(inside, tolerance);
  EXPECT_NEAR(outside, inside, 1e-8);  // the rim's shift of 10⁻⁹ r
  // The minimax count, rounded up to the ladder of circleSegments (at most
  // a quarter more segments, so at least 1/1.25² of the error).
  EXPECT_GT(outside, 0.5 * tolerance / (1.25 * 1.25));
  const double inscribedSegments = std::ceil(kPi / std::acos(1.0 - tolerance / r));
  EXPECT_GE(double(rim) * std::sqrt(2.0), 0.95 * inscribedSegments);
  EXPECT_LE(double(rim) * std::sqrt(2.0), 1.25 * 1.05 * inscribedSegments);
  EXPECT_EQ(circleSegments(int(rim)), int(rim));
}

TEST(Tessellation, CircleSegmentsClimbALadderOfAtMostAQuarter) {
  int previous = 0;
  for (int n = 8; n < 100'000; ++n) {  // a circle has at least 8
    const int rung = circleSegments(n);
    EXPECT_GE(rung, n);
    EXPECT_LE(rung, 1.25 * n);
    EXPECT_GE(rung, previous);
    EXPECT_EQ(circleSegments(rung), rung);
    // m·2^k with m in [4, 8)
    int m = rung;
    while (m >= 8) {
      ASSERT_EQ(m % 2, 0) << rung;
      m /= 2;
    }
    EXPECT_GE(m, 4) << rung;
    previous = rung;
  }
  EXPECT_EQ(circleSegments(33), 40);
  EXPECT_EQ(circleSegments(100), 112);
}

TEST(Tessellation, FrustumsOnASharedRimOfNearbyRadiiMeetOnTheSamePolygon) {
  // A frustum's segments follow its larger radius: 20.5 and 21.5 differ,
  // but rounded up the ladder they are one rung, so the top rim of the
  // lower frustum is the bottom rim of the upper one, point for point.
  const double tolerance = 0.01;
  TriangleMesh lower = cone(20.0, 20.5, 2.0)->tessellate(tolerance, Bounds::everything());
  TriangleMesh upper = cone(20.5, 21.5, 2.0)->tessellate(tolerance, Bounds::everything());
  std::set<std::tuple<double, double>> top, bottom;
  for (const dvec3& p : lower.points)
    if (p.z == 2.0) top.emplace(p.x, p.y);
  for (const dvec3& p : upper.points)
    if (p.z == 0.0) bottom.emplace(p.x, p.y);
  EXPECT_EQ(top.size(), 80u);  // 72 and 73 segments, both up to 80
  EXPECT_EQ(top, bottom);
}

// The points of a rim at height z, and the largest distance of the mesh's
// triangles (sampled 30 × 30) from the cone through (r1, 0) and (r2, h).
std::set<std::tuple<double, double>> rimAt(const TriangleMesh& mesh, double z) {
  std::set<std::tuple<double, double>> rim;
  for (const dvec3& p : mesh.points)
    if (p.z == z && (p.x != 0.0 || p.y != 0.0)) rim.emplace(p.x, p.y);
  return rim;
}
double coneDistance(const TriangleMesh& mesh, double r1, double r2, double h) {
  double worst = 0.0;
  for (const auto& t : mesh.triangles)
    for (int u = 0; u <= 30; ++u)
      for (int v = 0; u + v <= 30; ++v) {
        const dvec3 p = (double(u) * mesh.points[t[0]] + double(v) * mesh.points[t[1]] +
                         double(30 - u - v) * mesh.points[t[2]]) /
                        30.0;
        if (p.z <= 0.0 || p.z >= h) continue;  // the caps are flat and exact
        worst = std::max(worst, std::abs((std::hypot(p.x, p.y) - r1) * h - (r2 - r1) * p.z) /
                                    std::hypot(h, r2 - r1));
      }
  return worst;
}

TEST(Tessellation, AFrustumsRimsAreThePolygonsOfTheirOwnRadii) {
  // 14 and 16 take 64 and 80 segments, each rim its own, so that frustums
  // stacked on any rim meet on the same points; the side between them
  // stays within the tolerance of the cone.
  const double tolerance = 0.01;
  const TriangleMesh frustum = cone(14.0, 16.0, 2.0)->tessellate(tolerance, Bounds::everything());
  const TriangleMesh below = cone(12.0, 14.0, 2.0)->tessellate(tolerance, Bounds::everything());
  const TriangleMesh above = cone(16.0, 15.0, 2.0)->tessellate(tolerance, Bounds::everything());
  EXPECT_EQ(rimAt(frustum, 0.0).size(), 64u);
  EXPECT_EQ(rimAt(frustum, 2.0).size(), 80u);
  EXPECT_EQ(rimAt(frustum, 0.0), rimAt(below, 2.0));
  EXPECT_EQ(rimAt(frustum, 2.0), rimAt(above, 0.0));
  EXPECT_LE(coneDistance(frustum, 14.0, 16.0, 2.0), tolerance);
  EXPECT_EQ(meshDefect(frustum).text, "");
}

TEST(Tessellation, ASteepConeKeepsOnePolygonForBothRims) {
  // 10 and 1 would take 56 and 20 segments; a side zipped between them
  // strays past the tolerance, so both rims take the larger radius's.
  const double tolerance = 0.01;
  const TriangleMesh steep = cone(10.0, 1.0, 5.0)->tessellate(tolerance, Bounds::everything());
  EXPECT_EQ(rimAt(steep, 0.0).size(), rimAt(steep, 5.0).size());
  EXPECT_LE(coneDistance(steep, 10.0, 1.0, 5.0), tolerance);
  EXPECT_EQ(meshDefect(steep).text, "");
}

TEST(Tessellation, VertexCountFollowsTheTolerance) {
  // A quarter of the tolerance: about twice the segments in each curved
  // direction (segments ∝ 1/√tol), so 4× the vertices of a doubly curved
  // surface, 2× those of a cylinder; flat primitives do not change.
  auto ratio = [](const Primitive& p, double tol) {
    return double(p.tessellate(tol / 4.0, Bounds::everything()).points.size()) /
           double(p.tessellate(tol, Bounds::everything()).points.size());
  };
  // The geodesic sphere's frequency is a whole number: 4 up to its rounding.
  EXPECT_NEAR(ratio(*Primitive::create<Sphere>(10.0), 0.01), 4.0, 0.5);
  EXPECT_NEAR(ratio(*Primitive::create<Torus>(10.0, 3.0), 0.01), 4.0, 0.2);
  EXPECT_NEAR(ratio(*Primitive::create<Torus>(1.0, 3.0), 0.01), 4.0, 0.2);
  // (Radius 50: some hundred segments, so rounding them up moves the
  // ratio by a percent at most.)
  EXPECT_NEAR(ratio(*cone(50.0, 50.0, 10.0), 0.01), 2.0, 0.03);
  EXPECT_NEAR(ratio(*cone(50.0, 0.0, 10.0), 0.01), 2.0, 0.03);
  EXPECT_EQ(ratio(*Primitive::create<Box>(dvec3(1.0)), 0.01), 1.0);
  EXPECT_EQ(ratio(*platonicSolid(Platonic::Icosahedron, 1.0), 0.01), 1.0);
}

TEST(Tessellation, SmallCurvesKeepEightSegmentsAndBigOnesAreNotOverRefined) {
  // A hole of radius 0.1 at tolerance 1 is still an octagon.
  TriangleMesh pin = cone(0.1, 0.1, 1.0)->tessellate(1.0, Bounds::everything());
  EXPECT_EQ(pin.points.size(), 2u * 8u);  // two rims; the caps are strips
  // A sphere of radius 1000 at 0.1: triangles of edge √(6 r tol) ≈ 24,
  // a geodesic sphere of frequency about 46: some 21 000 points, not millions.
  TriangleMesh big = Primitive::create<Sphere>(1000.0)->tessellate(0.1, Bounds::everything());
  EXPECT_LT(big.points.size(), 60'000u);
}

TEST(Tessellation, TooFineAToleranceIsRefusedBeforeAllocating) {
  // Doubly curved at radius 100, 1e-9 needs ~5e11 triangles. A cone is
  // curved one way only: 1e-9 is ~4e6 triangles, within the limit, but
  // 1e-12 needs ~1.3e8.
  const std::pair<std::shared_ptr<Primitive>, double> cases[] = {
      {Primitive::create<Sphere>(100.0), 1e-9},
      {Primitive::create<Torus>(100.0, 20.0), 1e-9},
      {Primitive::create<Torus>(10.0, 20.0), 1e-9},
      {cone(100.0, 0.0, 10.0), 1e-12}};
  for (const auto& [p, tolerance] : cases) {
    try {
      p->tessellate(tolerance, Bounds::everything());
      ADD_FAILURE() << p->kind() << " accepted " << tolerance;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("tolerance"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(p->kind() + ":", 0), 0u) << e.what();
    }
  }
  for (double bad : {0.0, -1.0, std::nan("")})
    EXPECT_THROW(Primitive::create<Sphere>(1.0)->tessellate(bad, Bounds::everything()),
                 std::invalid_argument);
}

TEST(Tessellation, HornTorusIsRefused) {
  try {
    Primitive::create<Torus>(2.0, 2.0)->tessellate(0.01, Bounds::everything());
    ADD_FAILURE() << "horn torus accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("horn"), std::string::npos) << e.what();
  }
}

TEST(Tessellation, PolesAndSeamsShareVertices) {
  // A sphere: the geodesic sphere of the lowest frequency, 2, shares the
  // points on the icosahedron's edges: 10·2² + 2 points, 20·2² triangles.
  TriangleMesh s = Primitive::create<Sphere>(1.0)->tessellate(0.5, Bounds::everything());
  EXPECT_EQ(s.points.size(), 10u * 4u + 2u);
  EXPECT_EQ(s.triangles.size(), 20u * 4u);
  // Euler: a closed genus-0 mesh has V − E + F = 2; a ring torus genus 1.
  auto euler = [](const TriangleMesh& m) {
    return long(m.points.size()) - long(m.triangles.size() * 3 / 2) + long(m.triangles.size());
  };
  EXPECT_EQ(euler(s), 2);
  EXPECT_EQ(euler(Primitive::create<Torus>(3.0, 1.0)->tessellate(0.1, Bounds::everything())), 0);
  EXPECT_EQ(euler(Primitive::create<Torus>(0.5, 1.0)->tessellate(0.1, Bounds::everything())), 2);
  EXPECT_EQ(euler(cone(0.0, 1.0, 1.0)->tessellate(0.1, Bounds::everything())), 2);
}

TEST(Tessellation, FlatPrimitivesAreExact) {
  TriangleMesh box = Primitive::create<Box>(dvec3(1.0, 2.0, 3.0))->tessellate(1.0, {});
  EXPECT_EQ(box.points.size(), 8u);
  EXPECT_EQ(box.triangles.size(), 12u);
  EXPECT_DOUBLE_EQ(box.volume(), 6.0);
  // The Platonic solids: their vertices, each face fanned into F − 2.
  const int faceTriangles[5] = {4, 12, 8, 36, 20};
  for (int i = 0; i < 5; ++i) {
    auto solid = static_cast<Platonic>(i);
    TriangleMesh m = platonicSolid(solid, 2.0)->tessellate(1.0, {});
    EXPECT_EQ(int(m.points.size()), platonicInfo(solid).vertices) << platonicInfo(solid).name;
    EXPECT_EQ(int(m.triangles.size()), faceTriangles[i]) << platonicInfo(solid).name;
    for (const dvec3& v : m.points) EXPECT_NEAR(glm::length(v), 2.0, 1e-12);
    // The corners are the vertices as tabulated, bit for bit, not where
    // three planes meet in doubles (an octahedron's tips were 1 ulp short).
    const std::vector<dvec3> vertices = platonicVertices(solid, 10.0);
    for (const dvec3& v : platonicSolid(solid, 10.0)->tessellate(1.0, {}).points)
      EXPECT_NE(std::find(vertices.begin(), vertices.end(), v), vertices.end())
          << platonicInfo(solid).name << " " << v.x << ", " << v.y << ", " << v.z;
  }
  // The polyhedron's own triangles.
  TriangleMesh cube = cubeMesh()->tessellate(1.0, {});
  EXPECT_EQ(cube.triangles.size(), 12u);
  EXPECT_DOUBLE_EQ(cube.volume(), 1.0);
}

TEST(Tessellation, RepeatedAndTouchingPlanesGiveNoExtraFaces) {
  using Plane = ConvexPolyhedron::Plane;
  std::vector<Plane> planes = platonicPlanes(Platonic::Hexahedron, std::sqrt(3.0));
  planes.push_back(planes[0]);                                         // repeated
  planes.push_back({glm::normalize(dvec3(1, 1, 0)), std::sqrt(2.0)});  // touches an edge
  planes.push_back({glm::normalize(dvec3(1, 1, 1)), std::sqrt(3.0)});  // touches a corner
  planes.push_back({dvec3(0, 0, 2), 5.0});                             // misses
  TriangleMesh m = Primitive::create<ConvexPolyhedron>(planes)->tessellate(0.1, {});
  expectValidMesh(m);
  EXPECT_EQ(m.points.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_NEAR(m.volume(), 8.0, 1e-12);
}

TEST(Tessellation, ManyPlanesBeyondTheExactAnalysis) {
  // 2000 planes tangent to the unit sphere (more than kExactPlanes): the
  // polytope holds the ball, and every mesh point lies on a face.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<ConvexPolyhedron::Plane> planes;
  for (int i = 0; i < 2000; ++i)
    planes.push_back({glm::normalize(dvec3(normal(rng), normal(rng), normal(rng))), 1.0});
  auto solid = Primitive::create<ConvexPolyhedron>(planes);
  ASSERT_TRUE(solid->vertices().empty());
  TriangleMesh m = solid->tessellate(0.01, {});
  expectValidMesh(m);
  EXPECT_GT(m.volume(), 4.0 / 3.0 * kPi);
  EXPECT_LT(m.volume(), 4.0 / 3.0 * kPi * 1.05);
  for (const dvec3& p : m.points) EXPECT_NEAR(polytopeDistance(p, planes), 0.0, 1e-9);
}

TEST(Tessellation, UnboundedPrimitivesNeedAFiniteRegion) {
  auto half = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 0.0);
  auto wedge = Primitive::create<ConvexPolyhedron>(
      std::vector<ConvexPolyhedron::Plane>{{{1, 0, 0}, 0.0}, {{0, 1, 0}, 0.0}}, "wedge");
  for (const std::shared_ptr<Primitive>& p :
       {std::shared_ptr<Primitive>(half), std::shared_ptr<Primitive>(wedge)}) {
    try {
      p->tessellate(0.1, Bounds::everything());
      ADD_FAILURE() << p->kind() << " meshed without a region";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), p->kind() +
                                           ": is unbounded; intersect it with a bounded solid "
                                           "(e.g. clip(...)) to export it");
    }
  }
}

TEST(Tessellation, HalfSpaceCoversTheRegionWithOneFaceOnThePlane) {
  const Bounds region{dvec3(0.0), dvec3(1.0)};
  const double tol = 0.01;
  const Bounds grown = regionWithMargin(region, tol);
  EXPECT_TRUE(grown.contains(region.lo - dvec3(1e-3)) && grown.contains(region.hi + dvec3(1e-3)));
  // z <= 0.4: the grown box up to the plane, exactly.
  TriangleMesh cut = Primitive::create<HalfSpace>(dvec3(0, 0, 2), 0.8)->tessellate(tol, region);
  expectValidMesh(cut);
  Bounds b = cut.bounds();
  EXPECT_EQ(b.hi.z, 0.4);
  EXPECT_EQ(b.lo, grown.lo);
  EXPECT_NEAR(cut.volume(), b.size().x * b.size().y * b.size().z, 1e-12);
  // Tilted through the centre of a region centred on the origin: half the
  // grown box, by symmetry.
  const Bounds centred{dvec3(-1.0), dvec3(1.0)};
  const Bounds grownCentred = regionWithMargin(centred, tol);
  TriangleMesh tilted = Primitive::create<HalfSpace>(dvec3(1, 2, 3), 0.0)->tessellate(tol, centred);
  expectValidMesh(tilted);
  dvec3 s = grownCentred.size();
  EXPECT_NEAR(tilted.volume(), s.x * s.y * s.z / 2.0, 1e-12);
  for (const dvec3& p : tilted.points) EXPECT_LE(glm::dot(dvec3(1, 2, 3), p), 1e-12);
  // A plane above the region: the whole grown box; below: nothing.
  TriangleMesh all = Primitive::create<HalfSpace>(dvec3(0, 0, 1), 5.0)->tessellate(tol, region);
  expectValidMesh(all);
  EXPECT_EQ(all.triangles.size(), 12u);
  EXPECT_EQ(all.bounds().lo, grown.lo);
  EXPECT_EQ(all.bounds().hi, grown.hi);
  EXPECT_TRUE(Primitive::create<HalfSpace>(dvec3(0, 0, 1), -5.0)->tessellate(tol, region).empty());
  // Under a mirror frame the mesh stays outward, in world space: the
  // object's z <= -0.4 is the world's z >= 0.4.
  auto mirrored = std::dynamic_pointer_cast<const Primitive>(
      Primitive::create<HalfSpace>(dvec3(0, 0, 1), -0.4)->transformed(Affine::mirror({0, 0, 1})));
  TriangleMesh flipped = mirrored->tessellate(tol, region);
  expectValidMesh(flipped);
  EXPECT_GT(flipped.volume(), 0.0);
  // z >= 0.4 in the world.
  EXPECT_NEAR(flipped.bounds().lo.z, 0.4, 1e-12);
  EXPECT_NEAR(flipped.bounds().hi.z, grown.hi.z, 1e-12);
}

TEST(Tessellation, UnboundedConvexIsCutByTheGrownRegion) {
  const Bounds region{dvec3(-1.0, -1.0, 0.0), dvec3(1.0, 1.0, 2.0)};
  const double tol = 0.01;
  const Bounds grown = regionWithMargin(region, tol);
  // A prism along z: the triangle x >= 0, y >= 0, x + y <= 1.
  auto prism = Primitive::create<ConvexPolyhedron>(
      std::vector<ConvexPolyhedron::Plane>{{{-1, 0, 0}, 0.0}, {{0, -1, 0}, 0.0}, {{1, 1, 0}, 1.0}},
      "prism");
  TriangleMesh m = prism->tessellate(tol, region);
  expectValidMesh(m);
  EXPECT_NEAR(m.volume(), 0.5 * grown.size().z, 1e-12);
  // A slab 0 <= z <= 1, mirrored and scaled: still outward, |det| × volume.
  auto slab = Primitive::create<ConvexPolyhedron>(
      std::vector<ConvexPolyhedron::Plane>{{{0, 0, 1}, 1.0}, {{0, 0, -1}, 0.0}}, "slab");
  TriangleMesh flat = slab->tessellate(tol, region);
  expectValidMesh(flat);
  EXPECT_NEAR(flat.volume(), grown.size().x * grown.size().y, 1e-12);
  auto moved = std::dynamic_pointer_cast<const Primitive>(
      slab->transformed(Affine::scaling({2.0, 1.0, 1.0}).then(Affine::mirror({1, 0, 0}))));
  TriangleMesh world = moved->tessellate(tol, {dvec3(-2.0, -1.0, 0.0), dvec3(2.0, 1.0, 2.0)});
  expectValidMesh(world);
  EXPECT_GT(world.volume(), 0.0);
  // A region the solid does not reach: nothing.
  EXPECT_TRUE(prism->tessellate(tol, {dvec3(-5, -5, 0), dvec3(-4, -4, 1)}).empty());
}

}  // namespace
}  // namespace csgray::detail
