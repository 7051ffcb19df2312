#include "check/ray_grids.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <vector>

#include "check/axis_crossings.h"
#include "check/exact_volume.h"
#include "engine/boolean.h"
#include "engine/cancellation.h"
#include "engine/primitive.h"
#include "engine/span_list.h"
#include "export/cgal/mesh_boolean.h"

namespace csgray::detail {

namespace {

// Two faces face each other across a stretch when their outward normals
// are within about 25° of opposite: a wall or a gap. Across a sphere near
// its silhouette they do not, so a grazing ray finds no thin wall there.
constexpr double kFacing = -0.9;
// Normals this close to parallel (about 0.08°) make coinciding boundaries
// coinciding faces; otherwise the ray merely passes where two faces cross.
constexpr double kParallel = 1.0 - 1e-6;
// Grid volumes may differ by this many standard deviations of their
// sampling before the grids are said to disagree.
constexpr double kSigmas = 5.0;
// A mesh point whose distance from the exact surface, estimated along its
// own ray, is below this share of the tolerance is not measured along 13
// lines: the estimate is good, and the point cannot be the one that fails.
constexpr double kQuickShare = 0.5;

std::string describe(const Solid& solid) {
  std::string line = solid.origin().text();
  return line.empty() ? solid.kind() : solid.kind() + " (" + line + ")";
}

// The rays of the grids, each through the exact model (its distances from
// the exact surface asked of ExactDistance) and through the mesh.
class GridTracer {
 public:
  GridTracer(const Solid& solid, const MeshProbe& probe, const ExactDistance& exact,
             const CheckOptions& options, const Bounds& box)
      : solid_(solid), probe_(probe), exact_(exact), options_(options) {
    epsilon_ = exact.epsilon();
    cap_ = glm::length(box.size());
    partBox_ = {solid.bounds().lo - dvec3(epsilon_), solid.bounds().hi + dvec3(epsilon_)};
  }

  // One ray of a grid: its spans' length, the distances between the two
  // boundaries along it, its walls and gaps, and the faces of operands
  // that coincide on it.
  double trace(const Ray& ray, int axis, const AxisCrossings& mesh,
               const std::vector<AxisCrossings::Crossing>& crossings, GridTally& tally) const {
    SpanList spans;
    solid_.spans(ray, spans);
    struct Hit {
      double t;
      dvec3 normal;
    };
    std::vector<Hit> exact;
    double length = 0.0;
    // Is the gap after span k narrower than a contact's offset? The export
    // may close such a gap (solids placed less than the file's step apart),
    // so its two faces need not be in the mesh.
    auto closableGap = [&](std::uint32_t k) {
      return k + 1 < spans.size() && std::isfinite(spans[k].out.t) &&
             spans[k + 1].in.t - spans[k].out.t <= kContactOffset * options_.tolerance;
    };
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
        if (b == &s.in ? k > 0 && closableGap(k - 1) : closableGap(k)) continue;
        // The triangles this ray crosses bound the boundary's distance
        // from the mesh; CGAL finds the nearest of all only where that
        // bound is more than the tolerance.
        const dvec3 e = ray.at(b->t);
        double d = cap_;
        for (const AxisCrossings::Crossing& c : crossings) d = std::min(d, mesh.distance(e, c));
        if (d > options_.tolerance) d = probe_.distance(e);
        tally.distance(d, exact_.allowance(e, d), e, false);
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
        estimate =
            std::min(estimate, exact_.surfaceDistance(q, kFidelityReach * options_.tolerance));
      double allowed = exact_.allowance(q, estimate);
      if (estimate > allowed) {
        const ExactDistance::Projected found =
            exact_.distanceByProjection(q, kFidelityReach * options_.tolerance);
        if (found.distance * allowed < estimate * found.allowed) {
          estimate = found.distance;
          allowed = found.allowed;
        }
      }
      // The search costs some 7 000 queries of the part, so it is made
      // only for a point that would otherwise be the worst so far; it can
      // only lower the estimate, so a point that would not be is not.
      if (estimate > allowed && tally.worse(estimate, allowed)) {
        const ExactDistance::Projected searched = exact_.distanceBySearch(
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
    width = std::max(width, 2.0 * exact_.surfaceDistance(middle, reach));
    GridTally::thinnest(thinnest, width, middle);
  }

  void zeroLength(const Span& s, const Ray& ray, GridTally& tally) const {
    const dvec3 at = ray.at(s.in.t);
    if (!partBox_.contains(at)) return;  // as in scanOperands
    tally.warn("zero-length span",
               describe(*s.in.primitive) + " and " + describe(*s.out.primitive) +
                   " enclose nothing along a ray: they meet in a face, an edge or a point",
               at);
  }

  // Whether the boundaries of operands a and b, together at `at` with the
  // unit normal there, stay together a step away along the surface in four
  // directions: a face they share, or touch along. Surfaces tangent along
  // a line or at a point (a cylinder in a box that it fits) part as the
  // step squared over the radius of curvature, which a step of 10⁻³ of the
  // part's diagonal makes many times the epsilon that joins them: 10⁻⁶ of
  // the diagonal at a curvature of a thousandth of the diagonal's inverse.
  bool togetherAround(const Solid& a, const Solid& b, const dvec3& at, const dvec3& normal) const {
    const double step = 1e-3 * cap_;  // the box's diagonal
    const dvec3 u = glm::normalize(std::abs(normal.x) < 0.9 ? glm::cross(normal, dvec3(1, 0, 0))
                                                            : glm::cross(normal, dvec3(0, 1, 0)));
    const dvec3 v = glm::cross(normal, u);
    SpanList spansA, spansB;
    for (const dvec3& side : {u, -u, v, -v}) {
      // A line along the normal through the stepped point, over two steps
      // each way: where each operand's boundary crosses it.
      const Ray probe(at + step * side - 2.0 * step * normal, normal, 0.0, 4.0 * step);
      a.spans(probe, spansA);
      b.spans(probe, spansB);
      bool met = false;
      for (const Span& p : spansA)
        for (const Span& q : spansB)
          for (double ta : {p.in.t, p.out.t})
            for (double tb : {q.in.t, q.out.t})
              met = met || (std::isfinite(ta) && std::abs(ta - tb) <= epsilon_);
      if (!met) return false;
    }
    return true;
  }

  // Where the boundaries of two operands of a boolean node lie together on
  // the ray with parallel faces: they share a face (both enter or both
  // leave) or touch along one (one leaves where the other enters).
  void scanOperands(const Solid& node, const Ray& ray, GridTally& tally) const {
    std::span<const SolidPtr> operands = node.children();
    if (operands.empty()) return;
    struct Mark {
      double t;
      std::uint32_t operand;
      Boundary boundary;
      bool entering;
    };
    // Operands of a union that share a face or stand on one another are
    // ordinary modelling, which the export joins: only a difference's or
    // an intersection's faces that coincide change what the part is, and a
    // union's operands are only looked into, those the ray meets found
    // through its tree (a union of thousands, met by each grid ray).
    // Cutters of a difference that meet each other only make one larger
    // cutter; what matters is where they meet what they cut.
    auto* boolean = dynamic_cast<const Boolean*>(&node);
    const bool union_ = boolean && boolean->op() == Boolean::Op::Union;
    std::vector<Mark> marks;
    SpanList spans;
    auto scan = [&](std::uint32_t i, const Solid& operand) {
      operand.spans(ray, spans);
      for (const Span& s : spans) {
        if (s.length() <= epsilon_ && std::isfinite(s.in.t)) zeroLength(s, ray, tally);
        if (union_) continue;
        if (std::isfinite(s.in.t)) marks.push_back({s.in.t, i, s.in, true});
        if (std::isfinite(s.out.t)) marks.push_back({s.out.t, i, s.out, false});
      }
      scanOperands(operand, ray, tally);
    };
    if (union_) {
      boolean->forEachOperandHitBy(ray, [&](const Solid& operand) {
        scan(0, operand);
        return true;
      });
      return;
    }
    for (std::uint32_t i = 0; i < operands.size(); ++i)
      if (operands[i]->bounds().hitBy(ray)) scan(i, *operands[i]);
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
        const dvec3 normal = outwardNormal(m.boundary, at);
        const double cosine = glm::dot(normal, outwardNormal(n.boundary, at));
        if (std::abs(cosine) < kParallel) continue;
        if (!togetherAround(*operands[m.operand], *operands[n.operand], at, normal)) continue;
        const bool shared = m.entering == n.entering;
        // Operands of an intersection that share a face (a pattern clipped
        // to an outline of its height) are ordinary modelling too: a hair's
        // difference moves the face by a hair. Where they meet face to
        // face, it decides whether a sliver is left.
        if (shared && !difference) continue;
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
  const ExactDistance& exact_;
  const CheckOptions& options_;
  Bounds partBox_;        // the solid's own box, by epsilon_ larger
  double epsilon_ = 0.0;  // boundaries this close coincide
  double cap_ = 0.0;      // no distance inside the box is larger
};

}  // namespace

// The three grids: volume along each axis with its sampling deviation, and
// what their rays found.
void traceGrids(const Solid& solid, const MeshProbe& probe, const ExactDistance& exact,
                const TriangleMesh& mesh, const Bounds& box, const CheckOptions& options,
                CheckReport& report, GridTally& tally) {
  const GridTracer tracer(solid, probe, exact, options, box);
  const int n = options.grid;
  double sigma[3] = {0.0, 0.0, 0.0};
  for (int axis = 0; axis < 3; ++axis) {
    const RayGrid rays(box, axis, n, options.seed);
    std::vector<double> lengths(std::size_t(n) * n);
    std::vector<GridTally> rows(n);
    const AxisCrossings meshCrossings(mesh, box, axis, n);
    tbb::parallel_for(0, n, [&, cancel = cancelFlag()](int i) {
      stopIfCancelled(cancel);
      std::vector<AxisCrossings::Crossing> crossings;
      for (int j = 0; j < n; ++j) {
        const Ray ray = rays.ray(i, j);
        meshCrossings.crossings(ray.origin, i, j, crossings);
        lengths[std::size_t(i) * n + j] =
            tracer.trace(ray, axis, meshCrossings, crossings, rows[i]);
      }
    });
    const RayGrid::Volume measured = rays.volume(lengths);
    report.volumeAlong[axis] = measured.volume;
    sigma[axis] = measured.sigma;
    for (const GridTally& row : rows) tally.merge(row);
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

}  // namespace csgray::detail
