// RoundedPolytope::objectTessellate: one closed mesh, valid by
// construction rather than by a boolean of the prisms, cylinders and balls
// (which touch each other tangentially, the case mesh booleans handle
// worst). The faces moved out by r, a strip of quads along each edge
// between the arcs at its two ends, and at each vertex a patch of sphere
// bounded by the same arcs: every arc point is made once and shared by the
// strip and the patches it bounds, so the pieces close up exactly.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <tuple>

#include "primitives/rounded_polytope.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

using Edge = RoundedPolytope::Edge;

// The unit vector at fraction s of the great arc from a to b (Shoemake,
// "Animating Rotation with Quaternion Curves", SIGGRAPH 1985).
dvec3 slerp(const dvec3& a, const dvec3& b, double s) {
  double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
  if (angle < 1e-9) return glm::normalize(a + s * (b - a));
  double sinAngle = std::sin(angle);
  return (std::sin((1.0 - s) * angle) / sinAngle) * a + (std::sin(s * angle) / sinAngle) * b;
}

class Builder {
 public:
  Builder(const RoundedPolytope::Shape& shape, double r, double step)
      : p_(shape.polytope), edges_(shape.edges), r_(r), step_(step) {}

  TriangleMesh build() {
    for (std::uint32_t f = 0; f < p_.faces.size(); ++f) face(f);
    arcs_.resize(edges_.size());
    for (std::size_t e = 0; e < edges_.size(); ++e) strip(e);
    for (std::uint32_t v = 0; v < p_.vertices.size(); ++v) patch(v);
    return std::move(mesh_);
  }

 private:
  // The mesh point at vertex v, r along dir. Named by (v, id, k): a face's
  // (id = the face, k = 0) or an edge arc's k-th inner point (id = the
  // number of faces + the edge), so each is made once.
  std::uint32_t point(std::uint32_t v, std::size_t id, int k, const dvec3& dir) {
    auto [it, added] = points_.try_emplace(std::make_tuple(v, id, k), 0);
    if (added) {
      it->second = static_cast<std::uint32_t>(mesh_.points.size());
      mesh_.points.push_back(p_.vertices[v] + r_ * dir);
    }
    return it->second;
  }
  std::uint32_t facePoint(std::uint32_t v, std::uint32_t f) {
    return point(v, f, 0, p_.faces[f].normal);
  }
  // Point k of edge e's arc at its vertex v (0: the left face's, m: the
  // right face's).
  std::uint32_t arcPoint(std::size_t e, std::uint32_t v, std::size_t k) {
    const std::vector<dvec3>& arc = arcs_[e];
    if (k == 0) return facePoint(v, edges_[e].left);
    if (k + 1 == arc.size()) return facePoint(v, edges_[e].right);
    return point(v, p_.faces.size() + e, static_cast<int>(k), arc[k]);
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh_.triangles.push_back({a, b, c});
  }

  // The face moved out: a convex polygon, fanned.
  void face(std::uint32_t f) {
    const auto& loop = p_.faces[f].loop;
    std::uint32_t first = facePoint(loop[0], f);
    for (std::size_t i = 1; i + 1 < loop.size(); ++i)
      triangle(first, facePoint(loop[i], f), facePoint(loop[i + 1], f));
  }

  // The arc of directions from the left face's normal n₁ to the right
  // face's n₂ about the edge: cos φ n₁ + sin φ m, where m = d × n₁ points
  // away from the left face in its plane (the face lies to the left of its
  // loop), for φ from 0 to the angle between the normals.
  void strip(std::size_t e) {
    const Edge& edge = edges_[e];
    const dvec3& n1 = p_.faces[edge.left].normal;
    const dvec3& n2 = p_.faces[edge.right].normal;
    dvec3 m = glm::cross(edge.direction, n1);
    // The polytope is convex, so the arc turns towards m; its angle from
    // the cross and dot products (accurate for small and straight angles
    // alike: the two sides of a flat polygon are π apart).
    double angle = std::atan2(glm::length(glm::cross(n1, n2)), glm::dot(n1, n2));
    std::size_t steps = std::max<std::size_t>(1, std::size_t(std::ceil(angle / step_)));
    std::vector<dvec3>& arc = arcs_[e];
    for (std::size_t k = 0; k <= steps; ++k) {
      double phi = angle * double(k) / double(steps);
      arc.push_back(k == 0 ? n1 : k == steps ? n2 : std::cos(phi) * n1 + std::sin(phi) * m);
    }
    // Outward: (A_{k+1} − A_k) × (B_k − A_k) is along the arc's tangent
    // × the edge, which is the outward direction.
    for (std::size_t k = 0; k < steps; ++k) {
      std::uint32_t a0 = arcPoint(e, edge.a, k), a1 = arcPoint(e, edge.a, k + 1);
      std::uint32_t b0 = arcPoint(e, edge.b, k), b1 = arcPoint(e, edge.b, k + 1);
      triangle(a0, a1, b1);
      triangle(a0, b1, b0);
    }
  }

  // The patch of sphere about vertex v: its boundary is the arcs of the
  // edges at v, walked from face to face about the vertex; it is filled
  // by rings between its centre direction and the boundary, each ring the
  // boundary's points moved the same fraction of the way to the centre.
  void patch(std::uint32_t v) {
    struct Corner {
      std::uint32_t index;
      dvec3 dir;
    };
    std::vector<Corner> boundary;
    // The edges at v by the face on their left when leaving v.
    std::map<std::uint32_t, std::size_t> leaving;  // face → edge leaving v along its loop
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      if (edges_[e].a == v) leaving[edges_[e].left] = e;
      if (edges_[e].b == v) leaving[edges_[e].right] = e;
    }
    if (leaving.empty()) return;
    std::uint32_t f = leaving.begin()->first;
    for (std::size_t guard = 0; guard < leaving.size(); ++guard) {
      std::size_t e = leaving.at(f);
      const Edge& edge = edges_[e];
      const std::vector<dvec3>& arc = arcs_[e];
      // Along the arc from face f's normal to the next face's.
      bool forward = edge.left == f;
      for (std::size_t i = 0; i + 1 < arc.size(); ++i) {
        std::size_t k = forward ? i : arc.size() - 1 - i;
        boundary.push_back({arcPoint(e, v, k), arc[k]});
      }
      f = forward ? edge.right : edge.left;
      if (f == leaving.begin()->first) break;
    }
    dvec3 centre(0.0);
    for (const Corner& c : boundary) centre += c.dir;
    centre = glm::normalize(centre);
    // Counter-clockwise about the centre seen from outside, as the
    // triangles must be.
    double turn = 0.0;
    for (std::size_t j = 0; j < boundary.size(); ++j)
      turn +=
          glm::dot(centre, glm::cross(boundary[j].dir, boundary[(j + 1) % boundary.size()].dir));
    if (turn < 0.0) std::reverse(boundary.begin(), boundary.end());
    double widest = 0.0;
    for (const Corner& c : boundary)
      widest = std::max(widest, std::acos(std::clamp(glm::dot(centre, c.dir), -1.0, 1.0)));
    std::size_t rings = std::max<std::size_t>(1, std::size_t(std::ceil(widest / step_)));
    const std::size_t n = boundary.size();
    std::vector<std::uint32_t> inner, outer(n);
    std::uint32_t apex = static_cast<std::uint32_t>(mesh_.points.size());
    mesh_.points.push_back(p_.vertices[v] + r_ * centre);
    for (std::size_t s = 1; s <= rings; ++s) {
      for (std::size_t j = 0; j < n; ++j) {
        if (s == rings) {
          outer[j] = boundary[j].index;
          continue;
        }
        outer[j] = static_cast<std::uint32_t>(mesh_.points.size());
        mesh_.points.push_back(p_.vertices[v] +
                               r_ * slerp(centre, boundary[j].dir, double(s) / double(rings)));
      }
      for (std::size_t j = 0; j < n; ++j) {
        std::size_t k = (j + 1) % n;
        if (s == 1) {
          triangle(apex, outer[j], outer[k]);
        } else {
          triangle(inner[j], outer[j], outer[k]);
          triangle(inner[j], outer[k], inner[k]);
        }
      }
      inner = outer;
    }
  }

  const Polytope& p_;
  const std::vector<Edge>& edges_;
  double r_, step_;
  TriangleMesh mesh_;
  std::vector<std::vector<dvec3>> arcs_;
  std::map<std::tuple<std::uint32_t, std::size_t, int>, std::uint32_t> points_;
};

}  // namespace

// Every arc is cut into steps of at most the angle whose chord stays within
// a quarter of the tolerance of the sphere (sagitta r(1 − cos(φ/2))): the
// patches' cells are about a step on each side but not square, and the
// triangles they are cut into reach up to about twice as far from their
// corners as a chord's middle from its ends, which is what stays within the
// tolerance. All points lie on the exact surface, and the solid is convex,
// so the mesh lies inside it.
TriangleMesh RoundedPolytope::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  const double half = 0.25 * tolerance;
  const double step = half >= radius_
                          ? std::numbers::pi / 2.0
                          : std::min(std::numbers::pi / 2.0, 2.0 * std::acos(1.0 - half / radius_));
  // The sphere's 4π of directions in cells of about step², two triangles
  // each, and each edge's strip.
  double triangles = 8.0 * std::numbers::pi / (step * step) +
                     double(shape_->edges.size()) * 2.0 * (std::numbers::pi / step + 1.0);
  requireTriangleBudget(kind(), triangles, tolerance);
  return Builder(*shape_, radius_, step).build();
}

}  // namespace csgray::detail
