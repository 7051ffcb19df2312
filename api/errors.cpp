#include "api/errors.h"

#include <filesystem>
#include <new>
#include <stdexcept>

#include "engine/cancellation.h"
#include "meshio/mesh_reader.h"
#include "script/script.h"

namespace csgray {

Error::Error(ErrorCode code, const std::string& message)
    : std::runtime_error(message), code_(code) {}

// Out of line: the exception's type information is then the library's own,
// one for every program that catches it.
Error::~Error() = default;

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::InvalidArgument:
      return "InvalidArgument";
    case ErrorCode::ScriptError:
      return "ScriptError";
    case ErrorCode::NotPrintable:
      return "NotPrintable";
    case ErrorCode::IoError:
      return "IoError";
    case ErrorCode::OutOfMemory:
      return "OutOfMemory";
    case ErrorCode::Internal:
      return "Internal";
    case ErrorCode::Cancelled:
      return "Cancelled";
  }
  return "Internal";
}

}  // namespace csgray

namespace csgray::detail {

void throwAsError(ErrorCode otherwise) {
  try {
    throw;
  } catch (const csgray::Error&) {
    throw;
  } catch (const Cancelled&) {
    throw csgray::Error(ErrorCode::Cancelled, "cancelled");
  } catch (const ScriptError& e) {
    throw csgray::Error(ErrorCode::ScriptError, e.what());
  } catch (const std::invalid_argument& e) {
    throw csgray::Error(ErrorCode::InvalidArgument, e.what());
  } catch (const std::bad_alloc&) {
    throw csgray::Error(ErrorCode::OutOfMemory, "out of memory");
  } catch (const std::exception& e) {
    throw csgray::Error(otherwise, e.what());
  } catch (...) {
    throw csgray::Error(ErrorCode::Internal, "unknown error");
  }
}

TriangleMesh readMeshFileAsError(const std::string& path) {
  if (!isReadableMeshName(path))
    throw csgray::Error(ErrorCode::InvalidArgument,
                        std::filesystem::path(path).filename().string() +
                            ": unknown mesh format; use .stl, .obj, .off, .ply or .3mf");
  try {
    return readMeshFile(path);
  } catch (const std::bad_alloc&) {
    throw csgray::Error(ErrorCode::OutOfMemory, "out of memory");
  } catch (const std::exception& e) {
    throw csgray::Error(ErrorCode::IoError, e.what());
  }
}

}  // namespace csgray::detail
