# Writes OUTPUT, a C++ file that holds the page's files (FILES, a list
# separated by ';' in the order given) as byte arrays, for page_assets.h.
#   cmake -DOUTPUT=... -DFILES=a.html;b.js -P embed_page.cmake
set(arrays "")
set(table "")
set(index 0)
foreach(file IN LISTS FILES)
  file(READ ${file} hex HEX)
  string(LENGTH "${hex}" digits)
  math(EXPR bytes "${digits} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," hex "${hex}")
  get_filename_component(name ${file} NAME)
  if(name MATCHES "\\.html$")
    set(type "text/html; charset=utf-8")
  elseif(name MATCHES "\\.js$")
    set(type "text/javascript; charset=utf-8")
  elseif(name MATCHES "\\.css$")
    set(type "text/css; charset=utf-8")
  else()
    set(type "application/octet-stream")
  endif()
  string(APPEND arrays "const unsigned char kFile${index}[] = {${hex}0};\n")
  string(APPEND table "    {\"/${name}\", \"${type}\", {reinterpret_cast<const char*>(kFile${index}), ${bytes}}},\n")
  math(EXPR index "${index} + 1")
endforeach()
file(WRITE ${OUTPUT}.new "// Made by view/embed_page.cmake from view/page/: do not edit.
#include \"view/page_assets.h\"

namespace csgray::detail {

namespace {
${arrays}
const PageAsset kAssets[] = {
${table}};
}  // namespace

std::span<const PageAsset> pageAssets() { return kAssets; }

}  // namespace csgray::detail
")
# Only a change touches the file, so that what includes it is not rebuilt.
file(COPY_FILE ${OUTPUT}.new ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.new)
