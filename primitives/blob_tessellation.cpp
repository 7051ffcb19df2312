// Blob::objectTessellate: surface nets on a grid (its exact part is
// blob.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <optional>
#include <unordered_map>
#include <vector>

#include "engine/solvers/quartic.h"
#include "primitives/blob.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

// A grid point's offset from the box's corner, a fraction of a cell, so
// that the grid's planes do not pass through the balls' centres (a
// symmetric blob would put grid points exactly on its surface).
constexpr double kGridShift = 0.3819660112501051;  // 2 − φ

// A crossing is kept this fraction of its edge away from the edge's ends
// (a grid point on the surface gives one crossing per edge there, not one
// point for all); the cell's point that averages them is pulled onto the
// surface after.
constexpr double kEdgeMargin = 1e-3;

// What the samples of straying() may be off by, as a part of the
// tolerance: the farthest point of a triangle lies between them.
constexpr double kSampledShare = 0.6;

class Grid {
 public:
  Grid(const Blob& blob, double cell) : blob_(blob), cell_(cell) {
    const Bounds box = blob.bounds();
    for (int a = 0; a < 3; ++a) {
      count_[a] = int(std::ceil(box.size()[a] / cell)) + 2;
      origin_[a] = box.center()[a] - 0.5 * count_[a] * cell + kGridShift * cell;
      // One more cell so that the shifted grid still covers the box.
      ++count_[a];
    }
  }

  double cells() const { return double(count_[0]) * count_[1] * count_[2]; }

  // Surface nets (Gibson, "Constrained Elastic SurfaceNets", MICCAI 1998;
  // the naive form): one point in each cell the surface passes, the mean
  // of the crossings on the cell's edges pulled onto the surface by
  // Newton's method along the gradient, and for each grid edge the
  // surface crosses, a quadrilateral of the points of the four cells
  // around it, cut along its shorter diagonal. Its triangles are about a
  // cell wide, with no slivers. Nothing when some edge of the result is
  // not shared by exactly two triangles (a cell the surface passes twice):
  // the caller takes a finer grid.
  std::optional<TriangleMesh> mesh() const {
    const int nx = count_[0] + 1, ny = count_[1] + 1, nz = count_[2] + 1;
    std::vector<double> value(std::size_t(nx) * ny * nz);
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) value[index(i, j, k)] = blob_.excess(point(i, j, k));
    auto inside = [&](std::size_t g) { return value[g] >= 0.0; };

    TriangleMesh mesh;
    std::vector<std::uint32_t> cellPoint(std::size_t(count_[0]) * count_[1] * count_[2],
                                         std::uint32_t(-1));
    auto pointOfCell = [&](int i, int j, int k) {
      const std::size_t c = (std::size_t(k) * count_[1] + j) * count_[0] + i;
      if (cellPoint[c] != std::uint32_t(-1)) return cellPoint[c];
      dvec3 sum(0.0);
      int crossings = 0;
      for (int a = 0; a < 3; ++a)
        for (int u = 0; u < 2; ++u)
          for (int v = 0; v < 2; ++v) {
            int at[3] = {i, j, k};
            at[(a + 1) % 3] += u;
            at[(a + 2) % 3] += v;
            const std::size_t g0 = index(at[0], at[1], at[2]);
            ++at[a];
            const std::size_t g1 = index(at[0], at[1], at[2]);
            if (inside(g0) == inside(g1)) continue;
            sum += inside(g0) ? edgeCrossing(g0, g1) : edgeCrossing(g1, g0);
            ++crossings;
          }
      dvec3 p = sum / double(crossings);
      for (int step = 0; step < 4; ++step) {
        const dvec3 gradient = blob_.fieldGradient(p);
        const double g2 = glm::dot(gradient, gradient);
        if (!(g2 > 0.0)) break;
        const dvec3 move = (blob_.excess(p) / g2) * gradient;
        // Not past half a cell: a flat stretch of the field would throw it.
        if (!(glm::length(move) < 0.5 * cell_)) break;
        p -= move;
      }
      cellPoint[c] = std::uint32_t(mesh.points.size());
      mesh.points.push_back(p);
      return cellPoint[c];
    };
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      int at[3];
      for (at[2] = 0; at[2] < nz; ++at[2])
        for (at[1] = 0; at[1] < ny; ++at[1])
          for (at[0] = 0; at[0] + (a == 0) < nx && at[1] + (a == 1) < ny && at[2] + (a == 2) < nz;
               ++at[0]) {
            const std::size_t g0 = index(at[0], at[1], at[2]);
            int next[3] = {at[0], at[1], at[2]};
            ++next[a];
            const std::size_t g1 = index(next[0], next[1], next[2]);
            if (inside(g0) == inside(g1)) continue;
            // The four cells around the edge, counter-clockwise seen from
            // the edge's +a end: their quadrilateral faces +a.
            std::uint32_t q[4];
            const int offsets[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}};
            for (int m = 0; m < 4; ++m) {
              int cell[3] = {at[0], at[1], at[2]};
              cell[b] += offsets[m][0];
              cell[c] += offsets[m][1];
              q[m] = pointOfCell(cell[0], cell[1], cell[2]);
            }
            // Outward: from the inside end towards the outside one.
            if (!inside(g0)) std::swap(q[1], q[3]);
            const dvec3 &p0 = mesh.points[q[0]], &p1 = mesh.points[q[1]], &p2 = mesh.points[q[2]],
                        &p3 = mesh.points[q[3]];
            if (glm::length(p2 - p0) <= glm::length(p3 - p1)) {
              mesh.triangles.push_back({q[0], q[1], q[2]});
              mesh.triangles.push_back({q[0], q[2], q[3]});
            } else {
              mesh.triangles.push_back({q[0], q[1], q[3]});
              mesh.triangles.push_back({q[1], q[2], q[3]});
            }
          }
    }
    // Every edge in both directions once: else a cell held two sheets.
    std::unordered_map<std::uint64_t, int> directed;
    for (const auto& t : mesh.triangles)
      for (int m = 0; m < 3; ++m) ++directed[(std::uint64_t(t[m]) << 32) | t[(m + 1) % 3]];
    for (const auto& [edge, count] : directed) {
      const auto opposite = directed.find((edge << 32) | (edge >> 32));
      if (count != 1 || opposite == directed.end() || opposite->second != 1) return std::nullopt;
    }
    return mesh;
  }

 private:
  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * (count_[1] + 1) + j) * (count_[0] + 1) + i;
  }
  dvec3 point(std::size_t g) const {
    const std::size_t nx = count_[0] + 1, ny = count_[1] + 1;
    return point(int(g % nx), int(g / nx % ny), int(g / (nx * ny)));
  }
  dvec3 point(int i, int j, int k) const { return origin_ + cell_ * dvec3(i, j, k); }

  // Where the field crosses the threshold on the segment from a (inside)
  // to b (outside): the one sign change that safeguarded Newton finds.
  dvec3 edgeCrossing(std::uint32_t a, std::uint32_t b) const {
    const dvec3 pa = point(a), pb = point(b), d = pb - pa;
    auto f = [&](double t) {
      const dvec3 p = pa + t * d;
      // Outside (excess < 0) is the solver's "inside" (value <= 0).
      return std::pair<double, double>(blob_.excess(p), glm::dot(blob_.fieldGradient(p), d));
    };
    const double t = bracketedRoot(f, 0.0, 1.0, false, 1e-12);
    return pa + std::clamp(t, kEdgeMargin, 1.0 - kEdgeMargin) * d;
  }

  const Blob& blob_;
  double cell_;
  int count_[3];
  dvec3 origin_;
};

// How far a mesh's triangles stray from the surface, estimated at their
// corners, centres and edge midpoints: the field's excess over its slope there, the
// distance to first order.
double straying(const Blob& blob, const TriangleMesh& mesh) {
  double worst = 0.0;
  auto distance = [&](const dvec3& p) {
    const double slope = glm::length(blob.fieldGradient(p));
    return slope > 0.0 ? std::abs(blob.excess(p)) / slope : kInfinity;
  };
  for (const auto& t : mesh.triangles) {
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    worst = std::max({worst, distance(a), distance((a + b + c) / 3.0), distance(0.5 * (a + b)),
                      distance(0.5 * (b + c)), distance(0.5 * (c + a))});
  }
  return worst;
}

}  // namespace

// The mesh of Grid::mesh() (surface nets). Where a cell's point is the
// mean of its crossings pulled onto the surface, every point of the mesh
// lies on it; the triangles between them are flat. The cell starts at a
// quarter of the smallest ball's radius and shrinks by a quarter until
// the triangles' corners, centres and edge midpoints are within
// kSampledShare of the tolerance of the surface, and while some cell holds
// two sheets of it. Marching tetrahedra were tried first: their slivers
// needed repairs after rounding and three times the triangles
// (docs/performance.md).
TriangleMesh Blob::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  double smallest = kInfinity;
  double area = 0.0;
  for (const BlobBall& ball : balls_) {
    smallest = std::min(smallest, ball.radius);
    if (ball.strength > 0.0) area += 4.0 * 3.141592653589793 * ball.radius * ball.radius;
  }
  double cell = smallest / 4.0;
  for (;;) {
    const Grid grid(*this, cell);
    // About four triangles for each cell's area of surface (at most the
    // balls' own), and the grid itself, sampled whole.
    requireTriangleBudget(kind(), std::max(4.0 * area / (cell * cell), grid.cells() / 10.0),
                          tolerance);
    std::optional<TriangleMesh> mesh = grid.mesh();
    if (mesh && mesh->empty())
      throw std::invalid_argument(
          "blob: its field reaches the threshold nowhere (raise a strength or lower the "
          "threshold)");
    // The samples are not the farthest points: two fifths are kept in hand.
    if (mesh && straying(*this, *mesh) <= kSampledShare * tolerance) return std::move(*mesh);
    cell *= 0.75;
  }
}

}  // namespace csgray::detail
