// OpenSCAD's surface(): a grid of heights as a solid (docs/script.md,
// "Height maps"). The grid's points stand at whole x and y, each cell is
// four triangles about its middle point (at the mean of its corners'
// heights), and the solid is closed by walls down to a flat base one unit
// below the lowest height, or at z = 0 if that is lower: OpenSCAD 2021.01's
// surface.cc builds the same solid (its base one polygon, ours triangles
// under the cells), so the volumes agree.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "primitives/mesh_solid.h"

namespace csgray::detail {

struct HeightMap {
  std::size_t rows = 0, columns = 0;
  std::vector<double> heights;  // row by row; row r is at y = r, column c at x = c
  double at(std::size_t row, std::size_t column) const { return heights[row * columns + column]; }
};

// Grids larger than this are refused (a mesh of some 2 GB).
inline constexpr std::size_t kMaxHeightMapPoints = std::size_t{1} << 24;

// The solid over the grid, from (0, 0) or centred on the origin in x and
// y. Throws std::invalid_argument for fewer than 2 rows or columns, more
// than kMaxHeightMapPoints, or a height that is not finite.
std::shared_ptr<MeshSolid> heightMapSolid(const HeightMap& map, bool center);

}  // namespace csgray::detail
