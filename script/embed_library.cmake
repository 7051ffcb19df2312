# Writes OUTPUT, a C++ file that holds the script library's Lua source
# (FILES, separated by ';', joined in the order given) for
# script/standard_library.cpp.
#   cmake -DOUTPUT=... -DFILES=a.lua;b.lua -P embed_library.cmake
set(hex_all "")
foreach(file IN LISTS FILES)
  file(READ ${file} hex HEX)
  string(APPEND hex_all "${hex}0a")
endforeach()
string(LENGTH "${hex_all}" digits)
math(EXPR bytes "${digits} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," hex_all "${hex_all}")
file(WRITE ${OUTPUT}.new "// Made by script/embed_library.cmake from script/library/: do not edit.
#include <string_view>

namespace csgray::detail {

namespace {
const unsigned char kSource[] = {${hex_all}0};
}  // namespace

extern const std::string_view kLibrarySource(reinterpret_cast<const char*>(kSource), ${bytes});

}  // namespace csgray::detail
")
file(COPY_FILE ${OUTPUT}.new ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.new)
