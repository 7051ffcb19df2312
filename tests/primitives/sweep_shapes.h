// Regions for the sweeps' tests, built from profile/ directly (the script's
// 2D shapes are tested on their own): squares, circles, polygons, and
// their analytic areas.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "profile/region.h"

namespace csgray::detail::test {

inline ProfileLoop polygonLoop(const std::vector<dvec2>& points) {
  ProfileLoop loop;
  for (std::size_t i = 0; i < points.size(); ++i)
    loop.edges.push_back(ProfileEdge::segment(points[i], points[(i + 1) % points.size()]));
  return loop;
}

inline ProfileLoop rectangleLoop(const dvec2& lo, const dvec2& hi) {
  return polygonLoop({lo, {hi.x, lo.y}, hi, {lo.x, hi.y}});
}

inline ProfileLoop circleLoop(const dvec2& center, double r) {
  return ProfileLoop{{ProfileEdge::arc(center, dmat2(r), 0.0, 2.0 * std::numbers::pi)}};
}

inline RegionPtr regionOf(std::vector<ProfileLoop> loops) {
  Profile p;
  p.loops = std::move(loops);
  return Region::leaf(std::move(p));
}

inline RegionPtr rectangle(const dvec2& lo, const dvec2& hi) {
  return regionOf({rectangleLoop(lo, hi)});
}
inline RegionPtr circle(const dvec2& center, double r) { return regionOf({circleLoop(center, r)}); }

// A regular n-gon's corners at radius r about the origin, with every other
// one pulled in to `inner` (a star, or a gear-like outline of many points).
inline std::vector<dvec2> starPoints(int n, double r, double inner) {
  std::vector<dvec2> points;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    const double radius = i % 2 == 0 ? r : inner;
    points.emplace_back(radius * std::cos(a), radius * std::sin(a));
  }
  return points;
}

inline double polygonArea(const std::vector<dvec2>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const dvec2& u = p[i];
    const dvec2& v = p[(i + 1) % p.size()];
    a += u.x * v.y - u.y * v.x;
  }
  return 0.5 * std::abs(a);
}

}  // namespace csgray::detail::test
