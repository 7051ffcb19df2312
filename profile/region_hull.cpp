// The convex hull of regions whose boundaries have circular arcs: gift
// wrapping (Jarvis's march) with a supporting line whose outward normal
// turns once round, over points and arcs. An arc can touch a supporting
// line only at the point whose radius is the line's normal, and only where
// the arc bulges outward (counterclockwise on an evaluated profile, whose
// outer loops run counterclockwise): each such arc is a feature valid for
// the normals of its angles; every vertex is a point feature. Between the
// pieces of arcs the hull runs along the common tangents (the bitangent of
// two circles with the same side outward, of radius 0 for points).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "profile/region_evaluation.h"

namespace csgray::detail {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kAngleSlack = 1e-12;

dvec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

struct Feature {
  dvec2 center{0.0};
  double radius = 0.0;  // 0 for a point
  double start = 0.0;   // an arc's first normal angle
  double span = kTwoPi;
  dvec2 from{0.0}, to{0.0};  // an arc's ends, exactly the loop's points
  std::size_t endPoint = 0;  // an arc's `to` as a point feature

  bool arc() const { return radius > 0.0; }
  // Is the normal at `angle` one of the arc's?
  bool valid(double angle) const {
    if (!arc() || span >= kTwoPi) return true;
    const double t = std::fmod(std::fmod(angle - start, kTwoPi) + kTwoPi, kTwoPi);
    return t <= span + kAngleSlack || t >= kTwoPi - kAngleSlack;
  }
  // How far the normal can turn from `angle` before the arc ends.
  double left(double angle) const {
    if (span >= kTwoPi) return kTwoPi;
    const double t = std::fmod(std::fmod(start + span - angle, kTwoPi) + kTwoPi, kTwoPi);
    return t > kTwoPi - kAngleSlack ? 0.0 : t;
  }
  dvec2 contact(double angle) const {
    if (!arc()) return center;
    if (span < kTwoPi) {
      const double t = std::fmod(std::fmod(angle - start, kTwoPi) + kTwoPi, kTwoPi);
      if (t <= kAngleSlack || t >= kTwoPi - kAngleSlack) return from;
      if (std::abs(t - span) <= kAngleSlack) return to;
    }
    return center + radius * direction(angle);
  }
  double support(double angle) const { return glm::dot(center, direction(angle)) + radius; }
};

// How far past `angle` the normal turns before feature j's support
// overtakes feature k's: the normal ψ of their common tangent with both on
// the inner side, where D·cos(ψ − α) = r_k − r_j for the centres' offset
// D·(cos α, sin α) rises through zero. Infinity if it never does.
double overtaking(const Feature& k, const Feature& j, double angle) {
  const dvec2 d = j.center - k.center;
  const double distance = glm::length(d);
  if (distance == 0.0) return std::numeric_limits<double>::infinity();
  const double q = (k.radius - j.radius) / distance;
  // |q| = 1: one touches the other's circle from inside, where acos loses
  // half the digits. A point on an arc's circle meets it at the point's own
  // angle; an arc never passes a point on its circle (nor a circle it
  // touches from inside): it hands over to its end point instead.
  double psi;
  if (std::abs(q) >= 1.0 - 1e-9) {
    if (!(q < 0.0 && !k.arc() && j.arc())) return std::numeric_limits<double>::infinity();
    psi = std::atan2(k.center.y - j.center.y, k.center.x - j.center.x);
  } else {
    psi = std::atan2(d.y, d.x) - std::acos(q);
  }
  double turn = std::fmod(psi - angle, kTwoPi);
  if (turn < -kAngleSlack) turn += kTwoPi;
  if (turn > kTwoPi - kAngleSlack) turn -= kTwoPi;
  return std::max(0.0, turn);
}

std::vector<Feature> featuresOf(const Profile& profile) {
  std::vector<Feature> features;
  for (const ProfileLoop& loop : profile.loops)
    for (const ProfileEdge& e : loop.edges) {
      Feature point;
      point.center = e.from;
      features.push_back(point);
      if (e.kind != ProfileEdge::Kind::Arc || e.angle1 <= e.angle0) continue;
      Feature arc;
      arc.center = e.center;
      arc.radius = std::sqrt(std::abs(glm::determinant(e.axes)));
      arc.start = e.angle0;
      arc.span = e.angle1 - e.angle0 >= kTwoPi - 1e-9 ? kTwoPi : e.angle1 - e.angle0;
      arc.from = e.from;
      arc.to = e.to;
      features.push_back(arc);
      Feature end;
      end.center = e.to;
      features.back().endPoint = features.size();
      features.push_back(end);
    }
  return features;
}

struct Piece {
  std::size_t feature;
  double in, out;  // normal angles
};

}  // namespace

Profile hull(std::span<const RegionPtr> regions, double ellipseTolerance) {
  Profile all;
  for (const RegionPtr& r : regions) {
    Profile p = evaluate(*r, ellipseTolerance);
    all.loops.insert(all.loops.end(), p.loops.begin(), p.loops.end());
  }
  const std::vector<Feature> features = featuresOf(all);
  if (features.empty()) return {};
  const ProfileBounds bounds = all.bounds();
  const double shortest = 1e-12 * glm::length(bounds.hi - bounds.lo);

  // Start at the lowest feature (its normal pointing down), the leftmost
  // of those as low, so that the march goes along a bottom edge.
  const double first = -0.5 * kPi;
  std::size_t start = 0;
  for (std::size_t i = 1; i < features.size(); ++i) {
    if (!features[i].valid(first)) continue;
    const double s = features[i].support(first), best = features[start].support(first);
    if (s > best + shortest ||
        (s >= best - shortest && features[i].contact(first).x < features[start].contact(first).x))
      start = i;
  }

  std::vector<Piece> pieces{{start, first, first}};
  double angle = first;
  for (std::size_t step = 0;; ++step) {
    if (step > 4 * features.size() + 8) throw std::logic_error("hull: the march did not close");
    const Feature& k = features[pieces.back().feature];
    const dvec2 here = k.contact(angle);
    double bestTurn = std::numeric_limits<double>::infinity(), bestReach = -1.0;
    std::size_t next = features.size();
    const auto consider = [&](std::size_t j, double turn) {
      if (turn > bestTurn + kAngleSlack) return;
      const Feature& f = features[j];
      if (!f.valid(angle + turn)) return;
      const double reach = glm::length(f.contact(angle + turn) - here);
      // A feature met where the current one is touches it without passing
      // it, except an arc that starts at the current point (an arc hands
      // over to its end point below).
      if (reach <= shortest && !(f.arc() && !k.arc() && f.left(angle + turn) > kAngleSlack)) return;
      if (turn < bestTurn - kAngleSlack || reach > bestReach) {
        bestTurn = std::min(bestTurn, turn);
        bestReach = reach;
        next = j;
      }
    };
    for (std::size_t j = 0; j < features.size(); ++j)
      if (j != pieces.back().feature) consider(j, overtaking(k, features[j], angle));
    // An arc's last normal hands over to its end point.
    if (k.arc() && k.span < kTwoPi) {
      const double left = k.left(angle);
      if (left < bestTurn - kAngleSlack) {
        bestTurn = left;
        bestReach = 0.0;
        next = k.endPoint;
      }
    }
    if (next == features.size()) break;  // one feature holds every normal: a circle
    angle += bestTurn;
    pieces.back().out = angle;
    if (angle >= first + kTwoPi - kAngleSlack) {
      // Round once: the first piece began where the last one arrived.
      if (pieces.size() > 1 && pieces.back().feature == start) {
        pieces.front().in = pieces.back().in - kTwoPi;
        pieces.pop_back();
      } else if (next == start) {
        pieces.front().in = angle - kTwoPi;
      }
      break;
    }
    pieces.push_back({next, angle, angle});
  }
  if (pieces.size() == 1 && pieces[0].out == first) pieces[0].out = first + kTwoPi;

  ProfileLoop loop;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& p = pieces[i];
    const Feature& f = features[p.feature];
    if (f.arc() && p.out - p.in > kAngleSlack) {
      ProfileEdge e = ProfileEdge::arc(f.center, dmat2(f.radius), p.in, p.out);
      const bool whole = p.out - p.in >= kTwoPi - kAngleSlack;
      e.from = f.contact(p.in);
      e.to = whole ? e.from : f.contact(p.out);
      if (whole) e.angle1 = e.angle0 + kTwoPi;
      loop.edges.push_back(e);
    }
    const Piece& q = pieces[(i + 1) % pieces.size()];
    const dvec2 a = f.contact(p.out), b = features[q.feature].contact(p.out);
    if (glm::length(b - a) > shortest) loop.edges.push_back(ProfileEdge::segment(a, b));
  }
  for (std::size_t i = 0; i < loop.edges.size(); ++i)
    loop.edges[(i + 1) % loop.edges.size()].from = loop.edges[i].to;
  Profile out;
  if (loop.edges.empty()) return out;
  out.loops.push_back(std::move(loop));
  if (area(out) <= shortest * glm::length(bounds.hi - bounds.lo)) out.loops.clear();
  return out;
}

}  // namespace csgray::detail
