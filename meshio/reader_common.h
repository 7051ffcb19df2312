// What the mesh readers (stl_reader.cpp, obj_reader.cpp, off_reader.cpp,
// ply_reader.cpp) share: messages that name where a file goes wrong, the
// words and lines of a text, numbers read strictly, and the builders that
// turn what was read into an indexed triangle mesh.
//
// In a namespace of their own, so that these short names (fail, Lines,
// Tokens) meet nothing else of csgray's at link time.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "meshio/mesh_reader.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail::mesh_reading {

// Throws std::invalid_argument("where: what").
[[noreturn]] void fail(const std::string& where, const std::string& what);

// A token for a message: at most 32 characters, control bytes shown as '?'
// so that a binary file cannot garble the terminal.
std::string shown(std::string_view token);

// A number for a message, as short as %g makes it ("nan", "inf", "1e+30").
std::string numberText(double value);

// The whole token as a number ('+' allowed before it), or nothing.
std::optional<double> parseDouble(std::string_view token);
// The token as a coordinate: what is not a finite number is refused with a
// message at `where`.
double coordinate(std::string_view token, const std::string& where);
// The whole token as a whole number ('+' allowed before it), or nothing.
std::optional<std::int64_t> parseInteger(std::string_view token);

// Refuses an empty file and one larger than the limit.
void checkSize(std::string_view bytes, const std::string& name, const MeshReadLimits& limits);

inline bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n';
}

// The whitespace-separated words of a line.
struct Tokens {
  std::string_view rest;
  bool next(std::string_view& token) {
    std::size_t begin = 0;
    while (begin < rest.size() && isSpace(rest[begin])) ++begin;
    if (begin == rest.size()) return false;
    std::size_t end = begin;
    while (end < rest.size() && !isSpace(rest[end])) ++end;
    token = rest.substr(begin, end - begin);
    rest.remove_prefix(end);
    return true;
  }
};

// The lines of a text, numbered from 1.
struct Lines {
  std::string_view text;
  std::size_t pos = 0;
  std::size_t number = 0;
  bool next(std::string_view& line) {
    if (pos >= text.size()) return false;
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    line = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    return true;
  }
};

// Collects triangles, merging identical vertex positions so that an STL
// file's triangle soup becomes an indexed mesh, and splitting polygons.
class MeshBuilder {
 public:
  MeshBuilder(const std::string& name, const MeshReadLimits& limits)
      : name_(name), limits_(limits) {}

  std::uint32_t vertex(dvec3 p) {
    // −0 and +0 are the same position.
    p += dvec3(0.0);
    std::array<std::uint64_t, 3> key;
    std::memcpy(key.data(), &p[0], sizeof(double));
    std::memcpy(key.data() + 1, &p[1], sizeof(double));
    std::memcpy(key.data() + 2, &p[2], sizeof(double));
    auto [it, added] = index_.try_emplace(key, std::uint32_t(mesh_.points.size()));
    if (added) mesh_.points.push_back(p);
    return it->second;
  }

  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (mesh_.triangles.size() >= limits_.maxTriangles)
      fail(name_, "more than " + std::to_string(limits_.maxTriangles) + " triangles");
    mesh_.triangles.push_back({a, b, c});
  }

  // A polygon of merged vertex indices, in order around it.
  void polygon(const std::vector<std::uint32_t>& corners);

  TriangleMesh finish() {
    if (mesh_.triangles.empty()) fail(name_, "the file has no triangles");
    return std::move(mesh_);
  }

 private:
  struct KeyHash {
    std::size_t operator()(const std::array<std::uint64_t, 3>& k) const {
      std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
      h = (h ^ (h >> 29) ^ k[1]) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 31) ^ k[2]) * 0x94D049BB133111EBull;
      return std::size_t(h ^ (h >> 32));
    }
  };
  void fan(const std::vector<std::uint32_t>& corners) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
      triangle(corners[0], corners[i], corners[i + 1]);
  }

  const std::string& name_;
  const MeshReadLimits& limits_;
  std::unordered_map<std::array<std::uint64_t, 3>, std::uint32_t, KeyHash> index_;
  TriangleMesh mesh_;
};

// Raw vertices and faces of an indexed format, turned into a mesh at the
// end: only vertices that faces use become points.
class IndexedMesh {
 public:
  std::vector<dvec3> points;

  void face(const std::vector<std::uint32_t>& rawCorners) {
    corners_.insert(corners_.end(), rawCorners.begin(), rawCorners.end());
    sizes_.push_back(std::uint32_t(rawCorners.size()));
  }
  // Triangles a face of `corners` corners adds; faces are checked against
  // the cap before they are stored.
  void countTriangles(std::size_t corners, const std::string& name, const MeshReadLimits& limits) {
    triangles_ += corners - 2;
    if (triangles_ > limits.maxTriangles)
      fail(name, "more than " + std::to_string(limits.maxTriangles) + " triangles");
  }

  TriangleMesh build(const std::string& name, const MeshReadLimits& limits) const {
    MeshBuilder builder(name, limits);
    constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> merged(points.size(), unused);
    std::vector<std::uint32_t> polygon;
    std::size_t next = 0;
    for (std::uint32_t size : sizes_) {
      polygon.clear();
      for (std::uint32_t k = 0; k < size; ++k) {
        std::uint32_t raw = corners_[next++];
        if (merged[raw] == unused) merged[raw] = builder.vertex(points[raw]);
        polygon.push_back(merged[raw]);
      }
      builder.polygon(polygon);
    }
    return builder.finish();
  }

 private:
  std::vector<std::uint32_t> corners_;
  std::vector<std::uint32_t> sizes_;
  std::uint64_t triangles_ = 0;
};

}  // namespace csgray::detail::mesh_reading
