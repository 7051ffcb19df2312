// A lib3mf object held for a scope: the 3MF writer and reader
// (mesh_writer.cpp, threemf_reader.cpp) release every object the library
// hands them. (lib3mf 1.x passes objects as PLib3MFBase*, a pointer to its
// opaque handle type, and counts their references.)
#pragma once

#include <Model/COM/NMR_DLLInterfaces.h>

namespace csgray::detail {

struct Released {
  NMR::PLib3MFBase* object = nullptr;
  Released() = default;
  explicit Released(NMR::PLib3MFBase* held) : object(held) {}
  Released(const Released&) = delete;
  Released& operator=(const Released&) = delete;
  ~Released() {
    if (object) NMR::lib3mf_release(object);
  }
};

}  // namespace csgray::detail
