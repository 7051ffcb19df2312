// What OpenSCAD users type by habit, and the csgray way to write it: a
// hint added to a script's error (docs/script.md, "Coming from OpenSCAD").
// Lua cannot parse `[1, 2, 3]` or `difference() { ... }`, and does not know
// `echo` or `text`; the message then says what to write instead.
#pragma once

#include <string>

namespace csgray::detail {

// For a call of a global that does not exist: "; <hint>" when name is one
// of OpenSCAD's (cube, translate, echo, text, abs, ...) or POV-Ray's
// (light_source, merge, lathe, ...), else "".
std::string otherToolNameHint(const std::string& name);

// For a method that does not exist, called as OpenSCAD's or POV-Ray's
// habit would call it on a part (s:color(...), s:texture(...),
// s:union(t)): "; <hint>", else "". isFunction: a global function of that
// name exists (union, hull, ...), which is then how to call it.
std::string methodNameHint(const std::string& name, bool isFunction);

// For an error: "; <hint>" when the line of the script where it happened
// (sourceLine) holds one of OpenSCAD's forms ($fn, [x, y, z], module,
// difference() { ... }, for (i = [a:b]), include <...>, ...), else "".
// syntaxError: Lua could not parse the script (most forms are only
// looked for then: `t[1]` is Lua too).
std::string openscadLineHint(const std::string& sourceLine, bool syntaxError);

// The text of line `line` (from 1) of source, or "" when there is none.
std::string lineOf(const std::string& source, int line);

}  // namespace csgray::detail
