// A libFuzzer target for the SVG reader (profile/svg_reader, with its XML
// reader, path data and strokes): every input must be read or refused with
// std::invalid_argument whose message is one line naming the file;
// anything else (a crash, a sanitizer report, another exception, a hang)
// is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "profile/svg_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    csgray::detail::readSvg(text, "input.svg", {});
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    if (!message.starts_with("input.svg") || message.find('\n') != std::string::npos)
      __builtin_trap();
  }
  return 0;
}
