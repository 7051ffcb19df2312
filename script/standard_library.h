// The script library: functions written in Lua itself (script/library/)
// and shipped inside csgray, defined as globals before a script runs, under
// the same sandbox as the script (function graphs, parametric surfaces,
// fractal mountains and compounds: docs/script.md, "Graphs, surfaces and
// fractals").
#pragma once

#include <lua.hpp>

namespace csgray::detail {

// The library's chunk name, as Lua's debug information gives it.
inline constexpr const char* kLibraryChunkName = "=csgray library";

// Runs the library's chunk, which defines its globals. It calls nothing
// that can fail on a script's account; a failure is csgray's bug.
void loadStandardLibrary(lua_State* L);

}  // namespace csgray::detail
