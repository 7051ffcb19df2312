#include "primitives/revolution.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "engine/solvers/quadratic.h"
#include "engine/solvers/quartic.h"
#include "primitives/check.h"

namespace csgray::detail {

namespace {

// The ray's curve in the profile plane, in s ∈ [-1, 1] over the window
// (t = middle + half·s): ρ(s)² = rho2(s), z(s) linear.
struct TurnedPath {
  double middle, half;
  SweepPolynomial rho2, z;

  double toS(double t) const { return (t - middle) / half; }
  dvec2 at(double t) const {
    const double s = toS(t);
    return {std::sqrt(std::max(0.0, polynomialValue(rho2.c, 2, s))), polynomialValue(z.c, 1, s)};
  }

  int roots(const SweepEdge& e, double t0, double t1, double* out) const {
    SweepPolynomial p;
    if (!e.arc) {
      // n_ρ·ρ = offset − n_z·z, squared unless the segment is a flat ring.
      const SweepPolynomial right = z * -e.normal.y + SweepPolynomial::linear(e.offset, 0.0);
      if (std::abs(e.normal.x) <= 1e-12) {
        p = right;
      } else {
        p = rho2 * (e.normal.x * e.normal.x) - right * right;
      }
    } else {
      // |M(u − c)|² = 1 with u = (ρ, z): ρ²|m0|² + 2ρ·(m0·P) + |P|² − 1 = 0,
      // P = (z − c_z)·m1 − c_ρ·m0 (m0, m1 the columns of M). With
      // L = m0·P and Q = ρ²|m0|² + |P|² − 1: 2ρL = −Q, squared 4ρ²L² = Q².
      const dvec2 m0 = e.toUnit[0], m1 = e.toUnit[1];
      const SweepPolynomial zc = z - SweepPolynomial::linear(e.center.y, 0.0);
      const SweepPolynomial px = zc * m1.x - SweepPolynomial::linear(e.center.x * m0.x, 0.0);
      const SweepPolynomial py = zc * m1.y - SweepPolynomial::linear(e.center.x * m0.y, 0.0);
      const SweepPolynomial L = px * m0.x + py * m0.y;
      const SweepPolynomial Q =
          rho2 * glm::dot(m0, m0) + px * px + py * py - SweepPolynomial::linear(1.0, 0.0);
      const double reference = glm::length(m0) * (std::abs(px.c[0]) + std::abs(px.c[1]) +
                                                  std::abs(py.c[0]) + std::abs(py.c[1]));
      if (std::abs(L.c[0]) + std::abs(L.c[1]) <= 1e-12 * reference) {
        p = Q;  // centred on the axis (a sphere or spheroid): no odd powers of ρ
      } else {
        p = rho2 * L * L * 4.0 - Q * Q;
      }
    }
    double s[4];
    const int count = sweepPolynomialRoots(p, toS(t0), toS(t1), s);
    for (int i = 0; i < count; ++i) out[i] = middle + half * s[i];
    return count;
  }
};

// Where a·(o + t·d) >= 0 along the ray: a half-space's span, with face.
void halfSpace(const Primitive* owner, double f0, double f1, std::uint32_t face, SpanList& out) {
  out.clear();
  const Boundary lo{-kInfinity, nullptr, 0, false}, hi{kInfinity, nullptr, 0, false};
  if (f1 == 0.0) {
    if (f0 >= 0.0) out.push_back(lo, hi);
    return;
  }
  const Boundary at{-f0 / f1, owner, face, false};
  if (f1 > 0.0) {
    out.push_back(at, hi);
  } else {
    out.push_back(lo, at);
  }
}

}  // namespace

Revolution::Revolution(RegionPtr region, double angleDegrees)
    : angleDegrees_(angleDegrees),
      angle_(angleDegrees * std::numbers::pi / 180.0),
      fullTurn_(angleDegrees >= 360.0) {
  if (!std::isfinite(angleDegrees) || !(angleDegrees > 0.0) || angleDegrees > 360.0) {
    std::ostringstream msg;
    msg << "rotate_extrude: angle must be in (0, 360] degrees (got " << angleDegrees << ")";
    throw std::invalid_argument(msg.str());
  }
  swept_ = std::make_shared<SweptRegion>(std::move(region), "rotate_extrude");
  const ProfileBounds& b = swept_->bounds();
  if (b.lo.x < -1e-12 * swept_->size()) {
    std::ostringstream msg;
    msg << "rotate_extrude: the region crosses the axis: it reaches x = " << b.lo.x
        << ", and every point must have x >= 0";
    throw std::invalid_argument(msg.str());
  }
}

void Revolution::objectSpans(const Ray& ray, SpanList& out) const {
  const dvec3& o = ray.origin;
  const dvec3& d = ray.dir;
  const ProfileBounds& b = swept_->bounds();
  // The bounding cylinder: ρ <= reach and the slab of the region's z,
  // grown a little, so that the window starts and ends outside the region
  // and an edge on the region's box is a crossing inside the window.
  const double pad = 1e-9 * swept_->size();
  const double reach = std::max(b.hi.x, 0.0) + pad;
  const double zlo = b.lo.y - pad, zhi = b.hi.y + pad;
  double t0 = -kInfinity, t1 = kInfinity;
  if (d.z == 0.0) {
    if (o.z < zlo || o.z > zhi) return;
  } else {
    t0 = (zlo - o.z) / d.z;
    t1 = (zhi - o.z) / d.z;
    if (t0 > t1) std::swap(t0, t1);
  }
  Interval around[2];
  const int n = quadraticSublevel(d.x * d.x + d.y * d.y, 2.0 * (o.x * d.x + o.y * d.y),
                                  o.x * o.x + o.y * o.y - reach * reach, around);
  if (n == 0) return;
  t0 = std::max(t0, around[0].lo);
  t1 = std::min(t1, around[n - 1].hi);
  if (!(t0 < t1) || !std::isfinite(t0) || !std::isfinite(t1) || t1 < ray.tMin || t0 > ray.tMax)
    return;

  TurnedPath path;
  path.middle = 0.5 * (t0 + t1);
  path.half = 0.5 * (t1 - t0);
  const double x0 = o.x + path.middle * d.x, x1 = path.half * d.x;
  const double y0 = o.y + path.middle * d.y, y1 = path.half * d.y;
  path.rho2.n = 2;
  path.rho2.c[0] = x0 * x0 + y0 * y0;
  path.rho2.c[1] = 2.0 * (x0 * x1 + y0 * y1);
  path.rho2.c[2] = x1 * x1 + y1 * y1;
  path.z = SweepPolynomial::linear(o.z + path.middle * d.z, path.half * d.z);

  // Pieces: ρ falls until the point of the line nearest the axis and rises
  // after it, z is linear, so a stretch on one side lies in its ends' box.
  double breaks[3] = {t0, t1, t1};
  int parts = 1;
  if (path.rho2.c[2] > 0.0) {
    const double nearest = path.middle + path.half * (-path.rho2.c[1] / (2.0 * path.rho2.c[2]));
    if (nearest > t0 && nearest < t1) {
      breaks[1] = nearest;
      parts = 2;
    }
  }
  SweepPiece pieces[8];
  int count = 0;
  for (int part = 0; part < parts; ++part) {
    const double a = breaks[part], bEnd = breaks[part + 1];
    dvec2 pa = path.at(a);
    for (int k = 0; k < 4; ++k) {
      const double ta = a + (bEnd - a) * k / 4, tb = k == 3 ? bEnd : a + (bEnd - a) * (k + 1) / 4;
      const dvec2 pb = path.at(tb);
      pieces[count++] = {ta, tb, glm::min(pa, pb), glm::max(pa, pb), false, pa, pb};
      pa = pb;
    }
  }
  SpanList spans;
  swept_->spans(this, path, t0, t1, kSweepStartFace, kSweepEndFace, pieces, count, spans);
  if (!fullTurn_ && !spans.empty()) {
    // The wedge: y >= 0 and x·sin a − y·cos a >= 0, both for a <= 180°,
    // either for more.
    SpanList first, second, wedge, cut;
    halfSpace(this, o.y, d.y, kSweepStartFace, first);
    const double sa = std::sin(angle_), ca = std::cos(angle_);
    halfSpace(this, o.x * sa - o.y * ca, d.x * sa - d.y * ca, kSweepEndFace, second);
    if (angle_ <= std::numbers::pi) {
      intersect(first, second, wedge);
    } else {
      unite(first, second, wedge);
    }
    intersect(spans, wedge, cut);
    spans = cut;
  }
  for (const Span& s : spans)
    if (!(s.out.t < ray.tMin || s.in.t > ray.tMax)) out.push_back(s);
}

bool Revolution::inWedge(const dvec3& p) const {
  if (fullTurn_) return true;
  const bool first = p.y >= 0.0;
  const bool second = p.x * std::sin(angle_) - p.y * std::cos(angle_) >= 0.0;
  return angle_ <= std::numbers::pi ? first && second : first || second;
}

bool Revolution::objectContains(const dvec3& p) const {
  if (!inWedge(p)) return false;
  return swept_->contains(dvec2(std::hypot(p.x, p.y), p.z));
}

// The profile's outward normal (n_ρ, n_z) turned to the point's meridian:
// n_ρ along the radial direction, n_z along z.
dvec3 Revolution::objectNormal(const dvec3& p, int face) const {
  if (face == int(kSweepStartFace)) return {0.0, -1.0, 0.0};
  if (face == int(kSweepEndFace)) return {-std::sin(angle_), std::cos(angle_), 0.0};
  const double rho = std::hypot(p.x, p.y);
  const dvec2 n = swept_->outwardNormal(std::uint32_t(face), dvec2(rho, p.z));
  if (!(rho > 0.0)) return {0.0, 0.0, n.y < 0.0 ? -1.0 : 1.0};
  return {n.x * p.x / rho, n.x * p.y / rho, n.y};
}

Bounds Revolution::objectBounds() const {
  const ProfileBounds& b = swept_->bounds();
  const double reach = std::max(b.hi.x, 0.0);
  return {dvec3(-reach, -reach, b.lo.y), dvec3(reach, reach, b.hi.y)};
}

}  // namespace csgray::detail
