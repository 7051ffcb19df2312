#include "engine/printable_token.h"

namespace csgray::detail {

std::string printableToken(std::string_view token, std::size_t length) {
  std::string out(token.substr(0, length));
  for (char& c : out) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) c = '?';
  }
  if (token.size() > length) out += "...";
  return out;
}

}  // namespace csgray::detail
