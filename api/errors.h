// How the library turns what its internals throw into csgray::Error: each
// public function runs its work through guarded().
#pragma once

#include <string>
#include <utility>

#include "csgray/error.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// From within a catch handler: throws the exception being handled as a
// csgray::Error. std::invalid_argument (a bad value) is InvalidArgument, a
// script's error ScriptError, std::bad_alloc OutOfMemory, a caller's cancel
// (engine/cancellation.h) Cancelled, a csgray::Error stays as it is, and any
// other std::exception is `otherwise`.
[[noreturn]] void throwAsError(ErrorCode otherwise);

// Runs f; what it throws leaves as a csgray::Error (see throwAsError).
template <class F>
auto guarded(ErrorCode otherwise, F&& f) -> decltype(f()) {
  try {
    return std::forward<F>(f)();
  } catch (...) {
    throwAsError(otherwise);
  }
}

// For the parts of the API whose failures are all bad parameters.
template <class F>
auto guarded(F&& f) -> decltype(f()) {
  return guarded(ErrorCode::Internal, std::forward<F>(f));
}

// A mesh file read for readMesh and Solid::fromMeshFile: an extension
// of none of the formats is InvalidArgument, as writeMesh's; a file that
// cannot be read, or is not a file of its format, IoError (the message
// names the file and where it went wrong).
TriangleMesh readMeshFileAsError(const std::string& path);

}  // namespace csgray::detail
