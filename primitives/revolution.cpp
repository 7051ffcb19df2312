#include "primitives/revolution.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "engine/solvers/quadratic.h"
#include "engine/solvers/quartic.h"
#include "primitives/check.h"

namespace csgray::detail {

namespace {

// The ray's curve in the profile plane, in s ∈ [-1, 1] over the window
// (t = middle + half·s): ρ(s)² = q0 + q1·s + q2·s², z(s) = z0 + z1·s. An
// edge's equation along it is written down in closed form from these
// coefficients, once per edge and ray.
struct TurnedPath {
  static constexpr bool kBoxedPieces = false;  // its one piece has no box: meets tests the curve
  double middle, half, inverseHalf;
  SweepPolynomial rho2, z;
  // For meets: 1 / z1 (0 for a level ray), the s where ρ² is least (or
  // NaN) and its value there, and an allowance for rounding in ρ² (in units of the part's
  // size squared, far above the rounding of q, far below any feature).
  double zRate = 0.0, nearest = 0.0, leastValue = 0.0, slack2 = 0.0;
  double rootSlack = 0.0;  // twice the spans' accepted distance of a root from its edge

  double toS(double t) const { return (t - middle) / half; }
  double q(double s) const { return (rho2.c[2] * s + rho2.c[1]) * s + rho2.c[0]; }
  dvec2 at(double t) const {
    const double s = (t - middle) * inverseHalf;  // (a product: at runs often)
    return {std::sqrt(std::max(0.0, polynomialValue(rho2.c, 2, s))), polynomialValue(z.c, 1, s)};
  }

  // Does the curve pass through the box? z picks the stretch of s where
  // the curve is in the box's slab; ρ² is a convex quadratic in s, so its
  // range there is that of its ends and its least point: the box is missed
  // when that range misses [ρlo², ρhi²]. (POV-Ray's lathe bounds each
  // segment by a cylindrical shell the same way; here it is exact, and
  // asked of the index's nodes as well.)
  bool meets(const SweepPiece& piece, const dvec2& lo, const dvec2& hi) const {
    double from = 0.0;
    return meetsFrom(piece, lo, hi, from);
  }
  bool meetsFrom(const SweepPiece&, const dvec2& lo, const dvec2& hi, double& from) const {
    // The slab first: most boxes the curve misses, it misses in z.
    double s0 = -1.0, s1 = 1.0;
    if (zRate != 0.0) {
      const double a = (lo.y - z.c[0]) * zRate, b = (hi.y - z.c[0]) * zRate;
      s0 = std::max(s0, std::min(a, b));
      s1 = std::min(s1, std::max(a, b));
      if (!(s0 <= s1)) return false;
    } else if (z.c[0] < lo.y || z.c[0] > hi.y) {
      return false;
    }
    const double q0 = q(s0), q1 = q(s1);
    const double least = nearest > s0 && nearest < s1 ? leastValue : std::min(q0, q1);
    // (A box reaching the axis has no inner radius; ρ² >= 0 up to rounding.)
    const double inner = lo.x > 0.0 ? lo.x * lo.x : 0.0;
    from = middle + half * s0;
    return (least <= hi.x * hi.x + slack2) & (std::max(q0, q1) >= inner - slack2);
  }

  int roots(const SweepEdge& e, double t0, double t1, double* out) const {
    SweepPolynomial p;
    const double* r = rho2.c;
    double w0 = 0.0, w1 = 0.0;
    if (!e.arc) {
      // n_ρ·ρ = offset − n_z·z = w0 + w1·s, squared unless the segment is a
      // flat ring: n_ρ²·ρ² − w² = 0.
      w0 = z.c[0] * -e.normal.y + e.offset;
      w1 = z.c[1] * -e.normal.y;
      if (std::abs(e.normal.x) <= 1e-12) {
        p.n = 1;
        p.c[0] = w0;
        p.c[1] = w1;
      } else {
        const double k = e.normal.x * e.normal.x;
        p.n = 2;
        p.c[0] = r[0] * k - w0 * w0;
        p.c[1] = r[1] * k - 2.0 * (w0 * w1);
        p.c[2] = r[2] * k - w1 * w1;
      }
    } else {
      // |M(u − c)|² = 1 with u = (ρ, z): ρ²|m0|² + 2ρ·(m0·P) + |P|² − 1 = 0,
      // P = (z − c_z)·m1 − c_ρ·m0 (m0, m1 the columns of M). With
      // L = m0·P and Q = ρ²|m0|² + |P|² − 1: 2ρL = −Q, squared 4ρ²L² = Q².
      const dvec2 m0 = e.toUnit[0], m1 = e.toUnit[1];
      const double zc0 = z.c[0] - e.center.y, zc1 = z.c[1];
      const double px0 = zc0 * m1.x - e.center.x * m0.x, px1 = zc1 * m1.x;
      const double py0 = zc0 * m1.y - e.center.x * m0.y, py1 = zc1 * m1.y;
      const double L0 = px0 * m0.x + py0 * m0.y, L1 = px1 * m0.x + py1 * m0.y;
      const double k = glm::dot(m0, m0);
      const double Q0 = r[0] * k + px0 * px0 + py0 * py0 - 1.0;
      const double Q1 = r[1] * k + 2.0 * (px0 * px1 + py0 * py1);
      const double Q2 = r[2] * k + px1 * px1 + py1 * py1;
      const double reference =
          glm::length(m0) * (std::abs(px0) + std::abs(px1) + std::abs(py0) + std::abs(py1));
      if (std::abs(L0) + std::abs(L1) <= 1e-12 * reference) {
        // Centred on the axis (a sphere or spheroid): no odd powers of ρ.
        p.n = 2;
        p.c[0] = Q0;
        p.c[1] = Q1;
        p.c[2] = Q2;
      } else {
        // 4ρ²L² − Q², the products written out.
        const double l0 = 4.0 * L0 * L0, l1 = 8.0 * L0 * L1, l2 = 4.0 * L1 * L1;
        p.n = 4;
        p.c[0] = r[0] * l0 - Q0 * Q0;
        p.c[1] = r[0] * l1 + r[1] * l0 - 2.0 * Q0 * Q1;
        p.c[2] = r[0] * l2 + r[1] * l1 + r[2] * l0 - (2.0 * Q0 * Q2 + Q1 * Q1);
        p.c[3] = r[1] * l2 + r[2] * l1 - 2.0 * Q1 * Q2;
        p.c[4] = r[2] * l2 - Q2 * Q2;
      }
    }
    double s[4];
    const int count = sweepPolynomialRoots(p, toS(t0), toS(t1), s);
    int kept = 0;
    for (int i = 0; i < count; ++i) {
      // Roots the spans would drop, dropped here without the point's square
      // root: z off the edge's slab by more than the accepted distance
      // (doubled), or a segment's root where n_ρ·ρ = −w, of its mirror image
      // in the axis, at least |w| off its line.
      const double zs = z.c[0] + z.c[1] * s[i];
      if (zs < e.box.lo.y - rootSlack || zs > e.box.hi.y + rootSlack) continue;
      const double w = w0 + w1 * s[i];
      if (!e.arc && e.normal.x * w < 0.0 && std::abs(w) > rootSlack) continue;
      out[kept++] = middle + half * s[i];
    }
    return kept;
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

SolidPtr Revolution::sweepOf(RegionPtr region) const {
  return placedAs(std::make_shared<Revolution>(std::move(region), angleDegrees_));
}

SolidPtr revolutionSolid(RegionPtr region, double angleDegrees) {
  if (!std::isfinite(angleDegrees) || angleDegrees == 0.0 || std::abs(angleDegrees) > 360.0) {
    std::ostringstream msg;
    msg << "rotate_extrude: angle must be in [-360, 0) or (0, 360] degrees (got " << angleDegrees
        << ")";
    throw std::invalid_argument(msg.str());
  }
  SolidPtr solid = Primitive::create<Revolution>(std::move(region), std::abs(angleDegrees));
  if (angleDegrees < 0.0) solid = solid->transformed(Affine::mirror(dvec3(0.0, 1.0, 0.0)));
  return solid;
}

Revolution::Revolution(RegionPtr region, double angleDegrees)
    : angleDegrees_(angleDegrees),
      angle_(angleDegrees * std::numbers::pi / 180.0),
      fullTurn_(angleDegrees >= 360.0) {
  if (!std::isfinite(angleDegrees) || !(angleDegrees > 0.0) || angleDegrees > 360.0) {
    std::ostringstream msg;
    msg << "rotate_extrude: angle must be in (0, 360] degrees (got " << angleDegrees << ")";
    throw std::invalid_argument(msg.str());
  }
  swept_ = std::make_shared<SweptRegion>(std::move(region), "rotate_extrude",
                                         /*exactCurves=*/false);
  const ProfileBounds& b = swept_->bounds();
  if (b.lo.x < -1e-12 * swept_->size()) {
    std::ostringstream msg;
    if (b.hi.x <= 0.0)
      msg << "rotate_extrude: the region lies on the side x < 0 of the axis (from x = " << b.lo.x
          << "), and every point must have x >= 0: mirror it first, r:mirror(1, 0)";
    else
      msg << "rotate_extrude: the region crosses the axis: it reaches x = " << b.lo.x
          << ", and every point must have x >= 0";
    throw std::invalid_argument(msg.str());
  }
}

void Revolution::objectSpans(const Ray& ray, SpanList& out) const { spansOf(ray, false, out); }

// The renderer asks an opaque solid for its first boundary only: the
// revolution then follows the ray's curve only as far as that.
void Revolution::objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const {
  spansOf(ray, true, out);
}

void Revolution::spansOf(const Ray& ray, bool firstOnly, SpanList& out) const {
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
  // ρ² <= reach²: quadraticSublevel's arithmetic for a > 0, inline (every
  // ray that meets the box comes here); a vertical ray is left to it.
  const double a = d.x * d.x + d.y * d.y, bq = 2.0 * (o.x * d.x + o.y * d.y),
               c = o.x * o.x + o.y * o.y - reach * reach;
  if (a > 0.0) {
    const double disc = bq * bq - 4.0 * a * c;
    if (disc < 0.0) return;
    const double q = -0.5 * (bq + std::copysign(std::sqrt(disc), bq));
    double r0 = q / a, r1 = q != 0.0 ? c / q : r0;
    if (r0 > r1) std::swap(r0, r1);
    t0 = std::max(t0, r0);
    t1 = std::min(t1, r1);
  } else {
    Interval around[2];
    const int n = quadraticSublevel(a, bq, c, around);
    if (n == 0) return;
    t0 = std::max(t0, around[0].lo);
    t1 = std::min(t1, around[n - 1].hi);
  }
  if (!(t0 < t1) || !std::isfinite(t0) || !std::isfinite(t1) || t1 < ray.tMin || t0 > ray.tMax)
    return;
  cutSweepWindow(ray, t0, t1);

  TurnedPath path;
  path.middle = 0.5 * (t0 + t1);
  path.half = 0.5 * (t1 - t0);
  path.inverseHalf = 1.0 / path.half;
  const double x0 = o.x + path.middle * d.x, x1 = path.half * d.x;
  const double y0 = o.y + path.middle * d.y, y1 = path.half * d.y;
  path.rho2.n = 2;
  path.rho2.c[0] = x0 * x0 + y0 * y0;
  path.rho2.c[1] = 2.0 * (x0 * x1 + y0 * y1);
  path.rho2.c[2] = x1 * x1 + y1 * y1;
  path.z = SweepPolynomial::linear(o.z + path.middle * d.z, path.half * d.z);

  path.zRate = path.z.c[1] != 0.0 ? 1.0 / path.z.c[1] : 0.0;
  path.nearest = path.rho2.c[2] > 0.0 ? -path.rho2.c[1] / (2.0 * path.rho2.c[2])
                                      : std::numeric_limits<double>::quiet_NaN();
  path.leastValue = path.q(path.nearest);
  path.slack2 = 1e-12 * swept_->size() * swept_->size();
  path.rootSlack = 2.0 * SweptRegion::kAcceptDistance * swept_->size();

  // One piece: meets tests the curve itself against the index's boxes.
  const SweepPiece piece{t0, t1, dvec2(0.0), dvec2(0.0), false, dvec2(0.0), dvec2(0.0)};
  // A full turn's spans go straight to out (spared a copy per ray).
  SpanList wedged;
  SpanList& spans = fullTurn_ ? out : wedged;
  const bool truncated = swept_->spans(this, path, t0, t1, kSweepStartFace, kSweepEndFace, &piece,
                                       1, spans, firstOnly);
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
    for (const Span& s : cut) out.push_back(s);
  }
  // Spans wholly outside the ray's range (only the cut's margins can hold
  // them) are left out.
  bool outside = false;
  for (const Span& s : out) outside = outside || s.out.t < ray.tMin || s.in.t > ray.tMax;
  if (outside) {
    const SpanList all = out;
    out.clear();
    for (const Span& s : all)
      if (!(s.out.t < ray.tMin || s.in.t > ray.tMax)) out.push_back(s);
  }
  if (truncated && (out.empty() || !(out.front().in.t > ray.tMin))) {
    // Cut short where the first boundary is not yet known (the curve only
    // touched an edge, the wedge cut the span away, or the ray starts
    // inside, where the first boundary is an exit): the whole spans.
    out.clear();
    spansOf(ray, false, out);
  }
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
