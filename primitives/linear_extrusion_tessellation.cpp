// LinearExtrusion::objectTessellate: the extrusion's mesh (its exact part
// is linear_extrusion.cpp).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <stdexcept>
#include <vector>

#include "engine/cancellation.h"
#include "primitives/linear_extrusion.h"
#include "primitives/profile_sweep_tessellation.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

// The top of a sweep scaled by 0 on one axis is a segment along the other
// (the seam), and each loop's top ring folds onto it. The mesh is a closed
// 2-manifold only where every ring runs once along the seam and once back
// (a loop monotone along that axis, as every convex one is: its two chains
// meet face to face there) and no two rings share a piece of it.
void requireSeamLoops(const TriangleMesh& mesh,
                      const std::vector<std::vector<std::uint32_t>>& rings, int along) {
  std::vector<std::pair<double, double>> spans;
  for (const auto& ring : rings) {
    // The senses of its steps along the seam, steps in place left out;
    // a ring that runs once along and once back turns twice, cyclically.
    std::vector<bool> forward;
    double lo = kInfinity, hi = -kInfinity;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const double a = mesh.points[ring[i]][along];
      const double b = mesh.points[ring[(i + 1) % ring.size()]][along];
      lo = std::min(lo, a);
      hi = std::max(hi, a);
      if (a != b) forward.push_back(b > a);
    }
    int turns = 0;
    for (std::size_t i = 0; i < forward.size(); ++i)
      turns += forward[i] != forward[(i + 1) % forward.size()];
    if (turns != 2)
      throw std::invalid_argument(
          "linear_extrude: a scale of 0 on one axis folds the top onto a segment, and an outline "
          "of this region runs back and forth along it (it must run once along and once back, as "
          "a convex one does); use a small positive scale");
    spans.emplace_back(lo, hi);
  }
  std::sort(spans.begin(), spans.end());
  for (std::size_t i = 1; i < spans.size(); ++i)
    if (spans[i].first <= spans[i - 1].second)
      throw std::invalid_argument(
          "linear_extrude: a scale of 0 on one axis folds the top onto a segment, and two of the "
          "region's outlines (or an outline and its hole) would meet there; use a small positive "
          "scale");
}

// The caps of a folded top have no area: dropped. The two chains of each
// ring meet along the seam at different points; each side triangle with an
// edge there is fanned from its third corner through the points of the
// seam within that edge, so that the chains share every edge of the seam.
void closeSeam(TriangleMesh& mesh, const std::vector<std::vector<std::uint32_t>>& rings,
               int along) {
  std::vector<bool> onSeam(mesh.points.size(), false);
  std::vector<std::pair<double, std::uint32_t>> seam;
  for (const auto& ring : rings)
    for (const std::uint32_t v : ring)
      if (!onSeam[v]) {
        onSeam[v] = true;
        seam.emplace_back(mesh.points[v][along], v);
      }
  std::sort(seam.begin(), seam.end());
  std::vector<TriangleMesh::Triangle> kept;
  kept.reserve(mesh.triangles.size());
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    int edge = -1, count = 0;
    for (int i = 0; i < 3; ++i) {
      if (onSeam[t[i]]) ++count;
      if (onSeam[t[i]] && onSeam[t[(i + 1) % 3]]) edge = i;
    }
    if (count == 3) continue;  // a cap's
    if (edge < 0) {
      kept.push_back(t);
      continue;
    }
    const std::uint32_t from = t[edge], to = t[(edge + 1) % 3], apex = t[(edge + 2) % 3];
    const double a = mesh.points[from][along], b = mesh.points[to][along];
    std::uint32_t previous = from;
    auto step = [&](std::uint32_t v) {
      kept.push_back({apex, previous, v});
      previous = v;
    };
    if (a < b) {
      for (auto it = std::upper_bound(seam.begin(), seam.end(), std::make_pair(a, ~0u));
           it != seam.end() && it->first < b; ++it)
        step(it->second);
    } else {
      for (auto it = std::lower_bound(seam.begin(), seam.end(), std::make_pair(a, 0u));
           it != seam.begin() && std::prev(it)->first > b; --it)
        step(std::prev(it)->second);
    }
    step(to);
  }
  mesh.triangles = std::move(kept);
}

}  // namespace

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
  // A scale of 0 on one axis flattens the top onto a segment of the other
  // axis (the seam): the axis along it, or −1.
  const int along = apex ? -1 : scale_.x == 0.0 ? 1 : scale_.y == 0.0 ? 0 : -1;
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
  const std::atomic<bool>* cancel = cancelFlag();  // read at each slice, as the sides are
  for (int k = 0; k <= slices; ++k) {
    stopIfCancelled(cancel);
    const double zeta = double(k) / slices;
    const dvec2 sigma(1.0 + (scale_.x - 1.0) * zeta, 1.0 + (scale_.y - 1.0) * zeta);
    const double angle = -twist_ * zeta, c = std::cos(angle), s = std::sin(angle);
    const double z = k == slices ? z0_ + height_ : z0_ + height_ * zeta;
    // The apex is one point, not a ring.
    const bool top = apex && k == slices;
    if (top) mesh.points.emplace_back(0.0, 0.0, z);
    // On the seam, points of one place are one point.
    std::map<double, std::uint32_t> seam;
    levels[k].resize(loops.size());
    for (std::size_t l = 0; l < loops.size(); ++l)
      for (const dvec2& u : loops[l]) {
        if (top) {
          levels[k][l].push_back(std::uint32_t(mesh.points.size() - 1));
          continue;
        }
        const dvec2 turned(c * u.x - s * u.y, s * u.x + c * u.y);
        dvec3 point(sigma.x * turned.x, sigma.y * turned.y, z);
        if (along >= 0 && k == slices) {
          point[1 - along] = 0.0;  // not −0
          const auto [at, fresh] = seam.emplace(point[along], std::uint32_t(mesh.points.size()));
          levels[k][l].push_back(at->second);
          if (fresh) mesh.points.push_back(point);
          continue;
        }
        levels[k][l].push_back(std::uint32_t(mesh.points.size()));
        mesh.points.push_back(point);
      }
    if (along >= 0 && k == slices) requireSeamLoops(mesh, levels[k], along);
  }
  addSweepFaces(mesh, loops, levels, false, false);
  if (along >= 0) closeSeam(mesh, levels.back(), along);
  return mesh;
}

}  // namespace csgray::detail
