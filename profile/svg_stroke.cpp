#include "profile/svg_stroke.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace csgray::detail {

namespace {

double cross(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }

RegionPtr polygonLeaf(const std::vector<dvec2>& corners) {
  ProfileLoop loop;
  for (std::size_t i = 0; i < corners.size(); ++i)
    loop.edges.push_back(ProfileEdge::segment(corners[i], corners[(i + 1) % corners.size()]));
  Profile profile;
  profile.loops.push_back(std::move(loop));
  return Region::leaf(std::move(profile));
}

RegionPtr discLeaf(const dvec2& center, double r) {
  Profile profile;
  profile.loops.push_back({{ProfileEdge::arc(center, dmat2(r), 0.0, 2.0 * std::numbers::pi)}});
  return Region::leaf(std::move(profile));
}

// The piece outside the corner v between the bands of the segments along
// d1 (in) and d2 (out), whose outer sides start at a and b: the mitre, or
// the square cut (Clipper's DoMiter and DoSquare).
RegionPtr joinPiece(const dvec2& v, const dvec2& d1, const dvec2& d2, const dvec2& a,
                    const dvec2& b, double h, StrokeStyle::Join join) {
  const dvec2 n1 = (a - v) / h, n2 = (b - v) / h;
  const double cosine = glm::dot(n1, n2);
  // Clipper mitres where 1 + cos φ >= 2 / limit² for the angle φ between
  // the normals, with its default limit of 2.
  if (join == StrokeStyle::Join::Miter && 1.0 + cosine >= 0.5)
    return polygonLeaf({v, a, v + h * (n1 + n2) / (1.0 + cosine), b});
  // The cut: the line at h from v across the bisector u, met by the two
  // outer sides.
  const dvec2 sum = n1 + n2;
  const dvec2 u = glm::length(sum) > 1e-12 ? glm::normalize(sum) : d1;
  const double t1 = (h - glm::dot(a - v, u)) / glm::dot(d1, u);
  const double t2 = (h - glm::dot(b - v, u)) / glm::dot(-d2, u);
  return polygonLeaf({v, a, a + t1 * d1, b - t2 * d2, b});
}

}  // namespace

RegionPtr strokeRegion(const std::vector<dvec2>& given, const StrokeStyle& style) {
  std::vector<dvec2> points;
  for (const dvec2& p : given)
    if (points.empty() || p != points.back()) points.push_back(p);
  if (points.size() < 2 || !(style.width > 0.0)) return nullptr;
  const double h = 0.5 * style.width;
  const std::size_t n = points.size();
  std::vector<RegionPtr> pieces;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const dvec2 d = glm::normalize(points[i + 1] - points[i]);
    const dvec2 normal(-d.y, d.x);
    dvec2 from = points[i], to = points[i + 1];
    if (style.cap == StrokeStyle::Cap::Square) {
      if (i == 0) from -= h * d;
      if (i + 2 == n) to += h * d;
    }
    pieces.push_back(
        polygonLeaf({from - h * normal, to - h * normal, to + h * normal, from + h * normal}));
  }
  if (style.cap == StrokeStyle::Cap::Round) {
    pieces.push_back(discLeaf(points.front(), h));
    pieces.push_back(discLeaf(points.back(), h));
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const dvec2 v = points[i];
    const dvec2 d1 = glm::normalize(v - points[i - 1]), d2 = glm::normalize(points[i + 1] - v);
    const double turn = cross(d1, d2);
    if (std::abs(turn) < 1e-12 && glm::dot(d1, d2) > 0.0) continue;  // straight on
    if (style.join == StrokeStyle::Join::Round) {
      pieces.push_back(discLeaf(v, h));
      continue;
    }
    // The outer side: right of a left turn, left of a right turn.
    const double side = turn > 0.0 ? -1.0 : 1.0;
    const dvec2 a = v + side * h * dvec2(-d1.y, d1.x), b = v + side * h * dvec2(-d2.y, d2.x);
    pieces.push_back(joinPiece(v, d1, d2, a, b, h, style.join));
  }
  return pieces.size() == 1 ? pieces.front()
                            : Region::boolean(Region::Op::Union, std::move(pieces));
}

}  // namespace csgray::detail
