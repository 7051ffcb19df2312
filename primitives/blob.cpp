#include "primitives/blob.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <stdexcept>

#include "engine/solvers/quartic.h"
#include "primitives/check.h"

namespace csgray::detail {

namespace {

// Where a ball's stretch of the line starts (adds its quartic) or ends
// (takes it away).
struct Event {
  double s;
  int ball;  // the ball's index + 1, negative where it ends
};

// A ball's field along the conditioned line b + s·u, as a quartic in s:
// strength·w², w = 1 − |b + s·u − c|²/r² = A·s² + B·s + C.
struct Quartic {
  double c[5];
};

Quartic ballQuartic(const dvec3& b, const dvec3& u, const dvec3& center, double r2,
                    double strength) {
  const dvec3 v = b - center;
  const double A = -1.0 / r2, B = -2.0 * glm::dot(v, u) / r2, C = 1.0 - glm::dot(v, v) / r2;
  return {{strength * C * C, strength * 2.0 * B * C, strength * (B * B + 2.0 * A * C),
           strength * 2.0 * A * B, strength * A * A}};
}

}  // namespace

Blob::Blob(std::vector<BlobBall> balls, double threshold)
    : balls_(std::move(balls)), threshold_(threshold) {
  requirePositive("blob", "threshold", threshold);
  if (balls_.empty()) throw std::invalid_argument("blob: needs at least one ball");
  if (balls_.size() > kMaxBalls) {
    std::ostringstream msg;
    msg << "blob: at most " << kMaxBalls << " balls (got " << balls_.size() << ")";
    throw std::invalid_argument(msg.str());
  }
  Bounds box;
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    const BlobBall& ball = balls_[i];
    const std::string at = "balls[" + std::to_string(i + 1) + "]";
    for (int k = 0; k < 3; ++k) requireFinite("blob", (at + ".center").c_str(), ball.center[k]);
    requirePositive("blob", (at + ".r").c_str(), ball.radius);
    requireFinite("blob", (at + ".strength").c_str(), ball.strength);
    if (ball.strength == 0.0)
      throw std::invalid_argument("blob: " + at + ".strength must not be 0");
    if (ball.strength > 0.0)
      box.include(Bounds{ball.center - ball.radius, ball.center + ball.radius});
  }
  if (box.empty())
    throw std::invalid_argument(
        "blob: needs a ball of positive strength (negative ones only take away)");
  center_ = box.center();
  size_ = 0.0;
  for (const BlobBall& ball : balls_)
    if (ball.strength > 0.0)
      size_ = std::max(size_, glm::length(ball.center - center_) + ball.radius);
}

double Blob::excess(const dvec3& p) const {
  double field = 0.0;
  for (const BlobBall& ball : balls_) {
    const dvec3 v = p - ball.center;
    const double w = 1.0 - glm::dot(v, v) / (ball.radius * ball.radius);
    if (w > 0.0) field += ball.strength * w * w;
  }
  return field - threshold_;
}

// ∇(s·w²) = 2·s·w·∇w, ∇w = −2(p − c)/r².
dvec3 Blob::fieldGradient(const dvec3& p) const {
  dvec3 gradient(0.0);
  for (const BlobBall& ball : balls_) {
    const dvec3 v = p - ball.center;
    const double r2 = ball.radius * ball.radius;
    const double w = 1.0 - glm::dot(v, v) / r2;
    if (w > 0.0) gradient -= (4.0 * ball.strength * w / r2) * v;
  }
  return gradient;
}

// Along a line each ball's field is a quartic in the line's parameter on
// the stretch inside the ball and zero elsewhere, so the sum is a quartic
// on each stretch between the points where some ball starts or ends
// (Wyvill, McPheeters and Wyvill, "Data Structure for Soft Objects", The
// Visual Computer 2(4), 1986; Nishimura et al.'s metaballs alike). Steps:
//  1. Condition: the line as b + s·u, u a unit vector, b its point nearest
//     the centre of the blob's bounding ball, lengths in units of that
//     ball's radius, so the quartics' coefficients are O(1) however far
//     the ray starts.
//  2. Each ball that the line crosses gives a stretch [m − h, m + h] and
//     its quartic; the stretches' ends, sorted, are the events of a sweep
//     that keeps the sum of the quartics of the balls the line is in.
//  3. On each stretch between events, the boundaries are where
//     threshold − sum changes sign: the roots of a quartic isolated
//     between the roots of its derivative (engine/solvers/quartic.h), the
//     torus's solver. The sign at each stretch's start is evaluated, so a
//     boundary that falls on an event is not lost.
//  4. Outside every ball the field is 0, below the threshold: the spans
//     start and end outside.
void Blob::objectSpans(const Ray& ray, SpanList& out) const { spansOf(ray, false, out); }

// A camera or shadow ray needs only the first boundary: an entry after the
// window's start ends the search, its span running on to the last event.
void Blob::objectSpansToFirstBoundary(const Ray& ray, SpanList& out) const {
  spansOf(ray, true, out);
}

void Blob::spansOf(const Ray& ray, bool firstOnly, SpanList& out) const {
  // 1. The conditioned line: t = t0 + s·scale.
  const double length = glm::length(ray.dir);
  const dvec3 u = ray.dir / length;
  const double t0 = glm::dot(center_ - ray.origin, u) / length;
  const dvec3 b = (ray.origin + t0 * ray.dir - center_) / size_;
  const double scale = size_ / length;
  if (glm::dot(b, b) >= 1.0) return;  // misses the bounding ball

  // 2. The balls' stretches.
  thread_local std::vector<Event> events;
  events.clear();
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    const BlobBall& ball = balls_[i];
    const dvec3 c = (ball.center - center_) / size_;
    const double r = ball.radius / size_;
    const double m = glm::dot(c - b, u);
    const dvec3 foot = b + m * u - c;
    const double left = r * r - glm::dot(foot, foot);
    if (!(left > 0.0)) continue;
    const double h = std::sqrt(left);
    events.push_back({m - h, int(i) + 1});
    events.push_back({m + h, -(int(i) + 1)});
  }
  if (events.empty()) return;
  std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) { return x.s < y.s; });

  // 3. The sweep. The spans in s, then mapped to t.
  double sum[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  int active = 0;
  bool inside = false;
  double entry = 0.0;
  const double sMin = (ray.tMin - t0) / scale, sMax = (ray.tMax - t0) / scale;
  // Closes the span from entry; true once a ray that needs only its first
  // boundary has it (the exit of a span it starts in).
  auto close = [&](double exit) {
    if (exit >= sMin && entry <= sMax)
      out.push_back(boundary(t0 + entry * scale), boundary(t0 + exit * scale));
    return firstOnly && exit > sMin;
  };
  for (std::size_t k = 0; k + 1 < events.size(); ++k) {
    const Event& e = events[k];
    const BlobBall& ball = balls_[std::abs(e.ball) - 1];
    const Quartic q = ballQuartic(b, u, (ball.center - center_) / size_,
                                  (ball.radius / size_) * (ball.radius / size_), ball.strength);
    const double sign = e.ball > 0 ? 1.0 : -1.0;
    active += e.ball > 0 ? 1 : -1;
    for (int j = 0; j < 5; ++j) sum[j] = active == 0 ? 0.0 : sum[j] + sign * q.c[j];
    const double lo = e.s, hi = events[k + 1].s;
    if (active == 0 || !(hi > lo)) continue;
    // threshold − sum <= 0 inside, its degree lowered past leading
    // coefficients that cancel (balls of opposite strengths).
    double p[5] = {threshold_ - sum[0], -sum[1], -sum[2], -sum[3], -sum[4]};
    double largest = 0.0;
    for (double c : p) largest = std::max(largest, std::abs(c));
    int degree = 4;
    while (degree > 0 && std::abs(p[degree]) <= 1e-14 * largest) --degree;
    const bool startsInside = polynomialValue(p, degree, lo) <= 0.0;
    if (startsInside != inside) {
      if (inside && close(lo)) return;
      entry = lo;
      inside = startsInside;
    }
    double roots[4];
    const int found = degree > 0 ? polynomialSublevelBoundaries(p, degree, lo, hi, roots) : 0;
    for (int j = 0; j < found; ++j) {
      if (inside && close(roots[j])) return;
      entry = roots[j];
      inside = !inside;
    }
    // A first boundary after the window's start is all such a ray needs.
    if (firstOnly && inside && entry > sMin) {
      close(events.back().s);
      return;
    }
  }
  // 4. Past the last event the field is 0: outside.
  if (inside) close(events.back().s);
}

bool Blob::objectContains(const dvec3& p) const { return excess(p) >= 0.0; }

dvec3 Blob::objectNormal(const dvec3& p, int) const {
  const dvec3 n = -fieldGradient(p);
  if (n == dvec3(0.0)) return p - center_;  // a flat spot of the field: not on a smooth surface
  return n;
}

Bounds Blob::objectBounds() const {
  Bounds box;
  for (const BlobBall& ball : balls_)
    if (ball.strength > 0.0)
      box.include(Bounds{ball.center - ball.radius, ball.center + ball.radius});
  return box;
}

}  // namespace csgray::detail
