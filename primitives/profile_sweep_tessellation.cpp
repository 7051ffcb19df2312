#include "primitives/profile_sweep_tessellation.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>

#include "engine/cancellation.h"
#include "engine/degrees.h"
#include "profile/pinch_points.h"
#include "profile/region_evaluation.h"
#include "tessellation/loop_crossings.h"
#include "tessellation/polygon_triangulation.h"

namespace csgray::detail {

namespace {

double cross(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }
double orient(const dvec2& a, const dvec2& b, const dvec2& c) { return cross(b - a, c - a); }

bool pointInLoop(const std::vector<dvec2>& loop, const dvec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const dvec2& a = loop[j];
    const dvec2& b = loop[i];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
      inside = !inside;
  }
  return inside;
}

struct Corner {
  dvec2 p;
  std::uint32_t id;
};

// Joins a hole (clockwise) to the polygon (counter-clockwise) by a bridge
// from the hole's rightmost point to a point of the polygon it sees.
void bridge(std::vector<Corner>& polygon, const std::vector<Corner>& hole) {
  std::size_t m = 0;
  for (std::size_t i = 1; i < hole.size(); ++i)
    if (hole[i].p.x > hole[m].p.x || (hole[i].p.x == hole[m].p.x && hole[i].p.y < hole[m].p.y))
      m = i;
  const dvec2 M = hole[m].p;
  // The nearest edge the half-line from M towards +x meets.
  double best = std::numeric_limits<double>::infinity();
  std::size_t visible = 0;
  dvec2 hit(0.0);
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const dvec2& a = polygon[i].p;
    const dvec2& b = polygon[(i + 1) % n].p;
    if (a.y == b.y || std::min(a.y, b.y) > M.y || std::max(a.y, b.y) < M.y) continue;
    const double x = a.x + (M.y - a.y) * (b.x - a.x) / (b.y - a.y);
    if (x < M.x || x - M.x >= best) continue;
    best = x - M.x;
    hit = dvec2(x, M.y);
    visible = a.x > b.x ? i : (i + 1) % n;
  }
  if (!std::isfinite(best)) {
    // No edge to the right (cannot happen for a hole inside): the nearest point.
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i)
      if (double e = glm::length(polygon[i].p - M); e < d) d = e, visible = i;
  } else if (polygon[visible].p != hit) {
    // A reflex point inside the triangle M, hit, P hides P: take the one of
    // them at the least angle from the half-line.
    const dvec2 P = polygon[visible].p;
    double bestCos = -2.0, bestDistance = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const dvec2& q = polygon[i].p;
      const dvec2& before = polygon[(i + n - 1) % n].p;
      const dvec2& after = polygon[(i + 1) % n].p;
      if (orient(before, q, after) > 0.0) continue;  // convex
      const double o1 = orient(M, hit, q), o2 = orient(hit, P, q), o3 = orient(P, M, q);
      const bool inside = (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
      if (!inside || q == M) continue;
      const dvec2 d = q - M;
      const double length = glm::length(d);
      if (!(length > 0.0)) continue;
      const double c = d.x / length;
      if (c > bestCos || (c == bestCos && length < bestDistance)) {
        bestCos = c;
        bestDistance = length;
        visible = i;
      }
    }
  }
  // A corner an earlier bridge doubled is in the polygon twice: the bridge
  // must leave the copy whose wedge of the inside it enters, or the joined
  // polygon overlaps itself.
  const dvec2 P = polygon[visible].p, d = M - P;
  for (std::size_t i = 0; i < n; ++i) {
    if (polygon[i].p != P) continue;
    const dvec2 &before = polygon[(i + n - 1) % n].p, &after = polygon[(i + 1) % n].p;
    const bool leftOfIn = cross(P - before, d) > 0.0, leftOfOut = cross(after - P, d) > 0.0;
    const bool convex = orient(before, P, after) > 0.0;
    if (convex ? leftOfIn && leftOfOut : leftOfIn || leftOfOut) {
      visible = i;
      break;
    }
  }
  std::vector<Corner> joined;
  joined.reserve(n + hole.size() + 2);
  for (std::size_t i = 0; i <= visible; ++i) joined.push_back(polygon[i]);
  for (std::size_t k = 0; k <= hole.size(); ++k) joined.push_back(hole[(m + k) % hole.size()]);
  joined.push_back(polygon[visible]);
  for (std::size_t i = visible + 1; i < n; ++i) joined.push_back(polygon[i]);
  polygon = std::move(joined);
}

// Ear clipping that cuts the ear with the shortest new edge first (a
// priority queue with lazy deletion). Cutting ears in the order met fans
// a cap out from a few corners into slivers across the whole part, whose
// boxes overlap most others' (a 1 200-point gear's cap: corners of 245
// triangles, edges of 100 across a part of 124): the export's booleans and
// its validity check then test far more pairs. Shortest first keeps the
// triangles local: a polygon's teeth are cut away first, then its body in
// rounds, each halving what is left.
void earClip(const std::vector<Corner>& polygon,
             const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& triangle) {
  const std::size_t n = polygon.size();
  if (n < 3) return;
  std::vector<std::size_t> prev(n), next(n);
  std::vector<bool> alive(n, true);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  // The corners in cells of a grid, for the test of what an ear holds.
  dvec2 lo = polygon[0].p, hi = polygon[0].p;
  for (const Corner& c : polygon) lo = glm::min(lo, c.p), hi = glm::max(hi, c.p);
  const std::size_t side = std::max<std::size_t>(1, std::size_t(std::sqrt(double(n) / 2.0)));
  const dvec2 size = glm::max(hi - lo, dvec2(1e-300));
  auto cellOf = [&](const dvec2& p, int axis) {
    const double f = (p[axis] - lo[axis]) / size[axis] * double(side);
    return std::min(side - 1, std::size_t(std::max(0.0, f)));
  };
  std::vector<std::vector<std::size_t>> cells(side * side);
  for (std::size_t i = 0; i < n; ++i)
    cells[cellOf(polygon[i].p, 1) * side + cellOf(polygon[i].p, 0)].push_back(i);

  auto isEar = [&](std::size_t i) {
    const dvec2 &a = polygon[prev[i]].p, &b = polygon[i].p, &c = polygon[next[i]].p;
    // Strictly convex, beyond rounding: a corner between collinear points
    // (an edge split for a twist) is cut later, with a third point off
    // their line.
    if (!(orient(a, b, c) > 1e-10 * glm::length(b - a) * glm::length(c - b))) return false;
    const dvec2 from = glm::min(a, glm::min(b, c)), to = glm::max(a, glm::max(b, c));
    for (std::size_t y = cellOf(from, 1); y <= cellOf(to, 1); ++y)
      for (std::size_t x = cellOf(from, 0); x <= cellOf(to, 0); ++x)
        for (std::size_t j : cells[y * side + x]) {
          if (!alive[j] || j == prev[i] || j == i || j == next[i]) continue;
          const dvec2& q = polygon[j].p;
          if (q == a || q == b || q == c) continue;
          if (orient(a, b, q) >= 0.0 && orient(b, c, q) >= 0.0 && orient(c, a, q) >= 0.0)
            return false;
        }
    return true;
  };
  // (squared length of the new edge, corner, the corner's stamp then)
  using Entry = std::tuple<double, std::size_t, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> ears;
  std::vector<std::uint32_t> stamp(n, 0);
  auto consider = [&](std::size_t i) {
    ++stamp[i];
    if (isEar(i)) {
      const dvec2 d = polygon[next[i]].p - polygon[prev[i]].p;
      ears.emplace(glm::dot(d, d), i, stamp[i]);
    }
  };
  for (std::size_t i = 0; i < n; ++i) consider(i);
  std::size_t remaining = n, last = 0;
  while (remaining > 3) {
    std::size_t i = n;
    while (!ears.empty() && i == n) {
      const auto [length, corner, when] = ears.top();
      ears.pop();
      if (alive[corner] && when == stamp[corner]) i = corner;
    }
    if (i == n) {
      // No ear (rounding, or a degenerate polygon): cut the corner that
      // turns left the most, so the cap stays closed.
      double most = -std::numeric_limits<double>::infinity();
      std::size_t j = last;
      for (std::size_t k = 0; k < remaining; ++k, j = next[j]) {
        const double o = orient(polygon[prev[j]].p, polygon[j].p, polygon[next[j]].p);
        if (o > most) most = o, i = j;
      }
    }
    triangle(polygon[prev[i]].id, polygon[i].id, polygon[next[i]].id);
    alive[i] = false;
    next[prev[i]] = next[i];
    prev[next[i]] = prev[i];
    last = prev[i];
    --remaining;
    consider(prev[i]);
    consider(next[i]);
  }
  triangle(polygon[prev[last]].id, polygon[last].id, polygon[next[last]].id);
}

}  // namespace

double signedArea2(const std::vector<dvec2>& loop) {
  double a = 0.0;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
    a += cross(loop[j], loop[i]);
  return a;
}

SweepLoops sweepLoops(const Region& region, double tolerance, const char* kind,
                      std::span<const CircleRim> rims, double rimTolerance, bool* pinched) {
  // Evaluated exactly (circles stay circles through the booleans), then
  // flattened: loops that neither cross nor share an edge, outer ones
  // counter-clockwise, holes clockwise.
  const Profile evaluated = evaluate(region, tolerance);
  // A boolean that leaves nothing (a disc less a larger one) sweeps into
  // nothing: a cutter of nothing cuts nothing, as the render shows.
  if (evaluated.loops.empty()) return {};
  if (pinched) *pinched = touchesItself(evaluated);
  auto loopsOf = [&](std::span<const CircleRim> on) {
    SweepLoops loops;
    for (std::vector<dvec2>& loop : flatten(evaluated, tolerance, on, rimTolerance))
      if (loop.size() >= 3 && signedArea2(loop) != 0.0) loops.push_back(std::move(loop));
    return loops;
  };
  SweepLoops loops = loopsOf(rims);
  // A cylinder's rim polygon lies partly outside its circle: where the
  // region comes within that of itself (a hole tangent to the outline, two
  // holes that overlap, each with its pin), the loops cross. They are
  // filled as they wind (positiveFill): a hole's polygon that reaches past
  // the outline opens it there, by less than the tolerance, and the hole
  // stays the polygon of the pin in it, which fills it without crevices.
  // Where that still meets itself (two circles tangent in a heart's cusp),
  // the inscribed polygons are taken.
  if (!rims.empty() && loopsMeet(loops)) {
    std::vector<std::array<dvec2, 2>> segments;
    for (const auto& loop : loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        segments.push_back({loop[i], loop[(i + 1) % loop.size()]});
    SweepLoops filled;
    for (std::vector<dvec2>& loop : flatten(positiveFill(segments), tolerance))
      if (loop.size() >= 3 && signedArea2(loop) != 0.0) filled.push_back(std::move(loop));
    loops = !filled.empty() && !loopsMeet(filled) ? std::move(filled) : loopsOf({});
  }
  if (loops.empty())
    throw std::invalid_argument(std::string(kind) + ": the region has no area to export");
  return loops;
}

void triangulateLoops(
    const SweepLoops& loops, const std::vector<std::vector<std::uint32_t>>& ids,
    const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& triangle) {
  std::vector<std::size_t> outers, holes;
  for (std::size_t i = 0; i < loops.size(); ++i)
    (signedArea2(loops[i]) > 0.0 ? outers : holes).push_back(i);
  // Each hole belongs to the smallest outer loop around it.
  std::vector<std::vector<std::size_t>> holesOf(loops.size());
  for (std::size_t h : holes) {
    std::size_t owner = loops.size();
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t o : outers) {
      const double area = signedArea2(loops[o]);
      if (area < smallest && pointInLoop(loops[o], loops[h][0])) smallest = area, owner = o;
    }
    if (owner < loops.size()) holesOf[owner].push_back(h);
  }
  auto corners = [&](std::size_t loop) {
    std::vector<Corner> c;
    for (std::size_t k = 0; k < loops[loop].size(); ++k)
      c.push_back({loops[loop][k], ids[loop][k]});
    return c;
  };
  for (std::size_t o : outers) {
    std::vector<Corner> polygon = corners(o);
    std::vector<std::size_t>& mine = holesOf[o];
    auto rightmost = [&](std::size_t h) {
      double x = -std::numeric_limits<double>::infinity();
      for (const dvec2& p : loops[h]) x = std::max(x, p.x);
      return x;
    };
    std::sort(mine.begin(), mine.end(),
              [&](std::size_t a, std::size_t b) { return rightmost(a) > rightmost(b); });
    for (std::size_t h : mine) bridge(polygon, corners(h));
    earClip(polygon, triangle);
  }
}

void addSweepFaces(TriangleMesh& mesh, const SweepLoops& loops, const SweepLevels& levels,
                   bool closed, bool reversed,
                   const std::function<bool(int, std::size_t, std::size_t)>& otherDiagonal) {
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || c == a) return;
    mesh.triangles.push_back(reversed ? TriangleMesh::Triangle{a, c, b}
                                      : TriangleMesh::Triangle{a, b, c});
  };
  const int count = int(levels.size());
  const int sides = closed ? count : count - 1;
  // The quad a b c d (a = (i, k), b = (i + 1, k), c = (i + 1, k + 1),
  // d = (i, k + 1)) runs counter-clockwise seen from outside.
  // A caller may stop an export within a large sweep (a twisted one of a
  // million triangles took 0.3 s here): its flag is read at each level.
  const std::atomic<bool>* cancel = cancelFlag();
  for (int k = 0; k < sides; ++k) {
    stopIfCancelled(cancel);
    const int next = (k + 1) % count;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const std::size_t n = loops[l].size();
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const std::uint32_t a = levels[k][l][i], b = levels[k][l][j];
        const std::uint32_t c = levels[next][l][j], d = levels[next][l][i];
        if (otherDiagonal && otherDiagonal(k, l, i)) {
          add(a, b, d);
          add(b, c, d);
        } else {
          add(a, b, c);
          add(a, c, d);
        }
      }
    }
  }
  if (closed) return;
  // The ends: counter-clockwise seen from the last level's side there,
  // reversed at the first.
  triangulateLoops(loops, levels.front(),
                   [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { add(a, c, b); });
  triangulateLoops(loops, levels.back(),
                   [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { add(a, b, c); });
}

namespace {

// In a full turn, an edge of a loop from a point on the axis to one off it
// at the same height sweeps a flat disc, which the sides would make a fan
// about the axis point. Two such discs in one plane (a hub turned on a
// disc) then put every triangle of one against every triangle of the
// other at that point, and CGAL's corefinement of them took 20 s for
// 1 152 triangles; a cylinder's caps are strips for the same reason
// (cylinder_tessellation.cpp). So each such disc is cut as the polygon of
// its rim instead (a zig-zag strip: triangulatePolygon), facing as the
// fan faced, and the fan and its axis point are dropped.
void discsAsStrips(TriangleMesh& mesh, const SweepLoops& loops, const SweepLevels& levels) {
  std::vector<bool> pole(mesh.points.size(), false);
  std::vector<std::vector<std::uint32_t>> rims;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::size_t n = loops[l].size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const dvec2 &u = loops[l][i], &v = loops[l][j];
      if (u.y != v.y || (u.x == 0.0) == (v.x == 0.0)) continue;
      const std::size_t onAxis = u.x == 0.0 ? i : j, onRim = u.x == 0.0 ? j : i;
      pole[levels[0][l][onAxis]] = true;
      std::vector<std::uint32_t>& rim = rims.emplace_back();
      for (const auto& level : levels) rim.push_back(level[l][onRim]);
    }
  }
  if (rims.empty()) return;
  // The fans' sense: a disc's triangles face +z or −z together.
  std::vector<double> facing(mesh.points.size(), 0.0);
  std::vector<TriangleMesh::Triangle> kept;
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    const int at = pole[t[0]] ? 0 : pole[t[1]] ? 1 : pole[t[2]] ? 2 : -1;
    if (at < 0) {
      kept.push_back(t);
      continue;
    }
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    facing[t[at]] += (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  }
  mesh.triangles = std::move(kept);
  for (std::size_t r = 0; r < rims.size(); ++r) {
    std::vector<std::uint32_t>& rim = rims[r];
    // The rim's pole: the axis point at its height.
    const double z = mesh.points[rim.front()].z;
    double sense = 0.0;
    for (std::size_t p = 0; p < pole.size(); ++p)
      if (pole[p] && mesh.points[p].z == z) sense += facing[p];
    // The rim runs counter-clockwise seen from +z (the turn's sense).
    if (sense < 0.0) std::reverse(rim.begin(), rim.end());
    triangulatePolygon(mesh.points, rim, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      mesh.triangles.push_back({a, b, c});
    });
  }
  // The axis points no triangle uses now.
  std::vector<std::uint32_t> renumbered(mesh.points.size());
  std::vector<dvec3> points;
  std::vector<bool> used(mesh.points.size(), false);
  for (const TriangleMesh::Triangle& t : mesh.triangles)
    for (std::uint32_t v : t) used[v] = true;
  for (std::size_t p = 0; p < mesh.points.size(); ++p) {
    renumbered[p] = std::uint32_t(points.size());
    if (used[p]) points.push_back(mesh.points[p]);
  }
  for (TriangleMesh::Triangle& t : mesh.triangles)
    for (std::uint32_t& v : t) v = renumbered[v];
  mesh.points = std::move(points);
}

}  // namespace

TriangleMesh revolvedLoops(const SweepLoops& loops, double angleDegrees, int steps, bool fullTurn) {
  const int rings = fullTurn ? steps : steps + 1;
  TriangleMesh mesh;
  SweepLevels levels(rings, SweepLevels::value_type(loops.size()));
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const dvec2& u : loops[l]) {
      // A point on the axis is one vertex for every step.
      if (u.x == 0.0) mesh.points.emplace_back(0.0, 0.0, u.y);
      for (int k = 0; k < rings; ++k) {
        // Exact at multiples of 90°: a half turn's end face lies in the
        // plane y = 0, flush with a face there.
        const dvec2 at = u.x * unitCircleDegrees(angleDegrees * k / steps);
        if (u.x != 0.0) mesh.points.emplace_back(at.x, at.y, u.y);
        levels[k][l].push_back(std::uint32_t(mesh.points.size() - 1));
      }
    }
  addSweepFaces(mesh, loops, levels, fullTurn, true);
  if (fullTurn) discsAsStrips(mesh, loops, levels);
  return mesh;
}

}  // namespace csgray::detail
