#include "meshio/binary_stl_writer.h"

#include <tbb/parallel_for.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

namespace csgray::detail {

namespace {

// Stores x as 4 little-endian bytes at out, whatever the machine's byte
// order (the format's: 3D Systems, "StereoLithography Interface
// Specification", 1988); returns the place after them.
char* put(char* out, std::uint32_t x) {
  for (int k = 0; k < 4; ++k) *out++ = char((x >> (8 * k)) & 0xffu);
  return out;
}
char* put(char* out, const dvec3& v) {
  for (double x : {v.x, v.y, v.z}) out = put(out, std::bit_cast<std::uint32_t>(float(x)));
  return out;
}

// The triangle's unit normal, (r − q) × (p − q) over its length, or zero
// for a triangle without area: the terms in the order OpenMesh computed
// them for the files csgray wrote before, so that the floats stay the same.
dvec3 unitNormal(const dvec3& p, const dvec3& q, const dvec3& r) {
  const dvec3 a = r - q, b = p - q;
  const dvec3 n(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  return length != 0.0 ? n * (1.0 / length) : dvec3(0.0);
}

}  // namespace

void writeBinaryStl(const std::string& path, const std::string& file, const TriangleMesh& mesh) {
  if (mesh.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::runtime_error("cannot write " + path +
                             ": binary STL holds at most 2³² − 1 triangles");
  // Built in memory, then written at once.
  std::vector<char> bytes(84 + 50 * mesh.size(), '\0');
  // The header is free text; this is the one the files always had.
  std::memset(bytes.data(), ' ', 79);
  std::memcpy(bytes.data(), "binary stl file", 15);
  put(bytes.data() + 80, std::uint32_t(mesh.size()));
  // Each triangle's 50 bytes in their place (the last two, the attribute
  // byte count, 0), on all threads for a large mesh; a small one stays on
  // this thread, where starting TBB's scheduler would cost more.
  auto encode = [&](std::size_t i) {
    const TriangleMesh::Triangle& t = mesh.triangles[i];
    const dvec3 &p = mesh.points[t[0]], &q = mesh.points[t[1]], &r = mesh.points[t[2]];
    char* at = bytes.data() + 84 + 50 * i;
    for (const dvec3& v : {unitNormal(p, q, r), p, q, r}) at = put(at, v);
  };
  if (mesh.size() < 10000)
    for (std::size_t i = 0; i < mesh.size(); ++i) encode(i);
  else
    tbb::parallel_for(std::size_t(0), mesh.size(), encode);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path + ": cannot create a file there");
  out.write(bytes.data(), std::streamsize(bytes.size()));
  out.close();  // its failure too: the last bytes are written then
  if (!out) throw std::runtime_error("cannot write " + path + ": the write failed (disk full?)");
}

}  // namespace csgray::detail
