#include "primitives/superellipsoid.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <stdexcept>

#include "primitives/check.h"

namespace csgray::detail {

namespace {

// Newton steps before a ray that creeps along a near-tangency is settled
// where it stands: a double root halves the distance per step, so 80
// steps reach a part in 10¹⁵ of the chord.
constexpr int kMaxSteps = 80;

// A Newton step this small, in units of the chord, ends the search with
// that step taken: where Newton converges quadratically the step after it
// would be some 10⁻¹⁶ (so it is not evaluated), and where it creeps (a
// ray that grazes the surface) a boundary 10⁻⁸ along the ray is 10⁻¹⁶ off
// the surface.
constexpr double kConverged = 1e-8;

// The p-norm (a^p + b^p)^(1/p) of a, b >= 0 (p >= 1) and its partial
// derivatives (a/h)^(p−1) and (b/h)^(p−1). Computed with the larger of the
// two factored out, so that neither overflows nor vanishes for p up to
// 2/kMinExponent. pow() is most of a superellipsoid's time, and the
// exponents people write (e = 1, 0.5, 0.25, 0.2, 0.1, ...) make p a whole
// number, often a power of two: the power is then taken by squaring and
// the root by square roots where it can be.
struct PowerNorm {
  double h, da, db;
};

PowerNorm powerNorm(double a, double b, const Superellipsoid::Power& p) {
  const double big = std::max(a, b), small = std::min(a, b);
  if (big == 0.0) return {0.0, 0.0, 0.0};
  const double r = small / big;
  double rp = 1.0;
  if (p.whole > 0) {
    double square = r;
    for (int k = p.whole; k > 0; k >>= 1) {
      if (k & 1) rp *= square;
      square *= square;
    }
  } else {
    rp = std::pow(r, p.value);
  }
  double root = 1.0 + rp;
  if (p.halvings >= 0) {
    for (int k = 0; k < p.halvings; ++k) root = std::sqrt(root);
  } else {
    root = std::pow(root, 1.0 / p.value);
  }
  // h = big·root; ∂h/∂big = (big/h)^(p−1) = root/(1 + r^p), and
  // ∂h/∂small = (small/h)^(p−1) = r^(p−1)·∂h/∂big (1 at r = 0 when p = 1).
  const double dBig = root / (1.0 + rp);
  const double dSmall = r > 0.0 ? rp / r * dBig : (p.value == 1.0 ? dBig : 0.0);
  return a >= b ? PowerNorm{big * root, dBig, dSmall} : PowerNorm{big * root, dSmall, dBig};
}

// Where the line from + s·step meets the cube |x|, |y|, |z| <= 1 that holds
// the unit shape: [lo, hi], empty when lo > hi.
void cubeChord(const dvec3& from, const dvec3& step, double& lo, double& hi) {
  lo = -kInfinity;
  hi = kInfinity;
  for (int i = 0; i < 3; ++i) {
    if (step[i] == 0.0) {
      if (std::abs(from[i]) > 1.0) lo = kInfinity;
      continue;
    }
    double a = (-1.0 - from[i]) / step[i], b = (1.0 - from[i]) / step[i];
    if (a > b) std::swap(a, b);
    lo = std::max(lo, a);
    hi = std::min(hi, b);
  }
}

// Narrows [lo, hi] to where the line from + s·step lies in the ball of
// radius `reach` about the origin: empty (lo > hi) when it misses. The
// parameter of the point nearest the centre first, then the half chord
// from the distance there, which stays accurate for a line from afar.
void ballChord(const dvec3& from, const dvec3& step, double reach, double& lo, double& hi) {
  const double a = glm::dot(step, step);
  const double nearest = -glm::dot(from, step) / a;
  const dvec3 foot = from + nearest * step;
  const double left = reach * reach - glm::dot(foot, foot);
  if (!(left >= 0.0)) {
    lo = kInfinity;
    return;
  }
  const double half = std::sqrt(left / a);
  lo = std::max(lo, nearest - half);
  hi = std::min(hi, nearest + half);
}

// A radius that holds the unit shape: ‖v‖₂ <= max(1, 2^(1/2 − 1/k))·‖v‖_k
// for a pair v and k >= 1 (Hölder's inequality for k >= 2, the norms'
// order for k <= 2), applied to (x, y) with p and to (h, z) with q, bounds
// the Euclidean norm by that product of factors times the gauge.
double reachOf(double p, double q) {
  auto factor = [](double k) { return std::max(1.0, std::pow(2.0, 0.5 - 1.0 / k)); };
  return factor(p) * factor(q);
}

}  // namespace

Superellipsoid::Power Superellipsoid::Power::of(double p) {
  Power power{p, 0, -1};
  if (p == std::floor(p) && p <= 64.0) power.whole = int(p);
  for (int k = 0; k <= 6; ++k)
    if (p == double(1 << k)) power.halvings = k;
  return power;
}

Superellipsoid::Superellipsoid(const dvec3& radii, double e, double n)
    : radii_(radii),
      e_(e),
      n_(n),
      p_(Power::of(2.0 / e)),
      q_(Power::of(2.0 / n)),
      reach_(reachOf(p_.value, q_.value)) {
  requirePositive("superellipsoid", "radii[1]", radii.x);
  requirePositive("superellipsoid", "radii[2]", radii.y);
  requirePositive("superellipsoid", "radii[3]", radii.z);
  for (auto [name, value] : {std::pair{"e", e}, std::pair{"n", n}}) {
    if (!(value >= kMinExponent && value <= 2.0)) {
      std::ostringstream msg;
      msg << "superellipsoid: " << name << " must be from " << kMinExponent << " to 2 (got "
          << value << ")"
          << (value > 2.0 ? ": above 2 the shape pinches in, which is not offered" : "");
      throw std::invalid_argument(msg.str());
    }
  }
}

// The gauge F(p) = (h^q + |z|^q)^(1/q), h = (|x|^p + |y|^p)^(1/p), is
// positively homogeneous of degree 1 and, for p, q >= 1, a norm (the
// q-norm of the pair (p-norm of x and y, z)): convex, with the solid as
// its unit ball (Barr, "Superquadrics and Angle-Preserving
// Transformations", IEEE CG&A 1(1), 1981, writes the same surface as
// F^q = 1). Its gradient is the chain rule through the two norms.
Superellipsoid::Gauge Superellipsoid::unitGauge(const dvec3& p) const {
  const PowerNorm across = powerNorm(std::abs(p.x), std::abs(p.y), p_);
  const PowerNorm whole = powerNorm(across.h, std::abs(p.z), q_);
  const double toAcross = whole.da;
  return {whole.h, dvec3(std::copysign(toAcross * across.da, p.x),
                         std::copysign(toAcross * across.db, p.y), std::copysign(whole.db, p.z))};
}

// Newton's method on G(s) = F(from + s·step) − 1 from a point where G >= 0
// towards the solid. G is convex along the line, so each tangent meets
// zero at or before G's first root: the iterates climb to it without
// passing it, and a slope that no longer falls means G never reaches zero
// (the line passes by). At a crease of the surface (e or n at 2) the
// gradient is a subgradient, whose tangent lies below G as well.
double Superellipsoid::firstInside(const dvec3& from, const dvec3& step, double length) const {
  double s = 0.0;
  for (int k = 0; k < kMaxSteps; ++k) {
    const Gauge g = unitGauge(from + s * step);
    const double value = g.value - 1.0;
    if (value <= 0.0) return s;
    const double slope = glm::dot(g.gradient, step);
    if (!(slope < 0.0)) return -1.0;
    const double move = -value / slope;
    if (s + move > length) return -1.0;
    s += move;
    if (move <= kConverged * length) return s;
  }
  // Still creeping towards a double root: the line grazes the surface
  // within rounding; it counts as a touch.
  return s;
}

// The ray meets the solid in one stretch at most (it is convex). In the
// unit shape's space (the ray divided by the radii, t kept), the chord of
// the cube and the ball that hold the shape has ends outside it (or on
// it, at the centres of the cube's faces); the entry is found by
// firstInside from the chord's start forward, the exit by firstInside from
// its end backward. The ball turns away most rays that pass a rounded
// corner, and shortens the way of the others.
void Superellipsoid::objectSpans(const Ray& ray, SpanList& out) const { spansOf(ray, false, out); }

// A camera or shadow ray whose window starts before the entry needs no
// exit: the span it gets runs on to the chord's end.
void Superellipsoid::objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const {
  spansOf(ray, true, out);
}

void Superellipsoid::spansOf(const Ray& ray, bool firstOnly, SpanList& out) const {
  const dvec3 o = ray.origin / radii_, d = ray.dir / radii_;
  double lo, hi;
  cubeChord(o, d, lo, hi);
  if (lo <= hi) ballChord(o, d, reach_, lo, hi);
  if (!(lo <= hi) || hi < ray.tMin || lo > ray.tMax) return;
  const double length = hi - lo;
  const dvec3 start = o + lo * d, end = o + hi * d;
  const double in = firstInside(start, d, length);
  if (in < 0.0) return;
  const double tIn = lo + in;
  if (firstOnly && tIn > ray.tMin) {
    if (tIn <= ray.tMax) out.push_back(boundary(tIn), boundary(hi));
    return;
  }
  const double back = firstInside(end, -d, length - in);
  const double tOut = std::max(tIn, back < 0.0 ? tIn : hi - back);
  if (tOut < ray.tMin || tIn > ray.tMax) return;
  out.push_back(boundary(tIn), boundary(tOut));
}

bool Superellipsoid::objectContains(const dvec3& p) const {
  return unitGauge(p / radii_).value <= 1.0;
}

// The gradient of F(x/a, y/b, z/c): the unit shape's, divided by the radii.
dvec3 Superellipsoid::objectNormal(const dvec3& p, int) const {
  const dvec3 n = unitGauge(p / radii_).gradient / radii_;
  if (n == dvec3(0.0)) return p;  // only at the centre, which is not on the surface
  return n;
}

Bounds Superellipsoid::objectBounds() const { return {-radii_, radii_}; }

}  // namespace csgray::detail
