// CGAL's conversion of a circle to doubles (Epic_converter) copies a tuple
// that GCC 12 takes for uninitialised where it inlines it: a false alarm
// inside CGAL's and Boost's headers, silenced for this file only.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "profile/cgal/polygon_set.h"

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arrangement_2.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "profile/bezier.h"
#include "profile/region_evaluation.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

using ArcTraits = CGAL::Arr_circle_segment_traits_2<PlaneKernel>;
using ArcCurve = ArcTraits::X_monotone_curve_2;  // x-monotone

// The fill rules need to know which way, and how many, input curves run
// along each edge of the arrangement: each x-monotone piece counts +1 when
// it runs left to right (CGAL's xy order), -1 the other way, and
// overlapping pieces add their counts.
struct AddCounts {
  int operator()(int a, int b) const { return a + b; }
};
using CountedTraits = CGAL::Arr_curve_data_traits_2<ArcTraits, int, AddCounts>;
// A face's data: its winding number, kUnknownWinding before it is known.
using CountedArrangement =
    CGAL::Arrangement_2<CountedTraits, CGAL::Arr_face_extended_dcel<CountedTraits, int>>;
constexpr int kUnknownWinding = std::numeric_limits<int>::min();

enum class FillRule { EvenOdd, NonZero, Positive };

void requireFinite(double v, const char* what) {
  if (std::isfinite(v)) return;
  std::ostringstream msg;
  msg << "a region's " << what << " must be a finite number (got " << v << ")";
  throw std::invalid_argument(msg.str());
}

void requireFinite(const dvec2& p, const char* what) {
  requireFinite(p.x, what);
  requireFinite(p.y, what);
}

void requireFinite(const ProfileEdge& e) {
  requireFinite(e.from, "point");
  requireFinite(e.to, "point");
  if (e.bezier()) {
    requireFinite(e.control1, "control point");
    requireFinite(e.control2, "control point");
  }
  if (e.kind != ProfileEdge::Kind::Arc) return;
  requireFinite(e.center, "arc centre");
  requireFinite(e.axes[0], "arc radius");
  requireFinite(e.axes[1], "arc radius");
  requireFinite(e.angle0, "arc angle");
  requireFinite(e.angle1, "arc angle");
}

// The largest singular value of a 2×2 matrix: how far it stretches.
double largestStretch(const dmat2& m) {
  const double p = glm::dot(m[0], m[0]), s = glm::dot(m[1], m[1]), q = glm::dot(m[0], m[1]);
  return std::sqrt(0.5 * (p + s) + std::hypot(0.5 * (p - s), q));
}

dvec2 toDouble(const ArcTraits::Point_2& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

// The boundary of a face's CCB as a polygon whose curves run the way the
// CCB does (the face on their left), without antennae (edges with the face
// on both sides).
template <typename Circulator>
ArcPolygon polygonOf(Circulator first) {
  const ArcTraits traits;
  const auto opposite = traits.construct_opposite_2_object();
  std::vector<ArcCurve> curves;
  Circulator h = first;
  do {
    if (h->twin()->face() == h->face()) continue;
    const ArcCurve& c = h->curve();
    const bool leftToRight = h->direction() == CGAL::ARR_LEFT_TO_RIGHT;
    curves.push_back(leftToRight == c.is_directed_right() ? c : opposite(c));
  } while (++h != first);
  return ArcPolygon(curves.begin(), curves.end());
}

// Do two x-monotone pieces lie on one segment's line or one circle (with
// the same orientation)?
bool sameSupport(const ArcCurve& a, const ArcCurve& b) {
  if (a.is_linear() != b.is_linear()) return false;
  if (a.is_linear()) return a.supporting_line() == b.supporting_line();
  return a.orientation() == b.orientation() && a.supporting_circle() == b.supporting_circle();
}

// The angle an x-monotone arc sweeps from a to b (on a circle about c),
// signed as its orientation: an x-monotone arc sweeps at most π, so the
// difference of the angles is read in a window that holds [0, π] (or
// [-π, 0]) with room for rounding either side.
double pieceSweep(const dvec2& c, const dvec2& a, const dvec2& b, bool counterclockwise) {
  double d = std::atan2(b.y - c.y, b.x - c.x) - std::atan2(a.y - c.y, a.x - c.x);
  if (counterclockwise) {
    while (d < -0.5 * kPi) d += kTwoPi;
    while (d > 1.5 * kPi) d -= kTwoPi;
  } else {
    while (d > 0.5 * kPi) d -= kTwoPi;
    while (d < -1.5 * kPi) d += kTwoPi;
  }
  return d;
}

double edgeArea(const ProfileEdge& e) {
  const auto cross = [](const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; };
  if (e.kind == ProfileEdge::Kind::Segment) return 0.5 * cross(e.from, e.to);
  return 0.5 * (cross(e.center, e.to - e.from) + glm::determinant(e.axes) * (e.angle1 - e.angle0));
}

// One closed boundary of a polygon set as a loop: runs of pieces on one
// line or circle become one edge. Every end is the double of an exact
// point, computed once, so that the loop closes exactly.
ProfileLoop loopOf(const ArcPolygon& polygon) {
  const std::vector<ArcCurve> pieces(polygon.curves_begin(), polygon.curves_end());
  const std::size_t n = pieces.size();
  ProfileLoop loop;
  if (n == 0) return loop;
  // Start at a piece whose support differs from its predecessor's; a loop
  // that is all one circle is one run.
  std::size_t start = 0;
  while (start < n && sameSupport(pieces[(start + n - 1) % n], pieces[start])) ++start;
  const bool oneRun = start == n;
  if (oneRun) start = 0;
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // first piece, count
  for (std::size_t i = 0; i < n;) {
    std::size_t count = 1;
    while (i + count < n && !oneRun &&
           sameSupport(pieces[(start + i + count - 1) % n], pieces[(start + i + count) % n]))
      ++count;
    if (oneRun) count = n;
    runs.emplace_back((start + i) % n, count);
    i += count;
  }
  std::vector<dvec2> ends(n);  // each piece's source
  for (std::size_t i = 0; i < n; ++i) ends[i] = toDouble(pieces[i].source());
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto [first, count] = runs[r];
    const dvec2 from = ends[first];
    const dvec2 to = ends[(first + count) % n];
    const ArcCurve& piece = pieces[first];
    if (piece.is_linear()) {
      loop.edges.push_back(ProfileEdge::segment(from, to));
      continue;
    }
    const auto circle = piece.supporting_circle();
    const dvec2 c(CGAL::to_double(circle.center().x()), CGAL::to_double(circle.center().y()));
    const double radius = std::sqrt(CGAL::to_double(circle.squared_radius()));
    const bool ccw = piece.orientation() == CGAL::COUNTERCLOCKWISE;
    double sweep = 0.0;
    if (oneRun) {
      sweep = ccw ? kTwoPi : -kTwoPi;
    } else {
      for (std::size_t k = 0; k < count; ++k)
        sweep += pieceSweep(c, ends[(first + k) % n], ends[(first + k + 1) % n], ccw);
    }
    const double angle0 = std::atan2(from.y - c.y, from.x - c.x);
    ProfileEdge e = ProfileEdge::arc(c, dmat2(radius), angle0, angle0 + sweep);
    e.from = from;
    e.to = oneRun ? from : to;
    loop.edges.push_back(e);
  }
  return loop;
}

// Joins segments that follow each other on what doubles cannot tell from
// one line (the corner between them within `shortest` of the chord).
void mergeStraightRuns(ProfileLoop& loop, double shortest) {
  const auto straight = [&](const ProfileEdge& a, const ProfileEdge& b) {
    if (a.kind != ProfileEdge::Kind::Segment || b.kind != ProfileEdge::Kind::Segment) return false;
    const dvec2 chord = b.to - a.from;
    const double length = glm::length(chord);
    if (length <= shortest) return false;
    const dvec2 side = a.to - a.from;
    return std::abs(side.x * chord.y - side.y * chord.x) <= shortest * length &&
           glm::dot(side, chord) > 0.0 && glm::dot(b.to - a.to, chord) > 0.0;
  };
  bool merged = true;
  while (merged && loop.edges.size() > 3) {
    merged = false;
    for (std::size_t i = 0; i < loop.edges.size() && loop.edges.size() > 3; ++i) {
      const std::size_t next = (i + 1) % loop.edges.size();
      if (!straight(loop.edges[i], loop.edges[next])) continue;
      loop.edges[i].to = loop.edges[next].to;
      loop.edges.erase(loop.edges.begin() + static_cast<std::ptrdiff_t>(next));
      if (next < i) --i;  // the first edge went; i moved down
      merged = true;
    }
  }
  const std::size_t n = loop.edges.size();
  for (std::size_t i = 0; i < n; ++i) loop.edges[(i + 1) % n].from = loop.edges[i].to;
}

// Drops edges shorter than `shortest` (slivers of rounding where curves
// nearly touch), keeping the loop closed, and loops that are left with no
// area to speak of.
void dropSlivers(Profile& profile) {
  const ProfileBounds b = profile.bounds();
  if (b.empty()) return;
  const double size = glm::length(b.hi - b.lo);
  const double shortest = 1e-12 * size;
  Profile kept;
  for (ProfileLoop& loop : profile.loops) {
    ProfileLoop out;
    for (const ProfileEdge& e : loop.edges) {
      const bool whole =
          e.kind == ProfileEdge::Kind::Arc && std::abs(e.angle1 - e.angle0) >= kTwoPi;
      if (!whole && glm::length(e.to - e.from) <= shortest) continue;
      out.edges.push_back(e);
      if (out.edges.size() > 1) out.edges.back().from = out.edges[out.edges.size() - 2].to;
    }
    if (out.edges.empty()) continue;
    out.edges.front().from = out.edges.back().to;
    mergeStraightRuns(out, shortest);
    double area = 0.0;
    for (const ProfileEdge& e : out.edges) area += edgeArea(e);
    if (std::abs(area) <= shortest * size) continue;
    kept.loops.push_back(std::move(out));
  }
  profile = std::move(kept);
}

using CountedPiece = CountedTraits::X_monotone_curve_2;

// A curve's x-monotone pieces, each counted `weight` times the way the
// curve runs: +weight when that is left to right.
void addPieces(const CircleSegment& curve, int weight, std::vector<CountedPiece>& pieces) {
  const ArcTraits traits;
  std::vector<boost::variant<ArcTraits::Point_2, ArcCurve>> split;
  traits.make_x_monotone_2_object()(curve, std::back_inserter(split));
  for (const auto& item : split)
    if (const ArcCurve* piece = boost::get<ArcCurve>(&item))
      pieces.emplace_back(*piece, piece->is_directed_right() ? weight : -weight);
}

// The points about which the pieces (closed chains: each point is left as
// often as it is reached) wind as the rule says, as polygons with holes
// whose interiors are disjoint. The winding number is flooded from the
// unbounded face (0): crossing an edge from its left to its right takes
// away the count of the curves that run along it. The edges between two
// filled faces, or two empty ones, are then removed, so that each filled
// face left is a whole component: joining the faces one by one instead
// would sweep their shared edges again.
std::vector<ArcPolygonWithHoles> filledPolygons(const std::vector<CountedPiece>& pieces,
                                                FillRule rule) {
  CountedArrangement arrangement;
  CGAL::insert(arrangement, pieces.begin(), pieces.end());

  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f)
    f->set_data(kUnknownWinding);
  std::vector<CountedArrangement::Face_handle> stack{arrangement.unbounded_face()};
  stack.back()->set_data(0);
  const auto flood = [&](CountedArrangement::Face_handle f,
                         CountedArrangement::Ccb_halfedge_circulator first) {
    auto h = first;
    do {
      // f is on h's left; the curves that run h's way have it on theirs.
      const auto g = h->twin()->face();
      if (g->data() != kUnknownWinding) continue;
      const int along = h->curve().data();
      g->set_data(f->data() - (h->direction() == CGAL::ARR_LEFT_TO_RIGHT ? along : -along));
      stack.push_back(g);
    } while (++h != first);
  };
  while (!stack.empty()) {
    const auto f = stack.back();
    stack.pop_back();
    if (!f->is_unbounded()) flood(f, f->outer_ccb());
    for (auto i = f->inner_ccbs_begin(); i != f->inner_ccbs_end(); ++i) flood(f, *i);
  }
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    const int winding = f->data();
    const bool filled = rule == FillRule::EvenOdd   ? (winding & 1) != 0
                        : rule == FillRule::NonZero ? winding != 0
                                                    : winding > 0;
    f->set_data(filled ? 1 : 0);
  }
  std::vector<CountedArrangement::Halfedge_handle> inner;
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e)
    if (e->face()->data() == e->twin()->face()->data()) inner.push_back(e);
  for (const auto e : inner) arrangement.remove_edge(e);

  std::vector<ArcPolygonWithHoles> filled;
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    if (f->is_unbounded() || f->data() == 0) continue;
    std::vector<ArcPolygon> holes;
    for (auto i = f->inner_ccbs_begin(); i != f->inner_ccbs_end(); ++i) {
      ArcPolygon hole = polygonOf(*i);
      if (hole.size() > 0) holes.push_back(std::move(hole));
    }
    filled.emplace_back(polygonOf(f->outer_ccb()), holes.begin(), holes.end());
  }
  return filled;
}

// The curves' x-monotone pieces, each counted once the way it runs.
std::vector<CountedPiece> countedPieces(const std::vector<CircleSegment>& curves) {
  std::vector<CountedPiece> pieces;
  for (const CircleSegment& c : curves) addPieces(c, 1, pieces);
  return pieces;
}

ArcPolygonSet filledSet(const std::vector<CircleSegment>& curves, FillRule rule) {
  const std::vector<ArcPolygonWithHoles> filled = filledPolygons(countedPieces(curves), rule);
  ArcPolygonSet set;
  if (!filled.empty()) set.join(filled.begin(), filled.end());
  return set;
}

// Polygons with holes as a profile: outer loops counterclockwise, holes
// clockwise, slivers dropped.
Profile profileOfPolygons(const std::vector<ArcPolygonWithHoles>& polygons) {
  Profile profile;
  for (const ArcPolygonWithHoles& p : polygons) {
    if (p.is_unbounded()) throw std::logic_error("an evaluated region is unbounded");
    profile.loops.push_back(loopOf(p.outer_boundary()));
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) profile.loops.push_back(loopOf(*h));
  }
  dropSlivers(profile);
  return profile;
}

}  // namespace

PlaneKernel::Point_2 exactPoint(const dvec2& p) {
  return {PlaneKernel::FT(p.x), PlaneKernel::FT(p.y)};
}

std::vector<std::vector<CircleSegment>> exactLoops(const Profile& curved, double ellipseTolerance,
                                                   const CornerWeld* weld) {
  // Bézier curves are not circle segments: polygons within the tolerance.
  for (const ProfileLoop& loop : curved.loops)
    for (const ProfileEdge& e : loop.edges) requireFinite(e);
  const Profile profile = bezierEdgesFlattened(curved, ellipseTolerance);
  std::vector<std::vector<CircleSegment>> loops;
  for (const ProfileLoop& loop : profile.loops) {
    std::vector<CircleSegment> curves;
    const auto addSegment = [&](const dvec2& a, const dvec2& b) {
      if (a != b) curves.emplace_back(exactPoint(a), exactPoint(b));
    };
    const std::size_t n = loop.edges.size();
    const auto straight = [&](std::size_t i) {
      return loop.edges[i % n].kind == ProfileEdge::Kind::Segment;
    };
    for (std::size_t i = 0; i < n; ++i) {
      // Each edge starts where the one before it ends: a loop built in
      // doubles may miss that by a rounding error (an arc's end computed
      // from its angle), which would leave the arrangement a gap and drop
      // the loop.
      ProfileEdge e = loop.edges[i];
      e.from = loop.edges[i == 0 ? n - 1 : i - 1].to;
      requireFinite(e);
      if (e.kind == ProfileEdge::Kind::Segment) {
        if (weld && straight(i + n - 1)) e.from = (*weld)(e.from);
        if (weld && straight(i + 1)) e.to = (*weld)(e.to);
        addSegment(e.from, e.to);
        continue;
      }
      const double sweep = e.angle1 - e.angle0;
      const bool whole = std::abs(sweep) >= kTwoPi;
      if (e.circular()) {
        const double radius = glm::length(e.axes[0]);
        if (whole) {
          if (radius > 0.0) {
            const PlaneKernel::FT r(radius);
            curves.emplace_back(PlaneKernel::Circle_2(exactPoint(e.center), r * r));
          }
        } else if (e.from != e.to) {
          const PlaneKernel::FT r(radius);
          const PlaneKernel::Point_2 c = exactPoint(e.center), a = exactPoint(e.from),
                                     b = exactPoint(e.to);
          if (radius > 0.0 && CGAL::squared_distance(c, a) == r * r &&
              CGAL::squared_distance(c, b) == r * r) {
            // Ends on the circle exactly (an offset's corner of a box, its
            // tangent points on the axes): the arc of that circle, which a
            // circle(r) about the same centre then meets exactly.
            // Counter-clockwise where the angle grows through axes that do
            // not mirror (an SVG's flip of y does).
            const bool counterclockwise = (sweep > 0.0) == (glm::determinant(e.axes) > 0.0);
            const PlaneKernel::Circle_2 circle(
                c, r * r, counterclockwise ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE);
            curves.emplace_back(circle, CircleSegmentTraits::Point_2(a.x(), a.y()),
                                CircleSegmentTraits::Point_2(b.x(), b.y()));
          } else {
            // The circle through the ends and the middle: the ends are the
            // neighbours' exactly, the centre and radius as near as doubles
            // go. Three collinear points make a segment.
            const dvec2 middle = e.arcPoint(0.5 * (e.angle0 + e.angle1));
            curves.emplace_back(a, exactPoint(middle), b);
          }
        }
        continue;
      }
      // An ellipse that is not a circle: the affine image of the unit
      // circle's inscribed polygon, which strays from it by at most the
      // circle's sagitta times the map's largest stretch.
      const double turn = whole ? std::copysign(kTwoPi, sweep) : sweep;
      const int n = arcSegments(largestStretch(e.axes), std::abs(turn), ellipseTolerance, 4);
      dvec2 previous = e.from;
      for (int k = 1; k < n; ++k) {
        const dvec2 p = e.arcPoint(e.angle0 + turn * k / n);
        addSegment(previous, p);
        previous = p;
      }
      addSegment(previous, e.to);
    }
    if (!curves.empty()) loops.push_back(std::move(curves));
  }
  return loops;
}

ArcPolygonSet evenOddSet(const std::vector<std::vector<CircleSegment>>& loops) {
  std::vector<CircleSegment> curves;
  for (const auto& loop : loops) curves.insert(curves.end(), loop.begin(), loop.end());
  return filledSet(curves, FillRule::EvenOdd);
}

namespace {

ArcPolygonSet weldedSetOf(const Region& region, double ellipseTolerance, const CornerWeld& weld) {
  if (region.op() == Region::Op::Leaf)
    return evenOddSet(exactLoops(region.profile(), ellipseTolerance, &weld));
  const std::vector<RegionPtr>& operands = region.operands();
  // One aggregated join (CGAL's divide and conquer) rather than one join
  // per operand, each of which would sweep all that came before it again;
  // for a difference, of the cutters, taken away at once (A − B₁ − … − Bₙ
  // = A − (B₁ ∪ … ∪ Bₙ)): 400 holes cut one by one took a second.
  auto joined = [&](std::size_t from) {
    std::vector<ArcPolygonWithHoles> pieces;
    for (std::size_t i = from; i < operands.size(); ++i)
      weldedSetOf(*operands[i], ellipseTolerance, weld)
          .polygons_with_holes(std::back_inserter(pieces));
    ArcPolygonSet set;
    if (!pieces.empty()) set.join(pieces.begin(), pieces.end());
    return set;
  };
  if (region.op() == Region::Op::Union && operands.size() > 2) return joined(0);
  if (region.op() == Region::Op::Difference && operands.size() > 2) {
    ArcPolygonSet set = weldedSetOf(*operands.front(), ellipseTolerance, weld);
    set.difference(joined(1));
    return set;
  }
  ArcPolygonSet set = weldedSetOf(*operands.front(), ellipseTolerance, weld);
  for (std::size_t i = 1; i < operands.size(); ++i) {
    const ArcPolygonSet other = weldedSetOf(*operands[i], ellipseTolerance, weld);
    switch (region.op()) {
      case Region::Op::Union:
        set.join(other);
        break;
      case Region::Op::Intersection:
        set.intersection(other);
        break;
      case Region::Op::Difference:
        set.difference(other);
        break;
      case Region::Op::Leaf:
        break;
    }
  }
  return set;
}

}  // namespace

ArcPolygonSet polygonSetOf(const Region& region, double ellipseTolerance) {
  return weldedSetOf(region, ellipseTolerance, CornerWeld(region, ellipseTolerance));
}

Profile profileOf(const ArcPolygonSet& set) {
  std::vector<ArcPolygonWithHoles> polygons;
  set.polygons_with_holes(std::back_inserter(polygons));
  return profileOfPolygons(polygons);
}

Profile evaluate(const Region& region, double ellipseTolerance) {
  requireTolerance("a region's ellipses", ellipseTolerance);
  return profileOf(polygonSetOf(region, ellipseTolerance));
}

Profile positiveWindingFill(const std::vector<CircleSegment>& curves) {
  return profileOfPolygons(filledPolygons(countedPieces(curves), FillRule::Positive));
}

namespace {

Profile segmentsFilled(std::span<const std::array<dvec2, 2>> segments, FillRule rule) {
  std::vector<CountedPiece> pieces;
  pieces.reserve(segments.size());
  for (const auto& [from, to] : segments) {
    requireFinite(from, "point");
    requireFinite(to, "point");
    if (from != to) addPieces(CircleSegment(exactPoint(from), exactPoint(to)), 1, pieces);
  }
  return profileOfPolygons(filledPolygons(pieces, rule));
}

}  // namespace

Profile nonZeroFill(std::span<const std::array<dvec2, 2>> segments) {
  return segmentsFilled(segments, FillRule::NonZero);
}

Profile positiveFill(std::span<const std::array<dvec2, 2>> segments) {
  return segmentsFilled(segments, FillRule::Positive);
}

}  // namespace csgray::detail
