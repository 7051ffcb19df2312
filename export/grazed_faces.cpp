#include "export/grazed_faces.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>

namespace csgray::detail {

namespace {

// A triangle clipped by planes has at most three corners plus one per
// plane; the cutters meant here have a few planes (a box six).
using Polygon = std::vector<dvec3>;

// The part of the polygon where normal·p <= offset (Sutherland and
// Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974), into out.
void clip(const Polygon& in, const dvec3& normal, double offset, Polygon& out) {
  out.clear();
  for (std::size_t i = 0; i < in.size(); ++i) {
    const dvec3& a = in[i];
    const dvec3& b = in[(i + 1) % in.size()];
    const double sa = glm::dot(normal, a) - offset, sb = glm::dot(normal, b) - offset;
    if (sa <= 0.0) out.push_back(a);
    if ((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0))
      out.push_back(a + (sa / (sa - sb)) * (b - a));
  }
}

}  // namespace

GrazeTest::GrazeTest(const TriangleMesh& minuend, double tolerance,
                     std::function<bool(const dvec3&)> inside)
    : minuend_(minuend),
      tolerance_(tolerance),
      inside_(std::move(inside)),
      seen_(minuend.size(), 0) {
  boxes_.reserve(minuend.size());
  for (const TriangleMesh::Triangle& t : minuend.triangles) {
    Bounds box;
    for (std::uint32_t i : t) box.include(minuend.points[i]);
    boxes_.push_back(box);
    whole_.include(box);
  }
  // About four triangles a cell where they spread over the box's face.
  cells_ = std::clamp(int(std::sqrt(double(minuend.size()) / 4.0)), 1, 256);
  grid_.resize(std::size_t(cells_) * std::size_t(cells_));
  for (std::uint32_t i = 0; i < boxes_.size(); ++i) {
    int lo[2], hi[2];
    cellRange(boxes_[i], lo, hi);
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) grid_[std::size_t(y) * cells_ + x].push_back(i);
  }
}

void GrazeTest::cellRange(const Bounds& box, int lo[2], int hi[2]) const {
  for (int axis = 0; axis < 2; ++axis) {
    const double size = whole_.hi[axis] - whole_.lo[axis];
    auto cell = [&](double x) {
      const double at = size > 0.0 ? (x - whole_.lo[axis]) / size * cells_ : 0.0;
      return std::clamp(int(std::floor(at)), 0, cells_ - 1);
    };
    lo[axis] = cell(box.lo[axis]);
    hi[axis] = cell(box.hi[axis]);
  }
}

void GrazeTest::trianglesNear(const Bounds& box, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (!box.overlaps(whole_)) return;
  ++query_;
  int lo[2], hi[2];
  cellRange(box, lo, hi);
  for (int y = lo[1]; y <= hi[1]; ++y)
    for (int x = lo[0]; x <= hi[0]; ++x)
      for (std::uint32_t i : grid_[std::size_t(y) * cells_ + x])
        if (seen_[i] != query_) {
          seen_[i] = query_;
          if (boxes_[i].overlaps(box)) out.push_back(i);
        }
}

bool GrazeTest::clearGrazedFaces(std::vector<BoundingPlane>& planes, const Bounds& box) const {
  const double tolerance = tolerance_;
  const double loose = 2.0 * tolerance;
  // Only the triangles near the cutter: within the reach of its moved
  // faces and loosened prisms.
  const Bounds near{box.lo - dvec3(2.0 * loose), box.hi + dvec3(2.0 * loose)};
  std::vector<std::uint32_t> nearby;
  trianglesNear(near, nearby);
  if (nearby.empty()) return false;
  const std::vector<BoundingPlane> judged = planes;
  bool moved = false;
  Polygon polygon, clipped;
  for (std::size_t j = 0; j < judged.size(); ++j) {
    const BoundingPlane& face = judged[j];
    // How far beyond the face the minuend reaches within its prism and
    // slab; past the tolerance, the face cuts into it.
    double reach = 0.0;
    dvec3 furthest(0.0);
    // Points of the parts of triangles beyond the face, moved onto it:
    // where the exact minuend would reach past it if it does.
    std::vector<dvec3> over;
    for (std::uint32_t i : nearby) {
      const TriangleMesh::Triangle& t = minuend_.triangles[i];
      const dvec3 p[3] = {minuend_.points[t[0]], minuend_.points[t[1]], minuend_.points[t[2]]};
      auto beyond = [&](const BoundingPlane& plane, double by) {
        return glm::dot(plane.normal, p[0]) > plane.offset + by &&
               glm::dot(plane.normal, p[1]) > plane.offset + by &&
               glm::dot(plane.normal, p[2]) > plane.offset + by;
      };
      // Nothing beyond the face, or all of it beyond the slab or outside
      // the prism: not this face's (the usual case, tested first).
      if (glm::dot(face.normal, p[0]) <= face.offset &&
          glm::dot(face.normal, p[1]) <= face.offset && glm::dot(face.normal, p[2]) <= face.offset)
        continue;
      if (beyond(face, loose)) continue;
      bool outside = false;
      for (std::size_t k = 0; k < judged.size() && !outside; ++k)
        outside = k != j && beyond(judged[k], loose);
      if (outside) continue;
      polygon.assign(p, p + 3);
      for (std::size_t k = 0; k < judged.size() && !polygon.empty(); ++k) {
        if (k == j) continue;
        clip(polygon, judged[k].normal, judged[k].offset + loose, clipped);
        polygon.swap(clipped);
      }
      clip(polygon, face.normal, face.offset + loose, clipped);
      for (const dvec3& q : clipped)
        if (const double d = glm::dot(face.normal, q) - face.offset; d > reach) {
          reach = d;
          furthest = q;
        }
      // A grid of points on each triangle of the part's fan, on the face.
      constexpr int kSteps = 6;
      for (std::size_t k = 1; k + 1 < clipped.size(); ++k)
        for (int a = 0; a <= kSteps; ++a)
          for (int b = 0; a + b <= kSteps; ++b) {
            const dvec3 q = (double(a) * clipped[0] + double(b) * clipped[k] +
                             double(kSteps - a - b) * clipped[k + 1]) /
                            double(kSteps);
            over.push_back(q - (glm::dot(face.normal, q) - face.offset) * face.normal);
          }
      if (reach > tolerance) break;
    }
    if (!(reach > 0.0 && reach <= tolerance) || inside_(furthest - 0.5 * reach * face.normal))
      continue;
    // A skin thinner than the mesh's bulge (a pocket's top 0.002 inside a
    // rod's tangent plane) lies over the face where the mesh does, but the
    // point halfway to the mesh's furthest one may lie past it: the face's
    // own points a hair outwards, under the parts beyond it, are asked too.
    const double hairOut = 1e-9 * glm::length(box.size());
    if (std::any_of(over.begin(), over.end(),
                    [&](const dvec3& p) { return inside_(p + hairOut * face.normal); }))
      continue;
    planes[j].offset = face.offset + reach + 0.1 * tolerance;
    moved = true;
  }
  return moved;
}

}  // namespace csgray::detail
