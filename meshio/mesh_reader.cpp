#include "meshio/mesh_reader.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "engine/printable_token.h"
#include "io/input_file.h"
#include "meshio/reader_common.h"
#include "tessellation/polygon_triangulation.h"

namespace csgray::detail {

// ---- What the readers share --------------------------------------------------

namespace mesh_reading {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw std::invalid_argument(where + ": " + what);
}

std::string shown(std::string_view token) { return "\"" + printableToken(token, 32) + "\""; }

std::string numberText(double value) {
  // Whole numbers (counts, indices) in full: %g wrote index 2147483648 as
  // 2.14748e+09.
  char text[32];
  if (value == std::floor(value) && std::abs(value) < 1e18)
    std::snprintf(text, sizeof text, "%.0f", value);
  else
    std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::optional<double> parseDouble(std::string_view token) {
  // from_chars takes no leading '+', which some writers put before
  // exponents' mantissas.
  if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
  double value = 0.0;
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (end != token.data() + token.size()) return std::nullopt;
  // A number past the range of a double (1e999, 1e-400): from_chars
  // leaves the value unset; strtod rounds it to ±inf or 0 as a text
  // reader would.
  if (error == std::errc::result_out_of_range)
    return std::strtod(std::string(token).c_str(), nullptr);
  if (error != std::errc()) return std::nullopt;
  return value;
}

double coordinate(std::string_view token, const std::string& where) {
  std::optional<double> value = parseDouble(token);
  if (!value) fail(where, shown(token) + " is not a number");
  // "nan" and "inf" are written so; digits that overflow are too large.
  const bool written = token.find_first_of("iInN") != std::string_view::npos;
  if (!std::isfinite(*value))
    fail(where, "coordinate " + shown(token) +
                    (written ? " is not finite" : " is beyond the range of a double"));
  return *value;
}

std::optional<std::int64_t> parseInteger(std::string_view token) {
  if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
  std::int64_t value = 0;
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

void checkSize(std::string_view bytes, const std::string& name, const MeshReadLimits& limits) {
  if (bytes.empty()) fail(name, "the file is empty");
  if (bytes.size() > limits.maxFileBytes)
    fail(name,
         "the file is larger than the limit of " + std::to_string(limits.maxFileBytes) + " bytes");
}

void MeshBuilder::polygon(const std::vector<std::uint32_t>& corners) {
  // A polygon without area is fanned all the same; the validity check then
  // says what is wrong.
  auto add = [this](std::uint32_t a, std::uint32_t b, std::uint32_t c) { triangle(a, b, c); };
  if (!triangulatePolygon(mesh_.points, corners, add)) fan(corners);
}

}  // namespace mesh_reading

// ---- The reader by extension -------------------------------------------------

using namespace mesh_reading;

namespace {

std::string lowerExtension(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

bool isReadableMeshName(const std::string& name) {
  const std::string ext = lowerExtension(name);
  return ext == ".stl" || ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".3mf";
}

TriangleMesh readMesh(std::string_view bytes, const std::string& name,
                      const MeshReadLimits& limits) {
  const std::string ext = lowerExtension(name);
  if (ext == ".stl") return readStl(bytes, name, limits);
  if (ext == ".obj") return readObj(bytes, name, limits);
  if (ext == ".off") return readOff(bytes, name, limits);
  if (ext == ".ply") return readPly(bytes, name, limits);
  if (ext == ".3mf") return read3mf(bytes, name, limits);
  fail(name, "unknown mesh format " + shown(ext) + "; use .stl, .obj, .off, .ply or .3mf");
}

TriangleMesh readMeshFile(const std::string& path, const MeshReadLimits& limits) {
  const std::string name = std::filesystem::path(path).filename().string();
  // A folder, a FIFO or a device is refused by name (a FIFO would block).
  InputFile file(path);
  if (!file.problem().empty()) fail(name, file.problem());
  if (file.size() > limits.maxFileBytes)
    fail(name,
         "the file is larger than the limit of " + std::to_string(limits.maxFileBytes) + " bytes");
  std::string bytes;
  bytes.reserve(std::size_t(file.size()));
  if (!file.readUpTo(bytes, std::size_t(file.size())))
    fail(name, "cannot read the file: " + file.problem());
  return readMesh(bytes, name, limits);
}

}  // namespace csgray::detail
