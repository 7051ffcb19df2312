// A Lua state that scripts cannot escape: only the base, string, table,
// math and utf8 libraries, without anything that touches files, loads code
// or inspects the VM. Memory and instructions are capped; once a cap is hit
// the script is aborted, and pcall/xpcall cannot swallow that.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <lua.hpp>
#include <memory>
#include <string>

#include "engine/solid.h"
#include "script/script.h"

namespace csgray::detail {

class Sandbox {
 public:
  explicit Sandbox(const ScriptLimits& limits);
  ~Sandbox();
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  lua_State* state() const { return L_; }
  static Sandbox& of(lua_State* L);

  // Counts memory held outside Lua (solids) against the memory cap.
  // Raises a Lua error when the cap is exceeded.
  void charge(lua_State* L, std::size_t bytes);
  // Gives back what charge() counted, when the holder is collected.
  void release(std::size_t bytes) { used_ -= std::min(bytes, used_); }

  // Loads text (never binary) source and runs it; on success the results are
  // on the stack. Throws ScriptError with "chunk:line: message".
  int run(const std::string& source, const std::string& chunkName);

  // The file and line of the script code that called the running API
  // function; unknown when it was not called from Lua.
  SourceLine callerLine(lua_State* L);

  // Why the script was aborted, or empty.

 private:
  static void* allocate(void* ud, void* ptr, std::size_t oldSize, std::size_t newSize);
  static void countHook(lua_State* L, lua_Debug* ar);
  static int safePcall(lua_State* L);
  static int safeXpcall(lua_State* L);
  static int printToStderr(lua_State* L);
  static int setmetatableWithoutGc(lua_State* L);
  static int seededRandomseed(lua_State* L);
  // Raises the abort as a Lua error located at the given stack level.
  [[noreturn]] void abort(lua_State* L, const std::string& reason, int level);
  int finishProtectedCall(lua_State* L, int status, int base);

  lua_State* L_ = nullptr;
  ScriptLimits limits_;
  std::size_t used_ = 0;
  std::size_t sinceCollectorStep_ = 0;
  std::uint64_t executed_ = 0;
  std::string abortReason_;
  std::shared_ptr<const std::string> chunkName_;  // shared by the SourceLines of every solid
  // Set once the script is being aborted: the allocator then allows
  // kAbortReserve bytes past the cap for the error message.
  bool aborting_ = false;
  static constexpr std::size_t kAbortReserve = std::size_t{1} << 20;
};

}  // namespace csgray::detail
