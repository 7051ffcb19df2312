#include "primitives/linear_extrusion.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "engine/solvers/quartic.h"
#include "engine/solvers/sine_cosine.h"
#include "primitives/check.h"

namespace csgray::detail {

namespace {

// v turned by the angle whose cosine and sine are c and s.
dvec2 turned(const dvec2& v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

// (The twist's angles through sineCosine: a twisted path turns a point at
// every step of its root search, and the C library's sine and cosine were a
// third of a twisted gear's render.)
dvec2 rotated(const dvec2& v, double angle) {
  const SineCosine sc = sineCosine(angle);
  return turned(v, sc.cos, sc.sin);
}

// The ray's coordinates in a normalised parameter: t = middle + half·s,
// s ∈ [-1, 1] over the window, so that the polynomials' coefficients are
// of the size of the part however far away the ray starts.
struct Normalised {
  double middle, half;
  double toS(double t) const { return (t - middle) / half; }
  double toT(double s) const { return middle + half * s; }
};

// Without twist: u(t) = (x(t)/σx(t), y(t)/σy(t)), each a ratio of linear
// functions of t. An edge's implicit function times σx·σy (both positive
// in the slab), or times its square for an ellipse, is a polynomial:
// degree 1 and 2 for a uniform scale (the factors σ cancel), 2 and 4
// otherwise.
struct ScaledPath {
  static constexpr bool kBoxedPieces = true;  // each piece's image lies in its box
  Normalised n;
  SweepPolynomial x, y, sx, sy;  // in s
  bool uniform;
  SweepSegmentTest straight;  // uniform: the curve's segment

  dvec2 at(double t) const {
    const double s = n.toS(t);
    return {polynomialValue(x.c, 1, s) / polynomialValue(sx.c, 1, s),
            polynomialValue(y.c, 1, s) / polynomialValue(sy.c, 1, s)};
  }

  bool meets(const SweepPiece& piece, const dvec2& lo, const dvec2& hi) const {
    return uniform ? straight.meets(lo, hi) : sweepPieceMeets(piece, lo, hi);
  }

  int roots(const SweepEdge& e, double t0, double t1, double* out) const {
    if (e.bezier) return curveRoots(e, t0, t1, out);
    SweepPolynomial p;
    if (uniform) {
      // The products of linear polynomials written out.
      if (!e.arc) {
        p.n = 1;
        for (int i = 0; i < 2; ++i)
          p.c[i] = x.c[i] * e.normal.x + y.c[i] * e.normal.y - sx.c[i] * e.offset;
      } else {
        const double X0 = x.c[0] - sx.c[0] * e.center.x, X1 = x.c[1] - sx.c[1] * e.center.x;
        const double Y0 = y.c[0] - sx.c[0] * e.center.y, Y1 = y.c[1] - sx.c[1] * e.center.y;
        const double a0 = X0 * e.toUnit[0][0] + Y0 * e.toUnit[1][0];
        const double a1 = X1 * e.toUnit[0][0] + Y1 * e.toUnit[1][0];
        const double b0 = X0 * e.toUnit[0][1] + Y0 * e.toUnit[1][1];
        const double b1 = X1 * e.toUnit[0][1] + Y1 * e.toUnit[1][1];
        p.n = 2;
        p.c[0] = a0 * a0 + b0 * b0 - sx.c[0] * sx.c[0];
        p.c[1] = 2.0 * (a0 * a1) + 2.0 * (b0 * b1) - 2.0 * (sx.c[0] * sx.c[1]);
        p.c[2] = a1 * a1 + b1 * b1 - sx.c[1] * sx.c[1];
      }
    } else if (!e.arc) {
      p = x * sy * e.normal.x + y * sx * e.normal.y - sx * sy * e.offset;
    } else {
      const SweepPolynomial X = (x - sx * e.center.x) * sy, Y = (y - sy * e.center.y) * sx;
      const SweepPolynomial w0 = X * e.toUnit[0][0] + Y * e.toUnit[1][0];
      const SweepPolynomial w1 = X * e.toUnit[0][1] + Y * e.toUnit[1][1];
      const SweepPolynomial both = sx * sy;
      p = w0 * w0 + w1 * w1 - both * both;
    }
    double s[4];
    const int count = sweepPolynomialRoots(p, n.toS(t0), n.toS(t1), s);
    for (int i = 0; i < count; ++i) out[i] = n.toT(s[i]);
    return count;
  }

  // A Bézier curve (only on a uniform path: SweptRegion makes others
  // polygons). The straight image of the ray is the line A·u.x + B·u.y + C
  // = 0, from eliminating the ray's parameter r between u.x·σ(r) = x(r)
  // and u.y·σ(r) = y(r) (each linear in r); along the curve B(q) that is a
  // polynomial of the curve's degree in q, whose roots are where the side
  // (the curve's ruled surface) is met. Each root's point gives r back from
  // the better conditioned of the two equations.
  int curveRoots(const SweepEdge& e, double t0, double t1, double* out) const {
    if (!uniform) return 0;
    const double A = sx.c[1] * y.c[0] - sx.c[0] * y.c[1];
    const double B = x.c[1] * sx.c[0] - x.c[0] * sx.c[1];
    const double C = x.c[0] * y.c[1] - x.c[1] * y.c[0];
    SweepPolynomial p;
    p.n = e.curve.degree;
    for (int k = 0; k <= p.n; ++k) p.c[k] = A * e.curve.c[k].x + B * e.curve.c[k].y;
    p.c[0] += C;
    constexpr double kSlack = 1e-9;  // SweptRegion's kEdgeSlack: an end met through both its edges
    double q[4];
    const int found = sweepPolynomialRoots(p, -kSlack, 1.0 + kSlack, q);
    const double r0 = n.toS(t0), r1 = n.toS(t1);
    int count = 0;
    for (int i = 0; i < found; ++i) {
      const dvec2 u = e.curve.at(q[i]);
      const double kx = x.c[1] - u.x * sx.c[1], ky = y.c[1] - u.y * sx.c[1];
      const double r = std::abs(kx) >= std::abs(ky) ? (u.x * sx.c[0] - x.c[0]) / kx
                                                    : (u.y * sx.c[0] - y.c[0]) / ky;
      if (r >= r0 && r <= r1) out[count++] = n.toT(r);
    }
    return count;
  }
};

// With twist: u(t) = Rot(τ·ζ(t))·v(t), v = (x/σx, y/σy), τ the twist in
// radians. The roots of an edge's implicit function f(t) = g(u(t)) are
// isolated on bounded intervals: with bounds L1 on |f'| and L2 on |f''|
// over the piece, an interval of half-width w about m holds no root when
// |f(m)| > L1·w, and f is monotone on it when |f'(m)| > L2·w, so that a
// change of sign brackets its only root; otherwise it is halved. Intervals
// narrower than the resolution that may still hold roots are a grazing
// touch: reported as a double root, which the spans resolve by asking the
// region (profile_sweep.h).
// Pieces of a twisted path are at most this long (in units of the
// region's size), so that each piece's box holds few edges and each edge's
// roots are isolated over a short stretch.
constexpr double kTwistedPiece = 1.0 / 64.0;
constexpr int kMaxTwistedPieces = 512;

struct TwistedPath {
  static constexpr bool kBoxedPieces = true;
  Normalised n;
  dvec3 o, d;
  double z0, h, tau;
  dvec2 scale;
  double resolution;  // in t

  // Bounds over a stretch of the ray: |u| (reach), |u'| and |u''| per unit
  // t (speed, bend). Those of the window serve every piece while σ stays
  // within a factor of two over it; otherwise each piece gets its own: near
  // the apex of a scale of 0, σ falls to 1e-12 and the window's bounds grow
  // past 1e24, so that the root search refuses no interval and bisects
  // every edge down to the resolution.
  struct Bounds {
    double reach, speed, bend;
  };
  // The planar distance |xy(t)| is largest at an end, σ smallest at one.
  Bounds boundsOver(double ta, double tb) const {
    const dvec3 pa = o + ta * d, pb = o + tb * d;
    const double far = std::max(glm::length(dvec2(pa)), glm::length(dvec2(pb)));
    const double sigmaMin = std::max(1e-12, std::min(sigmaLeast(pa), sigmaLeast(pb)));
    const double dz = std::abs(d.z) / h;
    const double sigmaRate = std::max(std::abs(scale.x - 1.0), std::abs(scale.y - 1.0)) * dz;
    const double v = far / sigmaMin;
    const double dv = (glm::length(dvec2(d)) + v * sigmaRate) / sigmaMin;
    const double ddv = 2.0 * sigmaRate * dv / sigmaMin;
    const double spin = std::abs(tau) * dz;
    return {v, dv + spin * v, ddv + 2.0 * spin * dv + spin * spin * v};
  }
  // A lower bound on |u| over a stretch: |u| = |v| >= |xy| / max σ, with
  // |xy| least at the point of the segment nearest the axis.
  double nearestOver(double ta, double tb) const {
    const dvec3 pa = o + ta * d, pb = o + tb * d;
    const dvec2 a(pa), ab = dvec2(pb) - a;
    const double l2 = glm::dot(ab, ab);
    const double s = l2 > 0.0 ? std::clamp(-glm::dot(a, ab) / l2, 0.0, 1.0) : 0.0;
    const double sigmaMax = std::max(sigmaMost(pa), sigmaMost(pb));
    return glm::length(a + s * ab) / sigmaMax;
  }
  // The scale σ of the two axes at a point's height: the lesser, the greater.
  double sigmaAt(const dvec3& p, double s) const { return 1.0 + (s - 1.0) * (p.z - z0) / h; }
  double sigmaLeast(const dvec3& p) const {
    return std::min(sigmaAt(p, scale.x), sigmaAt(p, scale.y));
  }
  double sigmaMost(const dvec3& p) const {
    return std::max(sigmaAt(p, scale.x), sigmaAt(p, scale.y));
  }
  // Does σ fall below half its largest over the window [t0, t1]?
  bool sigmaVaries(double t0, double t1) const {
    const double a = sigmaLeast(o + t0 * d), b = sigmaLeast(o + t1 * d);
    return std::min(a, b) < 0.5 * std::max(a, b);
  }
  Bounds window;
  bool perPiece = false;  // bounds per piece, not the window's
  mutable struct {
    double t0 = kInfinity, t1 = kInfinity;
    Bounds bounds;
  } lastBounds;
  const Bounds& boundsFor(double t0, double t1) const {
    if (!perPiece) return window;
    // (The edges near a piece are solved one after another over the
    // piece: its bounds are worked out once.)
    if (t0 != lastBounds.t0 || t1 != lastBounds.t1) lastBounds = {t0, t1, boundsOver(t0, t1)};
    return lastBounds.bounds;
  }

  bool scaled = true;  // scale is not (1, 1); without scale σ = 1 and v = xy, no division

  // The turn at the middle of a stretch, for a root search along it: the
  // edges near a piece are searched one after another over the piece, so
  // it is worked out once a piece.
  struct Turn {
    double t0 = kInfinity, t1 = kInfinity, t = 0.0;
    SineCosine sc{0.0, 1.0};
  };
  mutable Turn lastTurn;
  const Turn& turnFor(double t0, double t1) const {
    if (t0 != lastTurn.t0 || t1 != lastTurn.t1) {
      const double t = 0.5 * (t0 + t1);
      lastTurn = {t0, t1, t, sineCosine(tau * zeta(t))};
    }
    return lastTurn;
  }

  double zeta(double t) const { return (o.z + t * d.z - z0) / h; }
  bool meets(const SweepPiece& piece, const dvec2& lo, const dvec2& hi) const {
    return sweepPieceMeets(piece, lo, hi);
  }
  // v(t) = xy(t)/σ(t), the untwisted point, at z = ζ(t). (Without scale
  // the quotients by σ = 1 would give xy bit for bit.)
  dvec2 untwisted(double t, double z) const {
    if (!scaled) return {o.x + t * d.x, o.y + t * d.y};
    return {(o.x + t * d.x) / (1.0 + (scale.x - 1.0) * z),
            (o.y + t * d.y) / (1.0 + (scale.y - 1.0) * z)};
  }
  // v'(t) for the v at ζ(t) = z: (xy' − v·σ')/σ.
  dvec2 untwistedVelocity(const dvec2& v, double z) const {
    if (!scaled) return {d.x, d.y};
    const double dz = d.z / h;
    const double sx = 1.0 + (scale.x - 1.0) * z, sy = 1.0 + (scale.y - 1.0) * z;
    return {(d.x - v.x * (scale.x - 1.0) * dz) / sx, (d.y - v.y * (scale.y - 1.0) * dz) / sy};
  }
  dvec2 at(double t) const {
    const double z = zeta(t);
    return rotated(untwisted(t, z), tau * z);
  }

  int roots(const SweepEdge& e, double t0, double t1, double* out) const {
    // |∇g| and the norm of the Hessian of g over the curve's reach.
    const Bounds& b = boundsFor(t0, t1);
    double grad = 1.0, hess = 0.0;
    if (e.arc) {
      const glm::dmat2 g = glm::transpose(e.toUnit) * e.toUnit;
      const double norm =
          std::sqrt(g[0][0] * g[0][0] + g[0][1] * g[0][1] + g[1][0] * g[1][0] + g[1][1] * g[1][1]);
      grad = 2.0 * norm * (b.reach + glm::length(e.center));
      hess = 2.0 * norm;
    }
    const double L1 = grad * b.speed, L2 = hess * b.speed * b.speed + grad * b.bend;
    // The turn Rot(τζ) along the stretch, from the one at its middle.
    const Turn& middle = turnFor(t0, t1);
    const double spin = tau * (d.z / h);
    auto turnAt = [&](double t) { return sineCosineBeside(middle.sc, spin * (t - middle.t)); };
    // The implicit function and its slope along the curve, with one sine
    // and cosine for the point and its velocity: u'(t) by the product rule,
    // u = Rot(τζ)·v, u' = Rot(τζ)·(v' + τζ'·J·v).
    auto f = [&](double t) {
      const double z = zeta(t), dz = d.z / h;
      const SineCosine sc = turnAt(t);
      const double c = sc.cos, sn = sc.sin;
      const dvec2 v = untwisted(t, z);
      const dvec2 u = turned(v, c, sn);
      const dvec2 du = turned(untwistedVelocity(v, z) + tau * dz * dvec2(-v.y, v.x), c, sn);
      const double value = e.implicit(u);
      const dvec2 gradient =
          e.arc ? 2.0 * (glm::transpose(e.toUnit) * (e.toUnit * (u - e.center))) : e.normal;
      return std::pair<double, double>(value, glm::dot(gradient, du));
    };
    auto valueAt = [&](double t) {
      const SineCosine sc = turnAt(t);
      return e.implicit(turned(untwisted(t, zeta(t)), sc.cos, sc.sin));
    };
    int count = 0;
    struct Interval {
      double lo, hi;
    };
    Interval stack[64];
    int top = 0;
    stack[top++] = {t0, t1};
    while (top > 0 && count < 7) {
      const Interval iv = stack[--top];
      const double m = 0.5 * (iv.lo + iv.hi), w = 0.5 * (iv.hi - iv.lo);
      const auto [value, slope] = f(m);
      if (std::abs(value) > L1 * w) continue;
      if (std::abs(slope) > L2 * w) {
        // Monotone: a root where the ends differ in sign.
        const double flo = valueAt(iv.lo), fhi = valueAt(iv.hi);
        if ((flo <= 0.0) != (fhi <= 0.0))
          out[count++] = bracketedRoot(f, iv.lo, iv.hi, flo <= 0.0, 1e-3 * resolution);
        continue;
      }
      if (w <= resolution || top + 2 > 64) {
        out[count++] = m;  // grazing: twice, so that the spans ask the region
        out[count++] = m;
        continue;
      }
      // The later half first on the stack, so roots come out in order.
      stack[top++] = {m, iv.hi};
      stack[top++] = {iv.lo, m};
    }
    return count;
  }
};

}  // namespace

std::optional<std::vector<std::vector<dvec2>>> LinearExtrusion::polygonLoops() const {
  if (twist_ != 0.0 || scale_.x != scale_.y) return std::nullopt;
  const Region& region = *swept_->region();
  std::vector<std::vector<dvec2>> loops;
  for (const ProfileLoop& loop : evaluate(region, evaluationTolerance(region)).loops) {
    loops.emplace_back();
    for (const ProfileEdge& e : loop.edges) {
      if (e.kind != ProfileEdge::Kind::Segment) return std::nullopt;
      loops.back().push_back(e.from);
    }
  }
  return loops;
}

SolidPtr LinearExtrusion::sweepOf(RegionPtr region) const {
  return placedAs(std::make_shared<LinearExtrusion>(std::move(region), height_, z0_ != 0.0,
                                                    twistDegrees_, scale_));
}

LinearExtrusion::LinearExtrusion(RegionPtr region, double height, bool center, double twistDegrees,
                                 dvec2 scale)
    : height_(height),
      z0_(center ? -0.5 * height : 0.0),
      twistDegrees_(twistDegrees),
      twist_(twistDegrees * std::numbers::pi / 180.0),
      scale_(scale) {
  requirePositive("linear_extrude", "height", height);
  requireFinite("linear_extrude", "twist", twistDegrees);
  if (std::abs(twistDegrees) > kMaxTwistDegrees) {
    std::ostringstream msg;
    msg << "linear_extrude: twist must be at most " << kMaxTwistDegrees
        << " degrees either way (got " << twistDegrees << ")";
    throw std::invalid_argument(msg.str());
  }
  for (double s : {scale.x, scale.y}) {
    if (!std::isfinite(s) || s < 0.0) {
      std::ostringstream msg;
      msg << "linear_extrude: scale must be >= 0 and finite (got " << s << ")";
      throw std::invalid_argument(msg.str());
    }
  }
  // Straight paths (no twist, a uniform scale) meet Bézier curves exactly.
  const bool straight = twistDegrees == 0.0 && scale.x == scale.y;
  swept_ = std::make_shared<SweptRegion>(std::move(region), "linear_extrude", straight);
}

dvec2 LinearExtrusion::profilePoint(const dvec3& p) const {
  const double zeta = (p.z - z0_) / height_;
  const dvec2 v(p.x / (1.0 + (scale_.x - 1.0) * zeta), p.y / (1.0 + (scale_.y - 1.0) * zeta));
  return twist_ == 0.0 ? v : rotated(v, twist_ * zeta);
}

void LinearExtrusion::objectSpans(const Ray& ray, SpanList& out) const { spansOf(ray, false, out); }

// The renderer asks an opaque solid for its first boundary only: the
// extrusion then follows the ray's curve only as far as that.
void LinearExtrusion::objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const {
  spansOf(ray, true, out);
}

void LinearExtrusion::spansOf(const Ray& ray, bool firstOnly, SpanList& out) const {
  const dvec3& o = ray.origin;
  const dvec3& d = ray.dir;
  // The slab, and the box of the sides.
  double t0 = -kInfinity, t1 = kInfinity;
  std::uint32_t face0 = kSweepStartFace, face1 = kSweepEndFace;
  // A scale of 0 makes the top a point or a segment, where the map to the
  // profile plane is singular: the window stops just below it.
  const double top = z0_ + height_ * (std::min(scale_.x, scale_.y) > 0.0 ? 1.0 : 1.0 - 1e-12);
  if (d.z == 0.0) {
    if (o.z < z0_ || o.z > top) return;
  } else {
    t0 = (z0_ - o.z) / d.z;
    t1 = (top - o.z) / d.z;
    if (t0 > t1) std::swap(t0, t1), std::swap(face0, face1);
  }
  // The sides' box, grown a little so that an edge on it is a crossing
  // inside the window.
  const Bounds box = objectBounds();
  const double pad = 1e-9 * swept_->size() * std::max({1.0, scale_.x, scale_.y});
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = box.lo[axis] - pad, hi = box.hi[axis] + pad;
    if (d[axis] == 0.0) {
      if (o[axis] < lo || o[axis] > hi) return;
      continue;
    }
    double a = (lo - o[axis]) / d[axis], b = (hi - o[axis]) / d[axis];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  if (!(t0 < t1) || t1 < ray.tMin || t0 > ray.tMax) return;
  cutSweepWindow(ray, t0, t1);

  SpanList spans;
  bool truncated = false;
  const Normalised n{0.5 * (t0 + t1), 0.5 * (t1 - t0)};
  if (twist_ == 0.0) {
    ScaledPath path;
    path.n = n;
    const double zm = (o.z + n.middle * d.z - z0_) / height_, zs = n.half * d.z / height_;
    path.x = SweepPolynomial::linear(o.x + n.middle * d.x, n.half * d.x);
    path.y = SweepPolynomial::linear(o.y + n.middle * d.y, n.half * d.y);
    path.sx = SweepPolynomial::linear(1.0 + (scale_.x - 1.0) * zm, (scale_.x - 1.0) * zs);
    path.sy = SweepPolynomial::linear(1.0 + (scale_.y - 1.0) * zm, (scale_.y - 1.0) * zs);
    path.uniform = scale_.x == scale_.y;
    SweepPiece pieces[8];
    int count = 0;
    if (path.uniform) {
      // The curve is a straight line in the plane (a projective image of
      // the ray): one piece, tested against the index as a segment.
      const dvec2 a = path.at(t0), b = path.at(t1);
      pieces[count++] = {t0, t1, glm::min(a, b), glm::max(a, b), true, a, b};
      path.straight = SweepSegmentTest(a, b);
    } else {
      // Each coordinate is monotone in t: a piece lies in its ends' box.
      const int k = 8;
      dvec2 a = path.at(t0);
      for (int i = 0; i < k; ++i) {
        const double ta = t0 + (t1 - t0) * i / k,
                     tb = i + 1 == k ? t1 : t0 + (t1 - t0) * (i + 1) / k;
        const dvec2 b = path.at(tb);
        pieces[count++] = {ta, tb, glm::min(a, b), glm::max(a, b), false, a, b};
        a = b;
      }
    }
    truncated = swept_->spans(this, path, t0, t1, face0, face1, pieces, count, spans, firstOnly);
  } else {
    TwistedPath path;
    path.n = n;
    path.o = o;
    path.d = d;
    path.z0 = z0_;
    path.h = height_;
    path.tau = twist_;
    path.scale = scale_;
    path.scaled = scale_ != dvec2(1.0);
    path.resolution = 1e-9 * swept_->size() / std::max(glm::length(d), 1e-300);
    path.window = path.boundsOver(t0, t1);
    path.perPiece = path.sigmaVaries(t0, t1);
    // Pieces short enough that each box is a small part of the region.
    const double length = path.window.speed * (t1 - t0);
    // (Clamped as a double: near the apex of a scale of 0 the count passes
    // what an int holds, and its conversion made one piece of the window.)
    const int k = int(std::clamp(std::ceil(length / (kTwistedPiece * swept_->size())), 1.0,
                                 double(kMaxTwistedPieces)));
    SweepPiece pieces[kMaxTwistedPieces];
    int count = 0;
    const auto piece = [&](int i, double& ta, double& tb) {
      ta = t0 + (t1 - t0) * i / k;
      tb = i + 1 == k ? t1 : t0 + (t1 - t0) * (i + 1) / k;
    };
    if (!path.perPiece) {
      const double speed = path.window.speed;
      // The middles' turns: every eighth through sineCosine, each of the
      // others the one before turned by a piece's step. (Off by a few units
      // in the last place, which the index's boxes, grown by a billionth of
      // the region, take in.)
      const SineCosine step =
          sineCosineBeside({0.0, 1.0}, twist_ * (d.z / height_) * (t1 - t0) / k);
      SineCosine turn{0.0, 1.0};
      for (int i = 0; i < k; ++i) {
        double ta, tb;
        piece(i, ta, tb);
        const double tm = 0.5 * (ta + tb);
        const double z = path.zeta(tm);
        turn = i % 8 == 0 ? sineCosine(twist_ * z)
                          : SineCosine{turn.sin * step.cos + turn.cos * step.sin,
                                       turn.cos * step.cos - turn.sin * step.sin};
        const dvec2 m = turned(path.untwisted(tm, z), turn.cos, turn.sin);
        const double r = speed * 0.5 * (tb - ta);
        pieces[count++] = {ta, tb, m - dvec2(r), m + dvec2(r), false, m, m};
      }
    } else {
      // A piece whose points all lie farther from the axis than the
      // region's corners cannot meet it, and is left out.
      const ProfileBounds& region = swept_->bounds();
      const double corner = glm::length(glm::max(glm::abs(region.lo), glm::abs(region.hi))) + pad;
      for (int i = 0; i < k; ++i) {
        double ta, tb;
        piece(i, ta, tb);
        if (path.nearestOver(ta, tb) > corner) continue;
        // The square about the middle, within the disc of the reach.
        const TwistedPath::Bounds& b = path.boundsFor(ta, tb);
        const dvec2 m = path.at(0.5 * (ta + tb));
        const double r = b.speed * 0.5 * (tb - ta);
        const dvec2 lo = glm::max(m - dvec2(r), dvec2(-b.reach));
        const dvec2 hi = glm::min(m + dvec2(r), dvec2(b.reach));
        pieces[count++] = {ta, tb, lo, hi, false, m, m};
      }
    }
    truncated = swept_->spans(this, path, t0, t1, face0, face1, pieces, count, spans, firstOnly);
  }
  for (const Span& s : spans)
    if (!(s.out.t < ray.tMin || s.in.t > ray.tMax)) out.push_back(s);
  if (truncated && (out.empty() || !(out.front().in.t > ray.tMin))) {
    // Cut short where the first boundary is not yet known (the curve only
    // touched an edge, or the ray starts inside, where the first boundary
    // is an exit): the whole spans.
    out.clear();
    spansOf(ray, false, out);
  }
}

bool LinearExtrusion::objectContains(const dvec3& p) const {
  if (p.z < z0_ || p.z > z0_ + height_) return false;
  const double zeta = (p.z - z0_) / height_;
  if (!(1.0 + (scale_.x - 1.0) * zeta > 0.0) || !(1.0 + (scale_.y - 1.0) * zeta > 0.0))
    return false;
  return swept_->contains(profilePoint(p));
}

// The gradient of g(u(p)) by the chain rule, u = Rot(−ψ)·S⁻¹·p_xy with
// ψ = −τζ: ∂u/∂(x, y) = Rot(τζ)·S⁻¹, whose transpose S⁻¹·Rot(−τζ) takes
// the profile's normal n to the normal's x and y; and ∂u/∂z =
// Rot(τζ)·(−σ'ᵢvᵢ/σᵢ) + τζ'·J·u (J the quarter turn), whose dot product
// with n is its z.
dvec3 LinearExtrusion::objectNormal(const dvec3& p, int face) const {
  if (face == int(kSweepStartFace)) return {0.0, 0.0, -1.0};
  if (face == int(kSweepEndFace)) return {0.0, 0.0, 1.0};
  const double zeta = (p.z - z0_) / height_;
  const dvec2 sigma(1.0 + (scale_.x - 1.0) * zeta, 1.0 + (scale_.y - 1.0) * zeta);
  if (!(sigma.x > 0.0) || !(sigma.y > 0.0)) return {0.0, 0.0, 1.0};  // the apex
  const dvec2 v(p.x / sigma.x, p.y / sigma.y);
  const double angle = twist_ * zeta;
  const dvec2 u = rotated(v, angle);
  const dvec2 n = swept_->outwardNormal(std::uint32_t(face), u);
  const dvec2 back = rotated(n, -angle);
  const dvec2 xy(back.x / sigma.x, back.y / sigma.y);
  const dvec2 rate((scale_.x - 1.0) / height_, (scale_.y - 1.0) / height_);
  const dvec2 dudz = rotated(dvec2(-rate.x * v.x / sigma.x, -rate.y * v.y / sigma.y), angle) +
                     (twist_ / height_) * dvec2(-u.y, u.x);
  return {xy.x, xy.y, glm::dot(n, dudz)};
}

Bounds LinearExtrusion::objectBounds() const {
  const ProfileBounds& b = swept_->bounds();
  Bounds box;
  box.lo.z = z0_;
  box.hi.z = z0_ + height_;
  if (twist_ == 0.0) {
    for (int axis = 0; axis < 2; ++axis) {
      const double s = scale_[axis];
      box.lo[axis] = std::min(b.lo[axis], s * b.lo[axis]);
      box.hi[axis] = std::max(b.hi[axis], s * b.hi[axis]);
    }
    return box;
  }
  const double r =
      std::max({glm::length(b.lo), glm::length(b.hi), glm::length(dvec2(b.lo.x, b.hi.y)),
                glm::length(dvec2(b.hi.x, b.lo.y))});
  for (int axis = 0; axis < 2; ++axis) {
    const double reach = r * std::max(1.0, scale_[axis]);
    box.lo[axis] = -reach;
    box.hi[axis] = reach;
  }
  return box;
}

}  // namespace csgray::detail
