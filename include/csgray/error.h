// Errors of the csgray library: every function that fails throws
// csgray::Error, whose code says what kind of failure it is and whose
// message is one line for the user, the same the csgray command and its
// scripts give ("sphere: r must be > 0 (got -1)").
#pragma once

#include <stdexcept>
#include <string>

#include "csgray/types.h"

namespace csgray {

enum class ErrorCode {
  InvalidArgument,  // a parameter out of range, a missing one, a degenerate shape
  ScriptError,      // a part script failed: the message names its file and line
  NotPrintable,     // no closed, valid mesh can be made of the part (unbounded, touching, ...)
  IoError,          // a file could not be read or written
  OutOfMemory,      // memory ran out
  Internal,         // anything else: a bug in csgray
  Cancelled,  // stopped by the caller (the cancel of RenderOptions, ExportOptions, CheckOptions)
};

// "InvalidArgument", ...
CSGRAY_API const char* errorCodeName(ErrorCode code);

class CSGRAY_API Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message);
  ~Error() override;

  ErrorCode code() const noexcept { return code_; }

 private:
  ErrorCode code_;
};

}  // namespace csgray
