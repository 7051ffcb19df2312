#include "scene/swept_hulls.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"
#include "primitives/sphere.h"
#include "profile/region.h"
#include "profile/region_evaluation.h"
#include "profile/shapes.h"

namespace csgray::detail {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

// An edge of a profile, left out when it has no length.
void addSegment(ProfileLoop& loop, const dvec2& a, const dvec2& b) {
  if (a != b) loop.edges.push_back(ProfileEdge::segment(a, b));
}

ProfileEdge circleArc(const dvec2& centre, double r, double angle0, double angle1) {
  return ProfileEdge::arc(centre, dmat2(r), angle0, angle1);
}

// A turned profile (counter-clockwise in (ρ, z)) placed with its axis from
// origin along the unit direction axis.
SolidPtr turned(ProfileLoop loop, const dvec3& origin, const dvec3& axis) {
  Profile profile;
  profile.loops.push_back(std::move(loop));
  SolidPtr solid = Primitive::create<Revolution>(Region::leaf(std::move(profile)), 360.0);
  return AxisFrame(axis).place(solid, origin);
}

}  // namespace

SolidPtr sphereAt(const Ball& ball) {
  return Primitive::create<Sphere>(ball.radius)->transformed(Affine::translation(ball.centre));
}

AxisFrame::AxisFrame(const dvec3& axis) : a(axis) {
  dvec3 helper = std::abs(axis.x) < 0.9 ? dvec3(1.0, 0.0, 0.0) : dvec3(0.0, 1.0, 0.0);
  u = glm::normalize(glm::cross(helper, axis));
  w = glm::cross(axis, u);
}

SolidPtr AxisFrame::place(const SolidPtr& solid, const dvec3& origin) const {
  glm::dmat4 m(glm::dvec4(u, 0.0), glm::dvec4(w, 0.0), glm::dvec4(a, 0.0), glm::dvec4(origin, 1.0));
  return solid->transformed(Affine::fromMatrix(m));
}

SolidPtr extrudedDiscHull(const std::vector<Disc>& discs, const AxisFrame& frame, double from,
                          double to) {
  std::vector<RegionPtr> regions;
  double size = 0.0;
  for (const Disc& d : discs) {
    regions.push_back(circleRegion(d.radius, std::nullopt)->transformed({dmat2(1.0), d.centre}));
    size = std::max(size, glm::length(d.centre) + d.radius);
  }
  RegionPtr outline = Region::leaf(hull(regions, 1e-9 * size));
  SolidPtr solid = Primitive::create<LinearExtrusion>(outline, to - from, false, 0.0, dvec2(1.0));
  return frame.place(solid, from * frame.a);
}

// The hull of two balls: both, and the cone frustum between them that
// touches each along a circle. In the half-plane (ρ, z) with a's centre at
// the origin and b's at (0, d), the common tangent n·p = c with unit
// normal n = (cos β, sin β) has n·a + r_a = n·b + r_b, so d sin β =
// r_a − r_b. Equal radii make a capsule.
SolidPtr twoBallHull(const Ball& a, const Ball& b) {
  dvec3 axis = b.centre - a.centre;
  double d = glm::length(axis);
  if (d + b.radius <= a.radius) return sphereAt(a);
  if (d + a.radius <= b.radius) return sphereAt(b);
  double beta = std::asin((a.radius - b.radius) / d);
  ProfileEdge low = circleArc({0.0, 0.0}, a.radius, -kHalfPi, beta);
  ProfileEdge high = circleArc({0.0, d}, b.radius, beta, kHalfPi);
  low.from = {0.0, -a.radius};  // on the axis exactly
  high.to = {0.0, d + b.radius};
  ProfileLoop loop;
  loop.edges.push_back(low);
  addSegment(loop, low.to, high.from);
  loop.edges.push_back(high);
  addSegment(loop, high.to, low.from);
  return turned(std::move(loop), a.centre, axis / d);
}

// The rounded cylinder in (ρ, z): radius R, height H from z = 0, rims
// rounded with radius f, turned about z.
SolidPtr roundedCylinder(double R, double H, double f) {
  ProfileEdge low = circleArc({R - f, f}, f, -kHalfPi, 0.0);
  ProfileEdge high = circleArc({R - f, H - f}, f, 0.0, kHalfPi);
  low.from = {R - f, 0.0};
  low.to = {R, f};
  high.from = {R, H - f};
  high.to = {R - f, H};
  ProfileLoop loop;
  addSegment(loop, {0.0, 0.0}, low.from);
  loop.edges.push_back(low);
  addSegment(loop, low.to, high.from);
  loop.edges.push_back(high);
  addSegment(loop, high.to, {0.0, H});
  addSegment(loop, {0.0, H}, {0.0, 0.0});
  return turned(std::move(loop), dvec3(0.0), {0.0, 0.0, 1.0});
}

}  // namespace csgray::detail
