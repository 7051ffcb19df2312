// Shared pieces of the primitives' tessellations: how many segments a curve
// needs for a chord tolerance, the limit on a mesh's size, surfaces of
// revolution from a profile, and convex polytopes from their planes.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "engine/bounds.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// No primitive is tessellated to more triangles than this: a tolerance far
// too fine for the part is an error, not hours of work and a full memory.
constexpr std::size_t kMaxTessellationTriangles = 20'000'000;

// The fewest segments that keep a polygon inscribed in an arc of the given
// radius and angle (radians) within tolerance of it: the sagitta of a chord
// over angle φ is r(1 − cos(φ/2)), so φ = 2·acos(1 − tol/r). Never fewer
// than minSegments, so that a tiny hole at a coarse tolerance stays a hole
// with a recognisable shape.
int arcSegments(double radius, double angle, double tolerance, int minSegments = 8);

// The segments of a full circle that solids standing on each other may
// share (a cylinder's or cone's rim): n rounded up to the next number of
// the form m·2^k with m in [2^b, 2^(b+1)) (b = kCircleLadderBits: 8, 10,
// 12, 14, 16, 20, 24, 28, 32, 40, ...), at most a quarter more. Rims of
// nearby radii then get the same polygon, so that frustums stacked on a
// shared rim meet triangle for triangle and are glued instead of
// corefined (a 40-frustum stack exported 5× faster for it, the plates
// with their holes no slower; docs/performance.md).
constexpr int kCircleLadderBits = 2;
int circleSegments(int n);

// How the cylinder, the cone and the torus tessellate a circle about their
// axis, so that a torus fillet on a cylinder of its outer radius, or a
// frustum on another's rim, puts its circle on the same points: `segments`
// steps (circleSegments), each point a factor `out` = 2/(1 + cos(π/n))
// outside the circle, which puts the polygon's edge midpoints as far
// inside (the minimax placement, which needs √2 fewer segments than an
// inscribed polygon: ρ(1 − c)/(1 + c) <= t is an inscribed sagitta
// ρ(1 − c) of at most 2ρt/(ρ + t), c = cos(π/n)).
//
// The points are also moved in or out by at most a part in 10⁹ of the
// radius (`shift`), differently at each step, so that no four of them lie
// on one circle: a hole through a plate puts its rim into the plate's
// face, and CGAL's triangulation of that face must otherwise settle every
// in-circle test of cocircular points in exact arithmetic (a plate with
// 64 holes exported a quarter faster for it; shifting both ways did
// better than inwards only: 1.7 s against 2.3 s for examples/bracket.lua).
// The segments are chosen for nine tenths of the tolerance less that
// shift, so that a torus turned on the same polygon has at least a tenth
// left for its tube.
struct CirclePolygon {
  int segments = 0;
  double out = 1.0;
  double shift = 0.0;
  double error = 0.0;  // how far the polygon of the radius it was made for strays
  // The angle of step 0 from +x: 0 but for a cylinder that takes a turned
  // revolution's ring (export/swept_rims.h).
  double phase = 0.0;
  // The distance from the axis of step s's point, for a circle of radius rho.
  double radiusAt(double rho, std::uint32_t s) const {
    return rho * out * (1.0 + shift * (double((s * 7919u) % 17u) - 8.0) / 8.0);
  }
  // Step s's point for a circle of radius rho about the origin, the steps
  // counted counter-clockwise from +x.
  glm::dvec2 pointAt(double rho, std::uint32_t s) const {
    const double theta = phase + 2.0 * std::numbers::pi * s / segments;
    const double r = radiusAt(rho, s);
    return {r * std::cos(theta), r * std::sin(theta)};
  }
};
// The polygon of circles of radius up to `radius`, within `tolerance`.
CirclePolygon circlePolygon(double radius, double tolerance);

// Throws std::invalid_argument when a tessellation of kind would need more
// than kMaxTessellationTriangles triangles at this tolerance.
void requireTriangleBudget(const std::string& kind, double triangles, double tolerance);

// Throws std::invalid_argument naming kind unless tolerance is a positive
// finite number.
void requireTolerance(const std::string& kind, double tolerance);

// ---- Surfaces of revolution ---------------------------------------------------

// The triangles revolveProfile makes at most, for the budget check that must
// come before the profile is built.
double revolvedTriangles(double profileEdges, double segments);

// The closed surface swept by a polygonal profile of points (ρ, z), ρ >= 0,
// turned about the z axis in `segments` equal steps: profile point (ρ, z)
// at step s is (ρ·cos θ, ρ·sin θ, z), θ = 2πs/segments. The solid must lie
// to the left of the profile as it is walked (in the half-plane with ρ to
// the right and z up), i.e. the profile runs counter-clockwise around the
// cross-section; then the triangles are counter-clockwise from outside.
// An open profile must start and end on the axis (ρ = 0), and only there;
// those points become single pole vertices. A closed profile (the last
// point joins the first) must stay off the axis.
//
// Every quad of the mesh is an isosceles trapezoid between two parallel
// chords of the circles of its profile points, so each point p of it is,
// in the meridian half-plane through p, a point q of a profile chord moved
// towards the axis by the factor λ ∈ [cos(π/segments), 1]. Hence
//   dist(p, surface) <= dist(q, profile curve) + ρmax·(1 − cos(π/segments)):
// the profile's chord error plus the sagitta of the largest circle. A
// doubly curved surface splits its tolerance between the two.
//
// With a circle polygon, each ring is that polygon's (CirclePolygon::
// radiusAt, the minimax placement): a mesh point is then q moved off the
// axis by a factor within 1 ± (1 − c)/(1 + c), so the bound's second term
// is the polygon's error at ρmax instead.
TriangleMesh revolveProfile(const std::vector<glm::dvec2>& profile, int segments, bool closed,
                            const CirclePolygon* circle = nullptr);

// ---- Convex polytopes -----------------------------------------------------------

// The closed half-space normal·p <= offset, normal of unit length.
struct BoundingPlane {
  dvec3 normal;
  double offset = 0.0;
};

// The mesh of the convex polytope where the planes meet inside `box` (a
// finite box; its six faces are planes too, so the result is bounded).
// Each face is the plane's polygon, found by clipping a square that covers
// the box by every other plane, its corners placed where three planes meet
// (exact up to rounding) and shared between faces; the polygon is fanned
// into triangles. Planes that only touch the polytope (or repeat another)
// give no face. Empty when the planes and the box have no volume in common.
TriangleMesh convexPolytopeMesh(const std::vector<BoundingPlane>& planes, const Bounds& box);

// The message of an unbounded primitive given no finite region.
void requireFiniteRegion(const std::string& kind, const Bounds& region);

// The region grown on every side by a margin (1% of its diagonal plus the
// tolerance), so that the faces an unbounded primitive's mesh is closed by
// lie outside the region, and nothing the region holds is on them.
Bounds regionWithMargin(const Bounds& region, double tolerance);

}  // namespace csgray::detail
