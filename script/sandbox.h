// A Lua state that scripts cannot escape: only the base, string, table,
// math and utf8 libraries, without anything that touches files, loads code
// or inspects the VM. Memory and instructions are capped; once a cap is hit
// the script is aborted, and pcall/xpcall cannot swallow that. Work that
// runs no Lua instructions counts against the instruction budget too: an
// error caught, by the frames it unwinds, and memory allocated, by its size.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <lua.hpp>
#include <memory>
#include <string>
#include <vector>

#include "engine/solid.h"
#include "script/held_objects.h"
#include "script/script.h"

namespace csgray::detail {

class Sandbox {
 public:
  explicit Sandbox(const ScriptLimits& limits);
  ~Sandbox();
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  lua_State* state() const { return L_; }
  // Where the script's print() goes: a line of text, without its newline;
  // standard error when unset (the command's choice).
  std::function<void(const std::string& line)> print;
  static Sandbox& of(lua_State* L);

  // Counts memory held outside Lua against the memory cap. Ends the script
  // when the cap is exceeded (after collecting what is dead).
  void charge(lua_State* L, std::size_t bytes);
  // Gives back what charge() counted, when the holder is collected.
  void release(std::size_t bytes) { used_ -= std::min(bytes, used_); }
  // The cap charge() holds the script's memory to, in bytes.
  std::size_t memoryLimit() const { return limits_.memoryBytes; }

  // C++ objects that the script's values share (held_objects.h): each is
  // counted once, from when a value first holds it until it is destroyed.
  struct HeldObject {
    std::shared_ptr<const void> object;
    std::size_t bytes;
  };
  bool holds(const std::shared_ptr<const void>& object) const { return held_.counts(object); }
  // Counts objects that are not counted yet (each once), as charge() does.
  void hold(lua_State* L, const std::vector<HeldObject>& objects);

  // Ends the script: the memory limit was reached (a C++ allocation failed).
  [[noreturn]] void outOfMemory(lua_State* L);
  // Raises an error at the line of the script that called the running C
  // function, also through pcall (which luaL_error would name instead).
  [[noreturn]] void raise(lua_State* L, const std::string& message);

  // Loads text (never binary) source and runs it; on success the results are
  // on the stack. Throws ScriptError with "chunk:line: message".
  int run(const std::string& source, const std::string& chunkName);

  // The file and line of the script code that called the running API
  // function; unknown when it was not called from Lua.
  SourceLine callerLine(lua_State* L);
  // "chunk:line: " for the innermost Lua function of the script at or
  // above level (the script library's are passed over), or "".
  std::string where(lua_State* L, int level) const;

 private:
  static void* allocate(void* ud, void* ptr, std::size_t oldSize, std::size_t newSize);
  static void countHook(lua_State* L, lua_Debug* ar);
  // Counts work that ran no instructions against the budget (lua_sethook
  // may be called anywhere, the allocator too).
  void addWork(std::uint64_t instructions);
  static int safePcall(lua_State* L);
  static int safeXpcall(lua_State* L);
  static int countUnwinding(lua_State* L);
  // print(): its values joined by tabs, to the host's callback or stderr.
  static int printLine(lua_State* L);
  static int positionBareError(lua_State* L);
  static int checkedSetmetatable(lua_State* L);
  static int seededRandomseed(lua_State* L);
  // Raises the abort as a Lua error located at the given stack level; the
  // first abort's reason and place stand for the whole run.
  [[noreturn]] void abort(lua_State* L, const std::string& reason, int level);
  int finishProtectedCall(lua_State* L, int status, int base);
  bool overCap(std::size_t bytes) const {
    return bytes > limits_.memoryBytes - std::min(used_, limits_.memoryBytes);
  }
  std::string memoryReason() const;
  std::string instructionReason() const;
  lua_State* L_ = nullptr;
  ScriptLimits limits_;
  std::size_t used_ = 0;
  std::size_t sinceCollectorStep_ = 0;
  std::uint64_t executed_ = 0;
  std::string abortReason_;
  std::string abortWhere_;  // "chunk:line: " where the first abort happened
  HeldObjects held_;
  std::shared_ptr<const std::string> chunkName_;  // shared by the SourceLines of every solid
  // Set once the script is being aborted: the allocator then allows
  // kAbortReserve bytes past the cap for the error message.
  bool aborting_ = false;
  static constexpr std::size_t kAbortReserve = std::size_t{1} << 20;
};

}  // namespace csgray::detail
