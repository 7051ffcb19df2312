#include "cli/warning.h"

#include <iostream>

namespace csgray::detail {

void printWarning(const std::string& message) {
  std::cerr << "csgray: warning: " << message << "\n";
}

}  // namespace csgray::detail
