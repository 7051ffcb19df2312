#include "tessellation/tessellation.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace csgray::detail {

void requireTriangleBudget(const std::string& kind, double triangles, double tolerance) {
  if (triangles <= double(kMaxTessellationTriangles)) return;
  std::ostringstream msg;
  msg.precision(3);
  msg << kind << ": a tolerance of " << tolerance << " would need about " << triangles
      << " triangles (the limit is " << double(kMaxTessellationTriangles)
      << "); give a larger tolerance";
  throw std::invalid_argument(msg.str());
}

int arcSegments(double radius, double angle, double tolerance, int minSegments) {
  if (!(radius > tolerance)) return minSegments;
  const double step = 2.0 * std::acos(1.0 - tolerance / radius);
  const double n = std::ceil(angle / step);
  // Far past any budget: let the caller's requireTriangleBudget say so.
  if (n > 1e9) return 1'000'000'000;
  return std::max(minSegments, static_cast<int>(n));
}

int circleSegments(int n) {
  // The rungs between 2^(b+1)·s and 2^(b+2)·s are the multiples of s.
  int scale = 1;
  while (n > (2 << kCircleLadderBits) * scale && scale < (1 << 28)) scale *= 2;
  return (n + scale - 1) / scale * scale;
}

CirclePolygon circlePolygon(double radius, double tolerance) {
  constexpr double kShift = 1e-9;  // of the radius, at most
  CirclePolygon polygon;
  polygon.shift = tolerance > 4.0 * kShift * radius ? kShift : 0.0;
  // The shift is of the pushed-out radius, at most 2/(1 + cos(π/8)) < 2 r.
  // A tenth of the tolerance is left for the tube of a torus turned on
  // the same polygon.
  const double error = 0.9 * tolerance - 2.0 * polygon.shift * radius;
  polygon.segments = circleSegments(
      arcSegments(radius, 2.0 * std::numbers::pi, 2.0 * radius * error / (radius + error)));
  const double c = std::cos(std::numbers::pi / polygon.segments);
  polygon.out = 2.0 / (1.0 + c);
  polygon.error = radius * (1.0 - c) / (1.0 + c) + 2.0 * polygon.shift * radius;
  return polygon;
}

void requireTolerance(const std::string& kind, double tolerance) {
  if (tolerance > 0.0 && std::isfinite(tolerance)) return;
  std::ostringstream msg;
  msg << kind << ": the tolerance must be a positive finite number (got " << tolerance << ")";
  throw std::invalid_argument(msg.str());
}

// ---- Surfaces of revolution ---------------------------------------------------------

double revolvedTriangles(double profileEdges, double segments) {
  return 2.0 * profileEdges * segments;
}

TriangleMesh revolveProfile(const std::vector<glm::dvec2>& profile, int segments, bool closed,
                            const CirclePolygon* circle) {
  const std::size_t n = profile.size();
  const auto steps = static_cast<std::uint32_t>(segments);
  if (n < 2 || segments < 3) throw std::logic_error("revolveProfile: too few points");
  auto onAxis = [&](std::size_t k) { return profile[k].x == 0.0; };
  for (std::size_t k = 0; k < n; ++k) {
    bool end = !closed && (k == 0 || k + 1 == n);
    if (onAxis(k) != end) throw std::logic_error("revolveProfile: axis points only at the ends");
  }
  TriangleMesh mesh;
  // The first vertex of each profile point: one on the axis, else a ring.
  std::vector<std::uint32_t> first(n);
  std::vector<double> cosines(steps), sines(steps);
  for (std::uint32_t s = 0; s < steps; ++s) {
    double theta = 2.0 * std::numbers::pi * s / segments;
    cosines[s] = std::cos(theta);
    sines[s] = std::sin(theta);
  }
  for (std::size_t k = 0; k < n; ++k) {
    first[k] = static_cast<std::uint32_t>(mesh.points.size());
    const glm::dvec2& q = profile[k];
    if (onAxis(k)) {
      mesh.points.emplace_back(0.0, 0.0, q.y);
      continue;
    }
    for (std::uint32_t s = 0; s < steps; ++s) {
      const double rho = circle ? circle->radiusAt(q.x, s) : q.x;
      mesh.points.emplace_back(rho * cosines[s], rho * sines[s], q.y);
    }
  }
  auto vertex = [&](std::size_t k, std::uint32_t s) {
    return onAxis(k) ? first[k] : first[k] + s % steps;
  };
  const std::size_t edges = closed ? n : n - 1;
  mesh.triangles.reserve(2 * edges * steps);
  for (std::size_t k = 0; k < edges; ++k) {
    std::size_t next = (k + 1) % n;
    for (std::uint32_t s = 0; s < steps; ++s) {
      // The quad a b c d: a → b along the circle of k (θ growing), then up
      // the profile; (b − a) × (d − a) points away from the solid.
      std::uint32_t a = vertex(k, s), b = vertex(k, s + 1);
      std::uint32_t c = vertex(next, s + 1), d = vertex(next, s);
      if (!onAxis(k) && !onAxis(next)) {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      } else if (onAxis(k)) {
        mesh.triangles.push_back({a, c, d});  // a = b, the pole
      } else {
        mesh.triangles.push_back({a, b, c});  // c = d, the pole
      }
    }
  }
  return mesh;
}

// ---- Convex polytopes -----------------------------------------------------------------

namespace {

// A corner of a face polygon, and the plane whose line (in the face's
// plane) runs from it to the next corner; -1 for the sides of the square
// the polygon starts as.
struct Corner {
  dvec3 point;
  int edge;
};

// Where three planes meet (Cramer's rule with the triple product as the
// determinant), if they meet at a well-defined point.
bool meetOfPlanes(const BoundingPlane& a, const BoundingPlane& b, const BoundingPlane& c,
                  dvec3& out) {
  dvec3 bc = glm::cross(b.normal, c.normal);
  double det = glm::dot(a.normal, bc);
  if (!(std::abs(det) > 1e-9)) return false;
  out = (a.offset * bc + b.offset * glm::cross(c.normal, a.normal) +
         c.offset * glm::cross(a.normal, b.normal)) /
        det;
  return true;
}

// Face f's polygon, counter-clockwise about its normal: a square covering
// the box in the plane, clipped by every other plane (Sutherland and
// Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974). Points within
// eps of a plane count as on it, so a plane through a vertex adds none.
std::vector<Corner> facePolygon(const std::vector<BoundingPlane>& planes, std::size_t f,
                                const Bounds& box, double eps) {
  const BoundingPlane& face = planes[f];
  const dvec3& n = face.normal;
  const dvec3 centre = box.center();
  const dvec3 origin = centre - (glm::dot(n, centre) - face.offset) * n;
  // Any unit vector across n, from the axis least along it.
  dvec3 axis(0.0);
  axis[std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z) ? 0
       : std::abs(n.y) <= std::abs(n.z)                                 ? 1
                                                                        : 2] = 1.0;
  const dvec3 u = glm::normalize(glm::cross(n, axis));
  const dvec3 w = glm::cross(n, u);
  // The plane meets the box within half its diagonal of the centre's foot.
  const double half = glm::length(box.size());
  std::vector<Corner> polygon = {{origin + half * (-u - w), -1},
                                 {origin + half * (u - w), -1},
                                 {origin + half * (u + w), -1},
                                 {origin + half * (-u + w), -1}};
  std::vector<Corner> clipped;
  std::vector<double> side;
  for (std::size_t j = 0; j < planes.size() && polygon.size() >= 3; ++j) {
    if (j == f) continue;
    const BoundingPlane& cut = planes[j];
    if (glm::dot(cut.normal, n) > 1.0 - 1e-12) {
      // Parallel and facing the same way: the nearer plane (the first of
      // equal ones) bounds the solid; the other only touches it, if at all.
      if (cut.offset < face.offset - eps || (cut.offset <= face.offset + eps && j < f)) return {};
      continue;
    }
    side.resize(polygon.size());
    for (std::size_t k = 0; k < polygon.size(); ++k)
      side[k] = glm::dot(cut.normal, polygon[k].point) - cut.offset;
    clipped.clear();
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      std::size_t next = (k + 1) % polygon.size();
      const Corner& a = polygon[k];
      double sa = side[k], sb = side[next];
      if (sa <= eps) clipped.push_back({a.point, sb > eps && sa >= -eps ? int(j) : a.edge});
      bool leaves = sa < -eps && sb > eps, enters = sa > eps && sb < -eps;
      if (!leaves && !enters) continue;
      dvec3 p;
      if (a.edge < 0 || !meetOfPlanes(face, planes[std::size_t(a.edge)], cut, p)) {
        double t = sa / (sa - sb);
        p = a.point + t * (polygon[next].point - a.point);
      }
      clipped.push_back({p, leaves ? int(j) : a.edge});
    }
    std::swap(polygon, clipped);
  }
  if (polygon.size() < 3) return {};
  return polygon;
}

}  // namespace

TriangleMesh convexPolytopeMesh(const std::vector<BoundingPlane>& given, const Bounds& box) {
  std::vector<BoundingPlane> planes = given;
  for (int axis = 0; axis < 3; ++axis) {
    dvec3 n(0.0);
    n[axis] = 1.0;
    planes.push_back({n, box.hi[axis]});
    planes.push_back({-n, -box.lo[axis]});
  }
  // Lengths relative to the size and the place of the box: rounding in a
  // corner is ~1e-16 of that, far below eps, and distinct vertices closer
  // than weld would make faces too thin to matter.
  const double scale = glm::length(box.size()) + glm::length(box.center());
  const double eps = 1e-12 * scale, weld = 1e-9 * scale;

  std::vector<std::vector<Corner>> faces;
  for (std::size_t f = 0; f < planes.size(); ++f) {
    std::vector<Corner> polygon = facePolygon(planes, f, box, eps);
    if (!polygon.empty()) faces.push_back(std::move(polygon));
  }
  // Weld the corners of all faces: sorted by x, each joins the first
  // earlier corner within `weld` of it.
  std::vector<const dvec3*> corners;
  for (const auto& face : faces)
    for (const Corner& c : face) corners.push_back(&c.point);
  std::vector<std::size_t> order(corners.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return corners[a]->x < corners[b]->x; });
  TriangleMesh mesh;
  std::vector<std::uint32_t> id(corners.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const dvec3& p = *corners[order[i]];
    bool found = false;
    for (std::size_t j = i; j-- > 0 && p.x - corners[order[j]]->x <= weld;) {
      if (glm::length(p - *corners[order[j]]) <= weld) {
        id[order[i]] = id[order[j]];
        found = true;
        break;
      }
    }
    if (!found) {
      id[order[i]] = static_cast<std::uint32_t>(mesh.points.size());
      mesh.points.push_back(p);
    }
  }
  // Each face, its welded corners once, fanned from the first.
  std::size_t next = 0;
  for (const auto& face : faces) {
    std::vector<std::uint32_t> ring;
    for (std::size_t k = 0; k < face.size(); ++k, ++next)
      if (ring.empty() || ring.back() != id[next]) ring.push_back(id[next]);
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    for (std::size_t k = 1; k + 1 < ring.size(); ++k)
      mesh.triangles.push_back({ring[0], ring[k], ring[k + 1]});
  }
  return mesh;
}

void requireFiniteRegion(const std::string& kind, const Bounds& region) {
  if (region.finite() || region.empty()) return;
  throw std::invalid_argument(
      kind + ": is unbounded; intersect it with a bounded solid (e.g. clip(...)) to export it");
}

Bounds regionWithMargin(const Bounds& region, double tolerance) {
  double margin = 0.01 * glm::length(region.size()) + tolerance;
  return {region.lo - dvec3(margin), region.hi + dvec3(margin)};
}

}  // namespace csgray::detail
