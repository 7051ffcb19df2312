// Revolution::objectTessellate: the revolution's mesh (its exact part is
// revolution.cpp).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "primitives/profile_sweep_tessellation.h"
#include "primitives/revolution.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

// The region's loops (within half the tolerance, outer ones counter-
// clockwise in the (ρ, z) plane, so that the solid lies to their left)
// turned about the axis in steps of the sagitta rule for the largest
// radius (the other half): a point of the mesh is then within the loops'
// chord error plus that sagitta of the surface (tessellation.h,
// revolveProfile). A loop point on the axis is one vertex, shared by every
// step. With an angle under 360° the loops at both ends of the turn are
// the wedge's flat faces, triangulated as an extrusion's caps are; a full
// turn closes on itself.
TriangleMesh Revolution::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  SweepLoops loops = sweepLoops(*swept_->region(), 0.5 * tolerance, "rotate_extrude");
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
  const double half = 0.5 * tolerance;
  const int least = std::max(3, int(std::ceil(8.0 * angle_ / (2.0 * std::numbers::pi))));
  const int steps = arcSegments(reach, angle_, half, least);
  requireTriangleBudget(kind(), 2.0 * double(points) * (steps + 1), tolerance);
  const int rings = fullTurn_ ? steps : steps + 1;

  TriangleMesh mesh;
  // ids[loop][i][k]: loop point i at step k (one id for all k on the axis).
  std::vector<std::vector<std::vector<std::uint32_t>>> ids(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const dvec2& u : loops[l]) {
      std::vector<std::uint32_t>& at = ids[l].emplace_back();
      if (u.x == 0.0) {
        at.assign(rings, std::uint32_t(mesh.points.size()));
        mesh.points.emplace_back(0.0, 0.0, u.y);
        continue;
      }
      for (int k = 0; k < rings; ++k) {
        const double theta = angle_ * k / steps;
        at.push_back(std::uint32_t(mesh.points.size()));
        mesh.points.emplace_back(u.x * std::cos(theta), u.x * std::sin(theta), u.y);
      }
    }
  // Sides: the quad a b c d between loop points i, i + 1 and steps k, k + 1
  // (a = (i, k), b = (i, k + 1), c = (i + 1, k + 1), d = (i + 1, k)) faces
  // out when the solid lies left of the loop; on the axis it is a triangle,
  // and an edge along the axis sweeps nothing.
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::size_t n = loops[l].size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      if (loops[l][i].x == 0.0 && loops[l][j].x == 0.0) continue;
      for (int k = 0; k < steps; ++k) {
        const int next = fullTurn_ ? (k + 1) % steps : k + 1;
        const std::uint32_t a = ids[l][i][k], b = ids[l][i][next];
        const std::uint32_t c = ids[l][j][next], d = ids[l][j][k];
        if (a != b) mesh.triangles.push_back({a, b, c});
        if (c != d) mesh.triangles.push_back({a, c, d});
      }
    }
  }
  if (!fullTurn_) {
    // The flat faces: at angle 0 the outward normal is −y, which a loop
    // counter-clockwise in (ρ, z) has; at the end angle it is reversed.
    for (int end = 0; end < 2; ++end) {
      const int k = end == 0 ? 0 : steps;
      std::vector<std::vector<std::uint32_t>> at(loops.size());
      for (std::size_t l = 0; l < loops.size(); ++l)
        for (const auto& point : ids[l]) at[l].push_back(point[k]);
      triangulateLoops(loops, at, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (end == 0) {
          mesh.triangles.push_back({a, b, c});
        } else {
          mesh.triangles.push_back({a, c, b});
        }
      });
    }
  }
  return mesh;
}

}  // namespace csgray::detail
