#include "check/part_check.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <vector>

#include "check/axis_crossings.h"
#include "export/cgal/mesh_boolean.h"
#include "export/cgal/mesh_probe.h"
#include "export/cgal/mesh_validity.h"
#include "meshfile/mesh_writer.h"
#include "engine/boolean.h"
#include "tessellation/mesh_shells.h"
#include "engine/primitive.h"

namespace csgray::detail {

namespace {

// Two faces face each other across a stretch when their outward normals
// are within about 25° of opposite: a wall or a gap. Across a sphere near
// its silhouette they do not, so a grazing ray finds no thin wall there.
constexpr double kFacing = -0.9;
// Normals this close to parallel (about 0.08°) make coinciding boundaries
// coinciding faces; otherwise the ray merely passes where two faces cross.
constexpr double kParallel = 1.0 - 1e-6;
// Below this cosine between a line and a face's normal, the distance from
// a point to the face is not measured along that line (see surfaceDistance).
constexpr double kGrazing = 0.2;
// Grid volumes may differ by this many standard deviations of their
// sampling before the grids are said to disagree.
constexpr double kSigmas = 5.0;
// A mesh point whose distance from the exact surface, estimated along its
// own ray, is below this share of the tolerance is not measured along 13
// lines: the estimate is good, and the point cannot be the one that fails.
constexpr double kQuickShare = 0.5;
// A mesh point further than this many tolerances from the exact surface is
// reported as this far: the check has failed by then.
constexpr double kFidelityReach = 100.0;
// The last measure of a mesh point that the others put beyond what is
// allowed (Checker::distanceBySearch): this many lines through it, then
// kSearchRounds rounds of kSearchAround lines ever closer to each of the
// kSearchLeads best.
constexpr int kSearchLines = 1024;
constexpr std::size_t kSearchLeads = 8;
constexpr int kSearchRounds = 10;
constexpr int kSearchAround = 64;
constexpr std::size_t kListed = 10;  // disagreeing points listed
constexpr std::size_t kWarningKinds = 20;

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

// splitmix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014): a jitter per ray that does not depend on
// which thread traces it, so every run of a check gives the same figures.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
double unit(std::uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

dvec3 axisVector(int axis) {
  dvec3 d(0.0);
  d[axis] = 1.0;
  return d;
}

// The outward normal of the solid at a boundary.
dvec3 outwardNormal(const Boundary& b, const dvec3& p) {
  dvec3 n = b.primitive->normal(p, b.face);
  return b.flip ? -n : n;
}

std::string describe(const Solid& solid) {
  std::string line = solid.origin().text();
  return line.empty() ? solid.kind() : solid.kind() + " (" + line + ")";
}

std::string format(const dvec3& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

// What the rays of one row of a grid found; rows are merged in order, so
// that the figures do not depend on the threads.
struct Tally {
  // The sampled point furthest from the other boundary for what is
  // allowed there.
  double fidelity = 0.0, fidelityAllowed = 1.0;
  dvec3 fidelityAt{0.0};
  bool fidelityFromMesh = false;
  std::optional<Stretch> wall, gap;
  bool unbounded = false;
  // Warnings by what they say but where: one for each pair of script
  // lines, however many faces and rays show it.
  std::map<std::string, CheckWarning> warnings;

  // Would a point d away where `allowed` is allowed be the worst so far?
  bool worse(double d, double allowed) const { return d * fidelityAllowed > fidelity * allowed; }
  void distance(double d, double allowed, const dvec3& at, bool fromMesh) {
    if (worse(d, allowed)) {
      fidelity = d;
      fidelityAllowed = allowed;
      fidelityAt = at;
      fidelityFromMesh = fromMesh;
    }
  }
  static void thinnest(std::optional<Stretch>& best, double thickness, const dvec3& at) {
    if (!best || thickness < best->thickness) best = Stretch{thickness, at};
  }
  void warn(const std::string& kind, const std::string& what, const dvec3& at) {
    auto [it, added] = warnings.try_emplace(kind + ": " + what);
    if (added) {
      it->second.kind = kind;
      it->second.message = what + ", at " + format(at);
      it->second.location = at;
    } else {
      ++it->second.rays;
    }
  }
  void merge(const Tally& other) {
    distance(other.fidelity, other.fidelityAllowed, other.fidelityAt, other.fidelityFromMesh);
    if (other.wall) thinnest(wall, other.wall->thickness, other.wall->location);
    if (other.gap) thinnest(gap, other.gap->thickness, other.gap->location);
    unbounded = unbounded || other.unbounded;
    for (const auto& [key, w] : other.warnings) {
      auto [it, added] = warnings.try_emplace(key, w);
      if (!added) it->second.rays += w.rays;
    }
  }
};

class Checker {
 public:
  Checker(const Solid& solid, const MeshProbe& probe, const CheckOptions& options,
          const Bounds& box)
      : solid_(solid), probe_(probe), options_(options) {
    const double diagonal = glm::length(box.size());
    epsilon_ = 1e-9 * std::max(1.0, diagonal);
    cap_ = diagonal;
    nudge_ = 1e-8 * diagonal * glm::normalize(dvec3(0.5257, 0.6095, 0.5934));
    partBox_ = {solid.bounds().lo - dvec3(epsilon_), solid.bounds().hi + dvec3(epsilon_)};
    hair_ = 1e-3 * options.tolerance;
    collectPrimitives(solid);
  }

  double epsilon() const { return epsilon_; }

  // The distance from p to the exact surface, estimated along 13 lines
  // through p (the axes, the face diagonals and the body diagonals of a
  // cube): a boundary at Δt with unit normal n is Δt·|n·d| away if the
  // surface is flat there (exact for a plane, off by O(δ²/radius) on a
  // curved one); the least over the boundaries. Faces a line grazes
  // (|n·d| < kGrazing) are left to the other lines. Several lines are
  // needed near an edge of the solid, where the nearest point is on the
  // edge and the lines along the axes may all miss the faces beside it.
  //
  // The lines pass a hair's breadth (1e-8 of the box) off p in a skew
  // direction: a mesh point found by an axis ray lies on an axis-aligned
  // face more often than not, and a line in the plane of a face grazes it.
  //
  // Only faces within `reach` of p are looked for, and a distance beyond
  // it is given as `reach`: the callers need no more, and a short line
  // meets few of a large boolean's operands.
  double surfaceDistance(const dvec3& p, double reach) const {
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

  // An upper bound on the distance from p to the exact surface, from
  // points of it found near p by projection rather than along lines: for
  // a mesh point that the lines of surfaceDistance put beyond what is
  // allowed. Those lines miss an edge where two faces meet at a shallow
  // angle (a sphere cut from a plane face leaves a wedge a few degrees
  // wide), when p lies on the part of a face that the other surface cut
  // off: the nearest boundary is then the edge, in a thin cone of
  // directions. So: for each face of a primitive near p, its point nearest
  // p, and for each pair of such faces, a point of the curve where they
  // meet (alternating projections, von Neumann 1950, which converge for
  // faces that cross); each point counts if the part's inside and outside
  // both come within a hair of it. Sound whatever it finds: the distance
  // to a boundary point is at least the distance to the surface.
  struct Projected {
    double distance;  // to a boundary point found, or the reach
    double allowed;   // what the mesh may be off there (see allowance)
  };
  Projected distanceByProjection(const dvec3& p, double reach) const {
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

  // An upper bound on the distance from p to the exact surface, searched
  // for along many lines through p, with what is allowed there: for a mesh
  // point that neither the 13 lines nor projection put within what is
  // allowed. A face cut down to a small patch by other operands (a torus
  // less a box and a cylinder) can lie nearer p than anything those find:
  // the lines pass beside the patch, and the point of the whole face
  // nearest p lies off the part. The lines cover the sphere of directions
  // kSearchLines times, then close in on the few best, each round half as
  // widely; every boundary they meet is a point of the exact surface, so
  // the bound is sound. The faces they meet within a few tolerances of the
  // nearest make the creases and corners of cornerAllowance.
  Projected distanceBySearch(const dvec3& p, double reach) const {
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
          Met& m =
              met.try_emplace({b->primitive, b->face}, Met{kInfinity, dvec3(0.0)}).first->second;
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

  // What the mesh may be off where faces with these outward normals meet.
  // Each face's mesh may be offset by the tolerance: two faces move their
  // crease by creaseStretch tolerances, and
  // three faces move their corner to x with nᵢ·x = tolerance for each,
  // x = N⁻¹(1, 1, 1)·tolerance for the matrix N of their normals (√3 ×
  // the tolerance at a cube's corner). Ten tolerances at most, as for a
  // knife edge.
  static double cornerAllowance(const std::vector<dvec3>& normals, double tolerance) {
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

  // Is p within what the mesh may be off the exact surface there, where
  // the two may classify it differently?
  bool withinBand(const dvec3& p) const {
    const double reach = kFidelityReach * options_.tolerance;
    const double d = surfaceDistance(p, reach);
    auto within = [&](double distance, double allowed) {
      return distance <= allowed * (1.0 + kCheckEstimateSlack) + epsilon_;
    };
    if (within(d, allowance(p, d))) return true;
    const Projected found = distanceByProjection(p, reach);
    return within(found.distance, found.allowed);
  }

  // How far the mesh may be from the exact surface at p, found d away:
  // the tolerance, or more where two faces meet at a crease. Each face's
  // mesh is within the tolerance of the face, and so may be offset by it;
  // where faces with normals an angle φ apart meet, offsetting both by the
  // tolerance moves their crease by tolerance / cos(φ/2) (√2 of it at a
  // right angle), and the mesh of a boolean is made of such offset faces.
  // Faces of other primitives (or other faces of p's) met within a few
  // tolerances of p along the 13 lines make a crease.
  double allowance(const dvec3& p, double d) const {
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

  // Two faces that meet tangentially (a torus round a cylinder, a sphere on
  // a plane) close a wedge that no offset of the tolerance bounds: each
  // face's mesh may stand a tolerance into it, so the meshes fill it as far
  // as its two sides are less than two tolerances apart, and the crease of
  // the mesh lies that far from the exact one (about 2√(tolerance·r) for a
  // side of curvature radius r against a plane). This is that distance
  // from p, the nearest way out of the wedge: along each of 16 directions
  // of the faces' tangent plane, the two faces are projected on from points
  // ever further out until they stand two tolerances apart; a direction
  // along the crease never gets there, nor one where a face ends. Faces
  // that lie on each other (boxes face to face) never part: no wedge, 0.
  double wedgeDepth(const dvec3& p, const Primitive& a, std::uint32_t faceA, const Primitive& b,
                    std::uint32_t faceB) const {
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

  // One ray of a grid: its spans' length, the distances between the two
  // boundaries along it, its walls and gaps, and the faces of operands
  // that coincide on it.
  double trace(const Ray& ray, int axis, const AxisCrossings& mesh,
               const std::vector<AxisCrossings::Crossing>& crossings, Tally& tally) const {
    SpanList spans;
    solid_.spans(ray, spans);
    struct Hit {
      double t;
      dvec3 normal;
    };
    std::vector<Hit> exact;
    double length = 0.0;
    for (std::uint32_t k = 0; k < spans.size(); ++k) {
      const Span& s = spans[k];
      if (!std::isfinite(s.in.t) || !std::isfinite(s.out.t)) {
        tally.unbounded = true;
        continue;
      }
      length += s.length();
      if (s.length() <= epsilon_) zeroLength(s, ray, tally);
      const dvec3 in = ray.at(s.in.t), out = ray.at(s.out.t);
      const dvec3 nIn = outwardNormal(s.in, in), nOut = outwardNormal(s.out, out);
      exact.push_back({s.in.t, nIn});
      exact.push_back({s.out.t, nOut});
      for (const Boundary* b : {&s.in, &s.out}) {
        // The triangles this ray crosses bound the boundary's distance
        // from the mesh; CGAL finds the nearest of all only where that
        // bound is more than the tolerance.
        const dvec3 e = ray.at(b->t);
        double d = cap_;
        for (const AxisCrossings::Crossing& c : crossings) d = std::min(d, mesh.distance(e, c));
        if (d > options_.tolerance) d = probe_.distance(e);
        tally.distance(d, allowance(e, d), e, false);
      }
      if (glm::dot(nIn, nOut) < kFacing) stretch(tally.wall, s.length(), nIn, nOut, in, out, axis);
      if (k > 0 && std::isfinite(spans[k - 1].out.t)) {
        const Boundary& before = spans[k - 1].out;
        const dvec3 from = ray.at(before.t);
        const dvec3 nFrom = outwardNormal(before, from);
        if (glm::dot(nFrom, nIn) < kFacing)
          stretch(tally.gap, s.in.t - before.t, nFrom, nIn, from, in, axis);
      }
    }

    // Each mesh crossing against the nearest exact boundary on the ray,
    // and against the other two axes where that is not near enough.
    for (const AxisCrossings::Crossing& c : crossings) {
      const dvec3 q = ray.at(c.t);
      double estimate = cap_;
      for (const Hit& h : exact)
        estimate = std::min(estimate, std::abs(h.t - c.t) * std::abs(h.normal[axis]));
      if (estimate > kQuickShare * options_.tolerance)
        estimate = std::min(estimate, surfaceDistance(q, kFidelityReach * options_.tolerance));
      double allowed = allowance(q, estimate);
      if (estimate > allowed) {
        const Projected found = distanceByProjection(q, kFidelityReach * options_.tolerance);
        if (found.distance * allowed < estimate * found.allowed) {
          estimate = found.distance;
          allowed = found.allowed;
        }
      }
      // The search costs some 7 000 queries of the part, so it is made
      // only for a point that would otherwise be the worst so far; it can
      // only lower the estimate, so a point that would not be is not.
      if (estimate > allowed && tally.worse(estimate, allowed)) {
        const Projected searched = distanceBySearch(
            q, std::min(estimate + 4.0 * options_.tolerance, kFidelityReach * options_.tolerance));
        if (searched.distance * allowed < estimate * searched.allowed) {
          estimate = searched.distance;
          allowed = searched.allowed;
        }
      }
      tally.distance(estimate, allowed, q, true);
    }
    scanOperands(solid_, ray, tally);
    return length;
  }

 private:
  // Alternating projections close in on the curve where two faces meet by
  // a factor cos²θ a round for faces θ apart: 2 000 rounds take faces 5°
  // apart from a reach away to within 1e-6 of it.
  static constexpr int kMaxProjections = 2000;

  void collectPrimitives(const Solid& solid) {
    if (const auto* primitive = dynamic_cast<const Primitive*>(&solid)) {
      primitives_.push_back(primitive);
      return;
    }
    for (const SolidPtr& child : solid.children()) collectPrimitives(*child);
  }

  // Moves x to the nearest crossing of the face by the line through x along
  // the face's normal there: x's foot on the face, exactly for planes and
  // spheres, near it on other surfaces. False if the line misses the face
  // within reach.
  static bool projectOnto(const Primitive& primitive, int face, dvec3& x, double reach) {
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

  // If the part's inside and outside both come within a hair of x, a
  // direction from x into the inside. Asked at x moved a hair along each
  // (unit) normal and each sum and difference of two, each way: near a
  // curve where two faces meet, one of these lies in each of the four
  // wedges between them, however thin.
  std::optional<dvec3> insideNear(const dvec3& x, std::initializer_list<dvec3> normals) const {
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

  // A stretch of the ray between two faces that face each other (outward
  // normals a at p and b at q, near opposite), a wall or a gap: its width
  // measured across the mean plane of the faces, whose normal is a − b
  // (their distance, for parallel faces), or twice the distance from its
  // middle to the nearest face (the largest ball there), whichever is
  // larger. The first is too small where the ray meets both faces at a
  // glancing angle, the second where the ray runs along a third face.
  void stretch(std::optional<Stretch>& thinnest, double length, const dvec3& a, const dvec3& b,
               const dvec3& p, const dvec3& q, int axis) const {
    double width = length * std::abs(glm::normalize(a - b)[axis]);
    if (thinnest && width >= thinnest->thickness) return;
    const dvec3 middle = 0.5 * (p + q);
    // Only a ball narrower than the thinnest so far can change it.
    const double reach = thinnest ? 0.5 * thinnest->thickness : cap_;
    width = std::max(width, 2.0 * surfaceDistance(middle, reach));
    Tally::thinnest(thinnest, width, middle);
  }

  void zeroLength(const Span& s, const Ray& ray, Tally& tally) const {
    const dvec3 at = ray.at(s.in.t);
    if (!partBox_.contains(at)) return;  // as in scanOperands
    tally.warn("zero-length span",
               describe(*s.in.primitive) + " and " + describe(*s.out.primitive) +
                   " enclose nothing along a ray: they meet in a face, an edge or a point",
               at);
  }

  // Where the boundaries of two operands of a boolean node lie together on
  // the ray with parallel faces: they share a face (both enter or both
  // leave) or touch along one (one leaves where the other enters).
  void scanOperands(const Solid& node, const Ray& ray, Tally& tally) const {
    std::span<const SolidPtr> operands = node.children();
    if (operands.empty()) return;
    struct Mark {
      double t;
      std::uint32_t operand;
      Boundary boundary;
      bool entering;
    };
    std::vector<Mark> marks;
    SpanList spans;
    for (std::uint32_t i = 0; i < operands.size(); ++i) {
      const Solid& operand = *operands[i];
      if (!operand.bounds().hitBy(ray)) continue;
      operand.spans(ray, spans);
      for (const Span& s : spans) {
        if (s.length() <= epsilon_ && std::isfinite(s.in.t)) zeroLength(s, ray, tally);
        if (std::isfinite(s.in.t)) marks.push_back({s.in.t, i, s.in, true});
        if (std::isfinite(s.out.t)) marks.push_back({s.out.t, i, s.out, false});
      }
      scanOperands(operand, ray, tally);
    }
    // Operands of a union that share a face or stand on one another are
    // ordinary modelling, which the export joins: only a difference's or
    // an intersection's faces that coincide change what the part is.
    // Cutters of a difference that meet each other only make one larger
    // cutter; what matters is where they meet what they cut.
    auto* boolean = dynamic_cast<const Boolean*>(&node);
    if (boolean && boolean->op() == Boolean::Op::Union) return;
    const bool difference = boolean && boolean->op() == Boolean::Op::Difference;
    std::sort(marks.begin(), marks.end(), [](const Mark& a, const Mark& b) { return a.t < b.t; });
    for (std::size_t a = 0; a < marks.size(); ++a)
      for (std::size_t b = a + 1; b < marks.size() && marks[b].t - marks[a].t <= epsilon_; ++b) {
        const Mark& m = marks[a];
        const Mark& n = marks[b];
        if (m.operand == n.operand) continue;
        if (difference && m.operand != 0 && n.operand != 0) continue;
        const dvec3 at = ray.at(m.t);
        // Outside the part's box the part is empty all around: faces that
        // meet there (the ends of cutters that reach past it) shape nothing.
        if (!partBox_.contains(at)) continue;
        const double cosine =
            glm::dot(outwardNormal(m.boundary, at), outwardNormal(n.boundary, at));
        if (std::abs(cosine) < kParallel) continue;
        const bool shared = m.entering == n.entering;
        // In operand order, so that "a and b" reads as the script wrote them.
        const bool inOrder = m.operand < n.operand;
        const Primitive& first = *(inOrder ? m : n).boundary.primitive;
        const Primitive& second = *(inOrder ? n : m).boundary.primitive;
        tally.warn(shared ? "coincident faces" : "touching faces",
                   describe(first) + " and " + describe(second) +
                       (shared ? " share a face" : " touch along a face") + " in the " +
                       describe(node),
                   at);
      }
  }

  const Solid& solid_;
  const MeshProbe& probe_;
  const CheckOptions& options_;
  Bounds partBox_;        // the solid's own box, by epsilon_ larger
  double epsilon_ = 0.0;  // boundaries this close coincide
  double cap_ = 0.0;      // no distance inside the box is larger
  dvec3 nudge_{0.0};      // off the point where surfaceDistance measures
  double hair_ = 0.0;     // how far from a point insideNear looks: a thousandth of the tolerance
  std::vector<const Primitive*> primitives_;  // the part's leaves, for distanceByProjection
};

// The three grids: volume along each axis with its sampling deviation, and
// what their rays found.
void traceGrids(const Checker& checker, const TriangleMesh& mesh, const Bounds& box,
                const CheckOptions& options, CheckReport& report, Tally& tally) {
  const int n = options.grid;
  double sigma[3] = {0.0, 0.0, 0.0};
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const double du = box.size()[u] / n, dv = box.size()[v] / n;
    const double cell = du * dv;
    std::vector<double> lengths(std::size_t(n) * n);
    std::vector<Tally> rows(n);
    const AxisCrossings meshCrossings(mesh, box, axis, n);
    tbb::parallel_for(0, n, [&](int i) {
      std::vector<AxisCrossings::Crossing> crossings;
      for (int j = 0; j < n; ++j) {
        // One ray at a random point of each cell (stratified sampling):
        // unbiased, and no aliasing with a regular pattern of holes.
        const std::uint64_t key =
            mix(options.seed ^ mix((std::uint64_t(axis) << 60) ^ (std::uint64_t(i) << 30) ^ j));
        dvec3 origin = box.lo;
        origin[u] += (i + unit(key)) * du;
        origin[v] += (j + unit(mix(key))) * dv;
        meshCrossings.crossings(origin, i, j, crossings);
        lengths[std::size_t(i) * n + j] =
            checker.trace(Ray(origin, axisVector(axis), -kInfinity, kInfinity), axis, meshCrossings,
                          crossings, rows[i]);
      }
    });
    double volume = 0.0, variance = 0.0;
    for (std::size_t k = 0; k < lengths.size(); ++k) volume += cell * lengths[k];
    // Collapsed strata (Cochran, Sampling Techniques, 3rd ed., §5A.12):
    // with one sample per cell, neighbouring cells in pairs give an upper
    // estimate of the variance, Σ (a·L₁ − a·L₂)².
    for (std::size_t k = 0; k + 1 < lengths.size(); k += 2)
      variance += std::pow(cell * (lengths[k] - lengths[k + 1]), 2);
    report.volumeAlong[axis] = volume;
    sigma[axis] = std::sqrt(variance);
    for (const Tally& row : rows) tally.merge(row);
  }
  report.exactVolume = (report.volumeAlong[0] + report.volumeAlong[1] + report.volumeAlong[2]) / 3;
  // The pair of grids furthest apart for their deviations decides.
  const double rounding = 1e-9 * std::abs(report.exactVolume);
  double worst = -1.0;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3;
    const double spread = std::abs(report.volumeAlong[a] - report.volumeAlong[b]);
    const double allowed = kSigmas * std::hypot(sigma[a], sigma[b]) + rounding;
    if (spread / allowed > worst) {
      worst = spread / allowed;
      report.gridSpread = spread;
      report.gridAllowed = allowed;
    }
  }
  const double sigmaOfMean =
      std::sqrt(sigma[0] * sigma[0] + sigma[1] * sigma[1] + sigma[2] * sigma[2]) / 3;
  report.volumeAllowed = options.tolerance * report.meshArea + kSigmas * sigmaOfMean + rounding;
}

void classify(const Solid& solid, const MeshProbe& probe, const Checker& checker, const Bounds& box,
              const CheckOptions& options, CheckReport& report) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<dvec3> points(options.samples);
  for (dvec3& p : points) p = box.lo + dvec3(uniform(rng), uniform(rng), uniform(rng)) * box.size();
  enum Verdict : std::uint8_t { Agree, InBand, Disagree };
  std::vector<std::uint8_t> verdicts(points.size());

  if (!points.empty()) probe.side(points[0]);  // builds CGAL's tree before the threads ask
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t k) {
    const MeshProbe::Side side = probe.side(points[k]);
    const bool exact = solid.contains(points[k]);
    if (side == MeshProbe::Side::Boundary)
      verdicts[k] = InBand;
    else if (exact == (side == MeshProbe::Side::Inside))
      verdicts[k] = Agree;
    else
      verdicts[k] = checker.withinBand(points[k]) ? InBand : Disagree;
  });
  report.points = points.size();
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (verdicts[k] == Agree) ++report.agree;
    if (verdicts[k] == InBand) ++report.inBand;
    if (verdicts[k] != Disagree) continue;
    ++report.disagreementCount;
    if (report.disagreements.size() < kListed) report.disagreements.push_back(points[k]);
  }
}

// The pieces a part is meant to be: a union's operands (unions within it
// looked through) joined where their boxes overlap; any other solid is one.
std::size_t modelPieces(const Solid& solid) {
  std::vector<Bounds> boxes;
  std::vector<const Solid*> pending = {&solid};
  while (!pending.empty()) {
    const Solid* s = pending.back();
    pending.pop_back();
    auto* node = dynamic_cast<const Boolean*>(s);
    if (node && node->op() == Boolean::Op::Union) {
      for (const SolidPtr& child : node->children()) pending.push_back(child.get());
    } else if (!s->bounds().empty()) {
      boxes.push_back(s->bounds());
    }
  }
  // Groups of overlapping boxes, by union-find.
  std::vector<std::size_t> parent(boxes.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::size_t pieces = boxes.size();
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j]) && root(i) != root(j)) {
        parent[root(j)] = root(i);
        --pieces;
      }
  return std::max<std::size_t>(pieces, 1);
}

}  // namespace

CheckReport checkMeshAgainstSolid(const Solid& solid, const TriangleMesh& mesh,
                                  const CheckOptions& options) {
  CheckReport report;
  report.options = options;
  report.triangles = mesh.size();
  if (!solid.bounds().finite()) {
    report.failure = "the part is unbounded: it has no mesh to check";
    return report;
  }
  if (mesh.empty()) {
    report.failure = "the mesh is empty";
    return report;
  }
  if (options.grid < 2 || options.grid > CheckOptions::kMaxGrid ||
      options.samples > CheckOptions::kMaxSamples || !(options.tolerance > 0.0)) {
    report.failure = "the grid must have 2 to " + std::to_string(CheckOptions::kMaxGrid) +
                     " rays a side, the samples be at most " +
                     std::to_string(CheckOptions::kMaxSamples) + ", and the tolerance be positive";
    return report;
  }
  report.meshDefect = meshDefect(mesh).text;
  const MeshShells shells = meshShells(mesh);
  report.shells = shells.count;
  report.modelPieces = modelPieces(solid);
  solid.prepare();
  const MeshProbe probe(mesh);
  report.meshVolume = probe.volume();
  report.meshArea = probe.area();

  // The box holds both: the mesh may lie up to the tolerance outside.
  Bounds box = solid.bounds();
  box.include(mesh.bounds());
  const dvec3 margin(2.0 * options.tolerance + 1e-6 * glm::length(box.size()));
  box = Bounds{box.lo - margin, box.hi + margin};

  const Checker checker(solid, probe, options, box);
  Tally tally;
  traceGrids(checker, mesh, box, options, report, tally);
  if (tally.unbounded) {
    report.failure = "the part is unbounded along a grid ray: it has no mesh to check";
    return report;
  }
  report.fidelity = tally.fidelity;
  // (With no distance found above zero, nothing more than the tolerance was allowed.)
  report.fidelityAllowed = tally.fidelity > 0.0 ? tally.fidelityAllowed : options.tolerance;
  report.fidelityAt = tally.fidelityAt;
  report.fidelityFromMesh = tally.fidelityFromMesh;
  report.thinnestWall = tally.wall;
  report.narrowestGap = tally.gap;

  if (probe.canClassify()) classify(solid, probe, checker, box, options, report);

  // Warnings: the degenerate booleans the rays met, most often met first,
  // then walls and gaps below what a printer makes.
  std::vector<CheckWarning> found;
  for (const auto& [key, w] : tally.warnings) found.push_back(w);
  std::stable_sort(found.begin(), found.end(),
                   [](const CheckWarning& a, const CheckWarning& b) { return a.rays > b.rays; });
  if (found.size() > kWarningKinds) {
    report.warningsLeftOut = found.size() - kWarningKinds;
    found.resize(kWarningKinds);
  }
  report.warnings = std::move(found);
  auto thin = [&](const std::optional<Stretch>& s, double limit, const char* kind,
                  const char* what) {
    if (!s || s->thickness >= limit) return;
    std::ostringstream m;
    m << what << " " << s->thickness << " thick at " << format(s->location) << ", under " << limit;
    report.warnings.push_back({kind, m.str(), s->location, 1});
  };
  if (report.shells > report.modelPieces) {
    const ShellApproach near = nearestShells(mesh, shells);
    std::ostringstream m;
    m << "the export falls into " << report.shells << " separate shells, more than the "
      << report.modelPieces << " piece" << (report.modelPieces == 1 ? "" : "s")
      << " the model is made of: two come within " << near.distance << " of each other at "
      << format(0.5 * (near.a + near.b))
      << ": a cut goes through there, or the model's pieces meet in an edge or a point";
    report.warnings.insert(report.warnings.begin(),
                           {"separate shells", m.str(), 0.5 * (near.a + near.b), 1});
  }
  thin(report.thinnestWall, options.minWall, "thin wall", "a wall");
  thin(report.narrowestGap, options.minGap, "narrow gap", "a gap");
  return report;
}

CheckReport checkPart(const Solid& solid, const CheckOptions& options) {
  TriangleMesh mesh;
  try {
    // Rounded to floats, as STL, OBJ, OFF and PLY files store them.
    mesh = meshOfSolid(solid, options.tolerance, storedCoordinate(MeshFormat::Stl, false)).mesh;
  } catch (const std::exception& e) {
    CheckReport report;
    report.options = options;
    report.failure = std::string("the part cannot be exported: ") + e.what();
    return report;
  }
  return checkMeshAgainstSolid(solid, mesh, options);
}

}  // namespace csgray::detail
