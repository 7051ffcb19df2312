// Sphere::objectTessellate: the geodesic mesh of a ball (its exact part is
// sphere.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "primitives/sphere.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

// The icosahedron's vertices (0, ±1, ±φ) and their cyclic permutations
// (Coxeter, Regular Polytopes, §3.7), and its faces counter-clockwise
// from outside.
constexpr double kPhi = 1.6180339887498949;
constexpr double kIcosahedron[12][3] = {{-1, kPhi, 0}, {1, kPhi, 0}, {-1, -kPhi, 0}, {1, -kPhi, 0},
                                        {0, -1, kPhi}, {0, 1, kPhi}, {0, -1, -kPhi}, {0, 1, -kPhi},
                                        {kPhi, 0, -1}, {kPhi, 0, 1}, {-kPhi, 0, -1}, {-kPhi, 0, 1}};
constexpr int kFaces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                               {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                               {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                               {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

// A fixed, generic rotation of the icosahedron, so that no ring of
// vertices lies in a coordinate plane: a sphere centred on a box's face
// would otherwise have edges in that face, which the exporter's booleans
// must then treat as coplanar (slower, and slivers).
dvec3 turned(const dvec3& p) {
  const double a = 0.3710, b = 0.2180;  // radians, chosen to be irrational-looking
  dvec3 q(p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z);
  return {q.x, q.y * std::cos(b) - q.z * std::sin(b), q.y * std::sin(b) + q.z * std::cos(b)};
}

// The geodesic sphere of frequency f: each face of the icosahedron cut
// into f² triangles, the points pushed out onto the sphere. A point of the
// grid is the weighted mean of the face's corners with integer weights
// that sum to f; points on an edge or a corner are keyed and computed from
// their weights on the icosahedron's vertex indices in ascending order, so
// neighbouring faces share them exactly.
TriangleMesh geodesicSphere(double radius, int f) {
  TriangleMesh mesh;
  std::map<std::array<int, 6>, std::uint32_t> shared;
  auto vertex = [&](const int corner[3], const int weight[3]) {
    // The corners with a weight, in ascending order of their index.
    std::vector<std::pair<int, int>> terms;
    for (int k = 0; k < 3; ++k)
      if (weight[k]) terms.emplace_back(corner[k], weight[k]);
    std::sort(terms.begin(), terms.end());
    std::array<int, 6> key;
    key.fill(-1);
    dvec3 sum(0.0);
    for (std::size_t k = 0; k < terms.size(); ++k) {
      key[2 * k] = terms[k].first;
      key[2 * k + 1] = terms[k].second;
      const double* c = kIcosahedron[terms[k].first];
      sum += double(terms[k].second) * dvec3(c[0], c[1], c[2]);
    }
    auto [it, added] = shared.try_emplace(key, std::uint32_t(mesh.points.size()));
    if (added) mesh.points.push_back(radius * turned(glm::normalize(sum)));
    return it->second;
  };
  for (const auto& face : kFaces) {
    // Row i of the face (i steps from corner 0 towards the opposite edge),
    // point j along the row.
    std::vector<std::vector<std::uint32_t>> rows(std::size_t(f) + 1);
    for (int i = 0; i <= f; ++i)
      for (int j = 0; j <= i; ++j) {
        const int weight[3] = {f - i, i - j, j};
        rows[i].push_back(vertex(face, weight));
      }
    for (int i = 0; i < f; ++i)
      for (int j = 0; j <= i; ++j) {
        mesh.triangles.push_back({rows[i][j], rows[i + 1][j], rows[i + 1][j + 1]});
        if (j < i) mesh.triangles.push_back({rows[i][j], rows[i + 1][j + 1], rows[i][j + 1]});
      }
  }
  return mesh;
}

// How far the mesh is from the sphere at most: its vertices are on the
// sphere, so the farthest point of a triangle is the foot of the
// perpendicular from the centre, at distance r − √(r² − ρ²) inside, for ρ
// the circumradius of the triangle (the foot is the circumcentre; it lies
// in the triangle because the geodesic triangles are acute).
double geodesicError(const TriangleMesh& mesh, double radius) {
  double worst = 0.0;
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    const double ab = glm::length(b - a), bc = glm::length(c - b), ca = glm::length(a - c);
    const double area2 = glm::length(glm::cross(b - a, c - a));  // twice the area
    const double rho = ab * bc * ca / (2.0 * area2);
    worst = std::max(worst, radius - std::sqrt(std::max(0.0, radius * radius - rho * rho)));
  }
  return worst;
}

// The unit geodesic sphere of frequency f and its error. Those of up to
// kCachedFrequency (82 000 triangles) are built once: a part's spheres
// mostly share a tolerance and so a frequency (plate(8) has 64 alike),
// and building one costs far more than copying it.
struct UnitGeodesic {
  TriangleMesh mesh;
  double error;
};
constexpr int kCachedFrequency = 64;
std::shared_ptr<const UnitGeodesic> unitGeodesic(int f) {
  auto build = [f] {
    TriangleMesh mesh = geodesicSphere(1.0, f);
    const double error = geodesicError(mesh, 1.0);
    return std::make_shared<const UnitGeodesic>(UnitGeodesic{std::move(mesh), error});
  };
  if (f > kCachedFrequency) return build();
  static std::mutex lock;
  static std::map<int, std::shared_ptr<const UnitGeodesic>> built;
  std::lock_guard guard(lock);
  auto& unit = built[f];
  if (!unit) unit = build();
  return unit;
}

}  // namespace

// A geodesic sphere: its triangles are nearly equal, so it needs about half
// the triangles of a latitude-longitude mesh for the same tolerance.
//
// The mesh straddles the sphere rather than lying inside it: with its
// vertices at radius ρ, every point of a face lies between ρ·c and ρ from
// the centre, c = 1 − (the largest sag of a unit geodesic sphere of the
// frequency). ρ = 2r/(1 + c) puts the vertices and the face centres the
// same distance r(1 − c)/(1 + c) outside and inside the sphere: half the
// error of an inscribed mesh, so half the triangles for a tolerance (the
// best a mesh of these faces can do, the minimax placement). The frequency
// starts from the largest triangle (near a face centre of the icosahedron,
// whose edge subtends 1.1071 rad; a triangle of edge L sags L²/(6r), so
// L = √(12 r tol)) and is raised until the measured error is within the
// tolerance.
TriangleMesh Sphere::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  const double edge = std::sqrt(12.0 * radius_ * std::min(tolerance, radius_));
  int f = std::max(2, int(std::ceil(1.1071 * radius_ / edge)));
  for (;;) {
    requireTriangleBudget(kind(), 20.0 * f * f, tolerance);
    const std::shared_ptr<const UnitGeodesic> unit = unitGeodesic(f);
    const double c = 1.0 - unit->error;
    if (radius_ * (1.0 - c) / (1.0 + c) <= tolerance) {
      const double rho = 2.0 * radius_ / (1.0 + c);
      TriangleMesh mesh = unit->mesh;
      for (dvec3& p : mesh.points) p *= rho;
      return mesh;
    }
    f = int(std::ceil(f * 1.1));
  }
}

}  // namespace csgray::detail
