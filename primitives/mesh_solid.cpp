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

#include "primitives/triangle_crossing.h"
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

[[noreturn]] void refuse(const std::string& message) {
  throw std::invalid_argument("polyhedron: " + message);
}

std::string pointList(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c);
}

// A direction for the parity rays of contains(), chosen away from the axes
// and the usual diagonals so that they rarely meet an edge exactly (the
// perturbation makes them correct anyway).
const dvec3 kProbeDirection = glm::normalize(dvec3(0.2718281828, 0.3141592654, 0.8660254038));

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
  double tMax = ray.tMax;
  forEachTriangleCrossing(bvh, points, triangles, ray, tMax, visit);
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

  // ---- The BVH over the triangles (triangle_crossing.h).
  mesh->bvh = triangleBvh(mesh->points, mesh->triangles, mesh->bounds);

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
  if (!usableRay(ray)) return;
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
  return triangleNormal(a, b, c);
}

Bounds MeshSolid::objectBounds() const { return mesh_->bounds; }

}  // namespace csgray::detail
