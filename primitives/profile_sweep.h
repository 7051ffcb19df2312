// What the sweeps of a region (linear_extrusion.h, revolution.h) share: a
// sweep is the preimage of a region under a map from space to the profile
// plane, so a ray is inside it where its image, a curve u(t) in the plane,
// is inside the region. SweptRegion finds where that curve crosses the
// edges of each leaf of the region, decides which stretches between
// crossings lie inside the leaf, and merges the leaves' spans as the
// region's tree says (docs/architecture.md, "Sweeps").
//
// The curve is given by a path object (see SweptRegion::spans) that knows
// the map: its point at t, and the roots of an edge's implicit function
// along it in closed form or numerically. Everything else is here: an index
// over the edges (a 2D bounding volume hierarchy) so that a ray tests only
// the edges near its curve, the even-odd classification, the faces and the
// edges' outward normals.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "engine/primitive.h"
#include "engine/solvers/quartic.h"
#include "engine/span_list.h"
#include "profile/bezier.h"
#include "profile/region.h"

namespace csgray::detail {

// Faces of a sweep: the two caps of an extrusion (or the two flat faces of
// a revolution's wedge), then one face per edge of the region's leaves, in
// forEachLeaf order.
inline constexpr std::uint32_t kSweepStartFace = 0;  // bottom cap, or the wedge's face at angle 0
inline constexpr std::uint32_t kSweepEndFace = 1;    // top cap, or the wedge's face at its angle
inline constexpr std::uint32_t kSweepFirstEdgeFace = 2;
// Set on an edge's face where the edge bounds a hole of the region's tree
// (a leaf subtracted once): the solid lies on the side its leaf does not,
// so the normal is reversed. Spans of a sweep never carry Boundary::flip.
inline constexpr std::uint32_t kSweepReversedFace = 1u << 30;

// One edge of a leaf, with what the crossings need at hand.
struct SweepEdge {
  bool arc = false;
  bool fullTurn = false;   // an arc all round its ellipse
  std::uint32_t leaf = 0;  // forEachLeaf's numbering
  dvec2 from{0.0}, to{0.0};
  // Segments: the unit normal and the line n·u = offset.
  dvec2 normal{0.0};
  double offset = 0.0;
  // Arcs: the ellipse is |toUnit·(u − center)| = 1; angles lo <= hi.
  dvec2 center{0.0};
  dmat2 toUnit{1.0};
  double lo = 0.0, hi = 0.0;
  // Bézier curves: the degree (0 for segments and arcs), the curve in the
  // power basis, and the edge it came from.
  int bezier = 0;
  BezierPolynomial curve;
  ProfileEdge source;
  double size = 0.0;     // largest semi-axis (arcs), length (segments), the box's diagonal (curves)
  double outward = 1.0;  // +1 when the gradient of the implicit function points out of the leaf
  ProfileBounds box;

  // The implicit function: n·u − offset, or |toUnit(u − center)|² − 1, or
  // for a curve the distance to its nearest point, signed by the side.
  double implicit(const dvec2& u) const;
  // Its gradient, turned to point out of the leaf.
  dvec2 outwardGradient(const dvec2& u) const;
  // Is u (a point on the edge's line or ellipse) on the edge, allowing
  // `slack` of its parameter (segment fraction, or radians)? clean: and not
  // within slack of an end.
  bool holds(const dvec2& u, double slack, bool& clean) const {
    if (arc) return arcHolds(u, slack, clean);
    if (bezier) {
      const double s = nearestBezierParameter(curve, u);
      clean = s > slack && s < 1.0 - slack;
      return true;  // the paths find a curve's roots for s in [-slack, 1 + slack] only
    }
    const dvec2 d = to - from;
    const double s = ((u.x - from.x) * d.x + (u.y - from.y) * d.y) / (d.x * d.x + d.y * d.y);
    clean = s > slack && s < 1.0 - slack;
    return s >= -slack && s <= 1.0 + slack;
  }
  // How far u is from the edge's line or ellipse, roughly (exact for
  // segments and circles).
  double distance(const dvec2& u) const {
    if (bezier) return glm::length(curve.at(nearestBezierParameter(curve, u)) - u);
    return arc ? arcDistance(u) : std::abs(normal.x * u.x + normal.y * u.y - offset);
  }
  // A curve's normal at its point nearest u: its tangent turned a quarter
  // clockwise (a segment's `normal` likewise), of unit length.
  dvec2 curveNormal(const dvec2& u) const;

 private:
  bool arcHolds(const dvec2& u, double slack, bool& clean) const;
  double arcDistance(const dvec2& u) const;
};

// A stretch of the curve, t0 <= t <= t1, whose image in the plane lies in
// the box lo–hi; straight: it lies on the segment from–to. Every field is
// given where a piece is made, and none has a default: a twisted path's
// array of 512 pieces is made for every ray, and filling it with defaults
// took a tenth of a twisted gear's render.
struct SweepPiece {
  double t0, t1;
  dvec2 lo, hi;
  bool straight;
  dvec2 from, to;
};

// Where the curve meets an edge.
struct SweepCrossing {
  double t;
  std::uint32_t face;
  bool clean;           // transversal, away from the edge's ends and from other crossings
  bool before = false;  // worked out by the spans: is the stretch that ends here inside?
};

class SweptRegion {
 public:
  // A root of a path is the edge's when the curve's point there is this
  // close to the edge's line or ellipse (in units of the region's size):
  // far above rounding, far below the distance of a squared equation's
  // mirrored roots (revolution.cpp) except next to the axis, where both
  // are the same crossing.
  static constexpr double kAcceptDistance = 1e-7;

  // Throws std::invalid_argument (naming `kind`) for an empty region or one
  // with non-finite coordinates. Without exactCurves (the paths that are
  // not straight lines: a twist, a non-uniform scale, a revolution) Bézier
  // curves are replaced by polygons within kCurveTolerance of the region's
  // size; straight paths meet them in closed form.
  SweptRegion(RegionPtr region, const char* kind, bool exactCurves = true);
  static constexpr double kCurveTolerance = 1e-6;

  const RegionPtr& region() const { return region_; }
  const ProfileBounds& bounds() const { return region_->bounds(); }
  double size() const { return size_; }
  const SweepEdge& edgeOfFace(std::uint32_t face) const {
    return edges_[(face & ~kSweepReversedFace) - kSweepFirstEdgeFace];
  }
  // The outward normal (any length) in the plane at u on an edge's face.
  dvec2 outwardNormal(std::uint32_t face, const dvec2& u) const {
    const dvec2 n = edgeOfFace(face).outwardGradient(u);
    return face & kSweepReversedFace ? -n : n;
  }
  std::size_t edgeCount() const { return edges_.size(); }

  // Is the point of the plane in the region (even-odd in each leaf, as
  // Profile::contains, through the edge index)?
  bool contains(const dvec2& u) const;

  // The spans of the curve of `path` within [t0, t1], where the ray is in
  // the sweep's slab (or bounding cylinder): boundaries at the window's
  // ends get faces face0 and face1. The pieces cover the window in order,
  // each with a box that holds its image. Path must provide
  //   dvec2 at(double t) const;
  //   int roots(const SweepEdge&, double t0, double t1, double* out) const;
  //   bool meets(const SweepPiece&, const dvec2& lo, const dvec2& hi) const;
  //   static constexpr bool kBoxedPieces;  // does each piece's box hold its image?
  // roots writes at most 8 values of t in [t0, t1] where the edge's
  // implicit function vanishes along the curve (more is harmless: each is
  // checked to lie on the edge; a root it misses must be a tangency).
  // meets says whether the curve over the piece may pass through the
  // closed box lo–hi (false only when it surely does not; sweepPieceMeets
  // is the test of the piece's box, and segment when straight): the index
  // asks it of its nodes and then of each edge's box before roots.
  //
  // firstOnly: only the first boundary is asked for (Solid's
  // spansToFirstBoundary). A path that provides
  //   bool meetsFrom(const SweepPiece&, const dvec2& lo, const dvec2& hi,
  //                  double& from) const;
  // (meets, and from: a t before which the curve is not in the box) then
  // has the index walked nearest box first, for each leaf whose box the
  // window starts outside: the leaf's spans are exact up to a little past
  // its first crossing and end there. A path with kBoxedPieces has its
  // pieces taken in order instead, to the same end. Leaves under unions
  // only (a union of them is exact up to the nearest of their ends, and is
  // cut there); the operands of intersections and differences give all
  // their spans. Returns true when the spans were cut so; if they are then
  // empty, or the first does not start inside the ray's window, the caller
  // must ask again without firstOnly.
  template <class Path>
  bool spans(const Primitive* owner, const Path& path, double t0, double t1, std::uint32_t face0,
             std::uint32_t face1, const SweepPiece* pieces, int pieceCount, SpanList& out,
             bool firstOnly = false) const;

 private:
  // A 2D bounding volume hierarchy over one leaf's edges. Every box (the
  // nodes' and the edges') is grown by pad_, so that a curve that passes
  // within rounding of an edge still reaches it.
  struct Node {
    dvec2 lo, hi;
    std::uint32_t start,
        count;  // leaf: items [start, start + count); inner: children start, start + 1
  };
  struct Item {
    dvec2 lo, hi;  // the edge's box
    std::uint32_t edge;
  };
  // The leaf's state (in or out) over a grid of cells on its box: a cell
  // that no edge passes through is wholly in or wholly out, and the state
  // at its centre answers for every point in it; a cell an edge may pass
  // through says "ask the edges". Rays that enter an extrusion through its
  // cap ask the leaf once, mostly far from any edge: the grid answers them
  // at once.
  enum class CellState : std::uint8_t { Outside, Inside, Crossed };
  struct Leaf {
    ProfileBounds box;
    std::vector<Node> nodes;
    std::vector<Item> items;
    std::vector<CellState> cells;  // row-major; empty: no grid
    // How many cells an edge may pass through lie in rows below r and
    // columns left of c, at [r·(columns + 1) + c] (a summed-area table,
    // Crow 1984): four reads tell whether any lies in a box of cells.
    std::vector<std::uint32_t> crossedBelow;
    int columns = 0, rows = 0;
    double cellsPerUnit = 0.0;  // 1 / a cell's side
    // The cell of a coordinate, clamped to the grid (NaN: the first);
    // monotonic, as buildCells needs.
    static int cellOf(double f, int count) {
      return f > 0.0 ? (f < double(count - 1) ? int(f) : count - 1) : 0;
    }
    int cellColumn(double x) const { return cellOf((x - box.lo.x) * cellsPerUnit, columns); }
    int cellRow(double y) const { return cellOf((y - box.lo.y) * cellsPerUnit, rows); }
    // Does no edge pass through the box lo–hi? (False without a grid.)
    bool edgeFree(const dvec2& lo, const dvec2& hi) const {
      if (crossedBelow.empty()) return false;
      const int c0 = cellColumn(lo.x), c1 = cellColumn(hi.x) + 1;
      const int r0 = cellRow(lo.y), r1 = cellRow(hi.y) + 1;
      const auto at = [this](int r, int c) {
        return crossedBelow[std::size_t(r) * (columns + 1) + c];
      };
      return at(r1, c1) - at(r0, c1) - at(r1, c0) + at(r0, c0) == 0;
    }
  };
  struct TreeNode {
    Region::Op op;
    std::uint32_t leaf;                   // for Op::Leaf
    std::vector<std::uint32_t> operands;  // indices into tree_
  };

  void buildIndex(Leaf& leaf, std::vector<std::uint32_t> edges);
  std::uint32_t addTree(const Region& region, std::uint32_t& nextLeaf);
  // Calls f(edge) for each edge of the leaf whose box (and the boxes of the
  // nodes above it) meets(lo, hi) accepts. The caller has asked it of the
  // root, whose box is the leaf's, grown.
  template <class Meets, class F>
  void forEachEdgeNear(const Leaf& leaf, Meets&& meets, F&& f) const;
  // The same for meetsFrom(lo, hi, from), nearest box first, leaving the
  // boxes the curve enters only past `bound` (which f may lower).
  template <class MeetsFrom, class F>
  void forEachEdgeInOrder(const Leaf& leaf, MeetsFrom&& meetsFrom, const double& bound,
                          F&& f) const;
  bool leafContains(std::uint32_t leaf, const dvec2& u) const;
  // The same from the leaf's edges: the even-odd count of those that a
  // ray from u to the nearest side of the leaf's box crosses.
  bool edgesContain(const Leaf& leaf, const dvec2& u) const;
  void buildCells(Leaf& leaf) const;
  bool treeContains(std::uint32_t node, const dvec2& u) const;
  template <class Path>
  void treeSpans(const Primitive* owner, std::uint32_t node, const Path& path, double t0, double t1,
                 std::uint32_t face0, std::uint32_t face1, const SweepPiece* pieces, int pieceCount,
                 bool firstOnly, double& exactTo, SpanList& out) const;

  // How far past an edge's end (a fraction of a segment, radians of an
  // arc) a crossing still counts as on it, and within which of an end it
  // is not clean: a vertex met through both its edges must not be lost.
  static constexpr double kEdgeSlack = 1e-9;

  RegionPtr region_;
  std::vector<SweepEdge> edges_;
  std::vector<Leaf> leaves_;
  std::vector<TreeNode> tree_;  // tree_[0] is the root
  double size_ = 1.0;
  double pad_ = 0.0;  // 1e-9 of size_
};

// Only boundaries within the ray's [tMin, tMax] are answers (solid.h), so
// a sweep's window that reaches past them is cut a little outside them:
// the stretch beyond is never traced (for a shadow ray, which starts on
// the part, often the most of it). A span may then end at the cut, inside
// the solid and outside the ray's range, as solid.h allows.
// A sweep of a region, as the exporter may take it apart: the same sweep
// of each operand of the region's boolean, combined by the same boolean,
// is the same solid (a sweep is a preimage, which commutes with booleans).
class RegionSweep {
 public:
  virtual ~RegionSweep() = default;
  virtual const RegionPtr& sweptRegion() const = 0;
  // The same sweep of another region, placed as this one.
  virtual SolidPtr sweepOf(RegionPtr region) const = 0;
};

inline void cutSweepWindow(const Ray& ray, double& t0, double& t1) {
  const double margin = 1e-6 * (t1 - t0);
  if (ray.tMin - margin > t0) t0 = ray.tMin - margin - 1e-9 * std::abs(ray.tMin);
  if (ray.tMax + margin < t1) t1 = ray.tMax + margin + 1e-9 * std::abs(ray.tMax);
}

// ---- polynomials in a normalised parameter s ∈ [-1, 1] -----------------------

// c[0] + c[1]·s + ... + c[n]·sⁿ, n <= 4.
struct SweepPolynomial {
  double c[5] = {0, 0, 0, 0, 0};
  int n = 0;

  static SweepPolynomial linear(double c0, double c1) {
    SweepPolynomial p;
    p.c[0] = c0;
    p.c[1] = c1;
    p.n = 1;
    return p;
  }
  SweepPolynomial operator*(const SweepPolynomial& o) const;
  SweepPolynomial operator+(const SweepPolynomial& o) const;
  SweepPolynomial operator-(const SweepPolynomial& o) const;
  SweepPolynomial operator*(double k) const;
};

// The roots in [s0, s1] of the polynomial, each once (a double root once
// or twice, or not at all when rounding keeps it off zero). Leading
// coefficients negligible next to the others are dropped first. Returns the
// count (at most 4). (Inline: it runs for every edge a ray's curve comes
// near.)
inline int sweepPolynomialRoots(const SweepPolynomial& p, double s0, double s1, double* roots) {
  int n = p.n;
  double scale = 0.0;
  for (int i = 0; i <= n; ++i) scale = std::max(scale, std::abs(p.c[i]));
  if (!(scale > 0.0) || !std::isfinite(scale)) return 0;
  // On [-1, 1] a term this small moves the polynomial by less than rounding.
  while (n > 0 && std::abs(p.c[n]) <= 1e-14 * scale) --n;
  if (n == 0) return 0;
  int count = 0;
  auto keep = [&](double s) {
    if (s >= s0 && s <= s1) roots[count++] = s;
  };
  if (n == 1) {
    keep(-p.c[0] / p.c[1]);
    return count;
  }
  if (n == 2) {
    // The cancellation-free form (Numerical Recipes 5.6); a double root is
    // kept once, a discriminant that rounding took below zero is a
    // tangency and gives nothing.
    const double a = p.c[2], b = p.c[1], c = p.c[0];
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double r0 = q / a, r1 = q != 0.0 ? c / q : r0;
    if (r0 > r1) std::swap(r0, r1);
    keep(r0);
    if (r1 != r0) keep(r1);
    return count;
  }
  return polynomialSublevelBoundaries(p.c, n, s0, s1, roots);
}

}  // namespace csgray::detail

#include "primitives/profile_sweep_spans.h"
