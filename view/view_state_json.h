// The session's state as the page reads it (GET /scene, GET /wait):
//
//   {"version": 3, "script": "part.lua", "error": "part.lua:7: ...",
//    "bounds": {"lo": [x,y,z], "hi": [x,y,z]} or null, "volume": 1234.5,
//    "ghosts": 1, "highlights": 2 (the solids the script marked so),
//    "camera": the script's {eye, lookAt, up, fov, ortho, orthoWidth} or null,
//    "parameters": [{"name", "line", "kind": "number"|"boolean"|"string"|
//                   "vector", "value", "default", "min", "max", "step",
//                   "choices", "description"}],
//    "files": ["part.lua", "bracket.stl"]}
#pragma once

#include <string>

#include "view/view_session.h"

namespace csgray::detail {

std::string stateJson(const SessionState& state, const std::string& script);

}  // namespace csgray::detail
