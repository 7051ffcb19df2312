// SweptRegion's templates (included by profile_sweep.h): the edge index's
// query and the spans of a path, leaf by leaf and merged by the tree.
#pragma once

#include <algorithm>
#include <cmath>

namespace csgray::detail {

namespace sweep_detail {

// Does the segment a–b meet the box lo–hi (closed)? The slab test in 2D.
inline bool segmentMeetsBox(const dvec2& a, const dvec2& b, const dvec2& lo, const dvec2& hi) {
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    const double d = b[axis] - a[axis];
    if (d == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
      continue;
    }
    double near = (lo[axis] - a[axis]) / d, far = (hi[axis] - a[axis]) / d;
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return false;
  }
  return true;
}

inline bool boxesMeet(const dvec2& alo, const dvec2& ahi, const dvec2& blo, const dvec2& bhi) {
  return alo.x <= bhi.x && blo.x <= ahi.x && alo.y <= bhi.y && blo.y <= ahi.y;
}

// Crossings of one leaf, kept between rays so that a ray allocates nothing
// once the buffer has grown (one buffer per thread; the leaves of a tree are
// done one after the other).
std::vector<SweepCrossing>& crossingBuffer();

}  // namespace sweep_detail

template <class F>
void SweptRegion::forEachEdgeNear(const Leaf& leaf, const dvec2& lo, const dvec2& hi, bool straight,
                                  const dvec2& a, const dvec2& b, F&& f) const {
  if (leaf.nodes.empty()) return;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = leaf.nodes[stack[--top]];
    if (!sweep_detail::boxesMeet(node.lo, node.hi, lo, hi)) continue;
    if (straight && !sweep_detail::segmentMeetsBox(a, b, node.lo, node.hi)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.start; i < node.start + node.count; ++i) f(leaf.items[i]);
    } else {
      stack[top++] = node.start;
      stack[top++] = node.start + 1;
    }
  }
}

template <class Path>
void SweptRegion::spans(const Primitive* owner, const Path& path, double t0, double t1,
                        std::uint32_t face0, std::uint32_t face1, const SweepPiece* pieces,
                        int pieceCount, SpanList& out) const {
  out.clear();
  if (!(t0 < t1)) return;
  treeSpans(owner, 0, path, t0, t1, face0, face1, pieces, pieceCount, out);
  bool flipped = false;
  for (const Span& s : out) flipped = flipped || s.in.flip || s.out.flip;
  if (!flipped) return;
  // A hole's boundaries, flipped by the difference, become reversed faces.
  SpanList unflipped;
  for (Span s : out) {
    for (Boundary* b : {&s.in, &s.out})
      if (b->flip) {
        b->flip = false;
        // (A cap is a cap whichever leaf it came from.)
        if ((b->face & ~kSweepReversedFace) >= kSweepFirstEdgeFace) b->face ^= kSweepReversedFace;
      }
    unflipped.push_back(s);
  }
  out = unflipped;
}

template <class Path>
void SweptRegion::treeSpans(const Primitive* owner, std::uint32_t index, const Path& path,
                            double t0, double t1, std::uint32_t face0, std::uint32_t face1,
                            const SweepPiece* pieces, int pieceCount, SpanList& out) const {
  out.clear();
  const TreeNode& node = tree_[index];
  if (node.op != Region::Op::Leaf) {
    SpanList operand, merged;
    bool first = true;
    for (std::uint32_t child : node.operands) {
      if (first) {
        treeSpans(owner, child, path, t0, t1, face0, face1, pieces, pieceCount, out);
        first = false;
        if (out.empty() && node.op != Region::Op::Union) return;
        continue;
      }
      treeSpans(owner, child, path, t0, t1, face0, face1, pieces, pieceCount, operand);
      if (node.op == Region::Op::Union) {
        if (operand.empty()) continue;
        unite(out, operand, merged);
      } else if (node.op == Region::Op::Intersection) {
        intersect(out, operand, merged);
      } else {
        if (operand.empty()) continue;
        subtract(out, operand, merged);
      }
      out = merged;
      if (out.empty() && node.op != Region::Op::Union) return;
    }
    return;
  }

  // A leaf: the crossings of the curve with its edges, from the edges near
  // each piece of the curve.
  const Leaf& leaf = leaves_[node.leaf];
  const double pad = 1e-9 * size_;
  bool touched = false;
  std::vector<SweepCrossing>& crossings = sweep_detail::crossingBuffer();
  crossings.clear();
  for (int k = 0; k < pieceCount; ++k) {
    const SweepPiece& piece = pieces[k];
    const dvec2 lo = piece.lo - dvec2(pad), hi = piece.hi + dvec2(pad);
    if (!sweep_detail::boxesMeet(lo, hi, leaf.box.lo, leaf.box.hi)) continue;
    touched = true;
    forEachEdgeNear(leaf, lo, hi, piece.straight, piece.from, piece.to, [&](std::uint32_t e) {
      const SweepEdge& edge = edges_[e];
      double roots[8];
      const int n = path.roots(edge, piece.t0, piece.t1, roots);
      for (int i = 0; i < n; ++i) {
        const dvec2 u = path.at(roots[i]);
        // Roots of a squared equation that are not the edge's own.
        if (!(edge.distance(u) <= kAcceptDistance * size_)) continue;
        bool clean = false;
        if (!edge.holds(u, kEdgeSlack, clean)) continue;
        crossings.push_back({roots[i], kSweepFirstEdgeFace + e, clean});
      }
    });
  }
  if (!touched) return;
  std::sort(crossings.begin(), crossings.end(),
            [](const SweepCrossing& a, const SweepCrossing& b) { return a.t < b.t; });
  // Crossings this close are a tangency, a vertex met through both its
  // edges, or a crossing found twice: the state after them is asked of the
  // leaf rather than counted.
  const double close = 1e-9 * (t1 - t0);
  const std::size_t n = crossings.size();
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (crossings[i + 1].t - crossings[i].t <= close) {
      crossings[i].clean = false;
      crossings[i + 1].clean = false;
    }

  // The stretches between crossings: each inside or out. A clean crossing
  // toggles the state of a stretch the leaf was asked about (or one that
  // was toggled from such); otherwise the leaf is asked at the stretch's
  // middle.
  const double reliableLength = 1e-7 * (t1 - t0);
  bool inside = false, reliable = false, previousClean = false;
  double a = t0;
  std::uint32_t faceA = face0;
  // The span being grown: stretches inside with only crossings that
  // changed nothing between them are one span.
  Span pending{};
  bool open = false;
  for (std::size_t i = 0; i <= n; ++i) {
    const double b = i < n ? crossings[i].t : t1;
    const std::uint32_t faceB = i < n ? crossings[i].face : face1;
    if (reliable && previousClean) {
      inside = !inside;
    } else {
      inside = leafContains(node.leaf, path.at(0.5 * (a + b)));
      reliable = b - a > reliableLength;
    }
    if (inside && b > a) {
      if (!open) pending.in = Boundary{a, owner, faceA, false};
      pending.out = Boundary{b, owner, faceB, false};
      open = true;
    } else if (!inside && b > a && open) {
      out.push_back(pending);
      open = false;
    }
    previousClean = i < n && crossings[i].clean;
    a = b;
    faceA = faceB;
  }
  if (open) out.push_back(pending);
}

}  // namespace csgray::detail
