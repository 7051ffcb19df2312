#include "scene/height_map.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/vec2.hpp>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace csgray::detail {

std::shared_ptr<MeshSolid> heightMapSolid(const HeightMap& map, bool center) {
  const std::size_t rows = map.rows, columns = map.columns;
  if (rows < 2 || columns < 2)
    throw std::invalid_argument(
        "a height map needs at least 2 rows and 2 columns of heights, got " + std::to_string(rows) +
        " × " + std::to_string(columns));
  if (rows * columns > kMaxHeightMapPoints || map.heights.size() != rows * columns)
    throw std::invalid_argument("a height map may have at most " +
                                std::to_string(kMaxHeightMapPoints) + " heights");
  double lowest = 0.0;  // OpenSCAD's base is never above z = -1 + the lowest, nor above 0
  for (double h : map.heights) {
    if (!std::isfinite(h) || std::abs(h) > 1e15)
      throw std::invalid_argument(
          "a height map's heights must be finite numbers of at most 1e15 either way");
    lowest = std::min(lowest, h - 1.0);
  }
  const double base = lowest;
  const glm::dvec2 origin =
      center ? -0.5 * glm::dvec2(double(columns - 1), double(rows - 1)) : glm::dvec2(0.0);

  std::vector<dvec3> points;
  points.reserve(rows * columns + (rows - 1) * (columns - 1) + 2 * (rows + columns));
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < columns; ++c)
      points.push_back({origin.x + double(c), origin.y + double(r), map.at(r, c)});
  auto top = [&](std::size_t r, std::size_t c) { return std::int64_t(r * columns + c); };
  const std::size_t firstMiddle = points.size();
  for (std::size_t r = 1; r < rows; ++r)
    for (std::size_t c = 1; c < columns; ++c) {
      const double mean =
          (map.at(r - 1, c - 1) + map.at(r - 1, c) + map.at(r, c - 1) + map.at(r, c)) / 4.0;
      points.push_back({origin.x + double(c) - 0.5, origin.y + double(r) - 0.5, mean});
    }
  auto middle = [&](std::size_t r, std::size_t c) {
    return std::int64_t(firstMiddle + (r - 1) * (columns - 1) + (c - 1));
  };
  // The base's points, under the grid's border.
  std::unordered_map<std::size_t, std::int64_t> baseIndex;
  auto below = [&](std::size_t r, std::size_t c) {
    auto [it, added] = baseIndex.try_emplace(r * columns + c, std::int64_t(points.size()));
    if (added) points.push_back({origin.x + double(c), origin.y + double(r), base});
    return it->second;
  };

  // Faces counterclockwise seen from outside, reversed at the end into
  // the clockwise order MeshSolid takes.
  std::vector<std::vector<std::int64_t>> faces;
  faces.reserve(4 * (rows - 1) * (columns - 1) + 4 * (rows + columns));
  for (std::size_t r = 1; r < rows; ++r)
    for (std::size_t c = 1; c < columns; ++c) {
      const std::int64_t a = top(r - 1, c - 1), b = top(r - 1, c), d = top(r, c), e = top(r, c - 1),
                         m = middle(r, c);
      faces.push_back({a, b, m});
      faces.push_back({b, d, m});
      faces.push_back({d, e, m});
      faces.push_back({e, a, m});
    }
  // The walls: x = 0 and x = last face −x and +x, y = 0 and y = last −y and +y.
  const std::size_t lastRow = rows - 1, lastColumn = columns - 1;
  for (std::size_t r = 1; r < rows; ++r) {
    faces.push_back({below(r - 1, 0), top(r - 1, 0), top(r, 0), below(r, 0)});
    faces.push_back({below(r, lastColumn), top(r, lastColumn), top(r - 1, lastColumn),
                     below(r - 1, lastColumn)});
  }
  for (std::size_t c = 1; c < columns; ++c) {
    faces.push_back({below(0, c), top(0, c), top(0, c - 1), below(0, c - 1)});
    faces.push_back(
        {below(lastRow, c - 1), top(lastRow, c - 1), top(lastRow, c), below(lastRow, c)});
  }
  // The base: two triangles under each cell. (A fan about its middle is
  // fewer triangles, but two maps turned against each other, as
  // OpenSCAD's example010 intersects them, then have bases whose every
  // triangle overlaps every other near the middle, which slows the
  // exporter's booleans by minutes.)
  for (std::size_t r = 1; r < rows; ++r)
    for (std::size_t c = 1; c < columns; ++c) {
      const std::int64_t a = below(r - 1, c - 1), b = below(r - 1, c), d = below(r, c),
                         e = below(r, c - 1);
      faces.push_back({a, e, d});  // counterclockwise seen from below
      faces.push_back({a, d, b});
    }
  for (auto& face : faces) std::reverse(face.begin(), face.end());
  return Primitive::create<MeshSolid>(points, faces);
}

}  // namespace csgray::detail
