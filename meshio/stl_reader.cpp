// readStl: STL, binary and ASCII (3D Systems, StereoLithography Interface
// Specification, 1989).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "meshio/mesh_reader.h"
#include "meshio/reader_common.h"

namespace csgray::detail {

using namespace mesh_reading;

namespace {

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
          // A fourth number is no part of STL: a mangled line, or a file
          // of another kind, whose points would be read wrong.
          if (tokens.next(token))
            fail(where, "a vertex has x, y and z only; this line has more (" + shown(token) + ")");
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

// Are at least three bytes in four printable ASCII or white space? In a
// binary STL's floats, NULs and bytes past 0x7e are about half (0.5f is
// 00 00 00 3F, -2.75f 00 00 30 C0), and 61 % of random bytes; in an ASCII
// STL they are the odd stray byte, or a name in UTF-8.
bool mostlyText(std::string_view bytes) {
  std::size_t other = 0;
  for (char c : bytes) {
    const auto byte = static_cast<unsigned char>(c);
    other += !(std::isprint(byte) || std::isspace(byte));
  }
  return other * 4 <= bytes.size();
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
      // the ASCII reader tripped on. (Not for a text file with a stray
      // control byte: its line says more than a count read from its text.)
      if (sized && !mostlyText(bytes.substr(84, 4096)))
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

}  // namespace csgray::detail
