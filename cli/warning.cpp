#include "cli/warning.h"

#include <algorithm>
#include <iostream>

#include "engine/printable_token.h"

namespace csgray::detail {

std::string terminalLine(std::string_view text) {
  std::string line(text);
  std::replace_if(
      line.begin(), line.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return printableToken(line, line.size());
}

void printWarning(const std::string& message) {
  std::cerr << "csgray: warning: " << terminalLine(message) << "\n";
}

}  // namespace csgray::detail
