#include "primitives/rounded_polytope.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <stdexcept>
#include <utility>

#include "primitives/check.h"

namespace csgray::detail {

namespace {

using Edge = RoundedPolytope::Edge;
using Side = RoundedPolytope::Side;

// The edges, each once, from the faces' loops: a→b of one face must meet
// b→a of exactly one other.
std::vector<Edge> edgesOf(const Polytope& p, const std::string& kind) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> faceOf;
  for (std::uint32_t f = 0; f < p.faces.size(); ++f) {
    const auto& loop = p.faces[f].loop;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      auto key = std::make_pair(loop[i], loop[(i + 1) % loop.size()]);
      if (!faceOf.emplace(key, f).second || key.first == key.second)
        throw std::invalid_argument(kind + ": the polytope's faces do not close");
    }
  }
  std::vector<Edge> edges;
  for (const auto& [key, left] : faceOf) {
    auto other = faceOf.find({key.second, key.first});
    if (other == faceOf.end())
      throw std::invalid_argument(kind + ": the polytope's faces do not close");
    if (key.first > key.second) continue;  // each edge from its lower vertex
    Edge e;
    e.a = key.first;
    e.b = key.second;
    e.left = left;
    e.right = other->second;
    dvec3 along = p.vertices[e.b] - p.vertices[e.a];
    e.length = glm::length(along);
    if (!(e.length > 0.0))
      throw std::invalid_argument(kind + ": the polytope has an edge of no length");
    e.direction = along / e.length;
    edges.push_back(e);
  }
  return edges;
}

// Each face's prism of height r: below its plane moved out by r, above the
// plane itself, and inside the planes through its edges square to it.
std::vector<Side> prismOf(const Polytope& p, const Polytope::Face& face, double r) {
  std::vector<Side> sides = {{face.normal, face.offset + r}, {-face.normal, -face.offset}};
  for (std::size_t i = 0; i < face.loop.size(); ++i) {
    const dvec3& a = p.vertices[face.loop[i]];
    const dvec3& b = p.vertices[face.loop[(i + 1) % face.loop.size()]];
    // The loop runs counter-clockwise about the normal, so the face lies to
    // the left of a→b and (b − a) × n points away from it.
    dvec3 out = glm::normalize(glm::cross(b - a, face.normal));
    sides.push_back({out, glm::dot(out, a)});
  }
  return sides;
}

// The interval of t where |o + t·d| <= r, o and d as seen from the centre;
// false if the line misses. The discriminant from the distance of the line
// to the centre, as Sphere's (Haines et al., "Precision Improvements for
// Ray/Sphere Intersection", Ray Tracing Gems 2019, ch. 7). A direction of
// no length (a ray along a cylinder's axis) is inside for every t or none.
bool ballInterval(const dvec3& o, const dvec3& d, double r, double& t0, double& t1) {
  double a = glm::dot(d, d);
  double c = glm::dot(o, o) - r * r;
  if (a == 0.0) {
    t0 = -kInfinity, t1 = kInfinity;
    return c <= 0.0;
  }
  double b = glm::dot(o, d);
  dvec3 closest = o - (b / a) * d;
  double disc = a * (r * r - glm::dot(closest, closest));
  if (disc < 0.0) return false;
  double q = -(b + std::copysign(std::sqrt(disc), b));
  t0 = c / q, t1 = q / a;
  if (q == 0.0) t0 = t1 = 0.0;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

// Cyrus and Beck's clipping of the line to the planes, as ConvexPolyhedron's.
bool prismInterval(const std::vector<Side>& sides, const Ray& ray, double& t0, double& t1) {
  t0 = -kInfinity, t1 = kInfinity;
  for (const Side& s : sides) {
    double denom = glm::dot(s.normal, ray.dir);
    double num = s.offset - glm::dot(s.normal, ray.origin);
    if (denom == 0.0) {
      if (num < 0.0) return false;
      continue;
    }
    double t = num / denom;
    if (denom > 0.0)
      t1 = std::min(t1, t);
    else
      t0 = std::max(t0, t);
    if (t0 > t1) return false;
  }
  return true;
}

// The edge's cylinder, from a to b.
bool edgeInterval(const Edge& e, const dvec3& a, double r, const Ray& ray, double& t0, double& t1) {
  dvec3 o = ray.origin - a;
  double oAlong = glm::dot(o, e.direction), dAlong = glm::dot(ray.dir, e.direction);
  if (!ballInterval(o - oAlong * e.direction, ray.dir - dAlong * e.direction, r, t0, t1))
    return false;
  if (dAlong == 0.0) return oAlong >= 0.0 && oAlong <= e.length;
  double s0 = -oAlong / dAlong, s1 = (e.length - oAlong) / dAlong;
  if (s0 > s1) std::swap(s0, s1);
  t0 = std::max(t0, s0), t1 = std::min(t1, s1);
  return t0 <= t1;
}

}  // namespace

RoundedPolytope::RoundedPolytope(Polytope polytope, double radius, std::string kind)
    : radius_(radius), kind_(std::move(kind)) {
  requirePositive(kind_.c_str(), "r", radius);
  if (polytope.dimension < 2 || polytope.faces.size() < 2)
    throw std::invalid_argument(kind_ + ": the polytope must be a polygon or a solid");
  auto shape = std::make_shared<Shape>();
  shape->edges = edgesOf(polytope, kind_);
  for (const Polytope::Face& face : polytope.faces)
    shape->prisms.push_back(prismOf(polytope, face, radius));
  shape->polytope = std::move(polytope);
  shape_ = std::move(shape);
}

void RoundedPolytope::objectSpans(const Ray& ray, SpanList& out) const {
  const Polytope& p = shape_->polytope;
  double tIn = kInfinity, tOut = -kInfinity;
  std::uint32_t faceIn = 0, faceOut = 0;
  auto take = [&](double t0, double t1, std::size_t face) {
    if (t0 < tIn) tIn = t0, faceIn = static_cast<std::uint32_t>(face);
    if (t1 > tOut) tOut = t1, faceOut = static_cast<std::uint32_t>(face);
  };
  double t0, t1;
  std::size_t face = 0;
  for (const std::vector<Side>& prism : shape_->prisms) {
    if (prismInterval(prism, ray, t0, t1)) take(t0, t1, face);
    ++face;
  }
  for (const Edge& e : shape_->edges) {
    if (edgeInterval(e, p.vertices[e.a], radius_, ray, t0, t1)) take(t0, t1, face);
    ++face;
  }
  for (const dvec3& v : p.vertices) {
    if (ballInterval(ray.origin - v, ray.dir, radius_, t0, t1)) take(t0, t1, face);
    ++face;
  }
  if (tIn > tOut || tOut < ray.tMin || tIn > ray.tMax) return;
  out.push_back(boundary(tIn, static_cast<int>(faceIn)), boundary(tOut, static_cast<int>(faceOut)));
}

bool RoundedPolytope::objectContains(const dvec3& q) const {
  const Polytope& p = shape_->polytope;
  auto inside = [&](const std::vector<Side>& sides) {
    for (const Side& s : sides)
      if (glm::dot(s.normal, q) > s.offset) return false;
    return true;
  };
  for (const std::vector<Side>& prism : shape_->prisms)
    if (inside(prism)) return true;
  if (p.dimension == 3) {
    bool inP = true;
    for (const Polytope::Face& f : p.faces) inP = inP && glm::dot(f.normal, q) <= f.offset;
    if (inP) return true;
  }
  // Within r of an edge (its ends included, so the vertices' balls too).
  for (const Edge& e : shape_->edges) {
    dvec3 o = q - p.vertices[e.a];
    double s = std::clamp(glm::dot(o, e.direction), 0.0, e.length);
    dvec3 off = o - s * e.direction;
    if (glm::dot(off, off) <= radius_ * radius_) return true;
  }
  return false;
}

dvec3 RoundedPolytope::objectNormal(const dvec3& q, int face) const {
  const Polytope& p = shape_->polytope;
  std::size_t i = static_cast<std::size_t>(face);
  if (i < p.faces.size()) return p.faces[i].normal;
  i -= p.faces.size();
  if (i < shape_->edges.size()) {
    const Edge& e = shape_->edges[i];
    dvec3 o = q - p.vertices[e.a];
    return o - glm::dot(o, e.direction) * e.direction;
  }
  return q - p.vertices[i - shape_->edges.size()];
}

Bounds RoundedPolytope::objectBounds() const {
  Bounds box = shape_->polytope.bounds();
  return {box.lo - dvec3(radius_), box.hi + dvec3(radius_)};
}

}  // namespace csgray::detail
