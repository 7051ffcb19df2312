// readPly: PLY, ASCII and binary of either byte order (Greg Turk, The PLY
// Polygon File Format, 1994).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "meshio/mesh_reader.h"
#include "meshio/reader_common.h"

namespace csgray::detail {

using namespace mesh_reading;

namespace {

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
// is for messages. In ASCII each item of an element is a line of its own
// (Turk: "each element on its own line"), which is what lets a vertex with
// a value missing be named by its line rather than shift every value after
// it by one.
class PlyValues {
 public:
  PlyValues(std::string_view data, std::size_t offset, std::size_t headerLines, PlyFormat format,
            const std::string& name)
      : data_(data), pos_(offset), line_(headerLines + 1), format_(format), name_(name) {}

  std::string where() const { return whereAt(pos_); }
  // Where the value last read begins.
  std::string whereLast() const { return whereAt(last_); }
  std::size_t remaining() const { return data_.size() - pos_; }

  // ASCII: the item (item `index` of `element`) begins on the next line
  // with something on it, and its values are all on that line.
  void beginItem(std::string_view element, std::uint64_t index) {
    element_ = element;
    item_ = index;
    if (format_ != PlyFormat::Ascii) return;
    while (pos_ < data_.size() && isSpace(data_[pos_])) line_ += data_[pos_++] == '\n';
  }
  // ASCII: nothing may be left on the item's line.
  void endItem() {
    if (format_ != PlyFormat::Ascii) return;
    while (pos_ < data_.size() && isBlank(data_[pos_])) ++pos_;
    if (pos_ < data_.size() && data_[pos_] != '\n')
      fail(where(), itemName() + ": the line has more values than the header declares");
  }

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

  static bool isBlank(char c) { return c != '\n' && isSpace(c); }
  std::string itemName() const { return std::string(element_) + " " + std::to_string(item_); }

  double nextText() {
    while (pos_ < data_.size() && isBlank(data_[pos_])) ++pos_;
    if (pos_ < data_.size() && data_[pos_] == '\n')
      fail(where(), itemName() + ": the line ends before the values the header declares");
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
  std::string_view element_;
  std::uint64_t item_ = 0;
};

}  // namespace

TriangleMesh readPly(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits) {
  checkSize(bytes, name, limits);
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
      values.beginItem(element.name, item);
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
      values.endItem();
      if (isVertex) raw.points.push_back(p);
    }
  }
  if (!sawFaces) fail(name, "the file has no faces");
  // Faces may come before the vertices in the file; indices were checked
  // against the declared count, which is what was read.
  return raw.build(name, limits);
}

}  // namespace csgray::detail
