#include "check/exact_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>
#include <map>
#include <numbers>
#include <utility>

#include "engine/span_list.h"

namespace csgray::detail {

namespace {

// Below this cosine between a line and a face's normal, the distance from
// a point to the face is not measured along that line (see surfaceDistance).
constexpr double kGrazing = 0.2;
// The last measure of a mesh point that the others put beyond what is
// allowed (ExactDistance::distanceBySearch): this many lines through it, then
// kSearchRounds rounds of kSearchAround lines ever closer to each of the
// kSearchLeads best.
constexpr int kSearchLines = 1024;
constexpr std::size_t kSearchLeads = 8;
constexpr int kSearchRounds = 10;
constexpr int kSearchAround = 64;

// 13 lines through a point: along the axes, the face diagonals and the
// body diagonals of a cube (one of each pair ±v).
const std::array<dvec3, 13> kLines = [] {
  std::array<dvec3, 13> lines;
  std::size_t k = 0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        const bool first = x > 0 || (x == 0 && (y > 0 || (y == 0 && z > 0)));
        if (first) lines[k++] = glm::normalize(dvec3(x, y, z));
      }
  return lines;
}();

// n directions spread evenly over the sphere: the Fibonacci lattice
// (González, "Measurement of areas on a sphere using Fibonacci and
// latitude-longitude lattices", Math. Geosci. 2010), z evenly spaced and
// the azimuth turned by the golden angle from one to the next.
std::vector<dvec3> fibonacciSphere(int n) {
  std::vector<dvec3> directions(n);
  const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(1.0 - z * z), phi = goldenAngle * i;
    directions[i] = dvec3(r * std::cos(phi), r * std::sin(phi), z);
  }
  return directions;
}
const std::vector<dvec3> kSearchDirections = fibonacciSphere(kSearchLines);
const std::vector<dvec3> kAroundDirections = fibonacciSphere(kSearchAround);

// How much further than the tolerance a crease may lie, between faces whose
// outward normals are φ apart (cosine = cos φ): each face's mesh may be
// offset by the tolerance, which moves the crease by 1 / cos(φ/2)
// tolerances, cos(φ/2) = √((1 + cos φ)/2); a knife edge is allowed ten.
double creaseStretch(double cosine) { return 1.0 / std::max(std::sqrt(0.5 * (1.0 + cosine)), 0.1); }
// Faces whose normals are further apart than this meet at a knife edge,
// where creaseStretch is capped: cos(φ/2) = 0.1.
constexpr double kKnifeCosine = 2.0 * 0.1 * 0.1 - 1.0;

}  // namespace

// The outward normal of the solid at a boundary.
dvec3 outwardNormal(const Boundary& b, const dvec3& p) {
  dvec3 n = b.primitive->normal(p, b.face);
  return b.flip ? -n : n;
}

ExactDistance::ExactDistance(const Solid& solid, const CheckOptions& options, const Bounds& box)
    : solid_(solid), options_(options) {
  const double diagonal = glm::length(box.size());
  epsilon_ = 1e-9 * std::max(1.0, diagonal);
  nudge_ = 1e-8 * diagonal * glm::normalize(dvec3(0.5257, 0.6095, 0.5934));
  hair_ = 1e-3 * options.tolerance;
  collectPrimitives(solid);
}

double ExactDistance::surfaceDistance(const dvec3& p, double reach) const {
  double best = reach;
  SpanList spans;
  const dvec3 off = p + nudge_;
  for (const dvec3& d : kLines) {
    const Ray line(off, d, -reach, reach);
    solid_.spans(line, spans);
    for (const Span& s : spans)
      for (const Boundary* b : {&s.in, &s.out}) {
        if (!(std::abs(b->t) < reach)) continue;  // also skips ±infinity
        const double cosine = std::abs(glm::dot(outwardNormal(*b, line.at(b->t)), d));
        if (cosine >= kGrazing) best = std::min(best, std::abs(b->t) * cosine);
      }
  }
  return best;
}

ExactDistance::Projected ExactDistance::distanceByProjection(const dvec3& p, double reach) const {
  struct Foot {
    const Primitive* primitive;
    int face;
    dvec3 point;
  };
  std::vector<Foot> feet;
  SpanList spans;
  for (const Primitive* primitive : primitives_) {
    const Bounds& b = primitive->bounds();
    if (glm::any(glm::lessThan(p + dvec3(reach), b.lo)) ||
        glm::any(glm::greaterThan(p - dvec3(reach), b.hi)))
      continue;
    // The faces of the primitive near p, from the 13 lines through p
    // against the primitive alone, each then projected to from p.
    std::vector<int> faces;
    for (const dvec3& d : kLines) {
      primitive->spans(Ray(p, d, -reach, reach), spans);
      for (const Span& span : spans)
        for (const Boundary* e : {&span.in, &span.out})
          if (std::abs(e->t) < reach &&
              std::find(faces.begin(), faces.end(), int(e->face)) == faces.end())
            faces.push_back(int(e->face));
    }
    for (int face : faces) {
      dvec3 q = p;
      if (projectOnto(*primitive, face, q, reach)) feet.push_back({primitive, face, q});
    }
  }
  // The point that leaves the mesh point most room: a crease farther away
  // may allow more than a face nearer by.
  Projected best{reach, options_.tolerance};
  auto keep = [&](const Projected& found) {
    if (found.distance * best.allowed < best.distance * found.allowed) best = found;
  };
  for (std::size_t i = 0; i < feet.size(); ++i) {
    const Foot& a = feet[i];
    const dvec3 na = a.primitive->normal(a.point, a.face);
    const double d = glm::distance(p, a.point) + hair_;
    if (d < best.distance && insideNear(a.point, {glm::normalize(na)}))
      keep({d, options_.tolerance});
    for (std::size_t j = i + 1; j < feet.size(); ++j) {
      const Foot& b = feet[j];
      dvec3 x = a.point;
      bool met = true;
      for (int k = 0; k < kMaxProjections && met; ++k) {
        const dvec3 before = x;
        met = projectOnto(*b.primitive, b.face, x, reach) &&
              projectOnto(*a.primitive, a.face, x, reach);
        if (glm::distance(before, x) < 0.01 * hair_) break;
      }
      const double d = glm::distance(p, x) + hair_;
      if (!met || d >= reach) continue;
      const dvec3 n[2] = {glm::normalize(a.primitive->normal(x, a.face)),
                          glm::normalize(b.primitive->normal(x, b.face))};
      const std::optional<dvec3> in = insideNear(x, {n[0], n[1]});
      if (!in) continue;
      // The part's outward normals there point away from its inside: a
      // crease whose normals are φ apart, as in allowance.
      const double cosine =
          glm::dot(n[0], n[1]) * (glm::dot(n[0], *in) * glm::dot(n[1], *in) > 0.0 ? 1.0 : -1.0);
      keep({d, options_.tolerance * creaseStretch(cosine)});
    }
  }
  return best;
}

ExactDistance::Projected ExactDistance::distanceBySearch(const dvec3& p, double reach) const {
  const double tolerance = options_.tolerance;
  struct Met {
    double t;
    dvec3 normal;  // outward, where the face is nearest
  };
  // The faces met from p, and from the nearest boundary point found.
  std::map<std::pair<const Primitive*, std::uint32_t>, Met> faces, facesThere;
  SpanList spans;
  // The nearest boundary along the ray from `from` in a direction, within
  // limit; every face met within it is noted in `met`.
  auto along = [&](const dvec3& from, const dvec3& direction, double limit, auto& met) {
    double nearest = limit;
    solid_.spans(Ray(from, direction, 0.0, limit), spans);
    for (const Span& s : spans)
      for (const Boundary* b : {&s.in, &s.out}) {
        if (!(b->t > 0.0 && b->t < limit) || !b->primitive) continue;
        nearest = std::min(nearest, b->t);
        Met& m = met.try_emplace({b->primitive, b->face}, Met{kInfinity, dvec3(0.0)}).first->second;
        if (b->t < m.t) m = {b->t, outwardNormal(*b, from + b->t * direction)};
      }
    return nearest;
  };
  struct Lead {
    double distance;
    dvec3 direction;
  };
  std::vector<Lead> leads;
  for (const dvec3& d : kSearchDirections)
    if (const double t = along(p, d, reach, faces); t < reach) leads.push_back({t, d});
  // Each of the nearest few may lead to the nearest patch.
  const std::size_t followed = std::min<std::size_t>(kSearchLeads, leads.size());
  std::partial_sort(leads.begin(), leads.begin() + followed, leads.end(),
                    [](const Lead& a, const Lead& b) { return a.distance < b.distance; });
  Lead best{reach, kSearchDirections[0]};
  for (std::size_t k = 0; k < followed; ++k) {
    Lead lead = leads[k];
    double spread = std::sqrt(4.0 * std::numbers::pi / kSearchLines);  // the lines' spacing
    for (int round = 0; round < kSearchRounds; ++round, spread *= 0.5) {
      const dvec3 centre = lead.direction;
      for (const dvec3& d : kAroundDirections) {
        const dvec3 direction = glm::normalize(centre + spread * d);
        const double t = along(p, direction, lead.distance + 4.0 * tolerance, faces);
        if (t < lead.distance) lead = {t, direction};
      }
    }
    if (lead.distance < best.distance) best = lead;
  }
  if (!(best.distance < reach)) return {reach, tolerance};
  // The faces within a few tolerances of the nearest point: the patches
  // of a corner there are larger seen from it than from p.
  const dvec3 there = p + best.distance * best.direction;
  for (const dvec3& d : kSearchDirections) along(there, d, 4.0 * tolerance, facesThere);
  for (const auto& [face, m] : faces)
    if (m.t <= best.distance + 4.0 * tolerance) facesThere.try_emplace(face, m);
  std::vector<dvec3> near;
  for (const auto& [face, m] : facesThere) near.push_back(glm::normalize(m.normal));
  return {best.distance, cornerAllowance(near, tolerance)};
}

bool ExactDistance::withinBand(const dvec3& p) const {
  const double reach = kFidelityReach * options_.tolerance;
  const double d = surfaceDistance(p, reach);
  auto within = [&](double distance, double allowed) {
    return distance <= allowed * (1.0 + kCheckEstimateSlack) + epsilon_;
  };
  if (within(d, allowance(p, d))) return true;
  const Projected found = distanceByProjection(p, reach);
  return within(found.distance, found.allowed);
}

double ExactDistance::allowance(const dvec3& p, double d) const {
  const double tolerance = options_.tolerance;
  if (d <= tolerance) return tolerance;
  struct Face {
    const Primitive* primitive;
    std::uint32_t face;
    dvec3 normal;
  };
  std::vector<Face> near;
  const double reach = 4.0 * tolerance + d;
  SpanList spans;
  for (const dvec3& dir : kLines) {
    const Ray line(p + nudge_, dir, -reach, reach);
    solid_.spans(line, spans);
    for (const Span& s : spans)
      for (const Boundary* b : {&s.in, &s.out})
        if (std::abs(b->t) <= reach && b->primitive)
          near.push_back({b->primitive, b->face, outwardNormal(*b, line.at(b->t))});
  }
  double cosine = 1.0;  // of the widest angle between two faces
  const Face* widest[2] = {nullptr, nullptr};
  for (std::size_t i = 0; i < near.size(); ++i)
    for (std::size_t j = i + 1; j < near.size(); ++j)
      if (near[i].primitive != near[j].primitive || near[i].face != near[j].face) {
        const double c = glm::dot(near[i].normal, near[j].normal);
        if (c < cosine) {
          cosine = c;
          widest[0] = &near[i];
          widest[1] = &near[j];
        }
      }
  const double allowed = tolerance * creaseStretch(cosine);
  if (cosine > kKnifeCosine) return allowed;
  return std::max(allowed, tolerance + wedgeDepth(p, *widest[0]->primitive, widest[0]->face,
                                                  *widest[1]->primitive, widest[1]->face));
}

double ExactDistance::cornerAllowance(const std::vector<dvec3>& normals, double tolerance) {
  double stretch = 1.0;
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j) {
      stretch = std::max(stretch, creaseStretch(glm::dot(normals[i], normals[j])));
      for (std::size_t k = j + 1; k < normals.size(); ++k) {
        // Rows of N are the normals; glm's matrices are column-major.
        const glm::dmat3 n = glm::transpose(glm::dmat3(normals[i], normals[j], normals[k]));
        if (std::abs(glm::determinant(n)) < 1e-6) continue;  // three faces along one line
        stretch = std::max(stretch, glm::length(glm::inverse(n) * dvec3(1.0)));
      }
    }
  return std::min(stretch, 10.0) * tolerance;
}

double ExactDistance::wedgeDepth(const dvec3& p, const Primitive& a, std::uint32_t faceA,
                                 const Primitive& b, std::uint32_t faceB) const {
  const double tolerance = options_.tolerance;
  const double reach = kFidelityReach * tolerance;
  dvec3 onA = p;
  if (!projectOnto(a, int(faceA), onA, reach)) return 0.0;
  const dvec3 n = glm::normalize(a.normal(onA, int(faceA)));
  const dvec3 u =
      glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
  const dvec3 v = glm::cross(n, u);
  double depth = reach;
  for (int k = 0; k < 16; ++k) {
    const double angle = std::numbers::pi * k / 8.0;
    const dvec3 t = std::cos(angle) * u + std::sin(angle) * v;
    for (double s = tolerance; s < depth; s *= std::sqrt(2.0)) {
      dvec3 x = onA + s * t, y = x;
      if (!projectOnto(a, int(faceA), x, reach) || !projectOnto(b, int(faceB), y, reach)) break;
      if (glm::distance(x, y) >= 2.0 * tolerance) {
        depth = std::min(depth, glm::distance(p, x));
        break;
      }
    }
  }
  return depth < reach ? depth : 0.0;
}

void ExactDistance::collectPrimitives(const Solid& solid) {
  if (const auto* primitive = dynamic_cast<const Primitive*>(&solid)) {
    primitives_.push_back(primitive);
    return;
  }
  for (const SolidPtr& child : solid.children()) collectPrimitives(*child);
}

bool ExactDistance::projectOnto(const Primitive& primitive, int face, dvec3& x, double reach) {
  const dvec3 n = primitive.normal(x, face);
  if (!(glm::dot(n, n) > 0.0)) return false;
  const Ray line(x, glm::normalize(n), -reach, reach);
  SpanList spans;
  primitive.spans(line, spans);
  double best = kInfinity;
  for (const Span& span : spans)
    for (const Boundary* e : {&span.in, &span.out})
      if (int(e->face) == face && std::abs(e->t) < std::abs(best)) best = e->t;
  if (!(std::abs(best) < reach)) return false;
  x = line.at(best);
  return true;
}

std::optional<dvec3> ExactDistance::insideNear(const dvec3& x,
                                               std::initializer_list<dvec3> normals) const {
  // The sums and differences first: they lie off both faces, so the
  // direction returned tells which side of each the inside is on.
  const std::vector<dvec3> units(normals.begin(), normals.end());
  std::vector<dvec3> directions;
  for (std::size_t i = 0; i < units.size(); ++i)
    for (std::size_t j = i + 1; j < units.size(); ++j)
      for (double sign : {1.0, -1.0}) {
        const dvec3 sum = units[i] + sign * units[j];
        if (glm::dot(sum, sum) > 1e-12) directions.push_back(glm::normalize(sum));
      }
  directions.insert(directions.end(), units.begin(), units.end());
  std::optional<dvec3> inside;
  bool outside = false;
  for (const dvec3& d : directions)
    for (double sign : {1.0, -1.0}) {
      if (solid_.contains(x + sign * hair_ * d)) {
        if (!inside) inside = sign * d;
      } else {
        outside = true;
      }
    }
  return outside ? inside : std::nullopt;
}

}  // namespace csgray::detail
