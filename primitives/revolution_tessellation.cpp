// Revolution::objectTessellate: the revolution's mesh (its exact part is
// revolution.cpp).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "primitives/profile_sweep_tessellation.h"
#include "primitives/revolution.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

// p and q (q ≤ 24) with angle = 360°·p/q, or nothing for an angle that is
// no such share of a turn.
std::optional<std::pair<int, int>> shareOfATurn(double degrees) {
  for (int q = 1; q <= 24; ++q) {
    const double p = degrees * q / 360.0;
    if (std::round(p) >= 1.0 && std::abs(p - std::round(p)) <= 1e-9 * q)
      return std::pair(int(std::round(p)), q);
  }
  return std::nullopt;
}

}  // namespace

// The region's loops (within half the tolerance, outer ones counter-
// clockwise in the (ρ, z) plane, so that the solid lies to their left)
// turned about the axis in steps of the sagitta rule for the largest
// radius (the other half): a point of the mesh is then within the loops'
// chord error plus that sagitta of the surface (tessellation.h,
// revolveProfile). A loop point on the axis is one vertex, shared by every
// step. With an angle under 360° the loops at both ends of the turn are
// the wedge's flat faces, triangulated as an extrusion's caps are; a full
// turn closes on itself.
Revolution::Turned Revolution::turned(double tolerance) const {
  requireTolerance(kind(), tolerance);
  bool pinched = false;
  SweepLoops loops =
      sweepLoops(*swept_->region(), 0.5 * tolerance, "rotate_extrude", {}, 0.0, &pinched);
  if (loops.empty()) return {{}, 0, pinched};  // a region without points: no solid
  const double axisSlack = 1e-12 * swept_->size();
  double reach = 0.0;
  std::size_t points = 0;
  for (auto& loop : loops) {
    points += loop.size();
    for (dvec2& u : loop) {
      if (u.x <= axisSlack) u.x = 0.0;
      reach = std::max(reach, u.x);
    }
  }
  if (!(reach > 0.0))
    throw std::invalid_argument("rotate_extrude: the region lies on the axis and has no volume");
  // A loop that meets the axis at one point only (a circle of radius r at
  // distance r) turns into a solid pinched to a point there, as a horn
  // torus is: no 2-manifold mesh holds it.
  for (const auto& loop : loops)
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (loop[i].x == 0.0 && loop[(i + 1) % loop.size()].x > 0.0 &&
          loop[(i + loop.size() - 1) % loop.size()].x > 0.0) {
        std::ostringstream msg;
        msg << "rotate_extrude: the region touches the axis at the one point (0, " << loop[i].y
            << "), where the solid pinches to a point that no printable mesh can hold; move the "
               "region off the axis a little, or let it meet the axis along an edge";
        throw std::invalid_argument(msg.str());
      }
  const double half = 0.5 * tolerance;
  const int least = std::max(3, int(std::ceil(8.0 * angle_ / (2.0 * std::numbers::pi))));
  int steps = arcSegments(reach, angle_, half, least);
  // A turn through 360°·p/q takes a multiple of p steps, so that its steps
  // are those of a whole turn of steps·q/p: a cylinder standing in its wall
  // can then take that turn's polygon (wallSteps), whatever the angle's
  // share (270°: a multiple of 3).
  if (const auto share = shareOfATurn(angleDegrees_); share && !fullTurn_)
    steps = (steps + share->first - 1) / share->first * share->first;
  requireTriangleBudget(kind(), 2.0 * double(points) * (steps + 1), tolerance);
  return {std::move(loops), steps, pinched};
}

TriangleMesh Revolution::objectTessellate(double tolerance, const Bounds&) const {
  const Turned made = turned(tolerance);
  if (made.loops.empty()) return {};
  TriangleMesh mesh = revolvedLoops(made.loops, angleDegrees_, made.steps, fullTurn_);
  mesh.pinched = made.pinched;
  return mesh;
}

// A wall: an edge of a loop at ρ = radius at both ends (to a part in 10⁹),
// whose stretch of z overlaps z0..z1 by more than a point.
std::optional<int> Revolution::wallSteps(double radius, double z0, double z1,
                                         double tolerance) const {
  const std::optional<std::pair<int, int>> share = shareOfATurn(angleDegrees_);
  if (!fullTurn_ && !share) return std::nullopt;
  const Turned made = turned(tolerance);
  // The steps of the whole turn that this one's are a share of.
  const int whole = fullTurn_ ? made.steps : made.steps / share->first * share->second;
  auto atRadius = [&](const dvec2& u) { return std::abs(u.x - radius) <= 1e-9 * radius; };
  for (const auto& loop : made.loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const dvec2 &u = loop[i], &v = loop[(i + 1) % loop.size()];
      if (atRadius(u) && atRadius(v) &&
          std::min(std::max(u.y, v.y), z1) > std::max(std::min(u.y, v.y), z0))
        return whole;
    }
  return std::nullopt;
}

std::optional<Revolution::CircleLoop> Revolution::circleLoop(const dvec2& center, double radius,
                                                             double tolerance) const {
  // The arc's points are on their circle to rounding; the centre asked
  // for may be off by what the frames' products and the grid of 2⁻³⁰, to
  // which the exporter snaps the frames of a part turned as a whole, leave
  // of it (as for a cylinder's rim, region_evaluation.h).
  constexpr double kSlack = 1e-9;
  const Turned made = turned(tolerance);
  for (const auto& loop : made.loops) {
    const std::size_t n = loop.size();
    if (n < 3) continue;
    dvec2 mean(0.0);
    for (const dvec2& u : loop) mean += u;
    mean /= double(n);
    if (glm::length(mean - center) > kSlack * (radius + glm::length(center)) + 0x1p-30) continue;
    auto onCircle = [&](const dvec2& u) {
      return std::abs(glm::length(u - mean) - radius) <= kSlack * radius;
    };
    if (!std::all_of(loop.begin(), loop.end(), onCircle)) continue;
    // Regular: each side the same chord, 2·r·sin(π/n).
    const double side = 2.0 * radius * std::sin(std::numbers::pi / double(n));
    bool regular = true;
    for (std::size_t i = 0; i < n && regular; ++i)
      regular = std::abs(glm::length(loop[(i + 1) % n] - loop[i]) - side) <= kSlack * radius;
    if (!regular) continue;
    const dvec2 first = loop[0] - mean;
    return CircleLoop{int(n), std::atan2(first.y, first.x)};
  }
  return std::nullopt;
}

}  // namespace csgray::detail
