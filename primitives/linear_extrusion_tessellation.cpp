// LinearExtrusion::objectTessellate: the extrusion's mesh (its exact part
// is linear_extrusion.cpp).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <vector>

#include "primitives/linear_extrusion.h"
#include "primitives/profile_sweep_tessellation.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

// The region's loops (within half the tolerance; circles on rims_, within
// the whole, where nothing else uses it) placed at slices
// ζ = k/N of the height, p = S(ζ)·Rot(−τζ)·u, with the sides between
// consecutive slices and a cap at each end (the same triangulation of the
// loops, reversed at the bottom). Slices: one without twist and with a
// uniform scale, where each side quad is planar (a trapezoid) and the mesh
// is exact up to the loops' chords. A twist turns a point at distance r by
// τ over the height, along a helix whose chords over N slices stay within
// the sagitta rule's r(1 − cos(τ/2N)); a non-uniform scale bends a side
// quad over an edge of length ℓ out of its plane by at most
// |sx − sy|·ℓ/(4N) (the bilinear patch between its corners is the exact
// surface). N and the edges cut shorter hold both within the other half
// of the tolerance.
std::shared_ptr<const LinearExtrusion> LinearExtrusion::withRims(
    std::vector<CircleRim> rims) const {
  auto copy = std::make_shared<LinearExtrusion>(*this);
  copy->rims_ = std::move(rims);
  return copy;
}

TriangleMesh LinearExtrusion::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  // Circles a cylinder stands on take its rim polygon (flatten()), at the
  // whole tolerance, as the cylinder's: the sides are straight prisms. A
  // scale above 1 stretches the polygons' chords with the profile, so they
  // are cut that much finer (a ring flared to twice its size and twisted
  // was 1.3 tolerances off at the top).
  bool pinched = false;
  const double grown = std::max({1.0, scale_.x, scale_.y});
  SweepLoops loops = sweepLoops(*swept_->region(), 0.5 * tolerance / grown, "linear_extrude",
                                prism() ? rims_ : std::vector<CircleRim>{}, tolerance, &pinched);
  if (loops.empty()) return {};  // a region without points: no solid
  auto measure = [&](double& reach, double& longest, std::size_t& points) {
    reach = longest = 0.0;
    points = 0;
    for (const auto& loop : loops) {
      points += loop.size();
      for (std::size_t i = 0; i < loop.size(); ++i) {
        reach = std::max(reach, glm::length(loop[i]));
        longest = std::max(longest, glm::length(loop[(i + 1) % loop.size()] - loop[i]));
      }
    }
  };
  double reach, longest;
  std::size_t points;
  measure(reach, longest, points);
  const bool apex = scale_.x == 0.0 && scale_.y == 0.0;
  if (apex && loops.size() > 1)
    throw std::invalid_argument(
        "linear_extrude: scale 0 makes every loop of the region end in one point at the top, "
        "which no closed 2-manifold mesh can have with more than one loop; use a small "
        "positive scale");
  if (!apex && (scale_.x == 0.0 || scale_.y == 0.0))
    throw std::invalid_argument(
        "linear_extrude: a scale of 0 on one axis flattens the top to a segment, which cannot be "
        "exported; use scale 0 on both axes or a small positive scale");
  const double half = 0.5 * tolerance;
  // A non-uniform scale bends a side quad over an edge of length ℓ out of
  // its plane by |sx − sy|·ℓ/(4N) between slices N apart.
  const double skew = std::abs(scale_.x - scale_.y);
  int slices = 1;
  if (twist_ != 0.0 || skew > 0.0) {
    // Half of the half for the helices' chords, half for the twist of a
    // side quad over an edge of length ℓ turned by Δθ between slices,
    // which bends it out of its plane by at most Δθ·ℓ/4: longer edges
    // are split. A skew without a twist has the whole half; with one,
    // half of it as well.
    const double stretch = grown;
    if (twist_ != 0.0) {
      const double r = reach * stretch;
      slices = arcSegments(r, std::abs(twist_), 0.5 * half, 1);
      requireTriangleBudget(kind(), 2.0 * double(points) * slices, tolerance);
    }
    // The longest edge that a turn of |τ|/N and the skew leave within the
    // tolerance. (Cutting the long edges rather than adding slices for
    // all: a letter's stem under a skew of 0.5 took 250 slices of every
    // one of its hundreds of short edges, 864 000 triangles.)
    auto longestFor = [&](double n) {
      double most = kInfinity;
      if (twist_ != 0.0) most = 4.0 * 0.5 * half * n / (std::abs(twist_) * stretch);
      if (skew > 0.0) most = std::min(most, 4.0 * (twist_ != 0.0 ? 0.5 : 1.0) * half * n / skew);
      return most;
    };
    // More slices than the helices need may take fewer triangles in all:
    // each slice turns less, so fewer edges are split. Of the counts up to
    // four times the least (a skew without a twist: up to the count that
    // splits no edge, by steps of a quarter), the one with the fewest side
    // quads.
    std::vector<int> counts;
    if (twist_ != 0.0) {
      for (int k = 0; k <= 48; ++k)
        counts.push_back(int(std::min(1e9, std::ceil(slices * (1.0 + k / 16.0)))));
    } else {
      const double unsplit = std::max(1.0, std::min(1e9, std::ceil(skew * longest / (4.0 * half))));
      for (double n = 1.0;; n = std::ceil(1.25 * n)) {
        counts.push_back(int(std::min(n, unsplit)));
        if (n >= unsplit) break;
      }
    }
    double fewest = kInfinity;
    for (const int n : counts) {
      double quads = 0.0;
      for (const auto& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i)
          quads += std::ceil(glm::length(loop[(i + 1) % loop.size()] - loop[i]) / longestFor(n));
      // Without a twist the caps count too: each cut is a point of both
      // (a circle under a skew cut into pieces at one slice took twice the
      // triangles of its twelve slices uncut). (The twist's choice is left
      // as it was made: its parts keep their meshes.)
      const double cost = twist_ != 0.0 ? quads * n : quads * (n + 1);
      if (cost < fewest) {
        fewest = cost;
        slices = n;
      }
    }
    const double most = longestFor(slices);
    if (longest > most) {
      requireTriangleBudget(kind(), 2.0 * double(points) * slices * std::ceil(longest / most),
                            tolerance);
      for (auto& loop : loops) {
        std::vector<dvec2> split;
        for (std::size_t i = 0; i < loop.size(); ++i) {
          const dvec2 a = loop[i], b = loop[(i + 1) % loop.size()];
          const int parts = int(std::ceil(glm::length(b - a) / most));
          for (int k = 0; k < parts; ++k) split.push_back(a + (b - a) * (double(k) / parts));
        }
        loop = std::move(split);
      }
      measure(reach, longest, points);
    }
  }
  requireTriangleBudget(kind(), 2.0 * double(points) * slices + 2.0 * double(points), tolerance);

  TriangleMesh mesh;
  mesh.pinched = pinched;
  SweepLevels levels(slices + 1);
  for (int k = 0; k <= slices; ++k) {
    const double zeta = double(k) / slices;
    const dvec2 sigma(1.0 + (scale_.x - 1.0) * zeta, 1.0 + (scale_.y - 1.0) * zeta);
    const double angle = -twist_ * zeta, c = std::cos(angle), s = std::sin(angle);
    const double z = k == slices ? z0_ + height_ : z0_ + height_ * zeta;
    // The apex is one point, not a ring.
    const bool top = apex && k == slices;
    if (top) mesh.points.emplace_back(0.0, 0.0, z);
    levels[k].resize(loops.size());
    for (std::size_t l = 0; l < loops.size(); ++l)
      for (const dvec2& u : loops[l]) {
        if (top) {
          levels[k][l].push_back(std::uint32_t(mesh.points.size() - 1));
          continue;
        }
        levels[k][l].push_back(std::uint32_t(mesh.points.size()));
        const dvec2 turned(c * u.x - s * u.y, s * u.x + c * u.y);
        mesh.points.emplace_back(sigma.x * turned.x, sigma.y * turned.y, z);
      }
  }
  addSweepFaces(mesh, loops, levels, false, false);
  return mesh;
}

}  // namespace csgray::detail
