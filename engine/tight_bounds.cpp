#include "engine/tight_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "engine/parts_box.h"
#include "engine/span_list.h"

namespace csgray::detail {

namespace {

constexpr int kGrid = 64;                     // rays across each side of the first grid
constexpr int kWindowRays = 9;                // across each side of a finer window
constexpr int kRefinements = 16;              // windows, each a quarter of the last
constexpr std::size_t kBest = 4;              // lines refined, of the first grid's best
constexpr std::size_t kPartsVisits = 100000;  // nodes partsBox may visit

// The lines parallel to axis `a`: the other two axes, and where a line
// through (u, v) on them meets the solid first and last.
class Lines {
 public:
  Lines(const Solid& solid, const Bounds& box, int a)
      : solid_(solid), box_(box), a_(a), b_((a + 1) % 3), c_((a + 2) % 3) {}

  // The lowest and highest coordinate along a of the solid on the line
  // through (u, v); false where the line misses it.
  bool extent(double u, double v, double& lo, double& hi) {
    dvec3 origin, direction(0.0);
    // From outside the box, so that the first span starts at an entry;
    // by its own size, so that a small part's hits keep their digits.
    const double margin = box_.size()[a_];
    origin[a_] = box_.lo[a_] - margin;
    origin[b_] = u;
    origin[c_] = v;
    direction[a_] = 1.0;
    double first = kInfinity, last = -kInfinity;
    reach(solid_, Ray(origin, direction, 0.0, 2.0 * margin + box_.size()[a_]), first, last);
    if (!(first <= last)) return false;
    lo = origin[a_] + first;
    hi = origin[a_] + last;
    return true;
  }

  // Widens [first, last] to where the ray meets the solid first and last.
  // A union's are its operands' first and last, a use's its child's:
  // asked one by one, so that a line through a row of 5 000 balls does not
  // merge their spans into one list at each ball (a grid of them took
  // 0.26 s, 0.05 s so).
  void reach(const Solid& solid, const Ray& ray, double& first, double& last) {
    if (const Boolean* node = solid.asBoolean(); node && node->op() == Boolean::Op::Union) {
      node->forEachOperandHitBy(ray, [&](const Solid& operand) {
        reach(operand, ray, first, last);
        return true;
      });
      return;
    }
    if (const Instance* use = solid.asInstance()) {  // (t is the same in the child's frame)
      reach(*use->child(), use->rayToChild(ray), first, last);
      return;
    }
    solid.spans(ray, spans_);
    if (spans_.empty()) return;
    first = std::min(first, spans_[0].in.t);
    last = std::max(last, spans_.back().out.t);
  }

  // The extremes of both sides (0: the highest, 1: the lowest, as -lo)
  // on the lines of a grid of n × n over [u0, u1] × [v0, v1], at the
  // cells' centres: each side's value (the larger the better) and where,
  // best first, at most `keep` of them. A line's extent gives both sides.
  struct Hit {
    double value;
    double u, v;
  };
  std::array<std::vector<Hit>, 2> grid(double u0, double u1, double v0, double v1, int n,
                                       std::size_t keep) {
    std::array<std::vector<Hit>, 2> hits;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u = u0 + (i + 0.5) / n * (u1 - u0), v = v0 + (j + 0.5) / n * (v1 - v0);
        double lo, hi;
        if (!extent(u, v, lo, hi)) continue;
        hits[0].push_back({hi, u, v});
        hits[1].push_back({-lo, u, v});
      }
    for (std::vector<Hit>& side : hits) {
      const std::size_t kept = std::min(keep, side.size());
      std::partial_sort(side.begin(), side.begin() + kept, side.end(),
                        [](const Hit& x, const Hit& y) {
                          return x.value > y.value ||
                                 (x.value == y.value && (x.u < y.u || (x.u == y.u && x.v < y.v)));
                        });
      side.resize(kept);
    }
    return hits;
  }

  // The highest and the lowest coordinate (as -lo), or none (the solid is
  // empty): the first grid's best lines for both, each refined.
  std::optional<std::array<double, 2>> extremes() {
    const double u0 = box_.lo[b_], u1 = box_.hi[b_], v0 = box_.lo[c_], v1 = box_.hi[c_];
    const std::array<std::vector<Hit>, 2> first = grid(u0, u1, v0, v1, kGrid, kBest);
    if (first[0].empty()) return std::nullopt;
    std::array<double, 2> found{};
    for (int side = 0; side < 2; ++side) {
      found[side] = first[side].front().value;
      for (Hit hit : first[side]) {
        // A window of two cells about the line, a quarter as wide each
        // time: its rays' spacing is the next window's half width.
        double du = (u1 - u0) / kGrid, dv = (v1 - v0) / kGrid;
        for (int k = 0; k < kRefinements; ++k) {
          const std::vector<Hit> closer =
              grid(std::max(u0, hit.u - du), std::min(u1, hit.u + du), std::max(v0, hit.v - dv),
                   std::min(v1, hit.v + dv), kWindowRays, 1)[side];
          if (!closer.empty() && closer.front().value > hit.value) hit = closer.front();
          du *= 2.0 / (kWindowRays - 1);
          dv *= 2.0 / (kWindowRays - 1);
        }
        found[side] = std::max(found[side], hit.value);
      }
    }
    return found;
  }

 private:
  const Solid& solid_;
  const Bounds& box_;
  int a_, b_, c_;
  SpanList spans_;
};

}  // namespace

Bounds tightBounds(const Solid& solid, bool* metNothing) {
  if (metNothing) *metNothing = false;
  const Bounds& given = solid.bounds();
  if (given.empty() || !given.finite()) return given;
  // The rays' box: bounds() within the parts' box.
  std::size_t budget = kPartsVisits;
  const Bounds loose = given.intersected(partsBox(solid, Affine(), budget));
  if (loose.empty()) {  // no primitive within the box (an intersection of apart parts)
    if (metNothing) *metNothing = true;
    return given;
  }
  // Rays across a box thinner than this cannot be placed finely enough
  // (a ball of radius 10⁻³²³).
  const dvec3 size = loose.size();
  if (!(std::min({size.x, size.y, size.z}) > 1e-100)) return loose;
  // The same points as one union where unions nest under transforms: a
  // part turned at each step of a loop, 490 steps deep, in 0.03 s for 1.1.
  const SolidPtr rays = solid.forRays();
  Bounds tight;
  for (int a = 0; a < 3; ++a) {
    Lines lines(*rays, loose, a);
    const std::optional<std::array<double, 2>> found = lines.extremes();
    if (!found) {  // the rays met nothing: the solid is empty
      if (metNothing) *metNothing = true;
      return loose;
    }
    const double hi = (*found)[0], lo = -(*found)[1];
    // Within the loose box; where the shapes' arithmetic overflowed (a
    // ball of radius 10³⁰⁰: its square is infinite), the loose box.
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) return loose;
    tight.lo[a] = std::max(loose.lo[a], lo);
    tight.hi[a] = std::min(loose.hi[a], hi);
  }
  return tight;
}

}  // namespace csgray::detail
