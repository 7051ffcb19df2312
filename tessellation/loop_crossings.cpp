#include "tessellation/loop_crossings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <limits>
#include <utility>

namespace csgray::detail {

namespace {

double orient(const dvec2& a, const dvec2& b, const dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Do the closed segments ab and cd meet? The orientations' signs decide a
// crossing; a zero sign (an end on the other's line) is then settled by
// the boxes, which also settles collinear segments (Cormen et al.,
// "Introduction to Algorithms", 33.1).
bool segmentsMeet(const dvec2& a, const dvec2& b, const dvec2& c, const dvec2& d) {
  auto within = [](const dvec2& p, const dvec2& q, const dvec2& r) {  // r in pq's box
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  const double o1 = orient(c, d, a), o2 = orient(c, d, b);
  const double o3 = orient(a, b, c), o4 = orient(a, b, d);
  if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) &&
      ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)))
    return true;
  return (o1 == 0.0 && within(c, d, a)) || (o2 == 0.0 && within(c, d, b)) ||
         (o3 == 0.0 && within(a, b, c)) || (o4 == 0.0 && within(a, b, d));
}

}  // namespace

bool loopsMeet(const std::vector<std::vector<dvec2>>& loops) {
  struct Edge {
    dvec2 a, b;
    std::uint32_t loop, index, size;
  };
  std::vector<Edge> edges;
  dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& loop = loops[l];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      edges.push_back({loop[i], loop[(i + 1) % loop.size()], std::uint32_t(l), std::uint32_t(i),
                       std::uint32_t(loop.size())});
      lo = glm::min(lo, loop[i]);
      hi = glm::max(hi, loop[i]);
    }
  }
  if (edges.size() < 3) return false;
  // About as many cells as edges, on a square grid over the loops' box.
  const dvec2 extent = glm::max(hi - lo, dvec2(1e-300));
  const double cell = std::sqrt(extent.x * extent.y / double(edges.size()));
  const int columns = std::clamp(int(extent.x / cell) + 1, 1, 4096);
  const int rows = std::clamp(int(extent.y / cell) + 1, 1, 4096);
  auto column = [&](double x) {
    return std::clamp(int((x - lo.x) / extent.x * columns), 0, columns - 1);
  };
  auto row = [&](double y) { return std::clamp(int((y - lo.y) / extent.y * rows), 0, rows - 1); };
  // (cell, edge) pairs, sorted by cell: each edge in every cell its box
  // covers.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;
  // Loops of a few long edges among many short ones, in a box of extreme
  // shape, could put each long edge in thousands of cells: past this many
  // entries the loops are said to meet, which costs the caller only the
  // polygons it would otherwise have taken.
  const std::size_t most = 64 * edges.size() + 4096;
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    const Edge& edge = edges[e];
    const int c0 = column(std::min(edge.a.x, edge.b.x)), c1 = column(std::max(edge.a.x, edge.b.x));
    const int r0 = row(std::min(edge.a.y, edge.b.y)), r1 = row(std::max(edge.a.y, edge.b.y));
    if (entries.size() + std::size_t(r1 - r0 + 1) * std::size_t(c1 - c0 + 1) > most) return true;
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) entries.emplace_back(std::uint32_t(r * columns + c), e);
  }
  std::sort(entries.begin(), entries.end());
  // Consecutive edges of one loop share a point, which is no meeting.
  auto adjacent = [](const Edge& p, const Edge& q) {
    if (p.loop != q.loop) return false;
    return (p.index + 1) % p.size == q.index || (q.index + 1) % q.size == p.index;
  };
  for (std::size_t begin = 0; begin < entries.size();) {
    std::size_t end = begin;
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j) {
        const Edge &p = edges[entries[i].second], &q = edges[entries[j].second];
        if (adjacent(p, q)) {
          // They share one point; they meet elsewhere only if they fold
          // back along one line.
          const bool pFirst = (p.index + 1) % p.size == q.index;
          const Edge &in = pFirst ? p : q, &out = pFirst ? q : p;
          const dvec2 u = in.a - in.b, v = out.b - out.a;
          if (u.x * v.y - u.y * v.x == 0.0 && u.x * v.x + u.y * v.y > 0.0) return true;
          continue;
        }
        if (segmentsMeet(p.a, p.b, q.a, q.b)) return true;
      }
    begin = end;
  }
  return false;
}

}  // namespace csgray::detail
