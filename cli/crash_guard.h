// Ends the process with a one-line error, not a core dump, when the mesh
// booleans crash. CGAL 5.5 has crashed on some degenerate contacts (a
// constrained triangulation of a face whose cut points nearly coincide);
// where csgray knows the case it retries or reports it, and this catches
// the rest: the message names the script and the boolean in progress (by
// the operands' script lines), and says what to try. For the commands
// that evaluate booleans and have no output file open yet (export writes
// its file only after), since the process ends at once.
//
// A handler for SIGSEGV, SIGBUS and SIGFPE on an alternate stack (a stack
// overflow still reaches it) writes the line and exits; only one guard at
// a time.
#pragma once

#include <string>

namespace csgray::detail {

class CrashGuard {
 public:
  explicit CrashGuard(const std::string& script);
  ~CrashGuard();  // the booleans ended
  CrashGuard(const CrashGuard&) = delete;
  CrashGuard& operator=(const CrashGuard&) = delete;
};

}  // namespace csgray::detail
