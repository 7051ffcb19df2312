#include "primitives/torus.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "engine/solvers/quartic.h"
#include "primitives/check.h"

namespace csgray::detail {

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Where the solver starts looking: just outside the bounding sphere, where
// the torus function is clearly positive (by at least 2·r·kMargin).
constexpr double kMargin = 1e-3;

// Newton steps that polish a root on the ray as given.
constexpr int kPolishSteps = 4;

// How narrow the bracket of a boundary gets (in units of the bounding
// sphere's radius) before the polish: Newton on the quartic along the ray
// as given doubles the digits at each step, so a bracket of 1e-8 leaves it
// one or two steps, where a bracket of a few ulps took the bracketing
// solver several more steps with two square roots each.
constexpr double kBracket = 1e-8;

// For a ray that needs only its first boundary: how far beyond an entry
// (in units of R + r) the torus must surely still be inside for the exit
// in the same piece not to be looked for. Far above the polish's steps.
constexpr double kFirstOnlyGap = 1e-6;

// Newton steps on a convex piece before a near-double root is left to the
// isolation of the quartic's roots: Newton halves the distance to a double
// root per step, so 60 steps reach kBracket from across the chord.
constexpr int kConvexSteps = 60;

// Signed distance from p to the surface along the meridian: the distance
// from the core circle minus r. Its sign is the torus's inside test, it has
// the same zeros as the quartic, and its slope along a unit direction is at
// most 1, which Newton likes. The slope is NaN on the axis (the bracketed
// solver bisects there).
struct MeridianDistance {
  double value, slope;
};

MeridianDistance meridianDistance(const dvec3& p, const dvec3& u, double R, double r) {
  double rho = std::sqrt(p.x * p.x + p.y * p.y);
  double w = rho - R;
  double d = std::sqrt(w * w + p.z * p.z);
  double slope = (w * (p.x * u.x + p.y * u.y) / rho + p.z * u.z) / d;
  return {d - r, slope};
}

// The line in the conditioned frame of objectSpans: b + s·u with u a unit
// vector, b the point nearest the centre, lengths in units of R + r; the
// torus's radii in those units; the stretch [lo, hi] where it may meet the
// torus, whose ends are outside it; t = t0 + s·scale on the ray as given.
struct ConditionedLine {
  dvec3 b, u;
  double R, r, lo, hi, t0, scale;
};

// The line of a ray in the conditioned frame (step 1 of objectSpans),
// narrowed to the ring-shaped box; false when the ray misses the torus
// there or meets that box only outside its window.
//
// The chord of the bounding sphere is narrowed to where the ray is in the
// slab |z| <= r and in the cylinder ρ <= R + r (each grown by the margin,
// so the ends stay outside the torus): a ray that misses this ring-shaped
// box, or crosses it only inside the hole (ρ < R − r at both ends of the
// piece: ρ² is convex along a line), misses the torus without a quartic;
// one that meets it solves on a shorter piece.
bool conditionedLine(const Ray& ray, const TorusInUnits& torus, ConditionedLine& line) {
  const dvec3& o = ray.origin;
  const dvec3& d = ray.dir;
  double dd = glm::dot(d, d);
  if (!(dd > 0.0)) return false;
  // The closest point to the centre, t = t0; a second pass removes what
  // rounding left of its component along d.
  // Reciprocals are multiplied where quotients were: four divisions a ray
  // instead of twelve, each about 13 cycles on the path. The frame may
  // differ in its last bit; the polish on the ray as given (kPolishSteps)
  // takes that out of the boundaries.
  const double invDd = 1.0 / dd;
  double t0 = -glm::dot(o, d) * invDd;
  dvec3 closest = o + t0 * d;
  double again = glm::dot(closest, d) * invDd;
  t0 -= again;
  closest -= again * d;
  const double size = torus.size;
  double len = std::sqrt(dd), invLen = 1.0 / len;
  dvec3 b = closest * (1.0 / size);  // the origin of s, in units of the bounding radius
  dvec3 u = d * invLen;              // unit direction
  double c = glm::dot(b, b);
  if (!(c < 1.0)) return false;  // misses the bounding sphere (or touches it on the equator)
  double reach = std::sqrt((1.0 + kMargin) * (1.0 + kMargin) - c);
  double scale = size * invLen;  // t = t0 + s·scale
  if (t0 + reach * scale < ray.tMin || t0 - reach * scale > ray.tMax) return false;
  double lo = -reach, hi = reach;
  const double slab = torus.slab;
  if (u.z != 0.0) {
    const double invUz = 1.0 / u.z;
    double a0 = (-slab - b.z) * invUz, a1 = (slab - b.z) * invUz;
    if (a0 > a1) std::swap(a0, a1);
    lo = std::max(lo, a0), hi = std::min(hi, a1);
  } else if (std::abs(b.z) > slab) {
    return false;
  }
  // ρ²(s) = a·s² + 2h·s + g against (1 + margin)².
  const double a = u.x * u.x + u.y * u.y, h = b.x * u.x + b.y * u.y, g = b.x * b.x + b.y * b.y;
  const double outer = (1.0 + kMargin) * (1.0 + kMargin);
  if (a > 0.0) {
    const double disc = h * h - a * (g - outer);
    if (!(disc > 0.0)) return false;
    const double root = std::sqrt(disc);
    const double invA = 1.0 / a;
    lo = std::max(lo, (-h - root) * invA), hi = std::min(hi, (-h + root) * invA);
  } else if (g > outer) {
    return false;
  }
  if (!(lo < hi)) return false;
  const double hole = torus.hole;
  auto rho2 = [&](double s) { return (a * s + 2.0 * h) * s + g; };
  if (hole > 0.0 && rho2(lo) < hole * hole && rho2(hi) < hole * hole) return false;
  if (t0 + hi * scale < ray.tMin || t0 + lo * scale > ray.tMax) return false;
  line = ConditionedLine{b, u, torus.R, torus.r, lo, hi, t0, scale};
  return true;
}

// A boundary at s, within the piece [lo, hi] of the line that holds no other.
struct Root {
  double s, lo, hi;
};

// The tube's own factor of the quartic along the line,
//   g(s) = |p|² + R² − r² − 2R·ρ = (ρ − R)² + z² − r²,   ρ = √(x² + y²),
// negative inside the torus and positive outside, with its slope. With
// |p|² = s² + 2e·s + c and ρ² = a·(s − sAxis)² + n, where sAxis is where
// the line passes nearest the axis, at distance √n, its second derivative
// is 2 − 2R·a·n/ρ³ (the distance from the axis has ρ'' = a·n/ρ³).
struct TubeFactor {
  double e, k, a, n, sAxis, R;

  std::pair<double, double> operator()(double s) const {
    const double w = s - sAxis;
    const double rho = std::sqrt(a * w * w + n);
    const double value = (s + 2.0 * e) * s + k - 2.0 * R * rho;
    const double slope = 2.0 * (s + e) - 2.0 * R * a * w / rho;
    return {value, slope};
  }
};

// The tube's factor on a line, and where it is convex or concave: g'' = 0
// at sAxis ± w, where ρ³ = R·a·n, so (s − sAxis)² = ((R·a·n)^(2/3) − n)/a;
// there are two such points when (R·a·n)² > n³, that is R²a² > n. g is
// concave between them (near the axis) and convex outside.
struct TubeOnLine {
  TubeFactor g;
  double w;          // half the concave stretch; −1 when there is none
  bool throughAxis;  // the line meets the axis, where g has a kink (or is flat, on it)

  // lo, the inflections strictly between lo and hi, and hi: the ends of
  // the pieces. Returns the count.
  int breaks(double lo, double hi, double out[4]) const {
    int count = 0;
    out[count++] = lo;
    if (w >= 0.0)
      for (double end : {g.sAxis - w, g.sAxis + w})
        if (end > out[count - 1] && end < hi) out[count++] = end;
    out[count++] = hi;
    return count;
  }
  // −1 on the concave piece [lo, hi], 1 on a convex one.
  double sign(double lo, double hi) const {
    return std::abs(0.5 * (lo + hi) - g.sAxis) < w ? -1.0 : 1.0;
  }
};

TubeOnLine tubeOnLine(const ConditionedLine& line) {
  const dvec3 &b = line.b, &u = line.u;
  const double R = line.R, r = line.r;
  const double a = u.x * u.x + u.y * u.y;
  // n = ((x² + y²)·a − (b·u in xy)²)/a, whose numerator is (b × u)z² by
  // Lagrange's identity: no cancellation.
  const double cross = b.x * u.y - b.y * u.x;
  TubeOnLine tube{TubeFactor{glm::dot(b, u), glm::dot(b, b) + R * R - r * r, a,
                             a > 0.0 ? cross * cross / a : b.x * b.x + b.y * b.y,
                             a > 0.0 ? -(b.x * u.x + b.y * u.y) / a : 0.0, R},
                  -1.0, false};
  const double n = tube.g.n;
  tube.throughAxis = !(n > 0.0);
  if (!tube.throughAxis && R * R * a * a > n) {
    const double ran = R * a * n;
    tube.w = std::sqrt((std::cbrt(ran * ran) - n) / a);
  }
  return tube;
}

enum class Search { Root, None, Undecided };

// Newton's method on a convex function h from an end x of [lo, hi] where h
// is positive, towards the nearest root: every tangent lies below a convex
// function, so each iterate stays on x's side of that root and they approach
// it monotonically (Kincaid and Cheney, "Numerical Analysis", §3.2, on
// Newton's method for convex functions). When h slopes away from the root
// side or an iterate leaves [lo, hi], there is no root; a near-double root,
// where convergence is slow, is left undecided after a bounded number of
// steps. The sign flips h into a convex function on concave pieces.
template <class F>
Search convexNewton(const F& g, double sign, double x, double lo, double hi, double& root) {
  const bool rightward = x == lo;
  for (int step = 0; step < kConvexSteps; ++step) {
    auto [value, slope] = g(x);
    value *= sign, slope *= sign;
    if (!(value > 0.0)) {
      root = x;  // rounding reached the root
      return Search::Root;
    }
    if (rightward ? !(slope < 0.0) : !(slope > 0.0)) return Search::None;
    double next = x - value / slope;
    if (!(next >= lo && next <= hi)) return Search::None;
    if (std::abs(next - x) <= kBracket) {
      root = next;
      return Search::Root;
    }
    x = next;
  }
  return Search::Undecided;
}

// The boundaries on [lo, hi] of the line in order, by isolating the
// quartic's roots (quartic.h); ring says the torus has no lemon (R >= r).
// Returns the count.
int boundariesByIsolation(const ConditionedLine& line, double lo, double hi, bool ring,
                          Root roots[4]) {
  const dvec3 &b = line.b, &u = line.u;
  const double R = line.R, r = line.r;
  // The quartic in s: with P(s) = |p|² + R² − r² = s² + 2e·s + k (e ≈ 0
  // is what is left of b·u) and x² + y² = a·s² + 2h·s + g,
  //   q(s) = P² − 4R²(a·s² + 2h·s + g),
  // and its derivative, whose sign changes split [lo, hi].
  double e = glm::dot(b, u);
  double k = glm::dot(b, b) + R * R - r * r;
  double a = u.x * u.x + u.y * u.y;
  double h = b.x * u.x + b.y * u.y;
  double quadratic = 4.0 * e * e + 2.0 * k - 4.0 * R * R * a;
  double linear = 4.0 * e * k - 8.0 * R * R * h;
  const double derivative[4] = {linear, 2.0 * quadratic, 12.0 * e, 4.0};
  double breaks[5];
  int count = 0;
  breaks[count++] = lo;
  double critical[3];
  int n = polynomialSublevelBoundaries(derivative, 3, lo, hi, critical);
  for (int i = 0; i < n; ++i)
    if (critical[i] > breaks[count - 1] && critical[i] < hi) breaks[count++] = critical[i];
  breaks[count++] = hi;

  auto distance = [&](double s) {
    MeridianDistance m = meridianDistance(b + s * u, u, R, r);
    return std::pair<double, double>(m.value, m.slope);
  };
  int found = 0;
  // Which side each break is on comes from the meridian distance, which
  // is exact in sign where the quartic may round. Within a piece where the
  // side changes, a ring torus's quartic (its second factor is positive
  // there) changes sign at the same point and is far cheaper to evaluate
  // (no square roots); a spindle's may also vanish on its lemon, so it
  // keeps the distance.
  const double quartic[5] = {k * k - 4.0 * R * R * (b.x * b.x + b.y * b.y), linear, quadratic,
                             4.0 * e, 1.0};
  auto polynomial = [&](double s) {
    return std::pair<double, double>(polynomialValue(quartic, 4, s),
                                     polynomialSlope(quartic, 4, s));
  };
  bool inside = distance(breaks[0]).first <= 0.0;
  for (int i = 1; i < count; ++i) {
    bool next = distance(breaks[i]).first <= 0.0;
    if (next != inside) {
      double s = ring ? bracketedRoot(polynomial, breaks[i - 1], breaks[i], inside, kBracket)
                      : bracketedRoot(distance, breaks[i - 1], breaks[i], inside, kBracket);
      roots[found++] = {s, breaks[i - 1], breaks[i]};
    }
    inside = next;
  }
  return found;
}

// The boundaries on the line's [lo, hi] in order, found piece by piece
// where the tube's factor g is convex or concave (TubeOnLine). On a
// convex piece, {g <= 0} is one interval, so the signs at its ends and
// Newton's method from the ends (convexNewton) find its boundaries; on a
// concave piece, the same for {g >= 0}. A piece this does
// not settle (a near-tangency), or the whole line when it meets the axis
// (where g has a kink), goes to the isolation of the quartic's roots on
// that piece alone. ring says the torus has no lemon (R >= r). Returns the
// count, or −1 if an end of [lo, hi] is inside (it cannot be).
//
// With firstOnly, when the first boundary is an entry after tMin on the
// ray as given (its piece starts there, and the polish keeps it in its
// piece), the search stops there and returns 1: the ray's first boundary
// is found, and its exit not looked for. An entry with an exit in the
// same piece is taken so only when the exit is surely more than
// kFirstOnlyGap beyond it (g < 0 there), so that the whole search would
// keep the span rather than find a tangency polished to a point.
int boundariesOnConvexPieces(const ConditionedLine& line, bool ring, bool firstOnly, double tMin,
                             Root roots[4]) {
  const TubeOnLine tube = tubeOnLine(line);
  const TubeFactor& g = tube.g;
  const bool throughAxis = tube.throughAxis;
  double breaks[4];
  const int count = tube.breaks(line.lo, line.hi, breaks);

  int found = 0;
  double gLo = g(breaks[0]).first;
  if (!(gLo > 0.0)) return -1;
  for (int i = 1; i < count; ++i) {
    const double lo = breaks[i - 1], hi = breaks[i];
    const double gHi = g(hi).first;
    const double sign = tube.sign(lo, hi);
    const bool loPositive = sign * gLo > 0.0, hiPositive = sign * gHi > 0.0;
    gLo = gHi;
    if (!throughAxis && !loPositive && !hiPositive) continue;  // the piece holds no boundary
    Root piece[4];
    int n = -1;
    double first, last;
    // The first boundary is an entry (the line starts outside); it ends the
    // search for firstOnly when its piece starts after tMin.
    const bool entryEnds = firstOnly && found == 0 && line.t0 + lo * line.scale > tMin;
    if (throughAxis) {
      // n stays −1: isolate.
    } else if (loPositive && hiPositive) {
      // Two boundaries or none: Newton from lo decides.
      Search from = convexNewton(g, sign, lo, lo, hi, first);
      const double beyond = first + kFirstOnlyGap;
      if (from == Search::None) {
        n = 0;
      } else if (from == Search::Root && entryEnds && beyond < hi && sign * g(beyond).first < 0.0) {
        roots[0] = {first, lo, first + 0.5 * kFirstOnlyGap};
        return 1;
      } else if (from == Search::Root && convexNewton(g, sign, hi, lo, hi, last) == Search::Root &&
                 first <= last) {
        const double middle = 0.5 * (first + last);
        piece[0] = {first, lo, middle};
        piece[1] = {last, middle, hi};
        n = 2;
      }
    } else if (convexNewton(g, sign, loPositive ? lo : hi, lo, hi, first) == Search::Root) {
      // One boundary, approached from the end where sign·g is positive.
      piece[0] = {first, lo, hi};
      n = 1;
      if (entryEnds) {
        roots[0] = piece[0];
        return 1;
      }
    }
    if (n < 0) n = boundariesByIsolation(line, lo, hi, ring, piece);
    if (found + n > 4) return -1;
    for (int j = 0; j < n; ++j) roots[found++] = piece[j];
  }
  if (!(gLo > 0.0) || found % 2 != 0) return -1;
  return found;
}

// g this far from 0 (in the conditioned units, where g is O(1), times
// 1 + the ray's start's distance from the line's closest point) says which
// side of the surface a point is on beyond doubt: far above the rounding
// of g and of the point's t, so the boundaries found exactly (to a few ulps
// of t after the polish) lie on the same side of it; far below what a
// shadow ray's start off the surface gives (1e-9 of the scene's size along
// the normal makes g about 2r times that in the torus's units).
constexpr double kClearly = 1e-12;

enum class Meets { Yes, No, Undecided };

// Does the torus meet the open window (sMin, sMax) of the line? The answer
// of the first boundary's search (Solid::meetsWindow), found with less:
// only the window's part of the line is searched, with no polish, and the
// search stops at a point surely inside. Yes at a point where g is clearly
// negative; no where g is clearly positive at the ends of the window's
// pieces and Newton's method proves each convex piece free of boundaries
// (a concave one positive at its ends is positive throughout). Anything
// nearer the surface (a window's end on it, a near-tangency) is undecided
// and left to the search for the first boundary.
Meets meetsOnWindow(const ConditionedLine& line, double sMin, double sMax) {
  const double lo = std::max(line.lo, sMin), hi = std::min(line.hi, sMax);
  if (!(lo < hi)) return Meets::No;
  const double clearly = kClearly * (1.0 + std::abs(line.t0 / line.scale));
  const TubeOnLine tube = tubeOnLine(line);
  const TubeFactor& g = tube.g;
  auto side = [&](double s) {
    const double value = g(s).first;
    return value < -clearly ? Meets::Yes : value > clearly ? Meets::No : Meets::Undecided;
  };
  // A ray through the tube's middle is inside where it crosses the plane
  // of the core circle: one evaluation, no search.
  if (line.u.z != 0.0) {
    const double across = -line.b.z / line.u.z;
    if (across > lo && across < hi && side(across) == Meets::Yes) return Meets::Yes;
  }
  if (tube.throughAxis) return Meets::Undecided;
  double breaks[4];
  const int count = tube.breaks(lo, hi, breaks);
  for (int i = 0; i < count; ++i)
    if (Meets at = side(breaks[i]); at != Meets::No) return at;
  for (int i = 1; i < count; ++i) {
    const double pieceLo = breaks[i - 1], pieceHi = breaks[i];
    if (tube.sign(pieceLo, pieceHi) < 0.0) continue;
    double entry;
    const Search search = convexNewton(g, 1.0, pieceLo, pieceLo, pieceHi, entry);
    if (search == Search::None) continue;
    if (search == Search::Undecided) return Meets::Undecided;
    // An entry: the window meets the torus if it is surely inside a little
    // beyond (not a tangency).
    const double beyond = entry + kFirstOnlyGap;
    return beyond < pieceHi && side(beyond) == Meets::Yes ? Meets::Yes : Meets::Undecided;
  }
  return Meets::No;
}

}  // namespace

Torus::Torus(double majorRadius, double minorRadius) : R_(majorRadius), r_(minorRadius) {
  requireFinite("torus", "R", majorRadius);
  requirePositive("torus", "r", minorRadius);
  if (majorRadius < 0.0) {
    std::ostringstream msg;
    msg << "torus: R must be >= 0 (got " << majorRadius << ")";
    throw std::invalid_argument(msg.str());
  }
  const double size = R_ + r_;
  inUnits_ = {size, R_ / size, r_ / size, r_ / size * (1.0 + kMargin),
              (R_ - r_) / size * (1.0 - kMargin)};
}

// The ray meets the surface where f(o + t·d) = 0, with
//   f(p) = (|p|² + R² − r²)² − 4R²(x² + y²)
//        = ((ρ − R)² + z² − r²)·((ρ + R)² + z² − r²),   ρ = √(x² + y²),
// a quartic in t (Cychosz, "Intersecting a ray with an elliptical torus",
// Graphics Gems II, 1991). The first factor is the torus; the second is
// positive except inside the lemon of a spindle torus (R < r), which lies
// inside the solid, so the quartic's roots are the surface's, plus, for a
// spindle, the lemon's. Steps:
//  1. Condition the quartic: move the origin to the point of the line
//     closest to the centre, make the direction unit and scale lengths so
//     the bounding sphere has radius 1. Then |p|² = s² + c with c <= 1 and
//     all coefficients are O(1), however far away the ray starts.
//  2. Find the boundaries where the tube's own factor g = (ρ − R)² + z² − r²
//     (the sign of the inside test) changes sign: g is convex along the
//     line except on one stretch near the axis, where it is concave, and
//     Newton's method from the ends of such a piece finds its boundaries
//     monotonically (boundariesOnConvexPieces). Where that does not settle
//     them (a line through the axis, a near-tangency), isolate the
//     quartic's roots (quartic.h): the roots of the derivative split the
//     chord into pieces where the quartic is monotone, the inside test at
//     the ends of each says whether it holds a boundary (the lemon's roots
//     never change that sign and are passed over), and a safeguarded
//     Newton–bisection finds it (boundariesByIsolation).
//  3. Polish each boundary by Newton on f along the ray as given, kept
//     inside its piece, taking a step only while |f| decreases.
//  4. Pair the boundaries (outside at both ends of the chord) into spans;
//     spans that polishing left empty are dropped and ones that touch are
//     joined, so a tangent ray gives a tiny span or nothing.
void Torus::objectSpans(const Ray& ray, SpanList& out) const { spansOf(ray, false, out); }

// A camera or shadow ray needs only the first boundary: an entry ends the
// search, and the span it starts ends at the end of the chord instead of
// the exit (Solid::spansToFirstBoundary allows it).
void Torus::objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const {
  spansOf(ray, true, out);
}

// A shadow ray asks only whether the torus meets its window: answered on
// the window's part of the line (meetsOnWindow) where that is beyond
// doubt, by the first boundary's spans otherwise. A shadow ray that starts
// on a torus and leaves it searches only the line beyond its start, where
// the whole search found the boundaries it starts from as well.
bool Torus::objectMeetsWindow(const Ray& ray, SpanList& scratch) const {
  ConditionedLine line;
  if (!conditionedLine(ray, inUnits_, line)) return false;
  const double sMin = (ray.tMin - line.t0) / line.scale;
  const double sMax = (ray.tMax - line.t0) / line.scale;
  switch (meetsOnWindow(line, sMin, sMax)) {
    case Meets::Yes:
      return true;
    case Meets::No:
      return false;
    case Meets::Undecided:
      break;
  }
  return Primitive::objectMeetsWindow(ray, scratch);
}

void Torus::spansOf(const Ray& ray, bool firstOnly, SpanList& out) const {
  // 1. The conditioned line, narrowed to the ring-shaped box.
  ConditionedLine line;
  if (!conditionedLine(ray, inUnits_, line)) return;
  const dvec3& o = ray.origin;
  const dvec3& d = ray.dir;
  const double t0 = line.t0, scale = line.scale, hi = line.hi;

  // 2. The boundaries, each with the piece it lies in: on the pieces where
  // the tube's own factor is convex or concave when that settles them, by
  // the isolation of the quartic's roots otherwise.
  Root roots[4];
  int found = boundariesOnConvexPieces(line, R_ >= r_, firstOnly, ray.tMin, roots);
  if (found < 0) return;  // cannot happen: the chord's ends are outside

  // 3. Polish on f(o + t·d) = first factor · second factor, with its
  // gradient 4(|p|² + R² − r²)·p − 8R²·(x, y, 0) for the slope.
  double R2 = R_ * R_, r2 = r_ * r_;
  auto f = [&](double t) {
    dvec3 p = o + t * d;
    double rho2 = p.x * p.x + p.y * p.y;
    double rho = std::sqrt(rho2);
    double z2r2 = p.z * p.z - r2;
    double value = ((rho - R_) * (rho - R_) + z2r2) * ((rho + R_) * (rho + R_) + z2r2);
    double P = rho2 + p.z * p.z + R2 - r2;
    dvec3 gradient = 4.0 * P * p - 8.0 * R2 * dvec3(p.x, p.y, 0.0);
    return std::pair<double, double>(value, glm::dot(gradient, d));
  };
  double t[4];
  for (int i = 0; i < found; ++i) {
    double lo = t0 + roots[i].lo * scale, hi = t0 + roots[i].hi * scale;
    double x = std::clamp(t0 + roots[i].s * scale, lo, hi);
    auto [value, slope] = f(x);
    for (int step = 0; step < kPolishSteps && value != 0.0; ++step) {
      double next = x - value / slope;
      if (!(next >= lo && next <= hi) || next == x) break;
      auto [v, s] = f(next);
      if (!(std::abs(v) < std::abs(value))) break;
      x = next;
      value = v;
      slope = s;
    }
    t[i] = x;
  }
  // Keep the order the pieces gave (polishing stays within them).
  for (int i = 1; i < found; ++i) t[i] = std::max(t[i], t[i - 1]);

  // 4. Spans: boundaries alternate in, out; a first boundary alone is an
  // entry, whose span ends at the end of the chord in its place.
  if (found == 1) {
    if (t[0] <= ray.tMax) out.push_back(boundary(t[0]), boundary(std::max(t[0], t0 + hi * scale)));
    return;
  }
  Span spans[2];
  int made = 0;
  for (int i = 0; i + 1 < found; i += 2) {
    if (!(t[i] < t[i + 1])) continue;  // a tangency polished to a point
    if (made > 0 && t[i] <= spans[made - 1].out.t) {
      spans[made - 1].out = boundary(t[i + 1]);  // a gap polished away
      continue;
    }
    spans[made++] = Span{boundary(t[i]), boundary(t[i + 1])};
  }
  for (int i = 0; i < made; ++i) {
    if (spans[i].out.t < ray.tMin || spans[i].in.t > ray.tMax) continue;
    out.push_back(spans[i]);
  }
}

bool Torus::objectContains(const dvec3& p) const {
  double w = std::sqrt(p.x * p.x + p.y * p.y) - R_;
  return w * w + p.z * p.z <= r_ * r_;
}

// Half the gradient of (ρ − R)² + z² − r². On the surface the gradient of
// the quartic f is this times 2·((ρ + R)² + z² − r²) = 8Rρ >= 0, the same
// direction, but it vanishes where that factor does (R = 0, a ball), so the
// torus's own factor is used.
dvec3 Torus::objectNormal(const dvec3& p, int) const {
  double rho = std::sqrt(p.x * p.x + p.y * p.y);
  if (rho == 0.0) {
    // On the axis: a pole of the ball (R = 0) or a cusp of a spindle.
    return {0.0, 0.0, p.z < 0.0 ? -1.0 : 1.0};
  }
  double radial = 1.0 - R_ / rho;
  dvec3 n(radial * p.x, radial * p.y, p.z);
  if (n == dvec3(0.0)) return {p.x, p.y, 0.0};  // on the core circle: not on the surface
  return n;
}

Bounds Torus::objectBounds() const {
  double outer = R_ + r_;
  return {dvec3(-outer, -outer, -r_), dvec3(outer, outer, r_)};
}

}  // namespace csgray::detail
