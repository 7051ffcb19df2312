// A libFuzzer target for one mesh reader, chosen by CSGRAY_FUZZ_FORMAT:
// every input must be read or refused with std::invalid_argument; anything
// else (a crash, a sanitizer report, another exception, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "meshio/mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    csgray::detail::TriangleMesh mesh =
        csgray::detail::readMesh(bytes, "input." CSGRAY_FUZZ_FORMAT);
    // The indices must name points.
    for (const auto& triangle : mesh.triangles)
      for (std::uint32_t v : triangle)
        if (v >= mesh.points.size()) __builtin_trap();
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
