// The page's files (view/page/), compiled in by view/embed_page.cmake: the
// viewer needs nothing beside the executable, and downloads nothing.
#pragma once

#include <span>
#include <string_view>

namespace csgray::detail {

struct PageAsset {
  std::string_view path;  // "/index.html", "/view.js", ...
  std::string_view type;  // its Content-Type
  std::string_view body;
};

std::span<const PageAsset> pageAssets();

}  // namespace csgray::detail
