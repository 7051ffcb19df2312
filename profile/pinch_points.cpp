#include "profile/pinch_points.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>
#include <vector>

namespace csgray::detail {

namespace {

// Far above the rounding of points that an exact evaluation rounds to
// doubles, far below any feature a part has.
constexpr double kHair = 0x1p-40;

// Is p on the edge away from its ends (within a hair)? The evaluated
// loops hold segments and circular arcs only.
bool insideOfEdge(const ProfileEdge& e, const dvec2& p, double hair) {
  if (glm::length(p - e.from) <= hair || glm::length(p - e.to) <= hair) return false;
  if (e.kind == ProfileEdge::Kind::Segment) {
    const dvec2 d = e.to - e.from;
    const double t = glm::dot(p - e.from, d) / glm::dot(d, d);
    return t > 0.0 && t < 1.0 && glm::length(e.from + t * d - p) <= hair;
  }
  if (e.kind != ProfileEdge::Kind::Arc) return false;
  const double r = glm::length(e.axes[0]);
  if (!(std::abs(glm::length(p - e.center) - r) <= hair)) return false;
  // The angle of p on the arc's circle, from angle0 the way it sweeps.
  const dvec2 unit = glm::inverse(e.axes) * (p - e.center);
  const double sweep = e.angle1 - e.angle0;
  double along = std::atan2(unit.y, unit.x) - e.angle0;
  const double turn = 2.0 * std::numbers::pi;
  along = std::fmod(along, turn);
  if (sweep > 0.0 && along < 0.0) along += turn;
  if (sweep < 0.0 && along > 0.0) along -= turn;
  return along / sweep > 0.0 && along / sweep < 1.0;
}

// The points where the boundary passes twice; with firstOnly, the first
// found.
std::vector<dvec2> pointsTouching(const Profile& evaluated, bool firstOnly) {
  std::vector<dvec2> found;
  const ProfileBounds box = evaluated.bounds();
  if (box.empty()) return found;
  const double size = std::max({1.0, box.hi.x - box.lo.x, box.hi.y - box.lo.y, std::abs(box.lo.x),
                                std::abs(box.lo.y), std::abs(box.hi.x), std::abs(box.hi.y)});
  const double hair = kHair * size;
  std::vector<dvec2> corners;
  struct Reach {
    ProfileBounds box;
    const ProfileEdge* edge;
  };
  std::vector<Reach> edges;
  for (const ProfileLoop& loop : evaluated.loops)
    for (const ProfileEdge& e : loop.edges) {
      corners.push_back(e.to);
      Reach reach{{}, &e};
      reach.box.include(e.from);
      reach.box.include(e.to);
      if (e.kind == ProfileEdge::Kind::Arc) {
        const double r = glm::length(e.axes[0]);
        reach.box.include(e.center - dvec2(r));
        reach.box.include(e.center + dvec2(r));
      }
      edges.push_back(reach);
    }
  const auto byX = [](const dvec2& a, const dvec2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  };
  std::sort(corners.begin(), corners.end(), byX);
  for (auto twice = std::adjacent_find(corners.begin(), corners.end()); twice != corners.end();
       twice = std::adjacent_find(twice + 1, corners.end())) {
    found.push_back(*twice);
    if (firstOnly) return found;
  }
  // A sweep along x: the edges whose boxes reach each corner's x.
  std::sort(edges.begin(), edges.end(),
            [](const Reach& a, const Reach& b) { return a.box.lo.x < b.box.lo.x; });
  std::vector<const Reach*> active;
  std::size_t next = 0;
  for (const dvec2& p : corners) {
    while (next < edges.size() && edges[next].box.lo.x <= p.x + hair)
      active.push_back(&edges[next++]);
    std::erase_if(active, [&](const Reach* r) { return r->box.hi.x < p.x - hair; });
    for (const Reach* r : active)
      if (p.y >= r->box.lo.y - hair && p.y <= r->box.hi.y + hair &&
          insideOfEdge(*r->edge, p, hair)) {
        found.push_back(p);
        if (firstOnly) return found;
        break;
      }
  }
  std::sort(found.begin(), found.end(), byX);
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

}  // namespace

bool touchesItself(const Profile& evaluated) { return !pointsTouching(evaluated, true).empty(); }

std::vector<dvec2> pinchPoints(const Profile& evaluated) {
  return pointsTouching(evaluated, false);
}

}  // namespace csgray::detail
