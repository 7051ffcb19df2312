#include "primitives/profile_sweep.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/solvers/quartic.h"

namespace csgray::detail {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr std::uint32_t kLeafEdges = 4;

// Is p between the arc and its chord? (Profile::contains's rule.)
bool inArcCap(const dvec2& p, const SweepEdge& e) {
  return inUnitArcCap(e.toUnit * (p - e.center), e.lo, e.hi);
}

ProfileBounds edgeBox(const ProfileEdge& e) {
  Profile one;
  one.loops.push_back(ProfileLoop{{e}});
  return one.bounds();
}

// The region with its Bézier curves replaced by polygons within tolerance.
RegionPtr curvesFlattened(const RegionPtr& region, double tolerance) {
  if (region->op() != Region::Op::Leaf) {
    std::vector<RegionPtr> operands;
    for (const RegionPtr& r : region->operands()) operands.push_back(curvesFlattened(r, tolerance));
    return Region::boolean(region->op(), std::move(operands));
  }
  for (const ProfileLoop& loop : region->profile().loops)
    for (const ProfileEdge& e : loop.edges)
      if (e.bezier()) return Region::leaf(bezierEdgesFlattened(region->profile(), tolerance));
  return region;
}

// The edge's middle point.
dvec2 middleOf(const SweepEdge& e) {
  if (e.bezier) return bezierPoint(e.source, 0.5);
  if (!e.arc) return 0.5 * (e.from + e.to);
  const double theta = 0.5 * (e.lo + e.hi);
  return e.center + glm::inverse(e.toUnit) * dvec2(std::cos(theta), std::sin(theta));
}

}  // namespace

namespace sweep_detail {
std::vector<SweepCrossing>& crossingBuffer() {
  thread_local std::vector<SweepCrossing> buffer;
  return buffer;
}
}  // namespace sweep_detail

// ---- SweepEdge -----------------------------------------------------------------

dvec2 SweepEdge::curveNormal(const dvec2& u) const {
  const double s = nearestBezierParameter(curve, u);
  dvec2 tangent = curve.slope(s);
  // At a cusp (or an end whose control point sits on it) the tangent
  // vanishes: the chord of a short stretch about s has its direction.
  if (!(glm::length(tangent) > 1e-12 * size))
    tangent =
        bezierPoint(source, std::min(1.0, s + 1e-6)) - bezierPoint(source, std::max(0.0, s - 1e-6));
  const double length = glm::length(tangent);
  return length > 0.0 ? dvec2(tangent.y, -tangent.x) / length : dvec2(0.0);
}

double SweepEdge::implicit(const dvec2& u) const {
  if (bezier) return glm::dot(curveNormal(u), u - curve.at(nearestBezierParameter(curve, u)));
  if (!arc) return glm::dot(normal, u) - offset;
  const dvec2 w = toUnit * (u - center);
  return glm::dot(w, w) - 1.0;
}

dvec2 SweepEdge::outwardGradient(const dvec2& u) const {
  if (bezier) return outward * curveNormal(u);
  if (!arc) return outward * normal;
  return outward * (glm::transpose(toUnit) * (toUnit * (u - center)));
}

bool SweepEdge::arcHolds(const dvec2& u, double slack, bool& clean) const {
  if (fullTurn) {
    clean = true;
    return true;
  }
  const dvec2 w = toUnit * (u - center);
  const double theta = std::atan2(w.y, w.x);
  // theta moved into [lo, lo + 2π).
  double x = lo + std::fmod(std::fmod(theta - lo, kTwoPi) + kTwoPi, kTwoPi);
  if (x >= lo + kTwoPi) x -= kTwoPi;
  clean = x > lo + slack && x < hi - slack;
  return x <= hi + slack || x >= lo + kTwoPi - slack;
}

double SweepEdge::arcDistance(const dvec2& u) const {
  const dvec2 w = toUnit * (u - center);
  return std::abs(glm::length(w) - 1.0) * size;
}

// ---- SweptRegion ------------------------------------------------------------------

SweptRegion::SweptRegion(RegionPtr region, const char* kind, bool exactCurves)
    : region_(std::move(region)) {
  if (!region_) throw std::invalid_argument(std::string(kind) + ": needs a region");
  const ProfileBounds& b = region_->bounds();
  if (b.empty())
    throw std::invalid_argument(std::string(kind) + ": the region is empty (it has no edges)");
  if (!std::isfinite(b.lo.x) || !std::isfinite(b.lo.y) || !std::isfinite(b.hi.x) ||
      !std::isfinite(b.hi.y))
    throw std::invalid_argument(std::string(kind) + ": the region's coordinates must be finite");
  size_ = std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, std::abs(b.lo.x), std::abs(b.hi.x),
                    std::abs(b.lo.y), std::abs(b.hi.y), 1e-300});
  pad_ = 1e-9 * size_;
  if (!exactCurves) region_ = curvesFlattened(region_, kCurveTolerance * size_);
  std::uint32_t nextLeaf = 0;
  addTree(*region_, nextLeaf);
  // The orientation of each edge: which side of it is the leaf's inside.
  for (SweepEdge& e : edges_) {
    const dvec2 m = middleOf(e);
    dvec2 g = e.arc      ? glm::transpose(e.toUnit) * (e.toUnit * (m - e.center))
              : e.bezier ? e.curveNormal(m)
                         : e.normal;
    const double length = glm::length(g);
    if (!(length > 0.0)) continue;
    g /= length;
    const double step = std::min(1e-7 * size_, 1e-3 * e.size);
    const bool before = leafContains(e.leaf, m - step * g);
    const bool after = leafContains(e.leaf, m + step * g);
    e.outward = before || !after ? 1.0 : -1.0;
  }
}

std::uint32_t SweptRegion::addTree(const Region& region, std::uint32_t& nextLeaf) {
  const std::uint32_t index = std::uint32_t(tree_.size());
  tree_.push_back(TreeNode{region.op(), 0, {}});
  if (region.op() != Region::Op::Leaf) {
    std::vector<std::uint32_t> operands;
    for (const RegionPtr& r : region.operands()) operands.push_back(addTree(*r, nextLeaf));
    tree_[index].operands = std::move(operands);
    return index;
  }
  const std::uint32_t leafIndex = nextLeaf++;
  tree_[index].leaf = leafIndex;
  std::vector<std::uint32_t> mine;
  for (const ProfileLoop& loop : region.profile().loops)
    for (const ProfileEdge& pe : loop.edges) {
      SweepEdge e;
      e.leaf = leafIndex;
      e.from = pe.from;
      e.to = pe.to;
      e.box = edgeBox(pe);
      if (pe.bezier()) {
        e.size = glm::length(e.box.hi - e.box.lo);
        if (!(e.size > 0.0)) continue;  // a point
        e.curve = bezierPolynomial(pe);
        e.bezier = e.curve.degree;
        e.source = pe;
      } else if (pe.kind == ProfileEdge::Kind::Segment) {
        const dvec2 d = pe.to - pe.from;
        const double length = glm::length(d);
        if (!(length > 0.0)) continue;  // a point: crosses nothing
        e.normal = dvec2(d.y, -d.x) / length;
        e.offset = glm::dot(e.normal, pe.from);
        e.size = length;
      } else {
        if (!(std::abs(glm::determinant(pe.axes)) > 0.0)) continue;  // a flat ellipse
        e.arc = true;
        e.center = pe.center;
        e.toUnit = glm::inverse(pe.axes);
        e.lo = std::min(pe.angle0, pe.angle1);
        e.hi = std::max(pe.angle0, pe.angle1);
        e.fullTurn = e.hi - e.lo >= kTwoPi;
        e.size = std::max(glm::length(pe.axes[0]), glm::length(pe.axes[1]));
      }
      mine.push_back(std::uint32_t(edges_.size()));
      edges_.push_back(e);
    }
  if (leaves_.size() <= leafIndex) leaves_.resize(leafIndex + 1);
  Leaf& leaf = leaves_[leafIndex];
  leaf.box = region.profile().bounds();
  buildIndex(leaf, std::move(mine));
  buildCells(leaf);
  return index;
}

void SweptRegion::buildIndex(Leaf& leaf, std::vector<std::uint32_t> edges) {
  if (edges.empty()) return;
  leaf.nodes.reserve(2 * edges.size() / kLeafEdges + 2);
  leaf.nodes.push_back({});
  const std::uint32_t root = 0;
  // Built in place: buildNode fills node `root` and appends the others.
  std::vector<std::uint32_t> order = std::move(edges);
  leaf.items.clear();
  struct Task {
    std::uint32_t node, begin, end;
  };
  std::vector<Task> tasks{{root, 0, std::uint32_t(order.size())}};
  while (!tasks.empty()) {
    Task task = tasks.back();
    tasks.pop_back();
    Node node{};
    node.lo = dvec2(1e300);
    node.hi = dvec2(-1e300);
    dvec2 clo(1e300), chi(-1e300);
    for (std::uint32_t i = task.begin; i < task.end; ++i) {
      const ProfileBounds& b = edges_[order[i]].box;
      node.lo = glm::min(node.lo, b.lo - dvec2(pad_));
      node.hi = glm::max(node.hi, b.hi + dvec2(pad_));
      const dvec2 c = 0.5 * (b.lo + b.hi);
      clo = glm::min(clo, c);
      chi = glm::max(chi, c);
    }
    if (task.end - task.begin <= kLeafEdges) {
      node.start = std::uint32_t(leaf.items.size());
      node.count = task.end - task.begin;
      for (std::uint32_t i = task.begin; i < task.end; ++i) {
        const ProfileBounds& b = edges_[order[i]].box;
        leaf.items.push_back({b.lo - dvec2(pad_), b.hi + dvec2(pad_), order[i]});
      }
      leaf.nodes[task.node] = node;
      continue;
    }
    // Split at the median of the centres along the longer side.
    const int axis = chi.x - clo.x >= chi.y - clo.y ? 0 : 1;
    const std::uint32_t mid = task.begin + (task.end - task.begin) / 2;
    std::nth_element(order.begin() + task.begin, order.begin() + mid, order.begin() + task.end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       const ProfileBounds& x = edges_[a].box;
                       const ProfileBounds& y = edges_[b].box;
                       return x.lo[axis] + x.hi[axis] < y.lo[axis] + y.hi[axis];
                     });
    node.start = std::uint32_t(leaf.nodes.size());
    node.count = 0;
    leaf.nodes[task.node] = node;
    leaf.nodes.push_back({});
    leaf.nodes.push_back({});
    tasks.push_back({node.start, task.begin, mid});
    tasks.push_back({node.start + 1, mid, task.end});
  }
}

void SweptRegion::buildCells(Leaf& leaf) const {
  // Square cells, about 256 an edge, at least 2¹² and at most 2¹⁶ in all:
  // an edge then passes through a few cells each, and most of the box's
  // area is in cells no edge passes through.
  const double width = leaf.box.hi.x - leaf.box.lo.x, height = leaf.box.hi.y - leaf.box.lo.y;
  if (leaf.items.empty() || !(width > 0.0) || !(height > 0.0)) return;
  const double cellCount = std::clamp(256.0 * double(leaf.items.size()), 4096.0, 65536.0);
  const double side = std::sqrt(width * height / cellCount);
  leaf.cellsPerUnit = 1.0 / side;
  leaf.columns = int(std::clamp(std::ceil(width / side), 1.0, 1024.0));
  leaf.rows = int(std::clamp(std::ceil(height / side), 1.0, 1024.0));
  const auto at = [&](int column, int row) { return std::size_t(row) * leaf.columns + column; };
  // A cell is the set of points that cellColumn and cellRow send to it.
  // Both are monotonic, so a box meets no cells but those between the
  // cells of its corners. Each edge is marked as pieces no longer than a
  // cell, each in the box of its ends grown by how far the curve may stray
  // from the chord between them, and by pad_ (more than the rounding of
  // the ends): a slanted edge marks the cells along it, not all those in
  // its box. The cells marked are all those an edge may pass through, and a
  // cell left free holds no point of any edge.
  std::vector<bool> crossed(std::size_t(leaf.columns) * leaf.rows, false);
  const auto markBox = [&](const dvec2& lo, const dvec2& hi) {
    for (int row = leaf.cellRow(lo.y); row <= leaf.cellRow(hi.y); ++row)
      for (int column = leaf.cellColumn(lo.x); column <= leaf.cellColumn(hi.x); ++column)
        crossed[at(column, row)] = true;
  };
  // Pieces of a curve p(θ), θ from a to b, each no longer than about a
  // cell; bulge: how far the curve may stray from a piece's chord.
  const auto markPieces = [&](auto&& point, double a, double b, double length, double curvature) {
    const int pieces = int(std::clamp(std::ceil(length / side), 1.0, 4096.0));
    const double step = (b - a) / pieces;
    // Linear interpolation's error: at most |p''| · step² / 8.
    const double bulge = curvature * step * step / 8.0 + pad_;
    dvec2 p = point(a);
    for (int k = 1; k <= pieces; ++k) {
      const dvec2 q = point(k == pieces ? b : a + k * step);
      markBox(glm::min(p, q) - dvec2(bulge), glm::max(p, q) + dvec2(bulge));
      p = q;
    }
  };
  for (const Item& item : leaf.items) {
    const SweepEdge& e = edges_[item.edge];
    if (e.bezier) {
      // The control polygon is no shorter than the curve, and |B''| is at
      // most n (n − 1) times the largest second difference of the control
      // points.
      const ProfileEdge& c = e.source;
      const bool cubic = c.kind == ProfileEdge::Kind::Cubic;
      const dvec2 last = cubic ? c.control2 : c.control1;
      const double polygon = glm::length(c.control1 - c.from) + glm::length(last - c.control1) +
                             (cubic ? glm::length(c.to - last) : glm::length(c.to - c.control1));
      const double curvature =
          cubic ? 6.0 * std::max(glm::length(c.from - 2.0 * c.control1 + c.control2),
                                 glm::length(c.control1 - 2.0 * c.control2 + c.to))
                : 2.0 * glm::length(c.from - 2.0 * c.control1 + c.to);
      markPieces([&](double t) { return bezierPoint(c, t); }, 0.0, 1.0, polygon, curvature);
      continue;
    }
    // A segment, or an arc's chord (the edges' test counts crossings of
    // the chord, and toggles between chord and arc).
    const auto onChord = [&](double f) { return e.from + f * (e.to - e.from); };
    markPieces(onChord, 0.0, 1.0, glm::length(e.to - e.from), 0.0);
    if (!e.arc) continue;
    const dmat2 axes = glm::inverse(e.toUnit);
    const auto onArc = [&](double angle) {
      return e.center + axes * dvec2(std::cos(angle), std::sin(angle));
    };
    // |p''| = |axes · (cos, sin)| is at most the axes' largest singular
    // value, itself at most their Frobenius norm (a sheared ellipse's
    // largest semi-axis may be longer than either column).
    const double reach = std::sqrt(glm::dot(axes[0], axes[0]) + glm::dot(axes[1], axes[1]));
    markPieces(onArc, e.lo, e.hi, reach * (e.hi - e.lo), reach);
  }
  leaf.crossedBelow.assign(std::size_t(leaf.rows + 1) * (leaf.columns + 1), 0);
  for (int row = 0; row < leaf.rows; ++row)
    for (int column = 0; column < leaf.columns; ++column) {
      const auto below = [&](int r, int c) -> std::uint32_t& {
        return leaf.crossedBelow[std::size_t(r) * (leaf.columns + 1) + c];
      };
      below(row + 1, column + 1) = below(row, column + 1) + below(row + 1, column) -
                                   below(row, column) + (crossed[at(column, row)] ? 1 : 0);
    }
  // Free cells side by side make one set of points that no edge passes
  // through, in or out as a whole: each connected group of them takes the
  // state at the centre of its first cell, asked of the edges once, and
  // checked at its last cell's (a centre where rounding misled the edges'
  // count, a ray along a curve's tangent, would else mislead the group).
  leaf.cells.assign(crossed.size(), CellState::Crossed);
  std::vector<bool> seen(crossed.size(), false);
  std::vector<std::pair<int, int>> stack, group;
  // A cell's centre, or nothing where rounding would put it in another
  // cell (a box far from the origin for its size).
  const auto centreOf = [&](int column, int row) -> std::optional<dvec2> {
    const dvec2 centre = leaf.box.lo + (dvec2(column, row) + 0.5) * side;
    if (leaf.cellColumn(centre.x) != column || leaf.cellRow(centre.y) != row) return std::nullopt;
    return centre;
  };
  for (int row = 0; row < leaf.rows; ++row)
    for (int column = 0; column < leaf.columns; ++column) {
      if (crossed[at(column, row)] || seen[at(column, row)]) continue;
      stack.assign(1, {column, row});
      group.clear();
      seen[at(column, row)] = true;
      while (!stack.empty()) {
        const auto [c, r] = stack.back();
        stack.pop_back();
        group.push_back({c, r});
        static constexpr int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        for (const auto& step : kSteps) {
          const int nc = c + step[0], nr = r + step[1];
          if (nc < 0 || nr < 0 || nc >= leaf.columns || nr >= leaf.rows) continue;
          if (crossed[at(nc, nr)] || seen[at(nc, nr)]) continue;
          seen[at(nc, nr)] = true;
          stack.push_back({nc, nr});
        }
      }
      const auto first = centreOf(group.front().first, group.front().second);
      const auto last = centreOf(group.back().first, group.back().second);
      if (!first || !last) continue;
      const bool inside = edgesContain(leaf, *first);
      if (group.size() > 1 && edgesContain(leaf, *last) != inside) continue;
      for (const auto& [c, r] : group)
        leaf.cells[at(c, r)] = inside ? CellState::Inside : CellState::Outside;
    }
}

bool SweptRegion::leafContains(std::uint32_t index, const dvec2& u) const {
  const Leaf& leaf = leaves_[index];
  if (u.x < leaf.box.lo.x || u.x > leaf.box.hi.x || u.y < leaf.box.lo.y || u.y > leaf.box.hi.y)
    return false;
  if (!leaf.cells.empty()) {
    const CellState state =
        leaf.cells[std::size_t(leaf.cellRow(u.y)) * leaf.columns + leaf.cellColumn(u.x)];
    if (state != CellState::Crossed) return state == CellState::Inside;
  }
  return edgesContain(leaf, u);
}

bool SweptRegion::edgesContain(const Leaf& leaf, const dvec2& u) const {
  // The ray goes to the nearest side of the leaf's box: along a line of
  // text it would cross every glyph after u, across it only those above
  // or below u. Turned by quarter turns so that it runs in +x (exactly:
  // coordinates swapped and negated), the tests are those of a ray in +x.
  const double reach[4] = {leaf.box.hi.x - u.x, leaf.box.hi.y - u.y, u.x - leaf.box.lo.x,
                           u.y - leaf.box.lo.y};
  const int turn = int(std::min_element(reach, reach + 4) - reach);
  static constexpr double kDirection[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const dvec2 end = u + (reach[turn] + 1.0) * dvec2(kDirection[turn][0], kDirection[turn][1]);
  const auto turned = [turn](const dvec2& p) {
    return turn == 1 ? dvec2(p.y, -p.x) : turn == 2 ? -p : turn == 3 ? dvec2(-p.y, p.x) : p;
  };
  const dvec2 v = turned(u);
  const dvec2 rayLo = glm::min(u, end), rayHi = glm::max(u, end);  // the ray's box
  bool inside = false;
  const auto meets = [&](const dvec2& lo, const dvec2& hi) {
    return sweep_detail::boxesMeet(rayLo, rayHi, lo, hi);
  };
  forEachEdgeNear(leaf, meets, [&](std::uint32_t i) {
    const SweepEdge& e = edges_[i];
    if (e.bezier) {
      if (turn == 0) {  // (the curve as it is, uncopied)
        if (bezierCrossesRight(v, e.source)) inside = !inside;
        return;
      }
      ProfileEdge curve = e.source;
      curve.from = turned(curve.from);
      curve.to = turned(curve.to);
      curve.control1 = turned(curve.control1);
      curve.control2 = turned(curve.control2);
      if (bezierCrossesRight(v, curve)) inside = !inside;
      return;
    }
    if (halfLineCrossesSegment(v, turned(e.from), turned(e.to))) inside = !inside;
    if (e.arc && inArcCap(u, e)) inside = !inside;  // (the same whichever way the ray goes)
  });
  return inside;
}

bool SweptRegion::treeContains(std::uint32_t index, const dvec2& u) const {
  const TreeNode& node = tree_[index];
  switch (node.op) {
    case Region::Op::Leaf:
      return leafContains(node.leaf, u);
    case Region::Op::Union:
      for (std::uint32_t c : node.operands)
        if (treeContains(c, u)) return true;
      return false;
    case Region::Op::Intersection:
      for (std::uint32_t c : node.operands)
        if (!treeContains(c, u)) return false;
      return true;
    case Region::Op::Difference:
      if (!treeContains(node.operands.front(), u)) return false;
      for (std::size_t i = 1; i < node.operands.size(); ++i)
        if (treeContains(node.operands[i], u)) return false;
      return true;
  }
  return false;
}

bool SweptRegion::contains(const dvec2& u) const { return treeContains(0, u); }

// ---- polynomials -----------------------------------------------------------------

SweepPolynomial SweepPolynomial::operator*(const SweepPolynomial& o) const {
  SweepPolynomial p;
  p.n = std::min(4, n + o.n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= o.n && i + j <= 4; ++j) p.c[i + j] += c[i] * o.c[j];
  return p;
}

SweepPolynomial SweepPolynomial::operator+(const SweepPolynomial& o) const {
  SweepPolynomial p;
  p.n = std::max(n, o.n);
  for (int i = 0; i <= 4; ++i) p.c[i] = c[i] + o.c[i];
  return p;
}

SweepPolynomial SweepPolynomial::operator-(const SweepPolynomial& o) const {
  return *this + o * -1.0;
}

SweepPolynomial SweepPolynomial::operator*(double k) const {
  SweepPolynomial p = *this;
  for (double& x : p.c) x *= k;
  return p;
}

}  // namespace csgray::detail
