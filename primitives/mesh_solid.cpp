#include "primitives/mesh_solid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>
#include <span>
#include <sstream>
#include <stdexcept>

#include "tessellation/mesh_edges.h"
#include "tessellation/polygon_triangulation.h"

namespace csgray::detail {

struct MeshSolid::Mesh {
  std::vector<dvec3> points;
  std::vector<Triangle> triangles;  // counter-clockwise seen from outside
  std::vector<std::uint32_t> faceOfTriangle;
  Bvh bvh;
  Bounds bounds;
  double volume = 0.0;
  bool turned = false;

  // Calls visit(triangle, t, sign) for every crossing of the ray with the
  // surface within the ray's window (up to the triangles' padded boxes),
  // sign +1 where the ray enters, −1 where it leaves; unordered.
  template <class Visit>
  void forEachCrossing(const Ray& ray, Visit&& visit) const;
};

namespace {

// Whether three points lie on one line, exactly: each component of the
// cross product (b − a) × (c − a) is zero when its two products are equal.
// In quadruple precision (113 bits) the differences of doubles of nearby
// exponents and their products are exact, so a sliver that doubles would
// round to no area at all (a float STL's, from an export) is told apart
// from a face that truly has none.
using Quad = __float128;
std::array<Quad, 3> quadCross(const dvec3& a, const dvec3& b, const dvec3& c) {
  const Quad ux = Quad(b.x) - Quad(a.x), uy = Quad(b.y) - Quad(a.y), uz = Quad(b.z) - Quad(a.z);
  const Quad vx = Quad(c.x) - Quad(a.x), vy = Quad(c.y) - Quad(a.y), vz = Quad(c.z) - Quad(a.z);
  return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}
bool collinear(const dvec3& a, const dvec3& b, const dvec3& c) {
  const std::array<Quad, 3> n = quadCross(a, b, c);
  return n[0] == 0 && n[1] == 0 && n[2] == 0;
}

// The unit normal of a triangle that is not collinear; in quadruple
// precision where doubles round its cross product to nothing.
dvec3 unitNormal(const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 n = glm::cross(b - a, c - a);
  if (n != dvec3(0.0)) return glm::normalize(n);
  const std::array<Quad, 3> q = quadCross(a, b, c);
  Quad largest = 0;
  for (Quad x : q) largest = std::max(largest, x < 0 ? -x : x);
  if (largest == 0) return n;
  return glm::normalize(
      dvec3(double(q[0] / largest), double(q[1] / largest), double(q[2] / largest)));
}

[[noreturn]] void refuse(const std::string& message) {
  throw std::invalid_argument("polyhedron: " + message);
}

std::string pointList(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c);
}

// ---- Exact sign of a·b − c·d --------------------------------------------------
//
// Error-free transformations (Shewchuk, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", 1997): a product is
// p + e exactly with e = fma(a, b, −p), and Two_Two_Diff turns
// (p₁ + e₁) − (p₂ + e₂) into a non-overlapping expansion whose largest
// non-zero component has the sign of the exact value.

void twoSum(double a, double b, double& x, double& y) {
  x = a + b;
  double bv = x - a, av = x - bv;
  y = (a - av) + (b - bv);
}

void twoDiff(double a, double b, double& x, double& y) {
  x = a - b;
  double bv = a - x, av = x + bv;
  y = (a - av) + (bv - b);
}

// (a1 + a0) − b = x2 + x1 + x0.
void twoOneDiff(double a1, double a0, double b, double& x2, double& x1, double& x0) {
  double i;
  twoDiff(a0, b, i, x0);
  twoSum(a1, i, x2, x1);
}

int signOf(double v) { return (v > 0.0) - (v < 0.0); }

int exactSignOfDifference(double a, double b, double c, double d) {
  double p = a * b, pe = std::fma(a, b, -p);
  double q = c * d, qe = std::fma(c, d, -q);
  double x[4], j, z;
  twoOneDiff(p, pe, qe, j, z, x[0]);
  twoOneDiff(j, z, q, x[3], x[2], x[1]);
  for (int i = 3; i >= 0; --i)
    if (x[i] != 0.0) return signOf(x[i]);
  return 0;
}

// ---- The ray's frame (Woop, Benthin and Wald 2013, section 3) ------------------
//
// The ray becomes the z axis through the origin by a translation, a
// permutation of the axes (z the largest direction component) and a shear;
// a vertex then projects to (x, y) across the ray and z along it, in units
// of the ray parameter. Every vertex is transformed the same way for every
// triangle it belongs to, and the 2D edge functions of the transformed
// vertices are evaluated with exact signs, so two triangles sharing an edge
// always agree on the side of it the ray passes (Woop et al. get exactness
// by evaluating float edge functions in double; in double precision the
// sign is made exact with the expansion above).
//
// A ray exactly on an edge or vertex is broken to one side by symbolic
// perturbation (Edelsbrunner and Mücke, "Simulation of Simplicity", 1990):
// the ray is taken to be moved by (ε, ε²) across itself, the same for all
// triangles, so it crosses exactly as many of them as a ray close by would:
// one where the surface goes through, none or two (one in, one out) where
// it grazes a silhouette.
class RayFrame {
 public:
  explicit RayFrame(const Ray& ray) : origin_(ray.origin) {
    dvec3 d = glm::abs(ray.dir);
    kz_ = d.x > d.y ? (d.x > d.z ? 0 : 2) : (d.y > d.z ? 1 : 2);
    kx_ = (kz_ + 1) % 3;
    ky_ = (kx_ + 1) % 3;
    // Keep the winding of projected triangles when looking down −z.
    if (ray.dir[kz_] < 0.0) std::swap(kx_, ky_);
    sx_ = ray.dir[kx_] / ray.dir[kz_];
    sy_ = ray.dir[ky_] / ray.dir[kz_];
    sz_ = 1.0 / ray.dir[kz_];
  }

  dvec3 project(const dvec3& p) const {
    dvec3 q = p - origin_;
    return {q[kx_] - sx_ * q[kz_], q[ky_] - sy_ * q[kz_], sz_ * q[kz_]};
  }

  // +1 if the ray enters the solid through triangle abc (counter-clockwise
  // seen from outside), −1 if it leaves, 0 if it misses; t where it meets.
  int cross(const dvec3& a, const dvec3& b, const dvec3& c, double& t) const {
    dvec3 A = project(a), B = project(b), C = project(c);
    int s = edgeSign(B, C);
    if (s == 0 || edgeSign(C, A) != s || edgeSign(A, B) != s) return 0;
    // U + V + W = −2·(projected area), which is positive for a triangle
    // seen from its back, that is where the ray enters.
    double u = C.x * B.y - C.y * B.x, v = A.x * C.y - A.y * C.x, w = B.x * A.y - B.y * A.x;
    double det = u + v + w;
    double lo = std::min({A.z, B.z, C.z}), hi = std::max({A.z, B.z, C.z});
    // Barycentric depth; a triangle almost edge-on may round det to 0 (or
    // its barycentrics out of range), but any depth within it will do there.
    t = det != 0.0 ? std::clamp((u * A.z + v * B.z + w * C.z) / det, lo, hi) : (lo + hi) / 2.0;
    return s;
  }

 private:
  // The sign of the edge function e(P, Q) = Q.x·P.y − Q.y·P.x at the ray
  // (the origin): exact, and never 0 for an edge that does not project to a
  // point. At the ray moved by δ = (ε, ε²), e grows by
  // (Q.y − P.y)·ε + (P.x − Q.x)·ε², which decides a tie. e(Q, P) = −e(P, Q)
  // in every case, which is what makes shared edges agree.
  static int edgeSign(const dvec3& P, const dvec3& Q) {
    double l = Q.x * P.y, r = Q.y * P.x, e = l - r;
    // Each product and the difference are rounded once: far above this
    // bound the computed sign is the exact one.
    if (std::abs(e) > 1e-15 * (std::abs(l) + std::abs(r))) return signOf(e);
    if (int s = exactSignOfDifference(Q.x, P.y, Q.y, P.x)) return s;
    if (Q.y != P.y) return Q.y > P.y ? 1 : -1;
    return signOf(P.x - Q.x);
  }

  dvec3 origin_;
  int kx_, ky_, kz_;
  double sx_, sy_, sz_;
};

// A direction for the parity rays of contains(), chosen away from the axes
// and the usual diagonals so that they rarely meet an edge exactly (the
// perturbation makes them correct anyway).
const dvec3 kProbeDirection = glm::normalize(dvec3(0.2718281828, 0.3141592654, 0.8660254038));

// A ray the crossing test can take: finite, with a direction.
bool usable(const Ray& ray) {
  auto finite = [](const dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  return finite(ray.origin) && finite(ray.dir) && ray.dir != dvec3(0.0);
}

struct Crossing {
  double t;
  std::uint32_t triangle;
  int sign;
};

// ---- Faces to triangles -----------------------------------------------------------

// Splits a polygon (indices into points, in the order that is to face out)
// into triangles with the same orientation (polygon_triangulation.h).
void triangulate(const std::vector<dvec3>& points, const std::vector<std::uint32_t>& polygon,
                 std::uint32_t face, std::vector<MeshSolid::Triangle>& out,
                 std::vector<std::uint32_t>& faceOf) {
  auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    out.push_back({a, b, c});
    faceOf.push_back(face);
  };
  if (!triangulatePolygon(points, polygon, emit))
    refuse("face " + std::to_string(face) + " is degenerate: its points are collinear");
}

// ---- Validation of the face graph --------------------------------------------------

// Every directed edge a→b must have exactly one opposite b→a, and no other
// use (tessellation/mesh_edges.h). Reports the bad edge that comes first in
// the order of the faces.
void checkEdges(const std::vector<std::vector<std::uint32_t>>& faces) {
  const std::vector<EdgeUse> uses = edgeUses(faces);
  // The face of a side: the last face whose first side is not after it.
  std::vector<std::uint32_t> firstSide(faces.size());
  for (std::size_t f = 0, sides = 0; f < faces.size(); sides += faces[f].size(), ++f)
    firstSide[f] = std::uint32_t(sides);
  auto faceOf = [&](const EdgeUse& use) {
    return std::uint32_t(std::upper_bound(firstSide.begin(), firstSide.end(), use.side) -
                         firstSide.begin() - 1);
  };

  std::uint32_t firstBad = std::numeric_limits<std::uint32_t>::max();
  std::string message;
  for (std::size_t g = 0; g < uses.size();) {
    const std::span<const EdgeUse> edge = usesOfEdge(uses, g);
    g += edge.size();
    const EdgeUse& first = edge[0];  // the first use in face order
    const EdgeFault fault = edgeFault(edge);
    if (fault == EdgeFault::None || first.side >= firstBad) continue;
    std::uint32_t lo = std::uint32_t(first.edge >> 32), hi = std::uint32_t(first.edge);
    auto name = [&](bool forward) {
      return forward ? std::to_string(lo) + "→" + std::to_string(hi)
                     : std::to_string(hi) + "→" + std::to_string(lo);
    };
    const std::size_t count = edge.size();
    if (fault == EdgeFault::NonManifold) {
      std::string list;
      std::size_t shown = std::min<std::size_t>(count, 6);
      for (std::size_t k = 0; k < shown; ++k)
        list += (k == 0                             ? ""
                 : k + 1 == shown && shown == count ? " and "
                                                    : ", ") +
                std::to_string(faceOf(edge[k]));
      if (shown < count) list += ", ...";
      message = "non-manifold edge " + std::to_string(lo) + "–" + std::to_string(hi) +
                ": it is used by " + std::to_string(count) + " faces (faces " + list +
                "); every edge must join exactly two faces";
    } else if (fault == EdgeFault::SameWay) {
      message = "inconsistent orientation: edge " + name(first.forward) +
                " is used twice in the same direction (faces " + std::to_string(faceOf(edge[0])) +
                " and " + std::to_string(faceOf(edge[1])) +
                "); list every face clockwise as seen from outside";
    } else {
      message = "open mesh: edge " + name(first.forward) + " (face " +
                std::to_string(faceOf(first)) + ") has no opposite face " + name(!first.forward);
    }
    firstBad = first.side;
  }
  if (!message.empty()) refuse(message);
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

template <class Visit>
void MeshSolid::Mesh::forEachCrossing(const Ray& ray, Visit&& visit) const {
  RayFrame frame(ray);
  double tMax = ray.tMax;
  bvh.traverse(ray, tMax, [&](std::uint32_t i, double) {
    const Triangle& tri = triangles[i];
    double t;
    if (int s = frame.cross(points[tri[0]], points[tri[1]], points[tri[2]], t)) visit(i, t, s);
    return true;
  });
}

MeshSolid::MeshSolid(const std::vector<dvec3>& points,
                     const std::vector<std::vector<std::int64_t>>& faces) {
  auto mesh = std::make_shared<Mesh>();
  // ---- Points and indices.
  if (points.size() < 4)
    refuse("needs at least 4 points (got " + std::to_string(points.size()) + ")");
  if (points.size() >= std::numeric_limits<std::uint32_t>::max())
    refuse("too many points (" + std::to_string(points.size()) + ")");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const dvec3& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      std::ostringstream msg;
      msg << "point " << i << " has a coordinate that is not finite (" << p.x << ", " << p.y << ", "
          << p.z << ")";
      refuse(msg.str());
    }
  }
  if (faces.size() < 4) refuse("needs at least 4 faces (got " + std::to_string(faces.size()) + ")");
  if (faces.size() >= std::numeric_limits<std::uint32_t>::max())
    refuse("too many faces (" + std::to_string(faces.size()) + ")");
  std::vector<std::vector<std::uint32_t>> polygons(faces.size());
  std::vector<std::uint32_t> lastFace(points.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    if (face.size() < 3)
      refuse("face " + std::to_string(f) + " has " + std::to_string(face.size()) +
             (face.size() == 1 ? " point" : " points") + "; a face needs at least 3");
    polygons[f].reserve(face.size());
    for (std::int64_t index : face) {
      if (index < 0 || index >= std::int64_t(points.size()))
        refuse("face " + std::to_string(f) + ": point index " + std::to_string(index) +
               " is out of range (there are " + std::to_string(points.size()) +
               " points, numbered from 0)");
      if (lastFace[index] == f)
        refuse("face " + std::to_string(f) + " uses point " + std::to_string(index) + " twice");
      lastFace[index] = f;
      polygons[f].push_back(std::uint32_t(index));
    }
  }
  checkEdges(polygons);

  // ---- Triangles, turned to face out counter-clockwise (the right-hand rule).
  mesh->points = points;
  for (std::uint32_t f = 0; f < polygons.size(); ++f) {
    std::reverse(polygons[f].begin(), polygons[f].end());
    triangulate(mesh->points, polygons[f], f, mesh->triangles, mesh->faceOfTriangle);
  }
  std::vector<std::vector<std::uint32_t>>().swap(polygons);
  for (const Triangle& tri : mesh->triangles)
    for (std::uint32_t v : tri) mesh->bounds.include(mesh->points[v]);
  double extent = std::max({mesh->bounds.size().x, mesh->bounds.size().y, mesh->bounds.size().z});

  for (std::uint32_t i = 0; i < mesh->triangles.size(); ++i) {
    const Triangle& tri = mesh->triangles[i];
    const dvec3 &a = mesh->points[tri[0]], &b = mesh->points[tri[1]], &c = mesh->points[tri[2]];
    // No area at all. A sliver whose area rounds to almost nothing is
    // kept: exported booleans have them (CGAL's exact check accepts them),
    // and a ray meets such a triangle rarely and exactly, as any other.
    if (collinear(a, b, c)) {
      std::uint32_t f = mesh->faceOfTriangle[i];
      // Named as the face runs in the input (clockwise).
      if (faces[f].size() == 3)
        refuse("face " + std::to_string(f) + " (points " + pointList(tri[2], tri[1], tri[0]) +
               ") is degenerate: it has no area");
      refuse("face " + std::to_string(f) + " is degenerate: its triangle (points " +
             pointList(tri[2], tri[1], tri[0]) + ") has no area");
    }
  }

  // ---- Shells (connected by shared points) and their volumes.
  std::vector<std::uint32_t> parent(mesh->points.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (const Triangle& tri : mesh->triangles)
    for (int k = 1; k < 3; ++k) {
      std::uint32_t a = findRoot(parent, tri[0]), b = findRoot(parent, tri[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<std::uint32_t> shellOfRoot(mesh->points.size(), 0);
  std::vector<std::uint32_t> shellOf(mesh->triangles.size());
  std::vector<std::uint32_t> shellFace, shellPoint;  // the first face and a point of each shell
  for (std::uint32_t i = 0; i < mesh->triangles.size(); ++i) {
    std::uint32_t root = findRoot(parent, mesh->triangles[i][0]);
    if (shellOfRoot[root] == 0) {
      shellFace.push_back(mesh->faceOfTriangle[i]);
      shellPoint.push_back(mesh->triangles[i][0]);
      shellOfRoot[root] = std::uint32_t(shellFace.size());
    }
    shellOf[i] = shellOfRoot[root] - 1;
  }
  // Divergence theorem: V = Σ a·(b × c)/6 over the triangles, the signed
  // volumes of the tetrahedra they span with a point of their shell (which
  // keeps the terms as small as the shell). The sum of their magnitudes
  // measures what rounding can do to it.
  std::vector<double> shellVolume(shellFace.size(), 0.0), shellScale(shellFace.size(), 0.0);
  for (std::uint32_t i = 0; i < mesh->triangles.size(); ++i) {
    const Triangle& tri = mesh->triangles[i];
    std::uint32_t s = shellOf[i];
    const dvec3& o = mesh->points[shellPoint[s]];
    double term = glm::dot(mesh->points[tri[0]] - o,
                           glm::cross(mesh->points[tri[1]] - o, mesh->points[tri[2]] - o)) /
                  6.0;
    shellVolume[s] += term;
    shellScale[s] += std::abs(term);
  }
  double volume = std::accumulate(shellVolume.begin(), shellVolume.end(), 0.0);
  if (volume < 0.0) {
    // Closed and consistently oriented but enclosing a negative volume: the
    // faces run counter-clockwise seen from outside.
    mesh->turned = true;
    volume = -volume;
    for (Triangle& tri : mesh->triangles) std::swap(tri[1], tri[2]);
    for (double& v : shellVolume) v = -v;
  }
  for (std::size_t s = 0; s < shellVolume.size(); ++s)
    if (!(std::abs(shellVolume[s]) > 1e-12 * shellScale[s]))
      refuse("the faces connected to face " + std::to_string(shellFace[s]) +
             " enclose no volume (a flat or doubled surface)");
  mesh->volume = volume;

  // ---- The BVH over the triangles' boxes, padded so that the rounding of
  // the box tests never loses a triangle that a ray meets on its edge
  // (good for ray origins within about a million mesh sizes).
  double scale = std::max({extent, glm::length(mesh->bounds.lo), glm::length(mesh->bounds.hi)});
  dvec3 pad(1e-9 * scale);
  std::vector<Bounds> boxes(mesh->triangles.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::uint32_t v : mesh->triangles[i]) boxes[i].include(mesh->points[v]);
    boxes[i].lo -= pad;
    boxes[i].hi += pad;
  }
  mesh->bvh = Bvh(boxes);

  // ---- A shell that faces inward bounds a cavity, and must lie inside
  // another shell: its points must have a positive winding number with
  // respect to the rest of the mesh.
  for (std::uint32_t s = 0; s < shellVolume.size(); ++s) {
    if (shellVolume[s] > 0.0) continue;
    int winding = 0;
    Ray probe(mesh->points[shellPoint[s]], kProbeDirection, 0.0, kInfinity);
    mesh->forEachCrossing(probe, [&](std::uint32_t tri, double t, int sign) {
      if (shellOf[tri] != s && t > 0.0) winding -= sign;
    });
    if (winding <= 0)
      refuse("inside-out shell: the faces connected to face " + std::to_string(shellFace[s]) +
             " run the other way from the rest of the mesh, but do not bound a cavity inside "
             "it; list every face clockwise as seen from outside");
  }
  mesh_ = std::move(mesh);
}

const std::vector<dvec3>& MeshSolid::points() const { return mesh_->points; }
const std::vector<MeshSolid::Triangle>& MeshSolid::triangles() const { return mesh_->triangles; }
std::uint32_t MeshSolid::faceOf(std::uint32_t triangle) const {
  return mesh_->faceOfTriangle.at(triangle);
}
double MeshSolid::volume() const { return mesh_->volume; }
bool MeshSolid::turned() const { return mesh_->turned; }

std::size_t MeshSolid::memoryBytes() const {
  return sizeof(Mesh) + mesh_->points.capacity() * sizeof(dvec3) +
         mesh_->triangles.capacity() * sizeof(Triangle) +
         mesh_->faceOfTriangle.capacity() * sizeof(std::uint32_t) + mesh_->bvh.memoryBytes();
}

void MeshSolid::objectSpans(const Ray& ray, SpanList& out) const {
  // (A NaN would also break the sort below.)
  if (!usable(ray)) return;
  // Spans need only be exact within the window (solid.h). A line leaves
  // the closed mesh as often as it enters it, so the winding number at
  // tMin is minus the sum of the crossings from tMin on: the line before
  // the window is never traversed. The scratch list is reused per thread:
  // no allocation per ray once it has grown to the mesh's depth complexity.
  thread_local std::vector<Crossing> crossings;
  crossings.clear();
  Ray half(ray.origin, ray.dir, ray.tMin, kInfinity);
  mesh_->forEachCrossing(half, [&](std::uint32_t tri, double t, int sign) {
    if (t >= ray.tMin) crossings.push_back({t, tri, sign});
  });
  if (crossings.empty()) return;
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });

  // Sweep the winding number along the line; crossings at (nearly) the
  // same t are one event, so a grazed silhouette (in and out at once) adds
  // nothing and spans stay disjoint with in < out.
  auto boundary = [&](const Crossing& c) { return Boundary{c.t, this, c.triangle, false}; };
  int winding = 0;
  for (const Crossing& c : crossings) winding -= c.sign;
  bool inside = winding > 0;
  // Inside at tMin: the span began before the window, where it is not an
  // answer; it is reported from −∞, as for an unbounded solid.
  Boundary start{-kInfinity, nullptr, 0, false};
  for (std::size_t i = 0; i < crossings.size();) {
    // (A ray grazing a silhouette edge enters and leaves there: one point.)
    double last = crossings[i].t + kSameT * std::abs(crossings[i].t);
    const Crossing *entry = nullptr, *exit = nullptr;
    for (; i < crossings.size() && crossings[i].t <= last; ++i) {
      const Crossing& c = crossings[i];
      winding += c.sign;
      if (c.sign > 0 && !entry) entry = &c;
      if (c.sign < 0 && !exit) exit = &c;
    }
    bool now = winding > 0;
    if (now == inside) continue;
    if (now) {
      if (entry->t > ray.tMax) break;  // the rest is beyond the window
      start = boundary(*entry);
    } else {
      out.push_back(start, boundary(*exit));
    }
    inside = now;
  }
  // With exact signs, every line enters the closed mesh as often as it
  // leaves, so the sweep ends outside (unless a triangle's box was missed).
}

bool MeshSolid::objectContains(const dvec3& p) const {
  // The winding number at p: crossings of a ray from p, each exit counting
  // +1 and each entry −1 (Jordan's theorem, with orientation).
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  int winding = 0;
  Ray probe(p, kProbeDirection, 0.0, kInfinity);
  mesh_->forEachCrossing(probe, [&](std::uint32_t, double t, int sign) {
    if (t > 0.0) winding -= sign;
  });
  return winding > 0;
}

dvec3 MeshSolid::objectNormal(const dvec3&, int face) const {
  const Triangle& tri = mesh_->triangles[std::size_t(face)];
  const dvec3 &a = mesh_->points[tri[0]], &b = mesh_->points[tri[1]], &c = mesh_->points[tri[2]];
  return unitNormal(a, b, c);
}

Bounds MeshSolid::objectBounds() const { return mesh_->bounds; }

}  // namespace csgray::detail
