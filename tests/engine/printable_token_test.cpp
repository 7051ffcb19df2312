// A file's token in an error message: cut to its length with "...", and
// control bytes (a NUL, which would end the message, an escape, which
// would clear the terminal) shown as '?'.
#include "engine/printable_token.h"

#include <gtest/gtest.h>

#include <string>

namespace csgray::detail {
namespace {

TEST(PrintableToken, ControlBytesAreShownAndLongTokensCut) {
  EXPECT_EQ(printableToken("LINE", 40), "LINE");
  EXPECT_EQ(printableToken(std::string("CIR\0CLE", 7), 40), "CIR?CLE");
  EXPECT_EQ(printableToken("\x1b[2J\x7f", 40), "?[2J?");
  EXPECT_EQ(printableToken("abcdef", 4), "abcd...");
  // Bytes of UTF-8 characters are not control bytes.
  EXPECT_EQ(printableToken("Ø 5", 40), "Ø 5");
}

}  // namespace
}  // namespace csgray::detail
