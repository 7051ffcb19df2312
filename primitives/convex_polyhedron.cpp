#include "primitives/convex_polyhedron.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "primitives/check.h"

namespace csgray::detail {

// A face index is the plane's index, up to kMaxPlanes - 1, so Boundary::face
// must hold more than 8 bits; widening it kept a Boundary at 24 bytes (the
// padding after the pointer had room), so spans did not grow.
static_assert(sizeof(Boundary::face) >= 2 &&
              (1ull << (8 * sizeof(Boundary::face))) > ConvexPolyhedron::kMaxPlanes);
static_assert(sizeof(Boundary) <= 24);

namespace {

using Plane = ConvexPolyhedron::Plane;

// ---- Bounds and emptiness --------------------------------------------------------
//
// A non-empty polyhedron P = {p : N p <= d} whose normals span R³ (a pointed
// one) is conv(V) + cone(R) (Minkowski-Weyl), where V are its vertices (the
// feasible points where three independent planes meet) and R the extreme
// rays of its recession cone {r : N r <= 0} (feasible directions along
// which two independent planes meet). So P is empty iff it has no vertex,
// and max x_a over P is max over V unless some ray has r_a > 0, when it is
// infinite. If the normals span only a plane or a line, P is that pointed
// set swept along the missing directions (its lineality): those are pinned
// by extra planes u·p = 0 for the analysis, and every axis they move along
// is unbounded.

// Thresholds on determinants of unit normals (|n_i·(n_j×n_k)|, |n_i×n_j|).
// Below kDegenerate they are rounding noise on a true zero (parallel or
// coplanar normals); above kWellConditioned the meeting point is accurate
// to ~1e-16/1e-9 relative. In between nothing can be trusted, and the
// analysis gives up (everything() bounds, no emptiness claim).
constexpr double kDegenerate = 1e-14;
constexpr double kWellConditioned = 1e-10;
// A meeting point is feasible if it violates no plane by more than this,
// relative to its size: accepting a point this far out only makes the box
// a little larger, which is safe.
constexpr double kFeasible = 1e-9;
// A direction is a recession direction if no unit normal leans into it by
// more than this: near-recessions count, which again only makes the box
// larger.
constexpr double kRay = 1e-12;

struct Analysis {
  bool empty = false;
  Bounds box;                   // exact when trusted and not empty
  std::vector<dvec3> vertices;  // when bounded
};

// Solves n_i·p = d_i for the three planes (Cramer's rule with the triple
// product as determinant), or nothing if they do not meet in one point.
std::optional<dvec3> meet(const Plane& a, const Plane& b, const Plane& c, bool& illConditioned) {
  dvec3 bc = glm::cross(b.normal, c.normal);
  double det = glm::dot(a.normal, bc);
  if (std::abs(det) <= kDegenerate) return std::nullopt;
  if (std::abs(det) < kWellConditioned) illConditioned = true;
  dvec3 p = a.offset * bc + b.offset * glm::cross(c.normal, a.normal) +
            c.offset * glm::cross(a.normal, b.normal);
  return p / det;
}

bool feasible(const std::vector<Plane>& planes, const dvec3& p) {
  double size = glm::length(p);
  for (const Plane& q : planes) {
    if (glm::dot(q.normal, p) - q.offset > kFeasible * (size + std::abs(q.offset))) return false;
  }
  return true;
}

bool recession(const std::vector<Plane>& planes, const dvec3& r) {
  for (const Plane& q : planes)
    if (glm::dot(q.normal, r) > kRay) return false;
  return true;
}

// Unit vectors spanning the directions perpendicular to every normal (the
// lineality space of the polyhedron), by the rank of the normals.
std::vector<dvec3> linealityOf(const std::vector<Plane>& planes, bool& illConditioned) {
  // The normal most independent of the first, then the one most
  // independent of both: the best conditioned basis this cheaply found.
  const dvec3& n0 = planes[0].normal;
  dvec3 c(0.0);
  for (std::size_t j = 1; j < planes.size(); ++j) {
    dvec3 cj = glm::cross(n0, planes[j].normal);
    if (glm::length(cj) > glm::length(c)) c = cj;
  }
  double s = glm::length(c);
  if (s > kDegenerate) {
    if (s < kWellConditioned) illConditioned = true;
    dvec3 u = c / s;
    double det = 0.0;
    for (const Plane& q : planes) det = std::max(det, std::abs(glm::dot(q.normal, u)));
    if (det <= kDegenerate) return {u};  // rank 2: a prism or wedge along u
    if (det < kWellConditioned) illConditioned = true;
    return {};  // rank 3
  }
  // Rank 1: all normals parallel to n0, a slab or a half-space. The two
  // directions across it, built from the axis least along n0 (exact zeros
  // for an axis-aligned n0, so its own axis stays bounded).
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(n0[a]) < std::abs(n0[axis])) axis = a;
  dvec3 e(0.0);
  e[axis] = 1.0;
  dvec3 u1 = glm::normalize(glm::cross(n0, e));
  dvec3 u2 = glm::normalize(glm::cross(n0, u1));
  return {u1, u2};
}

Analysis analyse(const std::vector<Plane>& given) {
  Analysis result;
  bool ill = false;
  std::vector<dvec3> lineality = linealityOf(given, ill);
  std::vector<Plane> planes = given;
  for (const dvec3& u : lineality) {
    planes.push_back({u, 0.0});
    planes.push_back({-u, 0.0});
  }
  const std::size_t n = planes.size();
  std::vector<dvec3> vertices;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        std::optional<dvec3> p = meet(planes[i], planes[j], planes[k], ill);
        if (p && feasible(planes, *p)) vertices.push_back(*p);
      }
  std::vector<dvec3> rays;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      dvec3 c = glm::cross(planes[i].normal, planes[j].normal);
      double s = glm::length(c);
      if (s <= kDegenerate) continue;
      for (dvec3 r : {c / s, -c / s})
        if (recession(planes, r)) rays.push_back(r);
    }
  if (ill) {
    // Claim nothing: no emptiness, no bounds.
    result.box = Bounds::everything();
    return result;
  }
  if (vertices.empty()) {
    result.empty = true;
    return result;
  }
  for (const dvec3& v : vertices) result.box.include(v);
  bool bounded = rays.empty() && lineality.empty();
  for (int a = 0; a < 3; ++a) {
    // Sound rather than tidy: any component, even rounding noise, along a
    // line or ray the solid contains makes the axis unbounded.
    for (const dvec3& u : lineality)
      if (u[a] != 0.0) result.box.lo[a] = -kInfinity, result.box.hi[a] = kInfinity;
    for (const dvec3& r : rays) {
      if (r[a] > 0.0) result.box.hi[a] = kInfinity;
      if (r[a] < 0.0) result.box.lo[a] = -kInfinity;
    }
  }
  if (bounded) {
    // Each vertex once: several triples meet at a vertex of degree > 3.
    for (const dvec3& v : vertices) {
      bool seen = std::any_of(result.vertices.begin(), result.vertices.end(), [&](const dvec3& w) {
        return glm::length(v - w) <= kFeasible * (glm::length(v) + glm::length(w));
      });
      if (!seen) result.vertices.push_back(v);
    }
  }
  return result;
}

// Many planes: the exact analysis of a subset of them, which contains the
// solid, so its box is safe and its emptiness proves the solid's. The
// subset is, for each of 26 directions around the sphere (the axes, the
// diagonals of the cube's edges and corners), the plane facing most nearly
// that way (the smaller offset on a tie); for a solid that is roughly
// round, those are close to the supporting planes, so the box is close.
Analysis analyseMany(const std::vector<Plane>& planes) {
  std::vector<std::size_t> chosen;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        if (x == 0 && y == 0 && z == 0) continue;
        dvec3 w = glm::normalize(dvec3(x, y, z));
        std::size_t best = 0;
        for (std::size_t i = 1; i < planes.size(); ++i) {
          double a = glm::dot(planes[i].normal, w), b = glm::dot(planes[best].normal, w);
          if (a > b + 1e-12 || (a >= b - 1e-12 && planes[i].offset < planes[best].offset)) best = i;
        }
        if (std::find(chosen.begin(), chosen.end(), best) == chosen.end()) chosen.push_back(best);
      }
  std::vector<Plane> subset;
  for (std::size_t i : chosen) subset.push_back(planes[i]);
  Analysis result = analyse(subset);
  result.vertices.clear();  // the subset's, not the solid's
  return result;
}

std::string planeName(const std::string& kind, std::size_t index) {
  return kind + ": plane " + std::to_string(index + 1);
}

}  // namespace

namespace {

// The planes with unit normals, checked: see the constructor's comment.
std::shared_ptr<std::vector<Plane>> unitPlanes(const std::vector<Plane>& planes,
                                               const std::string& kind_) {
  if (planes.empty()) throw std::invalid_argument(kind_ + ": needs at least one plane");
  if (planes.size() > ConvexPolyhedron::kMaxPlanes) {
    throw std::invalid_argument(kind_ + ": at most " +
                                std::to_string(ConvexPolyhedron::kMaxPlanes) + " planes (got " +
                                std::to_string(planes.size()) + ")");
  }
  auto unit = std::make_shared<std::vector<Plane>>();
  unit->reserve(planes.size());
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const Plane& q = planes[i];
    double len = glm::length(q.normal);
    if (!(len > 0.0) || !std::isfinite(len))
      throw std::invalid_argument(planeName(kind_, i) +
                                  ": normal must be a non-zero finite vector");
    requireFinite(planeName(kind_, i).c_str(), "offset", q.offset);
    // Unit normals make objectNormal unit and the tolerances of the
    // analysis relative to lengths.
    unit->push_back({q.normal / len, q.offset / len});
  }
  return unit;
}

}  // namespace

ConvexPolyhedron::ConvexPolyhedron(const std::vector<Plane>& planes, std::string kind)
    : kind_(std::move(kind)) {
  auto unit = unitPlanes(planes, kind_);
  Analysis a = unit->size() <= kExactPlanes ? analyse(*unit) : analyseMany(*unit);
  if (a.empty) {
    throw std::invalid_argument(kind_ +
                                ": the planes have no point in common (the solid is empty)");
  }
  box_ = a.box;
  planes_ = std::move(unit);
  vertices_ = std::make_shared<const std::vector<dvec3>>(std::move(a.vertices));
}

ConvexPolyhedron::ConvexPolyhedron(const std::vector<Plane>& planes, std::vector<dvec3> vertices,
                                   std::string kind)
    : planes_(unitPlanes(planes, kind)), kind_(std::move(kind)) {
  if (vertices.empty()) throw std::invalid_argument(kind_ + ": needs its vertices");
  for (const dvec3& v : vertices) box_.include(v);
  vertices_ = std::make_shared<const std::vector<dvec3>>(std::move(vertices));
}

void ConvexPolyhedron::objectSpans(const Ray& ray, SpanList& out) const {
  // Cyrus and Beck (1978), as Kay and Kajiya's slabs: the line is inside
  // plane i where n·o + t n·d <= d_i, a half-line ending at
  // t_i = (d_i - n·o)/(n·d), entering (n·d < 0) or leaving (n·d > 0). The
  // span is from the last entry to the first exit; each end keeps the
  // index of its plane as the face.
  double tIn = -kInfinity, tOut = kInfinity;
  std::uint32_t faceIn = 0, faceOut = 0;
  const std::vector<Plane>& planes = *planes_;
  for (std::uint32_t i = 0; i < planes.size(); ++i) {
    double denom = glm::dot(planes[i].normal, ray.dir);
    double num = planes[i].offset - glm::dot(planes[i].normal, ray.origin);
    if (denom == 0.0) {
      // Parallel: all inside this plane or all outside, like contains().
      if (num < 0.0) return;
      continue;
    }
    double t = num / denom;
    if (denom > 0.0) {
      if (t < tOut) tOut = t, faceOut = i;
    } else {
      if (t > tIn) tIn = t, faceIn = i;
    }
    if (tIn > tOut) return;
  }
  // A nearly parallel plane can put an end at ±inf on the wrong side.
  if (tOut == -kInfinity || tIn == kInfinity) return;
  if (tOut < ray.tMin || tIn > ray.tMax) return;
  // Ends at infinity belong to no surface (as for a half-space).
  auto end = [this](double t, std::uint32_t face) {
    Boundary b;
    b.t = t;
    if (std::isfinite(t)) {
      b.primitive = this;
      b.face = face;  // not boundary(): its face parameter is narrower
    }
    return b;
  };
  out.push_back(end(tIn, faceIn), end(tOut, faceOut));
}

bool ConvexPolyhedron::objectContains(const dvec3& p) const {
  for (const Plane& q : *planes_)
    if (glm::dot(q.normal, p) > q.offset) return false;
  return true;
}

dvec3 ConvexPolyhedron::objectNormal(const dvec3&, int face) const {
  return (*planes_)[static_cast<std::size_t>(face)].normal;
}

// ---- The Platonic solids ----------------------------------------------------

namespace {

constexpr double kPhi = std::numbers::phi;

// Radii and edges relative to the circumradius R, from the standard
// formulas in the edge a (Coxeter, Regular Polytopes, Table I; the same in
// any table of the solids):
//   tetrahedron   R = a√6/4               r = a√6/12            r/R = 1/3
//   cube          R = a√3/2               r = a/2               r/R = 1/√3
//   octahedron    R = a/√2                r = a/√6              r/R = 1/√3
//   dodecahedron  R = a√3(1 + √5)/4       r = a√(250 + 110√5)/20
//   icosahedron   R = a√(10 + 2√5)/4      r = a√3(3 + √5)/12
// The dodecahedron and the icosahedron, being dual, share
// r/R = √((5 + 2√5)/15) (≈ 0.7947).
const double kDualInradius = std::sqrt((5.0 + 2.0 * std::sqrt(5.0)) / 15.0);

const std::array<PlatonicInfo, 5> kInfo = {{
    {"tetrahedron", 4, 4, 1.0 / 3.0, 4.0 / std::sqrt(6.0)},
    {"hexahedron", 6, 8, 1.0 / std::sqrt(3.0), 2.0 / std::sqrt(3.0)},
    {"octahedron", 8, 6, 1.0 / std::sqrt(3.0), std::sqrt(2.0)},
    {"dodecahedron", 12, 20, kDualInradius, 4.0 / (std::sqrt(3.0) * (1.0 + std::sqrt(5.0)))},
    {"icosahedron", 20, 12, kDualInradius, 4.0 / std::sqrt(10.0 + 2.0 * std::sqrt(5.0))},
}};

// Every sign choice of the non-zero coordinates of v.
void addSigned(std::vector<dvec3>& out, const dvec3& v) {
  for (int s = 0; s < 8; ++s) {
    dvec3 w(s & 1 ? -v.x : v.x, s & 2 ? -v.y : v.y, s & 4 ? -v.z : v.z);
    bool redundant = (v.x == 0.0 && (s & 1)) || (v.y == 0.0 && (s & 2)) || (v.z == 0.0 && (s & 4));
    if (!redundant) out.push_back(w);
  }
}

// Every sign choice of (a, b, c) and of its cyclic permutations (b, c, a)
// and (c, a, b).
void addCyclic(std::vector<dvec3>& out, double a, double b, double c) {
  addSigned(out, {a, b, c});
  addSigned(out, {b, c, a});
  addSigned(out, {c, a, b});
}

// Directions (any length) of the vertices of the solid in its orientation.
std::vector<dvec3> vertexDirections(Platonic solid) {
  std::vector<dvec3> v;
  switch (solid) {
    case Platonic::Tetrahedron: {
      // Apex up; the base z = -1/3 is a circle of radius √(1 - 1/9) = 2√2/3.
      double rho = 2.0 * std::sqrt(2.0) / 3.0;
      v.push_back({0.0, 0.0, 1.0});
      for (int k = 0; k < 3; ++k) {
        double angle = 2.0 * std::numbers::pi * k / 3.0;
        v.push_back({rho * std::cos(angle), rho * std::sin(angle), -1.0 / 3.0});
      }
      break;
    }
    case Platonic::Hexahedron:
      addSigned(v, {1.0, 1.0, 1.0});
      break;
    case Platonic::Octahedron:
      addCyclic(v, 1.0, 0.0, 0.0);
      break;
    case Platonic::Dodecahedron:
      addSigned(v, {1.0, 1.0, 1.0});
      addCyclic(v, 0.0, 1.0 / kPhi, kPhi);
      break;
    case Platonic::Icosahedron:
      addCyclic(v, 0.0, 1.0, kPhi);
      break;
  }
  return v;
}

// Directions of the face normals: the vertices of the dual in the dual
// position (the face centres, seen from the centre).
std::vector<dvec3> faceDirections(Platonic solid) {
  std::vector<dvec3> n;
  switch (solid) {
    case Platonic::Tetrahedron:
      // Self-dual: the face opposite a vertex faces away from it.
      for (const dvec3& v : vertexDirections(solid)) n.push_back(-v);
      break;
    case Platonic::Hexahedron:
      addCyclic(n, 1.0, 0.0, 0.0);
      break;
    case Platonic::Octahedron:
      addSigned(n, {1.0, 1.0, 1.0});
      break;
    case Platonic::Dodecahedron:
      // The face with normal (0, φ, 1) has the vertices (±1, 1, 1),
      // (0, 1/φ, φ) and (±1/φ, φ, 0): each at φ + 1 along it.
      addCyclic(n, 0.0, kPhi, 1.0);
      break;
    case Platonic::Icosahedron:
      // The faces about the 3-fold axes (1, 1, 1) and the others: the face
      // with normal (0, φ, 1/φ) has the vertices (0, 1, φ) and (±1, φ, 0).
      addSigned(n, {1.0, 1.0, 1.0});
      addCyclic(n, 0.0, kPhi, 1.0 / kPhi);
      break;
  }
  return n;
}

void requireCircumradius(Platonic solid, double R) {
  requirePositive(platonicInfo(solid).name, "r", R);
}

}  // namespace

const PlatonicInfo& platonicInfo(Platonic solid) { return kInfo[static_cast<int>(solid)]; }

std::vector<dvec3> platonicVertices(Platonic solid, double R) {
  requireCircumradius(solid, R);
  std::vector<dvec3> v = vertexDirections(solid);
  for (dvec3& p : v) p = R * glm::normalize(p);
  return v;
}

std::vector<ConvexPolyhedron::Plane> platonicPlanes(Platonic solid, double R) {
  requireCircumradius(solid, R);
  double r = R * platonicInfo(solid).inradius;
  std::vector<ConvexPolyhedron::Plane> planes;
  for (const dvec3& n : faceDirections(solid)) planes.push_back({glm::normalize(n), r});
  return planes;
}

std::shared_ptr<ConvexPolyhedron> platonicSolid(Platonic solid, double R) {
  // Its vertices as Coxeter gives them, not as three planes meet in
  // doubles: an octahedron's tip at (0, 0, -R) exactly, flush with a face
  // there.
  return Primitive::create<ConvexPolyhedron>(platonicPlanes(solid, R), platonicVertices(solid, R),
                                             platonicInfo(solid).name);
}

}  // namespace csgray::detail
