#include "csgray/csgray.h"

namespace csgray {

// The project's version (CMakeLists.txt), which the CMake package and
// csgray.pc also give.
const char* version() { return CSGRAY_VERSION; }

}  // namespace csgray
