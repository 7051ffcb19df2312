// readOff: ASCII OFF (the Object File Format of Geomview's manual, "OFF
// Files"), with its optional header.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "meshio/mesh_reader.h"
#include "meshio/reader_common.h"

namespace csgray::detail {

using namespace mesh_reading;

TriangleMesh readOff(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits) {
  checkSize(bytes, name, limits);
  Lines lines{bytes};
  std::string_view line, token;
  // The next line with something on it, comments (from '#') removed.
  auto nextLine = [&](Tokens& tokens) {
    while (lines.next(line)) {
      tokens = Tokens{line.substr(0, line.find('#'))};
      Tokens probe = tokens;
      if (probe.next(token)) return true;
    }
    return false;
  };
  auto where = [&] { return name + ":" + std::to_string(lines.number); };
  Tokens tokens;
  if (!nextLine(tokens)) fail(name, "the file is empty");
  Tokens header = tokens;
  header.next(token);
  // OFF with optional prefixes for texture, colour and normal data (ST, C,
  // N) that follow each vertex; the header itself is optional.
  if (token.ends_with("OFF")) {
    if (token.find('4') != std::string_view::npos || token.find('n') != std::string_view::npos)
      fail(where(), shown(token) + " (higher-dimensional OFF) is not supported");
    tokens = header;
    // The counts may follow on the same line.
    Tokens probe = tokens;
    if (probe.next(token)) {
      if (token == "BINARY") fail(where(), "binary OFF is not supported");
    } else if (!nextLine(tokens)) {
      fail(where(), "the file ends before the vertex and face counts");
    }
  }
  std::int64_t counts[2];
  for (std::int64_t& count : counts) {
    std::optional<std::int64_t> value;
    if (!tokens.next(token) || !(value = parseInteger(token)) || *value < 0)
      fail(where(), "expected the vertex and face counts (whole numbers >= 0)");
    count = *value;
  }
  // A vertex line has at least 6 bytes ("0 0 0\n") and a face line 8:
  // counts the file cannot hold are refused before anything is allocated.
  const auto size = std::int64_t(bytes.size());
  if (counts[0] > size / 6 + 1)
    fail(where(), "declares " + std::to_string(counts[0]) +
                      " vertices, more than a file of this size holds");
  if (counts[1] > size / 8 + 1)
    fail(where(),
         "declares " + std::to_string(counts[1]) + " faces, more than a file of this size holds");
  IndexedMesh raw;
  raw.points.reserve(std::size_t(counts[0]));
  for (std::int64_t i = 0; i < counts[0]; ++i) {
    if (!nextLine(tokens))
      fail(where(), "the file ends after " + std::to_string(i) + " of " +
                        std::to_string(counts[0]) + " vertices (truncated?)");
    dvec3 p;
    for (int axis = 0; axis < 3; ++axis) {
      if (!tokens.next(token)) fail(where(), "a vertex needs x, y and z");
      p[axis] = coordinate(token, where());
    }
    raw.points.push_back(p);
  }
  std::vector<std::uint32_t> corners;
  for (std::int64_t f = 0; f < counts[1]; ++f) {
    if (!nextLine(tokens))
      fail(where(), "the file ends after " + std::to_string(f) + " of " +
                        std::to_string(counts[1]) + " faces (truncated?)");
    std::optional<std::int64_t> n;
    if (!tokens.next(token) || !(n = parseInteger(token)) || *n < 3)
      fail(where(), "a face begins with its number of vertices, at least 3; got " + shown(token));
    corners.clear();
    for (std::int64_t k = 0; k < *n; ++k) {
      if (!tokens.next(token))
        fail(where(), "the face has " + std::to_string(k) + " of its " + std::to_string(*n) +
                          " vertex indices");
      std::optional<std::int64_t> index = parseInteger(token);
      if (!index) fail(where(), shown(token) + " is not a vertex index");
      if (*index < 0 || *index >= counts[0])
        fail(where(), "face index " + std::to_string(*index) + " is out of range (" +
                          std::to_string(counts[0]) + " vertices)");
      corners.push_back(std::uint32_t(*index));
    }
    raw.countTriangles(corners.size(), name, limits);
    raw.face(corners);
  }
  // More lines than the header declares is a wrong header, not a hole.
  if (nextLine(tokens))
    fail(where(), "more faces than the " + std::to_string(counts[1]) + " the header declares");
  return raw.build(name, limits);
}

}  // namespace csgray::detail
