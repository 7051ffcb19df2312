// Blob::objectTessellate: marching tetrahedra on a grid (its exact part is
// blob.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
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

// A crossing is kept this fraction of its edge away from the edge's ends:
// crossings on edges that meet at a grid point near the surface would
// otherwise make triangles so thin that rounding to the 32-bit floats of
// a mesh file folds them over their neighbours. It moves a point off the
// surface by at most a thousandth of a cell, which straying() sees.
constexpr double kEdgeMargin = 1e-3;

// What the samples of straying() may be off by, as a part of the
// tolerance: the farthest point of a triangle lies between them.
constexpr double kSampledShare = 0.8;

// The six tetrahedra of a cube that share its diagonal from corner 0 to
// corner 7 (corner bits: x 1, y 2, z 4), one for each order of the axes
// (Freudenthal's, or Kuhn's, triangulation): neighbouring cubes cut their
// shared faces along the same diagonal, so the tetrahedra fit face to face.
constexpr int kTetrahedra[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                   {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

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

  TriangleMesh mesh() const {
    const int nx = count_[0] + 1, ny = count_[1] + 1, nz = count_[2] + 1;
    std::vector<double> value(std::size_t(nx) * ny * nz);
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) value[index(i, j, k)] = blob_.excess(point(i, j, k));

    TriangleMesh mesh;
    std::unordered_map<std::uint64_t, std::uint32_t> crossings;
    // The point where the surface crosses the edge from grid point a
    // (inside) to b (outside), shared by every tetrahedron with that edge.
    auto crossing = [&](std::uint32_t a, std::uint32_t b) {
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      auto [it, added] = crossings.try_emplace(key, std::uint32_t(mesh.points.size()));
      if (added) mesh.points.push_back(edgeCrossing(a, b));
      return it->second;
    };
    for (int k = 0; k < count_[2]; ++k)
      for (int j = 0; j < count_[1]; ++j)
        for (int i = 0; i < count_[0]; ++i) {
          std::uint32_t corner[8];
          for (int c = 0; c < 8; ++c)
            corner[c] = std::uint32_t(index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)));
          for (const auto& tet : kTetrahedra) {
            std::uint32_t in[4], out[4];
            int nIn = 0, nOut = 0;
            for (int v : tet) {
              const std::uint32_t g = corner[v];
              if (value[g] >= 0.0) {
                in[nIn++] = g;
              } else {
                out[nOut++] = g;
              }
            }
            if (nIn == 0 || nOut == 0) continue;
            if (nIn == 1 || nOut == 1) {
              // One corner apart from the other three: a triangle.
              const bool alone = nIn == 1;
              const std::uint32_t tip = alone ? in[0] : out[0];
              const std::uint32_t* rest = alone ? out : in;
              std::uint32_t p[3];
              for (int m = 0; m < 3; ++m)
                p[m] = alone ? crossing(tip, rest[m]) : crossing(rest[m], tip);
              addOriented(mesh, {p[0], p[1], p[2]}, tip, alone);
            } else {
              // Two and two: a quadrilateral through the four crossed edges,
              // in cyclic order a0b0, a0b1, a1b1, a1b0, cut along a diagonal.
              const std::uint32_t q[4] = {crossing(in[0], out[0]), crossing(in[0], out[1]),
                                          crossing(in[1], out[1]), crossing(in[1], out[0])};
              addOriented(mesh, {q[0], q[1], q[2]}, in[0], true);
              addOriented(mesh, {q[0], q[2], q[3]}, in[0], true);
            }
          }
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

  // Adds the triangle facing away from the grid point `from`, which is
  // inside the blob when fromInside, outside otherwise.
  void addOriented(TriangleMesh& mesh, std::array<std::uint32_t, 3> t, std::uint32_t from,
                   bool fromInside) const {
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    const double side = glm::dot(glm::cross(b - a, c - a), a - point(from));
    if ((side < 0.0) == fromInside) std::swap(t[1], t[2]);
    mesh.triangles.push_back({t[0], t[1], t[2]});
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

// Marching tetrahedra (Doi and Koide, "An Efficient Method of Triangulating
// Equi-Valued Surfaces by Using Tetrahedral Cells", IEICE Transactions
// E74(1), 1991): the field is sampled on a grid over the blob's box, each
// cube cut into six tetrahedra, and in each tetrahedron whose corners lie
// on both sides, a triangle or two join the points where the surface
// crosses its edges, found on each edge by safeguarded Newton. Crossings
// are shared by their edge, so the surface closes, and each piece lies in
// its own tetrahedron, so none cross. The cell starts at a quarter of the
// smallest ball's radius and halves until the triangles' centres and edge
// midpoints are within kSampledShare of the tolerance of the surface.
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
    TriangleMesh mesh = grid.mesh();
    if (mesh.empty())
      throw std::invalid_argument(
          "blob: its field reaches the threshold nowhere (raise a strength or lower the "
          "threshold)");
    // The samples are not the farthest points: a fifth is kept in hand.
    if (straying(*this, mesh) <= kSampledShare * tolerance) return mesh;
    cell *= 0.75;
  }
}

}  // namespace csgray::detail
