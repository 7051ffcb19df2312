// SweptRegion's templates (included by profile_sweep.h): the edge index's
// query and the spans of a path, leaf by leaf and merged by the tree.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace csgray::detail {

namespace sweep_detail {

// How far a segment's slab test may misplace it: the rounding of its
// ends' coordinates, a few units in the last place of the larger. A
// scale-0 extrusion's straight image of a ray runs from the region out to
// 10¹² times its size (its window stops just below the apex), and a ray
// through a corner then passed by both edges' boxes there, the corner's
// crossing lost (a ray along the axis of a pyramid's mirror image over
// the line from its centre to a corner found nothing).
inline double segmentSlack(const dvec2& a, const dvec2& b) {
  return 8.0 * std::numeric_limits<double>::epsilon() *
         std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
}

// Does the segment a–b meet the box lo–hi (closed, grown by the segment's
// slack)? The slab test in 2D.
inline bool segmentMeetsBox(const dvec2& a, const dvec2& b, const dvec2& boxLo,
                            const dvec2& boxHi) {
  const dvec2 lo = boxLo - dvec2(segmentSlack(a, b)), hi = boxHi + dvec2(segmentSlack(a, b));
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

// The test of a piece's box, and of its segment when it is straight: the
// meets of paths that know no better.
inline bool sweepPieceMeets(const SweepPiece& piece, const dvec2& lo, const dvec2& hi) {
  if (!sweep_detail::boxesMeet(piece.lo, piece.hi, lo, hi)) return false;
  return !piece.straight || sweep_detail::segmentMeetsBox(piece.from, piece.to, lo, hi);
}

// The slab test of the segment a–b against many boxes, with the reciprocals
// of its direction computed once (a straight curve's walk down the index).
class SweepSegmentTest {
 public:
  SweepSegmentTest() = default;
  SweepSegmentTest(const dvec2& a, const dvec2& b)
      : a_(a), lo_(glm::min(a, b)), hi_(glm::max(a, b)), slack_(sweep_detail::segmentSlack(a, b)) {
    for (int axis = 0; axis < 2; ++axis) {
      const double d = b[axis] - a[axis];
      flat_[axis] = d == 0.0;
      inverse_[axis] = flat_[axis] ? 0.0 : 1.0 / d;
    }
  }
  bool meets(const dvec2& boxLo, const dvec2& boxHi) const {
    const dvec2 lo = boxLo - dvec2(slack_), hi = boxHi + dvec2(slack_);
    if (!sweep_detail::boxesMeet(lo_, hi_, lo, hi)) return false;
    double t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
      if (flat_[axis]) continue;  // inside the box's range: boxesMeet said so
      double near = (lo[axis] - a_[axis]) * inverse_[axis],
             far = (hi[axis] - a_[axis]) * inverse_[axis];
      if (near > far) std::swap(near, far);
      t0 = std::max(t0, near);
      t1 = std::min(t1, far);
    }
    return t0 <= t1;
  }

 private:
  dvec2 a_{0.0}, lo_{0.0}, hi_{0.0}, inverse_{0.0};
  double slack_ = 0.0;  // sweep_detail::segmentSlack
  bool flat_[2] = {true, true};
};

template <class Meets, class F>
void SweptRegion::forEachEdgeNear(const Leaf& leaf, Meets&& meets, F&& f) const {
  if (leaf.nodes.empty()) return;
  // The nodes on the stack have been accepted (the root by the caller);
  // children are tested before they are pushed.
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = leaf.nodes[stack[--top]];
    if (node.count > 0) {
      for (std::uint32_t i = node.start; i < node.start + node.count; ++i) {
        const Item& item = leaf.items[i];
        if (node.count == 1 || meets(item.lo, item.hi)) f(item.edge);
      }
      continue;
    }
    for (std::uint32_t child = node.start; child < node.start + 2; ++child) {
      const Node& c = leaf.nodes[child];
      if (meets(c.lo, c.hi)) stack[top++] = child;
    }
  }
}

template <class MeetsFrom, class F>
void SweptRegion::forEachEdgeInOrder(const Leaf& leaf, MeetsFrom&& meetsFrom, const double& bound,
                                     F&& f) const {
  struct Entry {
    std::uint32_t node;
    double from;
  };
  Entry stack[64];
  int top = 0;
  double from = 0.0;
  if (!meetsFrom(leaf.nodes[0].lo, leaf.nodes[0].hi, from)) return;
  stack[top++] = {0, from};
  while (top > 0) {
    const Entry entry = stack[--top];
    if (entry.from > bound) continue;
    const Node& node = leaf.nodes[entry.node];
    if (node.count > 0) {
      for (std::uint32_t i = node.start; i < node.start + node.count; ++i) {
        const Item& item = leaf.items[i];
        if (node.count == 1 || (meetsFrom(item.lo, item.hi, from) && from <= bound)) f(item.edge);
      }
      continue;
    }
    // The nearer child on top.
    double from0 = 0.0, from1 = 0.0;
    const bool meets0 = meetsFrom(leaf.nodes[node.start].lo, leaf.nodes[node.start].hi, from0);
    const bool meets1 =
        meetsFrom(leaf.nodes[node.start + 1].lo, leaf.nodes[node.start + 1].hi, from1);
    if (meets0 && meets1 && from0 < from1) {
      stack[top++] = {node.start + 1, from1};
      stack[top++] = {node.start, from0};
    } else {
      if (meets0) stack[top++] = {node.start, from0};
      if (meets1) stack[top++] = {node.start + 1, from1};
    }
  }
}

template <class Path>
bool SweptRegion::spans(const Primitive* owner, const Path& path, double t0, double t1,
                        std::uint32_t face0, std::uint32_t face1, const SweepPiece* pieces,
                        int pieceCount, SpanList& out, bool firstOnly) const {
  out.clear();
  if (!(t0 < t1)) return false;
  double exactTo = t1;
  treeSpans(owner, 0, path, t0, t1, face0, face1, pieces, pieceCount, firstOnly, exactTo, out);
  const bool truncated = exactTo < t1;
  bool flipped = false;
  for (const Span& s : out) flipped = flipped || s.in.flip || s.out.flip;
  if (!flipped) return truncated;
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
  return truncated;
}

template <class Path>
void SweptRegion::treeSpans(const Primitive* owner, std::uint32_t index, const Path& path,
                            double t0, double t1, std::uint32_t face0, std::uint32_t face1,
                            const SweepPiece* pieces, int pieceCount, bool firstOnly,
                            double& exactTo, SpanList& out) const {
  out.clear();
  const TreeNode& node = tree_[index];
  if (node.op != Region::Op::Leaf) {
    // A union asks its operands for their first boundaries too: each one's
    // spans are exact up to where it was cut short, so the union's are up
    // to the nearest such point, and are cut there. (The operands of an
    // intersection or a difference give all their spans: a hole's far
    // boundary may be the first of the result.)
    const bool operandsFirst = firstOnly && node.op == Region::Op::Union;
    double operandsExactTo = t1;
    SpanList operand, merged;
    bool first = true;
    for (std::uint32_t child : node.operands) {
      if (first) {
        treeSpans(owner, child, path, t0, t1, face0, face1, pieces, pieceCount, operandsFirst,
                  operandsExactTo, out);
        first = false;
        if (out.empty() && node.op != Region::Op::Union) return;
        continue;
      }
      treeSpans(owner, child, path, t0, t1, face0, face1, pieces, pieceCount, operandsFirst,
                operandsExactTo, operand);
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
    if (operandsExactTo < t1) {
      exactTo = std::min(exactTo, operandsExactTo);
      merged.clear();
      for (Span s : out) {
        if (s.in.t >= operandsExactTo) break;
        if (s.out.t > operandsExactTo) s.out = Boundary{operandsExactTo, owner, face1, false};
        merged.push_back(s);
      }
      out = merged;
    }
    return;
  }

  // A leaf: the crossings of the curve with its edges, from the edges near
  // each piece of the curve.
  const Leaf& leaf = leaves_[node.leaf];
  if (leaf.nodes.empty()) return;
  // An end of the window clearly outside the leaf's box is outside it.
  // (The sweeps' windows end a pad past the region's box, beyond rounding.)
  const dvec2 boxLo = leaf.box.lo - dvec2(0.5 * pad_), boxHi = leaf.box.hi + dvec2(0.5 * pad_);
  const auto outsideBox = [&](const dvec2& u) {
    return u.x < boxLo.x || u.x > boxHi.x || u.y < boxLo.y || u.y > boxHi.y;
  };
  const bool startOutside = outsideBox(path.at(t0));
  bool touched = false;
  std::vector<SweepCrossing>& crossings = sweep_detail::crossingBuffer();
  crossings.clear();
  const auto addCrossings = [&](std::uint32_t e, double from, double to) {
    const SweepEdge& edge = edges_[e];
    double roots[8];
    const int n = path.roots(edge, from, to, roots);
    for (int i = 0; i < n; ++i) {
      const dvec2 u = path.at(roots[i]);
      // Roots of a squared equation that are not the edge's own.
      if (!(edge.distance(u) <= kAcceptDistance * size_)) continue;
      bool clean = false;
      if (!edge.holds(u, kEdgeSlack, clean)) continue;
      crossings.push_back({roots[i], kSweepFirstEdgeFace + e, clean});
    }
  };
  // Where the crossings found are all there are: the window's end, or in
  // the first-boundary mode a little past the first crossing: `bound`, the
  // first crossing found and a margin within which a crossing may still
  // change what it means. The stretches up to `end` are exact.
  double end = t1;
  double bound = kInfinity;
  const double margin = 1e-6 * (t1 - t0);
  const auto addBounding = [&](std::uint32_t e, const SweepPiece& piece) {
    const std::size_t before = crossings.size();
    addCrossings(e, piece.t0, piece.t1);
    for (std::size_t i = before; i < crossings.size(); ++i)
      bound = std::min(bound, crossings[i].t + margin);
  };
  bool ordered = false;
  if constexpr (requires(double from) { path.meetsFrom(pieces[0], dvec2(), dvec2(), from); }) {
    ordered = firstOnly && startOutside && pieceCount == 1;
    if (ordered) {
      // The index walked nearest box first, leaving the boxes the curve
      // enters only past the bound.
      const SweepPiece& piece = pieces[0];
      const auto meetsFrom = [&](const dvec2& lo, const dvec2& hi, double& from) {
        return path.meetsFrom(piece, lo, hi, from);
      };
      forEachEdgeInOrder(leaf, meetsFrom, bound, [&](std::uint32_t e) { addBounding(e, piece); });
      touched = true;
    }
  }
  // Pieces in boxes, in the first-boundary mode: taken in order, until the
  // next starts past the bound.
  const bool byPieces = Path::kBoxedPieces && firstOnly && !ordered && pieceCount > 1;
  for (int k = 0; k < pieceCount && !ordered; ++k) {
    const SweepPiece& piece = pieces[k];
    if (piece.t0 > bound) break;
    const auto meets = [&](const dvec2& lo, const dvec2& hi) { return path.meets(piece, lo, hi); };
    // (The root's box is the leaf's, grown.)
    if (!meets(leaf.nodes[0].lo, leaf.nodes[0].hi)) continue;
    touched = true;
    // A piece in cells that no edge passes through crosses none: most of a
    // twisted path's pieces, inside the region or out.
    if constexpr (Path::kBoxedPieces)
      if (leaf.edgeFree(piece.lo, piece.hi)) continue;
    forEachEdgeNear(leaf, meets, [&](std::uint32_t e) {
      if (byPieces) {
        addBounding(e, piece);
      } else {
        addCrossings(e, piece.t0, piece.t1);
      }
    });
  }
  if (bound < t1) {
    end = bound;
    exactTo = std::min(exactTo, end);
    std::size_t kept = 0;
    for (const SweepCrossing& c : crossings)
      if (c.t <= end) crossings[kept++] = c;
    crossings.resize(kept);
  }
  if (!touched) return;
  // By insertion: a ray meets few edges.
  for (std::size_t i = 1; i < crossings.size(); ++i) {
    const SweepCrossing c = crossings[i];
    std::size_t j = i;
    for (; j > 0 && c.t < crossings[j - 1].t; --j) crossings[j] = crossings[j - 1];
    crossings[j] = c;
  }
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
  // was toggled from such, or one at an end known to be outside);
  // otherwise the leaf is asked at the stretch's middle. The states are
  // worked out from an end known to be outside when there is one (forwards
  // from the start, else backwards from the end), so that most rays never
  // ask. Stretch k runs from crossing k − 1 (or t0) to crossing k (or t1);
  // its state is kept in crossing k's `before` (the last one in lastInside).
  const double reliableLength = 1e-7 * (t1 - t0);
  const auto stretchStart = [&](std::size_t k) { return k == 0 ? t0 : crossings[k - 1].t; };
  const auto stretchEnd = [&](std::size_t k) { return k == n ? end : crossings[k].t; };
  bool lastInside = false;
  const auto setState = [&](std::size_t k, bool inside) {
    if (k == n) {
      lastInside = inside;
    } else {
      crossings[k].before = inside;
    }
  };
  bool inside = false, reliable = false;
  const auto step = [&](std::size_t k, bool toggles) {
    if (reliable && toggles) {
      inside = !inside;
    } else {
      const double a = stretchStart(k), b = stretchEnd(k);
      inside = leafContains(node.leaf, path.at(0.5 * (a + b)));
      reliable = b - a > reliableLength;
    }
    setState(k, inside);
  };
  if (!startOutside && outsideBox(path.at(end))) {
    reliable = true;
    setState(n, false);
    for (std::size_t k = n; k-- > 0;) step(k, crossings[k].clean);
  } else {
    if (startOutside) {
      reliable = true;
      setState(0, false);
    } else {
      step(0, false);
    }
    for (std::size_t k = 1; k <= n; ++k) step(k, crossings[k - 1].clean);
  }

  double a = t0;
  std::uint32_t faceA = face0;
  // The span being grown: stretches inside with only crossings that
  // changed nothing between them are one span.
  Span pending{};
  bool open = false;
  for (std::size_t i = 0; i <= n; ++i) {
    const double b = i < n ? crossings[i].t : end;
    const std::uint32_t faceB = i < n ? crossings[i].face : face1;
    const bool stretchInside = i < n ? crossings[i].before : lastInside;
    if (stretchInside && b > a) {
      if (!open) pending.in = Boundary{a, owner, faceA, false};
      pending.out = Boundary{b, owner, faceB, false};
      open = true;
    } else if (!stretchInside && b > a && open) {
      out.push_back(pending);
      open = false;
    }
    a = b;
    faceA = faceB;
  }
  if (open) out.push_back(pending);
}

}  // namespace csgray::detail
