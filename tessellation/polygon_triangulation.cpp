#include "tessellation/polygon_triangulation.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <utility>
#include <vector>

namespace csgray::detail {

namespace {

// Twice the signed area of the triangle (a, b, c): positive for a left turn.
double turn(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Cuts a convex polygon (its corners in order) into a zig-zag strip: each
// triangle joins a corner from the front to one from the back. Unlike a fan,
// whose triangles all meet at one corner, a strip's triangles lie side by
// side, so their boxes overlap only their neighbours' (the mesh checks and
// BVHs test boxes against each other).
void strip(std::span<const std::uint32_t> ring,
           const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& triangle) {
  std::size_t front = 0, back = ring.size() - 1;
  for (bool fromFront = true; back - front >= 2; fromFront = !fromFront) {
    if (fromFront) {
      triangle(ring[front], ring[front + 1], ring[back]);
      ++front;
    } else {
      triangle(ring[front], ring[back - 1], ring[back]);
      --back;
    }
  }
}

}  // namespace

bool triangulatePolygon(
    std::span<const dvec3> points, std::span<const std::uint32_t> polygon,
    const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& triangle) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  if (n == 3) {
    triangle(polygon[0], polygon[1], polygon[2]);
    return true;
  }
  // Newell's normal (Tampieri, "Newell's method for computing the plane
  // equation of a polygon", Graphics Gems III, 1992): the polygon is cut in
  // the plane of its largest axis, seen so that it turns counter-clockwise.
  const dvec3& o = points[polygon[0]];
  dvec3 normal(0.0);
  for (std::size_t i = 0; i < n; ++i)
    normal += glm::cross(points[polygon[i]] - o, points[polygon[(i + 1) % n]] - o);
  const dvec3 m = glm::abs(normal);
  const int axis = m.x > m.y ? (m.x > m.z ? 0 : 2) : (m.y > m.z ? 1 : 2);
  if (!(normal[axis] != 0.0)) return false;
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  if (normal[axis] < 0.0) std::swap(u, v);

  std::vector<glm::dvec2> xy(n);
  std::vector<std::size_t> next(n), prev(n);
  for (std::size_t i = 0; i < n; ++i) {
    xy[i] = {points[polygon[i]][u], points[polygon[i]][v]};
    next[i] = (i + 1) % n;
    prev[i] = (i + n - 1) % n;
  }
  // Reflex (or flat) corners: only they can lie in an ear of a simple
  // polygon (Meisters, "Polygons have ears", 1975; Eberly, "Triangulation
  // by ear clipping", 2002), so only they are tested against one, which
  // makes a polygon with few of them cost little more than a convex one.
  std::vector<char> reflex(n), removed(n, 0);
  std::vector<std::size_t> reflexCorners;
  std::size_t reflexLeft = 0;
  auto classify = [&](std::size_t i) {
    const bool was = reflex[i];
    reflex[i] = !(turn(xy[prev[i]], xy[i], xy[next[i]]) > 0.0);
    if (reflex[i] && !was) reflexCorners.push_back(i), ++reflexLeft;
    if (was && !reflex[i]) --reflexLeft;
  };
  for (std::size_t i = 0; i < n; ++i) classify(i);
  // Ear clipping costs O(n·r) for r reflex corners, O(n²·r) at worst: a
  // polygon too large for it is cut as a strip as if it were convex (the
  // mesh's validity check says where the triangles then overlap).
  if (reflexLeft == 0 || n > kMaxEarClippedCorners) {
    strip(polygon, triangle);
    return true;
  }

  auto isEar = [&](std::size_t i) {
    if (reflex[i]) return false;
    const std::size_t a = prev[i], c = next[i];
    for (std::size_t r : reflexCorners) {
      if (removed[r] || !reflex[r] || r == a || r == c) continue;
      // Closed test: a corner on the cut a–c blocks it too.
      if (turn(xy[a], xy[i], xy[r]) >= 0.0 && turn(xy[i], xy[c], xy[r]) >= 0.0 &&
          turn(xy[c], xy[a], xy[r]) >= 0.0)
        return false;
    }
    return true;
  };
  std::size_t remaining = n, i = 0, tried = 0, clipped = 0;
  while (remaining > 3) {
    if (reflexLeft == 0) {  // what is left is convex
      std::vector<std::uint32_t> ring;
      ring.reserve(remaining);
      for (std::size_t k = 0, j = i; k < remaining; ++k, j = next[j]) ring.push_back(polygon[j]);
      strip(ring, triangle);
      return true;
    }
    // A simple polygon always has an ear; one that is not simple may have
    // none, and is cut anyway.
    if (isEar(i) || tried > remaining) {
      const std::size_t a = prev[i], c = next[i];
      triangle(polygon[a], polygon[i], polygon[c]);
      next[a] = c;
      prev[c] = a;
      removed[i] = 1;
      reflexLeft -= reflex[i];  // only when a polygon that is not simple is cut anyway
      --remaining;
      classify(a);
      classify(c);
      i = c;
      tried = 0;
      // Drop the corners that are gone or no longer reflex now and then.
      if (++clipped % 64 == 0)
        std::erase_if(reflexCorners, [&](std::size_t r) { return removed[r] || !reflex[r]; });
    } else {
      i = next[i];
      ++tried;
    }
  }
  triangle(polygon[prev[i]], polygon[i], polygon[next[i]]);
  return true;
}

}  // namespace csgray::detail
