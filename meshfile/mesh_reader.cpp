#include "meshfile/mesh_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "tessellation/polygon_triangulation.h"

namespace csgray::detail {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw std::invalid_argument(where + ": " + what);
}

// A token for a message: at most 32 characters, control bytes shown as '?'
// so that a binary file cannot garble the terminal.
std::string shown(std::string_view token) {
  std::string out = "\"";
  for (char c : token.substr(0, 32)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (token.size() > 32) out += "...";
  return out + "\"";
}

// A number for a message, as short as %g makes it ("nan", "inf", "1e+30").
std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

bool isSpace(char c) {
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

std::optional<double> parseDouble(std::string_view token) {
  // from_chars takes no leading '+', which some writers put before
  // exponents' mantissas.
  if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
  double value = 0.0;
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

double coordinate(std::string_view token, const std::string& where) {
  std::optional<double> value = parseDouble(token);
  if (!value) fail(where, shown(token) + " is not a number");
  if (!std::isfinite(*value)) fail(where, "coordinate " + shown(token) + " is not finite");
  return *value;
}

std::optional<std::int64_t> parseInteger(std::string_view token) {
  if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
  std::int64_t value = 0;
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

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

void MeshBuilder::polygon(const std::vector<std::uint32_t>& corners) {
  // A polygon without area is fanned all the same; the validity check then
  // says what is wrong.
  auto add = [this](std::uint32_t a, std::uint32_t b, std::uint32_t c) { triangle(a, b, c); };
  if (!triangulatePolygon(mesh_.points, corners, add)) fan(corners);
}

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

// ---- STL ------------------------------------------------------------------------

std::uint32_t littleEndian32(const char* p) {
  auto b = [p](int i) { return std::uint32_t(static_cast<unsigned char>(p[i])); };
  return b(0) | b(1) << 8 | b(2) << 16 | b(3) << 24;
}

float littleEndianFloat(const char* p) {
  std::uint32_t bits = littleEndian32(p);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

TriangleMesh readBinaryStl(std::string_view bytes, const std::string& name,
                           const MeshReadLimits& limits) {
  const std::uint64_t count = littleEndian32(bytes.data() + 80);
  if (count > limits.maxTriangles)
    fail(name, "declares " + std::to_string(count) + " triangles, more than the limit of " +
                   std::to_string(limits.maxTriangles));
  MeshBuilder builder(name, limits);
  for (std::uint64_t t = 0; t < count; ++t) {
    const std::uint64_t offset = 84 + 50 * t;
    std::uint32_t corner[3];
    for (int k = 0; k < 3; ++k) {
      dvec3 p;
      for (int axis = 0; axis < 3; ++axis) {
        const std::uint64_t at = offset + 12 + 12 * k + 4 * axis;
        p[axis] = littleEndianFloat(bytes.data() + at);
        if (!std::isfinite(p[axis]))
          fail(name + ": triangle " + std::to_string(t) + " (byte " + std::to_string(at) + ")",
               "coordinate " + numberText(p[axis]) + " is not finite");
      }
      corner[k] = builder.vertex(p);
    }
    builder.triangle(corner[0], corner[1], corner[2]);
  }
  return builder.finish();
}

TriangleMesh readAsciiStl(std::string_view bytes, const std::string& name,
                          const MeshReadLimits& limits) {
  enum class State { Outside, InSolid, InFacet, InLoop, AfterLoop };
  State state = State::Outside;
  bool sawSolid = false;
  MeshBuilder builder(name, limits);
  std::uint32_t corner[3];
  int corners = 0;
  Lines lines{bytes};
  std::string_view line, keyword, token;
  auto expect = [&](std::string_view what) {
    fail(name + ":" + std::to_string(lines.number),
         "expected " + std::string(what) + ", got " + shown(keyword));
  };
  std::string lowered;
  while (lines.next(line)) {
    // Keywords in any case (SOLID, FACET, ... from some writers); numbers
    // read the same in lower case.
    lowered.assign(line);
    for (char& c : lowered) c = char(std::tolower(static_cast<unsigned char>(c)));
    Tokens tokens{lowered};
    if (!tokens.next(keyword)) continue;
    const std::string where = name + ":" + std::to_string(lines.number);
    switch (state) {
      case State::Outside:
        if (keyword != "solid") expect("solid");
        sawSolid = true;
        state = State::InSolid;
        break;
      case State::InSolid:
        if (keyword == "endsolid") {
          state = State::Outside;
          break;
        }
        if (keyword != "facet") expect("facet or endsolid");
        if (!tokens.next(token) || token != "normal") fail(where, "expected facet normal nx ny nz");
        for (int k = 0; k < 3; ++k)
          if (!tokens.next(token)) fail(where, "the facet normal needs three numbers");
        state = State::InFacet;
        break;
      case State::InFacet:
        if (keyword != "outer" || !tokens.next(token) || token != "loop") expect("outer loop");
        corners = 0;
        state = State::InLoop;
        break;
      case State::InLoop:
        if (keyword == "endloop") {
          if (corners != 3)
            fail(where,
                 "the facet has " + std::to_string(corners) + " vertices; STL facets have 3");
          builder.triangle(corner[0], corner[1], corner[2]);
          state = State::AfterLoop;
          break;
        }
        if (keyword != "vertex") expect("vertex or endloop");
        if (corners == 3) fail(where, "the facet has more than 3 vertices; STL facets have 3");
        {
          dvec3 p;
          for (int axis = 0; axis < 3; ++axis) {
            if (!tokens.next(token)) fail(where, "a vertex needs x, y and z");
            p[axis] = coordinate(token, where);
          }
          corner[corners++] = builder.vertex(p);
        }
        break;
      case State::AfterLoop:
        if (keyword != "endfacet") expect("endfacet");
        state = State::InSolid;
        break;
    }
  }
  const std::string atEnd = name + ":" + std::to_string(lines.number);
  if (!sawSolid) fail(name, "the file is empty");
  if (state == State::InSolid) fail(atEnd, "the file ends without endsolid (truncated?)");
  if (state != State::Outside) fail(atEnd, "the file ends inside a facet (truncated?)");
  return builder.finish();
}

// ---- OBJ ------------------------------------------------------------------------

TriangleMesh readObjText(std::string_view bytes, const std::string& name,
                         const MeshReadLimits& limits) {
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
      raw.points.push_back(p);
    } else if (keyword == "f") {
      corners.clear();
      while (tokens.next(token)) {
        // v, v/vt, v/vt/vn or v//vn: the position index is before the '/'.
        std::string_view position = token.substr(0, token.find('/'));
        std::optional<std::int64_t> index = parseInteger(position);
        if (!index) fail(where, shown(token) + " is not a vertex index");
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

// ---- OFF ------------------------------------------------------------------------

TriangleMesh readOffText(std::string_view bytes, const std::string& name,
                         const MeshReadLimits& limits) {
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

// ---- PLY ------------------------------------------------------------------------

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<PlyType> plyType(std::string_view name) {
  static const std::pair<std::string_view, PlyType> names[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (auto [n, t] : names)
    if (n == name) return t;
  return std::nullopt;
}

std::size_t plySize(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;
  bool isList = false;
  PlyType countType = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, LittleEndian, BigEndian };

// The values after the header, read one by one as numbers; knows where it
// is for messages.
class PlyValues {
 public:
  PlyValues(std::string_view data, std::size_t offset, std::size_t headerLines, PlyFormat format,
            const std::string& name)
      : data_(data), pos_(offset), line_(headerLines + 1), format_(format), name_(name) {}

  std::string where() const { return whereAt(pos_); }
  // Where the value last read begins.
  std::string whereLast() const { return whereAt(last_); }
  std::size_t remaining() const { return data_.size() - pos_; }

  double next(PlyType type) {
    last_ = pos_;
    if (format_ == PlyFormat::Ascii) return nextText();
    const std::size_t size = plySize(type);
    if (remaining() < size) fail(where(), "the file ends inside the data (truncated?)");
    unsigned char b[8];
    for (std::size_t i = 0; i < size; ++i)
      b[format_ == PlyFormat::LittleEndian ? i : size - 1 - i] =
          static_cast<unsigned char>(data_[pos_ + i]);
    pos_ += size;
    std::uint64_t bits = 0;
    for (std::size_t i = size; i-- > 0;) bits = bits << 8 | b[i];
    switch (type) {
      case PlyType::Int8:
        return double(std::int8_t(bits));
      case PlyType::UInt8:
        return double(std::uint8_t(bits));
      case PlyType::Int16:
        return double(std::int16_t(bits));
      case PlyType::UInt16:
        return double(std::uint16_t(bits));
      case PlyType::Int32:
        return double(std::int32_t(bits));
      case PlyType::UInt32:
        return double(std::uint32_t(bits));
      case PlyType::Float32: {
        float f;
        auto u = std::uint32_t(bits);
        std::memcpy(&f, &u, sizeof f);
        return double(f);
      }
      case PlyType::Float64: {
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
    }
    return 0.0;
  }

  // Skips `count` values of a type; binary data is skipped without reading.
  void skip(std::uint64_t count, PlyType type) {
    if (format_ == PlyFormat::Ascii) {
      for (std::uint64_t i = 0; i < count; ++i) nextText();
      return;
    }
    if (count > remaining() / plySize(type))
      fail(where(), "the file ends inside the data (truncated?)");
    pos_ += std::size_t(count * plySize(type));
  }

  // A list's length: a whole number that the rest of the file can hold.
  std::uint64_t listLength(PlyType countType, PlyType itemType) {
    double n = next(countType);
    if (!(n >= 0) || n != std::floor(n)) fail(where(), "a list length must be a whole number");
    // ASCII items take at least two bytes each, binary ones their size.
    std::size_t least = format_ == PlyFormat::Ascii ? 2 : plySize(itemType);
    if (n > double(remaining() / least + 1))
      fail(where(), "a list of " + numberText(n) + " items is longer than the rest of the file " +
                        "(truncated?)");
    return std::uint64_t(n);
  }

 private:
  std::string whereAt(std::size_t pos) const {
    return format_ == PlyFormat::Ascii ? name_ + ":" + std::to_string(line_)
                                       : name_ + ": byte " + std::to_string(pos);
  }

  double nextText() {
    while (pos_ < data_.size() && isSpace(data_[pos_])) line_ += data_[pos_++] == '\n';
    std::size_t begin = pos_;
    while (pos_ < data_.size() && !isSpace(data_[pos_])) ++pos_;
    if (begin == pos_) fail(where(), "the file ends inside the data (truncated?)");
    std::string_view token = data_.substr(begin, pos_ - begin);
    std::optional<double> value = parseDouble(token);
    if (!value) fail(where(), shown(token) + " is not a number");
    return *value;
  }

  std::string_view data_;
  std::size_t pos_;
  std::size_t last_ = 0;
  std::size_t line_;
  PlyFormat format_;
  const std::string& name_;
};

TriangleMesh readPlyData(std::string_view bytes, const std::string& name,
                         const MeshReadLimits& limits) {
  Lines lines{bytes};
  std::string_view line, token;
  if (!lines.next(line)) fail(name, "the file is empty");
  if (Tokens{line}.next(token), token != "ply") fail(name + ":1", "not a PLY file (no \"ply\")");
  std::optional<PlyFormat> format;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (!ended && lines.next(line)) {
    const std::string where = name + ":" + std::to_string(lines.number);
    Tokens tokens{line};
    if (!tokens.next(token) || token == "comment" || token == "obj_info") continue;
    if (token == "end_header") {
      ended = true;
    } else if (token == "format") {
      tokens.next(token);
      if (token == "ascii")
        format = PlyFormat::Ascii;
      else if (token == "binary_little_endian")
        format = PlyFormat::LittleEndian;
      else if (token == "binary_big_endian")
        format = PlyFormat::BigEndian;
      else
        fail(where, "unknown format " + shown(token));
    } else if (token == "element") {
      PlyElement element;
      std::optional<std::int64_t> count;
      if (!tokens.next(token)) fail(where, "an element needs a name and a count");
      element.name = std::string(token);
      if (!tokens.next(token) || !(count = parseInteger(token)) || *count < 0)
        fail(where, "an element's count must be a whole number >= 0");
      element.count = std::uint64_t(*count);
      elements.push_back(std::move(element));
    } else if (token == "property") {
      if (elements.empty()) fail(where, "a property before any element");
      PlyProperty property;
      std::string_view type;
      if (!tokens.next(type)) fail(where, "a property needs a type and a name");
      if (type == "list") {
        std::string_view countType, itemType;
        tokens.next(countType);
        tokens.next(itemType);
        auto c = plyType(countType), i = plyType(itemType);
        if (!c || !i || *c == PlyType::Float32 || *c == PlyType::Float64)
          fail(where, "a list property needs an integer count type and an item type");
        property.isList = true;
        property.countType = *c;
        property.type = *i;
      } else {
        auto t = plyType(type);
        if (!t) fail(where, "unknown property type " + shown(type));
        property.type = *t;
      }
      if (!tokens.next(token)) fail(where, "a property needs a name");
      property.name = std::string(token);
      elements.back().properties.push_back(std::move(property));
    } else {
      fail(where, "unknown header line " + shown(token));
    }
  }
  if (!ended) fail(name, "the header has no end_header (truncated?)");
  if (!format) fail(name, "the header has no format line");

  PlyValues values(bytes, std::min(lines.pos, bytes.size()), lines.number, *format, name);
  // Counts the rest of the file cannot hold are refused before anything
  // is allocated: each value takes at least its size (binary) or two
  // bytes (ASCII).
  std::uint64_t vertexCount = 0;
  for (const PlyElement& element : elements) {
    std::uint64_t least = 0;
    for (const PlyProperty& p : element.properties)
      least += *format == PlyFormat::Ascii ? 2 : plySize(p.isList ? p.countType : p.type);
    if (least > 0 && element.count > values.remaining() / least)
      fail(name, "element " + element.name + " declares " + std::to_string(element.count) +
                     " items, more than the rest of the file holds (truncated?)");
    if (element.name == "vertex") vertexCount = element.count;
    if (element.name == "face" && element.count > limits.maxTriangles)
      fail(name, "declares " + std::to_string(element.count) + " faces, more than the limit of " +
                     std::to_string(limits.maxTriangles));
  }

  IndexedMesh raw;
  bool sawFaces = false;
  std::vector<std::uint32_t> corners;
  for (const PlyElement& element : elements) {
    const bool isVertex = element.name == "vertex", isFace = element.name == "face";
    int axisOf[3] = {-1, -1, -1};
    int indexList = -1;
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
      const PlyProperty& p = element.properties[i];
      for (int axis = 0; axis < 3 && isVertex && !p.isList; ++axis)
        if (p.name == std::string(1, char('x' + axis))) axisOf[axis] = int(i);
      if (isFace && p.isList && (p.name == "vertex_indices" || p.name == "vertex_index"))
        indexList = int(i);
    }
    if (isVertex && element.count > 0 && (axisOf[0] < 0 || axisOf[1] < 0 || axisOf[2] < 0))
      fail(name, "the vertex element has no x, y and z properties");
    if (isFace && indexList < 0) fail(name, "the face element has no vertex_indices list");
    if (element.properties.empty()) continue;
    if (isVertex) raw.points.reserve(std::size_t(element.count));
    for (std::uint64_t item = 0; item < element.count; ++item) {
      dvec3 p(0.0);
      for (std::size_t i = 0; i < element.properties.size(); ++i) {
        const PlyProperty& property = element.properties[i];
        if (property.isList) {
          std::uint64_t n = values.listLength(property.countType, property.type);
          if (int(i) != indexList) {
            values.skip(n, property.type);
            continue;
          }
          const std::string where = values.where();
          if (n < 3)
            fail(where, "face " + std::to_string(item) + " has " + std::to_string(n) +
                            " vertices, needs at least 3");
          corners.clear();
          for (std::uint64_t k = 0; k < n; ++k) {
            double index = values.next(property.type);
            if (index != std::floor(index))
              fail(values.whereLast(), "face " + std::to_string(item) + ": vertex index " +
                                           numberText(index) + " is not a whole number");
            if (!(index >= 0 && index < double(vertexCount)))
              fail(values.whereLast(), "face " + std::to_string(item) + ": vertex index " +
                                           numberText(index) + " is out of range (" +
                                           std::to_string(vertexCount) + " vertices)");
            corners.push_back(std::uint32_t(index));
          }
          raw.countTriangles(corners.size(), name, limits);
          raw.face(corners);
          sawFaces = true;
        } else {
          double value = values.next(property.type);
          for (int axis = 0; axis < 3; ++axis) {
            if (int(i) != axisOf[axis]) continue;
            if (!std::isfinite(value))
              fail(values.whereLast(), "vertex " + std::to_string(item) + ": coordinate " +
                                           numberText(value) + " is not finite");
            p[axis] = value;
          }
        }
      }
      if (isVertex) raw.points.push_back(p);
    }
  }
  if (!sawFaces) fail(name, "the file has no faces");
  // Faces may come before the vertices in the file; indices were checked
  // against the declared count, which is what was read.
  return raw.build(name, limits);
}

std::string lowerExtension(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void checkSize(std::string_view bytes, const std::string& name, const MeshReadLimits& limits) {
  if (bytes.empty()) fail(name, "the file is empty");
  if (bytes.size() > limits.maxFileBytes)
    fail(name,
         "the file is larger than the limit of " + std::to_string(limits.maxFileBytes) + " bytes");
}

}  // namespace

TriangleMesh readStl(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits) {
  checkSize(bytes, name, limits);
  // A binary file is known by its size, 84 + 50·n for the n its header
  // declares, even when its 80-byte header begins with "solid" as some
  // writers' do.
  const bool sized = bytes.size() >= 84;
  const std::uint64_t declared = sized ? littleEndian32(bytes.data() + 80) : 0;
  const std::uint64_t binarySize = 84 + 50 * declared;
  if (sized && binarySize == bytes.size()) return readBinaryStl(bytes, name, limits);
  std::string_view start = bytes.substr(0, 512);
  start.remove_prefix(std::min(start.find_first_not_of(" \t\r\n"), start.size()));
  // Keywords in any case: some writers use SOLID, FACET, ...
  std::string head(start.substr(0, 5));
  for (char& c : head) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (head == "solid") {
    try {
      return readAsciiStl(bytes, name, limits);
    } catch (const std::invalid_argument& e) {
      // Binary data after a "solid" header: say so rather than only what
      // the ASCII reader tripped on.
      if (sized && bytes.find('\0') != std::string_view::npos)
        fail(name, "a binary STL whose header begins with \"solid\", declaring " +
                       std::to_string(declared) + " triangles (" + std::to_string(binarySize) +
                       " bytes) in a file of " + std::to_string(bytes.size()) + " bytes");
      throw;
    }
  }
  if (!sized)
    fail(name,
         "truncated: " + std::to_string(bytes.size()) + " bytes, a binary STL has at least 84");
  fail(name, "binary STL declares " + std::to_string(declared) + " triangles, which take " +
                 std::to_string(binarySize) + " bytes, but the file has " +
                 std::to_string(bytes.size()) + " (truncated or wrong count)");
}

TriangleMesh readObj(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits) {
  checkSize(bytes, name, limits);
  return readObjText(bytes, name, limits);
}

TriangleMesh readOff(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits) {
  checkSize(bytes, name, limits);
  return readOffText(bytes, name, limits);
}

TriangleMesh readPly(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits) {
  checkSize(bytes, name, limits);
  return readPlyData(bytes, name, limits);
}

TriangleMesh readMesh(std::string_view bytes, const std::string& name,
                      const MeshReadLimits& limits) {
  const std::string ext = lowerExtension(name);
  if (ext == ".stl") return readStl(bytes, name, limits);
  if (ext == ".obj") return readObj(bytes, name, limits);
  if (ext == ".off") return readOff(bytes, name, limits);
  if (ext == ".ply") return readPly(bytes, name, limits);
  fail(name, "unknown mesh format " + shown(ext) + "; use .stl, .obj, .off or .ply");
}

TriangleMesh readMeshFile(const std::string& path, const MeshReadLimits& limits) {
  namespace fs = std::filesystem;
  const std::string name = fs::path(path).filename().string();
  std::error_code error;
  if (!fs::exists(path, error)) fail(name, "no such file");
  // A folder, a FIFO or a device is refused by name (a FIFO would block).
  if (!fs::is_regular_file(path, error)) fail(name, "not a regular file");
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) fail(name, "cannot read the file: " + error.message());
  if (size > limits.maxFileBytes)
    fail(name,
         "the file is larger than the limit of " + std::to_string(limits.maxFileBytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  std::string bytes(std::size_t(size), '\0');
  if (!in.read(bytes.data(), std::streamsize(size))) fail(name, "cannot read the file");
  return readMesh(bytes, name, limits);
}

}  // namespace csgray::detail
