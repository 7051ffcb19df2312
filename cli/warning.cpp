#include "cli/warning.h"

#include <iostream>

namespace csgray::detail {

std::string terminalLine(std::string_view text) {
  std::string line(text);
  for (char& c : line) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n' || c == '\r')
      c = ' ';
    else if (byte < 0x20 || byte == 0x7f)
      c = '?';
  }
  return line;
}

void printWarning(const std::string& message) {
  std::cerr << "csgray: warning: " << terminalLine(message) << "\n";
}

}  // namespace csgray::detail
