// Where a ray crosses a triangle mesh: the watertight ray/triangle test of
// Woop, Benthin and Wald ("Watertight Ray/Triangle Intersection", JCGT
// 2(1), 2013), its edge functions evaluated with exact signs and ties
// broken by a fixed perturbation of the ray, and a BVH over the triangles'
// boxes. A ray through an edge or a vertex crosses the surface exactly
// once there: no ray slips through a seam between triangles, and none
// meets the surface twice. The closed meshes of solids (mesh_solid.h) and
// the open meshes of surfaces (scene/surface_mesh.h) both use it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <utility>
#include <vector>

#include "engine/bvh.h"

namespace csgray::detail {

// Three indices into a list of points.
using MeshTriangle = std::array<std::uint32_t, 3>;

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
// sign is made exact with an expansion, triangle_crossing.cpp).
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
  static int signOf(double v) { return (v > 0.0) - (v < 0.0); }

  // The sign of a·b − c·d, exactly (triangle_crossing.cpp).
  static int exactSignOfDifference(double a, double b, double c, double d);

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

// Whether three points lie on one line, exactly (a triangle with no area).
bool collinear(const dvec3& a, const dvec3& b, const dvec3& c);
// The unit normal (b − a) × (c − a) of a triangle that is not collinear,
// also where doubles round the cross product to nothing.
dvec3 triangleNormal(const dvec3& a, const dvec3& b, const dvec3& c);

// A ray the crossing test can take: finite, with a direction.
bool usableRay(const Ray& ray);

// The BVH over the triangles' boxes, padded so that the rounding of the
// box tests never loses a triangle that a ray meets on its edge (good for
// ray origins within about a million mesh sizes); `bounds` is the box of
// all the triangles.
Bvh triangleBvh(const std::vector<dvec3>& points, const std::vector<MeshTriangle>& triangles,
                const Bounds& bounds);

// Calls visit(triangle, t, sign) for every crossing of the ray with the
// triangles within [ray.tMin, tMax] (up to the triangles' padded boxes),
// sign +1 where the ray meets a triangle from its back (where it enters a
// solid whose triangles run counter-clockwise seen from outside), −1 from
// its front; unordered. visit may lower tMax to prune triangles beyond it.
template <class Visit>
void forEachTriangleCrossing(const Bvh& bvh, const std::vector<dvec3>& points,
                             const std::vector<MeshTriangle>& triangles, const Ray& ray,
                             double& tMax, Visit&& visit) {
  RayFrame frame(ray);
  bvh.traverse(ray, tMax, [&](std::uint32_t i, double) {
    const MeshTriangle& tri = triangles[i];
    double t;
    if (int s = frame.cross(points[tri[0]], points[tri[1]], points[tri[2]], t)) visit(i, t, s);
    return true;
  });
}

}  // namespace csgray::detail
