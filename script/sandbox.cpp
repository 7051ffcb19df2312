#include "script/sandbox.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "scene/value_checks.h"
#include "script/lua_args.h"
#include "script/openscad_habits.h"
#include "script/standard_library.h"

namespace csgray::detail {

namespace {

// Does the message start with a position in the chunk, "chunk:12:", as
// Lua puts before error("text") and its own errors?
bool hasPosition(std::string_view message, std::string_view chunk) {
  if (chunk.starts_with('@') || chunk.starts_with('=')) chunk.remove_prefix(1);
  if (!message.starts_with(chunk) || message.size() <= chunk.size() + 1 ||
      message[chunk.size()] != ':')
    return false;
  std::size_t i = chunk.size() + 1, digits = 0;
  while (i < message.size() && message[i] >= '0' && message[i] <= '9') ++i, ++digits;
  return digits > 0 && i < message.size() && message[i] == ':';
}
constexpr int kHookInterval = 10000;  // instructions between budget checks
// What work that runs no instructions counts for, measured against a
// plain loop: an error caught (a C++ exception, since Lua is built as
// C++), each frame of the stack it unwinds (unwinding a recursion that
// overflowed Lua's stack takes hundreds of instructions' time per frame),
// and the bytes of an allocation (string.rep fills them, and copies them
// as its buffer grows).
constexpr std::uint64_t kErrorCost = 1000;
constexpr std::uint64_t kFrameCost = 500;
constexpr std::size_t kBytesPerInstruction = 4;
// The longest message a script's error gives (error() with a long text).
constexpr std::size_t kLongestMessage = 2000;

std::string mebibytes(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// The name of the function nearest `name` among the string keys of the
// table on top of the stack whose values are functions, written with
// `prefix` ("math."), or `nearest` if none is nearer: one edit away, or two
// from a name of six letters or more or one that starts with the same
// letter ("sqar", "square"; two edits make "wood" of "load").
// Ties go to the first name in alphabetical order: a table's own order
// follows a hash that is seeded anew every run.
void nearestFunction(lua_State* L, const std::string& name, std::string& nearest, std::size_t& best,
                     const std::string& prefix = "") {
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING && lua_isfunction(L, -1)) {
      const std::string key = lua_tostring(L, -2), candidate = prefix + key;
      const std::size_t d = editDistance(name, key);
      const bool near = d <= 1 || name.size() >= 6 ||
                        (!name.empty() && !key.empty() && name.front() == key.front());
      if (near && (d < best || (d == best && !nearest.empty() && candidate < nearest)))
        best = d, nearest = candidate;
    }
    lua_pop(L, 1);
  }
}

// What to add to Lua's "attempt to call a nil value (global 'name')": what
// csgray calls it, for the names OpenSCAD users type by habit, or else the
// global function whose name is nearest, as in "sphre(1)". For a method
// ("(method 'translat')"), the nearest method of any of the script API's
// types (the __index tables of the metatables in the registry); for a
// field ("math.sine(x)": "(field 'sine')"), the nearest library function. Reads
// tables only, so it is safe after any error.
std::string unknownCallHint(lua_State* L, const std::string& message) {
  // The libraries the sandbox leaves out, called or indexed.
  for (const char* closed : {"io", "os", "package", "require", "debug", "coroutine", "load",
                             "loadfile", "dofile", "collectgarbage"})
    for (const char* use : {"call", "index"})
      if (message.find(std::string("attempt to ") + use + " a nil value (global '" + closed +
                       "')") != std::string::npos)
        return std::string("; ") + closed +
               " is not available: scripts run in a sandbox, without files, processes or "
               "loaded code (docs/script.md, \"The sandbox\")";
  // OpenSCAD's constant, and its vector arithmetic ([1, 2, 3] + v, v * 2).
  if (message.find("a nil value (global 'PI')") != std::string::npos)
    return "; OpenSCAD's PI is math.pi here";
  if (message.find("attempt to perform arithmetic on a table value") != std::string::npos)
    return "; vectors are Lua tables here, which have no arithmetic: add or scale them number by "
           "number ({a[1] + b[1], a[2] + b[2], a[3] + b[3]})";
  static const std::string kNil = "attempt to call a nil value (";
  const std::size_t at = message.find(kNil);
  if (at == std::string::npos) return "";
  const std::size_t kindBegin = at + kNil.size(), kindEnd = message.find(" '", kindBegin);
  if (kindEnd == std::string::npos) return "";
  const std::string kind = message.substr(kindBegin, kindEnd - kindBegin);
  const std::size_t begin = kindEnd + 2, end = message.find('\'', begin);
  if (end == std::string::npos) return "";
  const std::string name = message.substr(begin, end - begin);
  // No API name is within two edits of a long one; measuring would be slow.
  if (name.size() > kShownLength) return "";
  std::string nearest;
  std::size_t best = 3;
  if (kind == "global") {
    if (std::string hint = otherToolNameHint(name); !hint.empty()) return hint;
    lua_pushglobaltable(L);
    nearestFunction(L, name, nearest, best);
    lua_pop(L, 1);
  } else if (kind == "field") {
    // The table is not named in the message: the nearest function of any
    // library table (math, string, table, utf8), named with its table.
    lua_pushglobaltable(L);
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
      if (lua_type(L, -2) == LUA_TSTRING && lua_istable(L, -1) &&
          std::string(lua_tostring(L, -2)) != LUA_GNAME)
        nearestFunction(L, name, nearest, best, std::string(lua_tostring(L, -2)) + ".");
      lua_pop(L, 1);
    }
    lua_pop(L, 1);  // the global table
  } else if (kind == "method") {
    // The types that have a method of that very name ("csgray.solid"):
    // the receiver is of another type.
    std::vector<std::string> owners;
    lua_pushnil(L);
    while (lua_next(L, LUA_REGISTRYINDEX) != 0) {
      if (lua_type(L, -2) == LUA_TSTRING && lua_istable(L, -1)) {
        lua_pushliteral(L, "__index");
        if (lua_rawget(L, -2) == LUA_TTABLE) {
          nearestFunction(L, name, nearest, best);
          lua_pushlstring(L, name.data(), name.size());
          if (lua_rawget(L, -2) == LUA_TFUNCTION) owners.push_back(lua_tostring(L, -4));
          lua_pop(L, 1);
        }
        lua_pop(L, 1);  // __index
      }
      lua_pop(L, 1);  // the registry's value
    }
    if (!owners.empty()) {
      std::sort(owners.begin(), owners.end());
      std::string list;
      for (std::string owner : owners) {
        if (owner.starts_with("csgray.")) owner.erase(0, 7);
        list += (list.empty() ? "" : ", ") + owner;
      }
      return "; " + name + " is a method of another kind of value (" + list + "), not of this one";
    }
    // A function called as a method, s:hull(t), or a habit of another
    // tool, s:color(...).
    lua_pushglobaltable(L);
    lua_pushlstring(L, name.data(), name.size());
    const bool isFunction = lua_rawget(L, -2) == LUA_TFUNCTION;
    lua_pop(L, 2);
    if (std::string hint = methodNameHint(name, isFunction); !hint.empty()) return hint;
  }
  return nearest.empty() ? "" : "; did you mean " + nearest + "?";
}

// Lua's message with the names it quotes ("(global 'name')", "to 'name'")
// shortened: a script may use a name of any length.
std::string withShortNames(std::string message) {
  for (const std::string kind :
       {"global '", "local '", "method '", "field '", "upvalue '", "constant '", "to '"}) {
    for (std::size_t at = message.find(kind); at != std::string::npos;
         at = message.find(kind, at + 1)) {
      const std::size_t begin = at + kind.size(), end = message.find('\'', begin);
      if (end == std::string::npos) break;
      message.replace(begin, end - begin, shortened(message.substr(begin, end - begin)));
    }
  }
  return message;
}

// The line "chunk:12: ..." names, or 0.
int errorLine(const std::string& message, const std::string& chunkName) {
  const std::string prefix = chunkName + ":";
  if (!message.starts_with(prefix)) return 0;
  int line = 0;
  for (std::size_t i = prefix.size();
       i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])) &&
       line < 100'000'000;
       ++i)
    line = line * 10 + (message[i] - '0');
  return line;
}

// The number of frames on the stack: the highest level lua_getstack finds.
int stackDepth(lua_State* L) {
  lua_Debug ar;
  int found = 0, missing = 1;
  while (lua_getstack(L, missing, &ar)) found = missing, missing *= 2;
  while (missing - found > 1) {
    int mid = found + (missing - found) / 2;
    (lua_getstack(L, mid, &ar) ? found : missing) = mid;
  }
  return found;
}
}  // namespace

Sandbox::Sandbox(const ScriptLimits& limits) : limits_(limits) {
  L_ = lua_newstate(&Sandbox::allocate, this);
  if (!L_) throw ScriptError("cannot create a Lua state");
  lua_sethook(L_, &Sandbox::countHook, LUA_MASKCOUNT, kHookInterval);

  // Only libraries that compute; no io, os, package, debug or coroutine.
  static const luaL_Reg libraries[] = {{LUA_GNAME, luaopen_base},
                                       {LUA_STRLIBNAME, luaopen_string},
                                       {LUA_TABLIBNAME, luaopen_table},
                                       {LUA_MATHLIBNAME, luaopen_math},
                                       {LUA_UTF8LIBNAME, luaopen_utf8}};
  for (const luaL_Reg& lib : libraries) {
    luaL_requiref(L_, lib.name, lib.func, 1);
    lua_pop(L_, 1);
  }
  // Remove what loads code from files or strings, controls the collector,
  // or writes warnings; string.dump makes binary chunks.
  for (const char* name : {"dofile", "loadfile", "load", "require", "collectgarbage", "warn"}) {
    lua_pushnil(L_);
    lua_setglobal(L_, name);
  }
  lua_getglobal(L_, LUA_STRLIBNAME);
  lua_pushnil(L_);
  lua_setfield(L_, -2, "dump");
  lua_pop(L_, 1);
  // Protected calls that cannot swallow an abort; print goes to stderr so
  // that standard output stays for csgray's own results.
  lua_register(L_, "pcall", &Sandbox::safePcall);
  lua_register(L_, "xpcall", &Sandbox::safeXpcall);
  lua_register(L_, "print", &Sandbox::printLine);
  // No finalizers for scripts: Lua runs __gc with hooks off, so a finalizer
  // escapes the instruction budget, and it could hand a collected value
  // back to the script. Lua marks a table for finalization only if its
  // metatable has __gc when set, so checking here is enough.
  lua_register(L_, "setmetatable", &Sandbox::checkedSetmetatable);
  // Reproducible scripts: the same random numbers on every run.
  lua_getglobal(L_, LUA_MATHLIBNAME);
  lua_getfield(L_, -1, "randomseed");
  lua_pushvalue(L_, -1);
  lua_pushinteger(L_, 42);
  lua_call(L_, 1, 0);
  // randomseed() without a seed would take one from the clock.
  lua_pushcclosure(L_, &Sandbox::seededRandomseed, 1);
  lua_setfield(L_, -2, "randomseed");
  lua_pop(L_, 1);
}

Sandbox::~Sandbox() {
  if (L_) lua_close(L_);
}

Sandbox& Sandbox::of(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return *static_cast<Sandbox*>(ud);
}

std::string Sandbox::memoryReason() const {
  return "script exceeded the memory limit of " + mebibytes(limits_.memoryBytes);
}

std::string Sandbox::instructionReason() const {
  return "script exceeded the instruction budget of " + std::to_string(limits_.instructions) +
         " (endless loop?)";
}

std::string Sandbox::where(lua_State* L, int level) const {
  // Reads the call stack only: safe inside the allocator too.
  lua_Debug ar;
  for (; lua_getstack(L, level, &ar); ++level)
    if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0 &&
        std::string_view(ar.source) != kLibraryChunkName)
      return *chunkName_ + ":" + std::to_string(ar.currentline) + ": ";
  return "";
}

void* Sandbox::allocate(void* ud, void* ptr, std::size_t oldSize, std::size_t newSize) {
  auto* self = static_cast<Sandbox*>(ud);
  std::size_t old = ptr ? oldSize : 0;  // oldSize is a type tag when ptr is null
  if (newSize == 0) {
    std::free(ptr);
    self->used_ -= old;
    return nullptr;
  }
  if (newSize > old) self->addWork((newSize - old) / kBytesPerInstruction);
  // While an abort builds its message ("file:line: reason"), a little room
  // past the cap, so that the message keeps its line.
  std::size_t cap = self->limits_.memoryBytes + (self->aborting_ ? kAbortReserve : 0);
  auto over = [&] { return newSize > old && self->used_ - old + newSize > cap; };
  if (over()) self->release(self->held_.sweep());  // objects that died count no more
  if (over()) {
    // Lua raises "not enough memory", which names no line; the line where
    // the limit was reached is kept for the message.
    if (self->abortReason_.empty()) {
      self->abortReason_ = self->memoryReason();
      if (self->L_ && self->chunkName_) self->abortWhere_ = self->where(self->L_, 0);
    }
    return nullptr;
  }
  void* block = std::realloc(ptr, newSize);
  if (block) self->used_ = self->used_ - old + newSize;
  return block;
}

void Sandbox::charge(lua_State* L, std::size_t bytes) {
  // Lua's collector paces itself by Lua's own allocations and does not see
  // what solids hold; a step per mebibyte charged lets it free dead solids
  // (and refund them) before they add up to the cap.
  sinceCollectorStep_ += bytes;
  if (sinceCollectorStep_ >= (std::size_t{1} << 20)) {
    lua_gc(L, LUA_GCSTEP, static_cast<int>(sinceCollectorStep_ >> 10));
    sinceCollectorStep_ = 0;
  }
  if (held_.sweepDue()) release(held_.sweep());
  // Checked before counting, so that used_ stays within the cap and the
  // abort's message fits in the allocator's reserve; dead values first
  // give back what they held.
  if (overCap(bytes)) {
    lua_gc(L, LUA_GCCOLLECT);
    release(held_.sweep());
  }
  if (overCap(bytes)) abort(L, memoryReason(), 1);
  used_ += bytes;
}

void Sandbox::hold(lua_State* L, const std::vector<HeldObject>& objects) {
  std::size_t bytes = 0;
  for (const HeldObject& o : objects) bytes += o.bytes + HeldObjects::kEntryBytes;
  charge(L, bytes);
  for (const HeldObject& o : objects)
    if (!held_.add(o.object, o.bytes + HeldObjects::kEntryBytes))
      release(o.bytes + HeldObjects::kEntryBytes);  // listed twice
}

void Sandbox::outOfMemory(lua_State* L) { abort(L, memoryReason(), 1); }

void Sandbox::raise(lua_State* L, const std::string& message) {
  lua_pushstring(L, (where(L, 1) + message).c_str());
  lua_error(L);
  std::abort();  // lua_error does not return
}

void Sandbox::abort(lua_State* L, const std::string& reason, int level) {
  if (abortReason_.empty()) {
    abortReason_ = reason;
    abortWhere_ = where(L, level);
  }
  aborting_ = true;  // the script is over: pcall cannot catch an abort
  lua_pushstring(L, (abortWhere_ + abortReason_).c_str());
  lua_error(L);
  std::abort();  // lua_error does not return
}

void Sandbox::addWork(std::uint64_t instructions) {
  executed_ += instructions;
  // Past the budget: the hook, which may raise the abort, runs at the next
  // instruction instead of up to kHookInterval later (a loop of a few
  // instructions around string.rep takes that long to get there).
  if (executed_ > limits_.instructions && L_)
    lua_sethook(L_, &Sandbox::countHook, LUA_MASKCOUNT, 1);
}

void Sandbox::countHook(lua_State* L, lua_Debug*) {
  Sandbox& self = of(L);
  self.executed_ += kHookInterval;
  // Level 0: inside a hook that is the Lua function being run.
  if (self.executed_ > self.limits_.instructions || !self.abortReason_.empty())
    self.abort(L, self.instructionReason(), 0);
}

int Sandbox::finishProtectedCall(lua_State* L, int status, int base) {
  if (status != LUA_OK) executed_ += kErrorCost;
  if (executed_ > limits_.instructions || !abortReason_.empty()) abort(L, instructionReason(), 1);
  lua_pushboolean(L, status == LUA_OK);
  lua_insert(L, base);
  return lua_gettop(L) - base + 1;
}

// The message handler of pcall and xpcall, run where the error was raised,
// before the stack unwinds: counts the frames it unwinds, then calls
// xpcall's handler (the upvalue), if any.
int Sandbox::countUnwinding(lua_State* L) {
  Sandbox& self = of(L);
  // An abort passes through: xpcall's handler could start more work (even
  // another xpcall with itself as handler) at every level it unwinds.
  if (self.aborting_) return 1;
  self.addWork(kFrameCost * static_cast<std::uint64_t>(stackDepth(L)));
  if (lua_isnone(L, lua_upvalueindex(1))) return 1;  // pcall: the error as it is
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, 1);
  return 1;
}

// pcall(f, ...): like Lua's, but an abort propagates.
int Sandbox::safePcall(lua_State* L) {
  luaL_checkany(L, 1);
  lua_pushcfunction(L, &Sandbox::countUnwinding);
  lua_insert(L, 1);  // the handler, then f and its arguments
  int status = lua_pcall(L, lua_gettop(L) - 2, LUA_MULTRET, 1);
  return of(L).finishProtectedCall(L, status, 2);
}

// xpcall(f, handler, ...): like Lua's, but an abort propagates.
int Sandbox::safeXpcall(lua_State* L) {
  luaL_checktype(L, 2, LUA_TFUNCTION);
  lua_pushvalue(L, 2);
  lua_pushcclosure(L, &Sandbox::countUnwinding, 1);
  lua_replace(L, 2);  // f, the counting handler, the arguments
  lua_pushvalue(L, 1);
  lua_pushvalue(L, 2);
  lua_replace(L, 1);
  lua_replace(L, 2);  // the handler, f, the arguments
  int status = lua_pcall(L, lua_gettop(L) - 2, LUA_MULTRET, 1);
  return of(L).finishProtectedCall(L, status, 2);
}

int Sandbox::seededRandomseed(lua_State* L) {
  Sandbox& self = of(L);
  if (lua_isnoneornil(L, 1))
    self.raise(L, "math.randomseed needs a seed here, so that every run builds the same part");
  lua_settop(L, std::min(lua_gettop(L), 2));  // Lua's randomseed reads two, as here
  for (int i = 1; i <= lua_gettop(L); ++i) {
    if (lua_type(L, i) != LUA_TNUMBER)
      self.raise(L, std::string("math.randomseed: the seed must be a whole number, got ") +
                        luaL_typename(L, i));
    int isInteger = 0;
    lua_tointegerx(L, i, &isInteger);
    if (!isInteger)
      self.raise(L, "math.randomseed: the seed must be a whole number, got " +
                        std::string(lua_tostring(L, i)));
  }
  // The library's own randomseed (the upvalue), which now cannot fail.
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

// setmetatable(t, mt) as Lua's, with messages that say what the script
// did wrong, and without __gc (see the constructor).
int Sandbox::checkedSetmetatable(lua_State* L) {
  Sandbox& self = of(L);
  if (lua_gettop(L) < 2)
    self.raise(L, "setmetatable takes 2 arguments, a table and a metatable or nil (got " +
                      std::to_string(lua_gettop(L)) + ")");
  if (lua_type(L, 1) == LUA_TUSERDATA) {
    // The API's name of the value (its metatable's __name: "solid").
    const bool named = luaL_getmetafield(L, 1, "__name") == LUA_TSTRING;
    self.raise(L, std::string("setmetatable: a ") + (named ? lua_tostring(L, -1) : "userdata") +
                      " cannot take a metatable; only a table can");
  }
  if (lua_type(L, 1) != LUA_TTABLE)
    self.raise(L, std::string("setmetatable: the first argument must be a table, got ") +
                      luaL_typename(L, 1));
  if (!lua_istable(L, 2) && !lua_isnil(L, 2))
    self.raise(L, std::string("setmetatable: the metatable must be a table or nil, got ") +
                      luaL_typename(L, 2));
  if (luaL_getmetafield(L, 1, "__metatable") != LUA_TNIL)
    self.raise(L, "setmetatable: the table's metatable is protected (it has __metatable)");
  if (lua_istable(L, 2)) {
    lua_pushstring(L, "__gc");
    if (lua_rawget(L, 2) != LUA_TNIL)
      self.raise(L, "__gc metamethods are not available in the sandbox");
    lua_pop(L, 1);
  }
  lua_settop(L, 2);
  lua_setmetatable(L, 1);
  return 1;
}

int Sandbox::printLine(lua_State* L) {
  const int n = lua_gettop(L);
  const Sandbox& sandbox = of(L);
  if (!sandbox.print) {
    for (int i = 1; i <= n; ++i) {
      std::size_t len = 0;
      const char* s = luaL_tolstring(L, i, &len);
      if (i > 1) std::fputc('\t', stderr);
      std::fwrite(s, 1, len, stderr);
      lua_pop(L, 1);
    }
    std::fputc('\n', stderr);
    return 0;
  }
  // The values as Lua strings joined on the stack (a __tostring that fails
  // leaves no C++ object behind), then the host's callback. One that throws
  // ends the script with its message; the exception itself may not cross
  // Lua's C frames, and the message is on the stack before Lua jumps.
  for (int i = 1; i <= n; ++i) {
    if (i > 1) lua_pushliteral(L, "\t");
    luaL_tolstring(L, i, nullptr);
  }
  lua_concat(L, n > 0 ? 2 * n - 1 : 0);
  bool failed = false;
  {
    std::size_t len = 0;
    const char* text = lua_tolstring(L, -1, &len);
    try {
      sandbox.print(std::string(text, len));
    } catch (const std::exception& e) {
      lua_pushfstring(L, "print: %s", e.what());
      failed = true;
    }
  }
  if (!failed) return 0;
  luaL_where(L, 1);  // "part.lua:2: " before the message, as luaL_error puts it
  lua_insert(L, -2);
  lua_concat(L, 2);
  return lua_error(L);
}

SourceLine Sandbox::callerLine(lua_State* L) {
  // The nearest Lua frame: a C function in between (pcall, table.sort's
  // comparator caller) has no line of its own.
  // The script library's frames (script/standard_library.h) are passed
  // over: a shape it made was asked for at the script's line that called it.
  SourceLine where;
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    if (!lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0) continue;
    if (std::string_view(ar.source) == kLibraryChunkName) continue;
    if (!where.known())
      where = SourceLine{chunkName_, ar.currentline, 0};
    else
      where.via = ar.currentline;  // the outermost Lua frame, the main chunk, comes last
  }
  return where;
}

// The message handler of the script's run. error(value) with a value that
// is not a string gets no position from Lua; this gives it the line that
// raised it, as every other error has (the first Lua frame up the stack:
// error itself is a C function). The chunk's name is the upvalue, since
// Lua's own short source is cut at 60 characters.
int Sandbox::positionBareError(lua_State* L) {
  const int type = lua_type(L, 1);
  const bool text = type == LUA_TSTRING || type == LUA_TNUMBER;
  const char* chunk = lua_tostring(L, lua_upvalueindex(1));
  if (text && (hasPosition(lua_tostring(L, 1), chunk) ||
               hasPosition(lua_tostring(L, 1), kLibraryChunkName)))
    return 1;
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level)
    if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0 &&
        std::string_view(ar.source) != kLibraryChunkName) {
      // error(42) and error("text", 0) carry no position: the line that
      // raised them is named, as for every other error.
      if (text)
        lua_pushfstring(L, "%s:%d: %s", chunk, ar.currentline, lua_tostring(L, 1));
      else
        lua_pushfstring(L, "%s:%d: error(%s) without a message", chunk, ar.currentline,
                        luaL_typename(L, 1));
      return 1;
    }
  return 1;
}

namespace {

// Hands Lua's parser the source a line at a time, so that an error it
// raises without a position (brackets nested past its limit: "C stack
// overflow") can name the line it was reading.
struct LineReader {
  std::string_view rest;
  int line = 0;  // of the last line handed out, from 1

  static const char* read(lua_State*, void* data, std::size_t* size) {
    auto& self = *static_cast<LineReader*>(data);
    if (self.rest.empty()) {
      *size = 0;
      return nullptr;
    }
    const std::size_t end = self.rest.find('\n');
    const std::string_view piece =
        self.rest.substr(0, end == std::string_view::npos ? self.rest.size() : end + 1);
    self.rest.remove_prefix(piece.size());
    ++self.line;
    *size = piece.size();
    return piece.data();
  }
};

}  // namespace

int Sandbox::run(const std::string& source, const std::string& chunkName) {
  lua_pushstring(L_, chunkName.c_str());
  lua_pushcclosure(L_, positionBareError, 1);
  const int handler = lua_gettop(L_);
  int base = handler;
  chunkName_ = std::make_shared<const std::string>(chunkName);
  LineReader reader{source};
  int status = lua_load(L_, LineReader::read, &reader, ("@" + chunkName).c_str(), "t");
  const bool syntaxError = status == LUA_ERRSYNTAX;
  if (status != LUA_OK && lua_type(L_, -1) == LUA_TSTRING &&
      !hasPosition(lua_tostring(L_, -1), chunkName)) {
    const std::string bare = lua_tostring(L_, -1);
    lua_pop(L_, 1);
    lua_pushfstring(
        L_, "%s:%d: %s%s", chunkName.c_str(), reader.line, bare.c_str(),
        bare == "C stack overflow" ? " (brackets, calls or tables nested too deeply)" : "");
  }
  if (status == LUA_OK) status = lua_pcall(L_, 0, LUA_MULTRET, handler);
  // A script that reached a limit has failed, also when no error reached
  // here: Lua retries a refused allocation after a full collection, and the
  // script may end before the next check.
  if (status == LUA_OK && abortReason_.empty()) return lua_gettop(L_) - base;
  std::string message;
  if (!abortReason_.empty()) {
    // An abort raised as a memory error carries Lua's generic text.
    message = abortWhere_ + abortReason_;
  } else {
    if (lua_type(L_, -1) == LUA_TSTRING || lua_type(L_, -1) == LUA_TNUMBER) {
      // With its length: a message may hold NUL bytes (error("a\0b")).
      std::size_t length = 0;
      const char* text = lua_tolstring(L_, -1, &length);
      message.assign(text, length);
    } else {
      message = std::string("error(") + luaL_typename(L_, -1) + ") without a message";
    }
    std::string hint = unknownCallHint(L_, message);
    // Else what an OpenSCAD user may have meant on the line of the error.
    if (hint.empty() || hint.starts_with("; did you mean"))
      if (std::string habit =
              openscadLineHint(lineOf(source, errorLine(message, chunkName)), syntaxError);
          !habit.empty())
        hint = habit;
    message = withShortNames(message) + hint;
  }
  lua_settop(L_, base);
  // Every message names the script, also those Lua gives without a
  // position (binary chunks, C stack overflow, non-string errors).
  if (message.rfind(chunkName + ":", 0) != 0) message = chunkName + ": " + message;
  // One line: a message with line breaks of its own is folded, and one
  // that the script made endless is cut. A NUL byte would end the
  // exception's text (a C string) there: shown as '?', as the terminal's
  // line shows other control bytes.
  for (char& c : message)
    if (c == '\n' || c == '\r')
      c = ' ';
    else if (c == '\0')
      c = '?';
  throw ScriptError(shortened(message, kLongestMessage));
}

}  // namespace csgray::detail
