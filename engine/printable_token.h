// A token of a file (a DXF entity's name, a height map's number) as an
// error message quotes it: a NUL byte would end the message there, since
// an exception's text is a C string, and an escape byte would move the
// terminal's cursor or clear its screen.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace csgray::detail {

// At most `length` bytes of the token, then "..." where it was longer;
// every control byte shown as '?'.
std::string printableToken(std::string_view token, std::size_t length);

}  // namespace csgray::detail
