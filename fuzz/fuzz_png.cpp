// A libFuzzer target for the PNG reader (io/png_reader): every input must
// be decoded or refused with std::runtime_error whose message is one
// line; anything else (a crash, a sanitizer report, another exception, a
// hang) is a bug. This build skips the chunks' CRC check, so that the
// fuzzer's changes reach the decoder behind it rather than all failing
// there.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "io/png_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    // A limit low enough that a hostile header cannot ask for gigabytes.
    csgray::detail::decodePng(bytes, 1L << 20);
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    if (message.empty() || message.find('\n') != std::string::npos) __builtin_trap();
  }
  return 0;
}
