// Superellipsoid::objectTessellate: a grid on the cube around the unit
// shape, pushed along rays from the centre onto the surface (its exact
// part is superellipsoid.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <unordered_map>
#include <vector>

#include "primitives/superellipsoid.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

// What the samples of the mesh may be off by, as parts of the tolerance:
// an edge's midpoint, and a triangle's centre or its long diagonal's
// midpoint, where the sags across the two directions of a cell add up.
constexpr double kEdgeShare = 0.45;
constexpr double kCellShare = 0.9;

// The cube's coordinates along one axis: a half from 0 to 1, mirrored.
std::vector<double> mirrored(const std::vector<double>& half) {
  std::vector<double> full;
  for (std::size_t k = half.size() - 1; k > 0; --k) full.push_back(-half[k]);
  full.insert(full.end(), half.begin(), half.end());
  return full;
}

// The grid of the cube's six faces, each face the product of two axes'
// coordinates: face (a, side) lies at coordinate side·1 of axis a, its
// cells spanned by the next two axes in cyclic order, so that their cross
// product points out of the face for side +1.
class CubeGrid {
 public:
  CubeGrid(const Superellipsoid& shape, std::array<std::vector<double>, 3> half)
      : shape_(shape), half_(std::move(half)) {
    for (int a = 0; a < 3; ++a) full_[a] = mirrored(half_[a]);
  }

  const std::array<std::vector<double>, 3>& half() const { return half_; }

  // The cube point of grid indices (one of them at an end of its axis),
  // pushed onto the unit shape: along the ray from the centre, so that
  // every direction keeps one point and the faces close up.
  dvec3 surfacePoint(const std::array<std::size_t, 3>& index) const {
    const dvec3 c(full_[0][index[0]], full_[1][index[1]], full_[2][index[2]]);
    return c / shape_.unitGauge(c).value;
  }

  // How far a point of the unit shape's space is from the surface in
  // model units, an upper bound: the length of the segment from it to the
  // surface along the ray from the centre, both points scaled by the radii.
  double error(const dvec3& unitPoint) const {
    const double f = shape_.unitGauge(unitPoint).value;
    return glm::length(unitPoint * shape_.radii()) * std::abs(1.0 - 1.0 / f);
  }

  // Visits every cell of every face: f(axis, side, the corner indices in
  // counter-clockwise order seen from outside, the intervals of the two
  // axes the cell spans as indices into the halves).
  template <class F>
  void forEachCell(F&& f) const {
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      const std::size_t nb = full_[b].size() - 1, nc = full_[c].size() - 1;
      for (int side : {-1, 1}) {
        const std::size_t at = side < 0 ? 0 : full_[a].size() - 1;
        for (std::size_t i = 0; i < nb; ++i)
          for (std::size_t j = 0; j < nc; ++j) {
            std::array<std::array<std::size_t, 3>, 4> corner;
            const std::size_t steps[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
            for (int k = 0; k < 4; ++k) {
              corner[k][a] = at;
              corner[k][b] = steps[k][0];
              corner[k][c] = steps[k][1];
            }
            if (side < 0) std::swap(corner[1], corner[3]);
            f(b, halfInterval(b, i), c, halfInterval(c, j), corner);
          }
      }
    }
  }

 private:
  // Interval i of an axis's full coordinates as an interval of its half.
  std::size_t halfInterval(int axis, std::size_t i) const {
    const std::size_t k = half_[axis].size() - 1;
    return i < k ? k - 1 - i : i - k;
  }

  const Superellipsoid& shape_;
  std::array<std::vector<double>, 3> half_;
  std::array<std::vector<double>, 3> full_;
};

// The two triangles of a cell: split along the diagonal nearer the
// surface.
struct CellSplit {
  std::array<int, 3> first, second;
  dvec3 diagonalMidpoint;
};

CellSplit splitCell(const CubeGrid& grid, const std::array<dvec3, 4>& v) {
  const dvec3 m02 = 0.5 * (v[0] + v[2]), m13 = 0.5 * (v[1] + v[3]);
  if (grid.error(m02) <= grid.error(m13)) return {{0, 1, 2}, {0, 2, 3}, m02};
  return {{0, 1, 3}, {1, 2, 3}, m13};
}

}  // namespace

// The grid starts at the cube's halves {0, 1} along each axis (the points
// of the six axis ends, an octahedron) and is refined where samples of its
// mesh are too far from the surface: an interval whose edges' midpoints
// are off by more than kEdgeShare of the tolerance, or whose cells' centres
// or diagonals are off by more than kCellShare, is cut in two, on all six
// faces at once, so the faces keep meeting point for point. Because the
// coordinate 0 stays in every axis, the shape's creases (the sections'
// corners at e = 2, the equator at n = 2) are edges of the mesh; near the
// rounded edges of a box-like shape (small e or n), where the surface turns
// within a short stretch of the cube, the intervals halve until they are
// short enough there.
TriangleMesh Superellipsoid::objectTessellate(double tolerance, const Bounds&) const {
  requireTolerance(kind(), tolerance);
  std::array<std::vector<double>, 3> half = {std::vector<double>{0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}};
  for (;;) {
    CubeGrid grid(*this, half);
    double cells = 0.0;
    for (int a = 0; a < 3; ++a)
      cells += double(half[(a + 1) % 3].size() - 1) * (half[(a + 2) % 3].size() - 1);
    requireTriangleBudget(kind(), 8.0 * 2.0 * cells, tolerance);

    std::array<std::vector<bool>, 3> cut;
    for (int a = 0; a < 3; ++a) cut[a].assign(half[a].size() - 1, false);
    grid.forEachCell([&](int b, std::size_t ib, int c, std::size_t ic,
                         const std::array<std::array<std::size_t, 3>, 4>& corner) {
      if (cut[b][ib] && cut[c][ic]) return;
      std::array<dvec3, 4> v;
      for (int k = 0; k < 4; ++k) v[k] = grid.surfacePoint(corner[k]);
      // Edges 0–1 and 2–3 run along one axis, 1–2 and 3–0 along the other
      // (which is which depends on the face's side).
      const bool firstAlongB = corner[0][b] != corner[1][b];
      const double edge01 =
          std::max(grid.error(0.5 * (v[0] + v[1])), grid.error(0.5 * (v[2] + v[3])));
      const double edge12 =
          std::max(grid.error(0.5 * (v[1] + v[2])), grid.error(0.5 * (v[3] + v[0])));
      const double alongB = firstAlongB ? edge01 : edge12, alongC = firstAlongB ? edge12 : edge01;
      if (alongB > kEdgeShare * tolerance) cut[b][ib] = true;
      if (alongC > kEdgeShare * tolerance) cut[c][ic] = true;
      const CellSplit split = splitCell(grid, v);
      const double inside = std::max(
          {grid.error(split.diagonalMidpoint),
           grid.error((v[split.first[0]] + v[split.first[1]] + v[split.first[2]]) / 3.0),
           grid.error((v[split.second[0]] + v[split.second[1]] + v[split.second[2]]) / 3.0)});
      if (inside > kCellShare * tolerance) cut[b][ib] = cut[c][ic] = true;
    });

    bool refined = false;
    for (int a = 0; a < 3; ++a) {
      std::vector<double> next;
      for (std::size_t k = 0; k + 1 < half[a].size(); ++k) {
        next.push_back(half[a][k]);
        if (cut[a][k]) next.push_back(0.5 * (half[a][k] + half[a][k + 1]));
      }
      next.push_back(1.0);
      refined = refined || next.size() != half[a].size();
      half[a] = std::move(next);
    }
    if (refined) continue;

    // The mesh: points shared between faces by their grid indices.
    TriangleMesh mesh;
    std::unordered_map<std::uint64_t, std::uint32_t> shared;
    auto vertex = [&](const std::array<std::size_t, 3>& index) {
      const std::uint64_t key = (std::uint64_t(index[0]) << 42) | (std::uint64_t(index[1]) << 21) |
                                std::uint64_t(index[2]);
      auto [it, added] = shared.try_emplace(key, std::uint32_t(mesh.points.size()));
      if (added) mesh.points.push_back(grid.surfacePoint(index) * radii_);
      return it->second;
    };
    grid.forEachCell([&](int, std::size_t, int, std::size_t,
                         const std::array<std::array<std::size_t, 3>, 4>& corner) {
      std::array<dvec3, 4> v;
      std::array<std::uint32_t, 4> id;
      for (int k = 0; k < 4; ++k) {
        v[k] = grid.surfacePoint(corner[k]);
        id[k] = vertex(corner[k]);
      }
      const CellSplit split = splitCell(grid, v);
      for (const auto& t : {split.first, split.second})
        mesh.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
    });
    return mesh;
  }
}

}  // namespace csgray::detail
