// readObj: Wavefront OBJ (Wavefront, Object Files (.obj), appendix B1 of the
// Advanced Visualizer manual), of which only the vertices (v) and faces (f)
// shape the solid.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "meshio/mesh_reader.h"
#include "meshio/reader_common.h"

namespace csgray::detail {

using namespace mesh_reading;

namespace {

// What may follow a corner's vertex index: "/vt", "/vt/vn" or "//vn",
// whole numbers. They do not shape the solid, but a corner written
// otherwise ("1/", "2/x") is a file that is not OBJ.
bool isCornerTail(std::string_view tail) {
  auto number = [](std::string_view text) { return !text.empty() && parseInteger(text); };
  const std::size_t second = tail.find('/', 1);
  if (second == std::string_view::npos) return number(tail.substr(1));
  const std::string_view texture = tail.substr(1, second - 1), normal = tail.substr(second + 1);
  return (texture.empty() || number(texture)) && number(normal);
}

}  // namespace

TriangleMesh readObj(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits) {
  checkSize(bytes, name, limits);
  IndexedMesh raw;
  // Positive indices may name vertices defined further on: they are
  // checked at the end, against the line they were on.
  struct Pending {
    std::size_t corner;
    std::size_t line;
    std::int64_t index;
  };
  std::vector<Pending> pending;
  std::vector<std::uint32_t> corners;
  std::vector<std::uint32_t> allCorners;
  std::vector<std::uint32_t> sizes;
  Lines lines{bytes};
  std::string_view line, keyword, token;
  while (lines.next(line)) {
    Tokens tokens{line};
    if (!tokens.next(keyword)) continue;
    const std::string where = name + ":" + std::to_string(lines.number);
    if (keyword == "v") {
      dvec3 p;
      for (int axis = 0; axis < 3; ++axis) {
        if (!tokens.next(token)) fail(where, "a vertex needs x, y and z");
        p[axis] = coordinate(token, where);
      }
      // What may follow is numbers: a weight w, or a colour r g b that
      // some programs write. A word there is a file that is not OBJ.
      while (tokens.next(token)) coordinate(token, where);
      raw.points.push_back(p);
    } else if (keyword == "f") {
      corners.clear();
      while (tokens.next(token)) {
        // v, v/vt, v/vt/vn or v//vn: the position index is before the '/'.
        const std::size_t slash = token.find('/');
        std::string_view position = token.substr(0, slash);
        std::optional<std::int64_t> index = parseInteger(position);
        if (!index) fail(where, shown(token) + " is not a vertex index");
        if (slash != std::string_view::npos && !isCornerTail(token.substr(slash)))
          fail(where, shown(token) + " is not a corner: OBJ writes v, v/vt, v/vt/vn or v//vn");
        const auto count = std::int64_t(raw.points.size());
        if (*index == 0) fail(where, "face index 0: OBJ counts vertices from 1");
        if (*index < 0) {
          // Relative to the vertices read so far: −1 is the last.
          if (*index < -count)  // (not −index > count: −INT64_MIN overflows)
            fail(where, "face index " + std::to_string(*index) + " is out of range (" +
                            std::to_string(count) + " vertices so far)");
          corners.push_back(std::uint32_t(count + *index));
        } else {
          if (*index > std::int64_t(std::numeric_limits<std::uint32_t>::max()))
            fail(where, "face index " + std::to_string(*index) + " is out of range");
          pending.push_back({allCorners.size() + corners.size(), lines.number, *index});
          corners.push_back(std::uint32_t(*index - 1));
        }
      }
      if (corners.size() < 3)
        fail(where,
             "a face needs at least 3 vertices, this one has " + std::to_string(corners.size()));
      raw.countTriangles(corners.size(), name, limits);
      allCorners.insert(allCorners.end(), corners.begin(), corners.end());
      sizes.push_back(std::uint32_t(corners.size()));
    }
    // Texture coordinates, normals, groups, materials, lines and the rest
    // do not change the solid.
  }
  for (const Pending& p : pending)
    if (p.index > std::int64_t(raw.points.size()))
      fail(name + ":" + std::to_string(p.line),
           "face index " + std::to_string(p.index) + " is out of range (" +
               std::to_string(raw.points.size()) + " vertices)");
  std::size_t next = 0;
  for (std::uint32_t size : sizes) {
    corners.assign(allCorners.begin() + std::ptrdiff_t(next),
                   allCorners.begin() + std::ptrdiff_t(next + size));
    raw.face(corners);
    next += size;
  }
  return raw.build(name, limits);
}

}  // namespace csgray::detail
