// The Lua sandbox: nothing that reaches files, processes or the VM's
// internals is reachable, and runaway scripts end with a clear error even
// when they try to catch it.
#include <gtest/gtest.h>

#include <chrono>

#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

std::string errorOf(const std::string& source, const ScriptLimits& limits = {}) {
  ScriptOptions options;
  options.limits = limits;
  return test::scriptError(source, options, "evil.lua");
}

TEST(Sandbox, RemovedFunctionsAreNil) {
  for (const char* name :
       {"io", "os", "package", "debug", "coroutine", "load", "loadfile", "dofile", "require",
        "collectgarbage", "string.dump", "loadstring", "module"}) {
    std::string source =
        std::string("assert(") + name + " == nil, '" + name + " is reachable') return sphere(1)";
    EXPECT_EQ(errorOf(source), "(no error)") << name;
  }
}

TEST(Sandbox, SafeLibrariesRemain) {
  EXPECT_EQ(errorOf(R"(
    assert(math.sqrt(16) == 4 and string.format('%d', 3) == '3' and table.concat({1, 2}) == '12')
    assert(utf8.char(72) == 'H' and select('#', 1, 2) == 2 and tostring(1) == '1')
    return sphere(1))"),
            "(no error)");
}

TEST(Sandbox, BinaryChunksAreRefused) {
  std::string binary = "\x1bLua\x54\x00 anything";
  EXPECT_NE(errorOf(binary).find("binary chunk"), std::string::npos) << errorOf(binary);
}

// A script that could reach __gc could destroy a solid still in use.
TEST(Sandbox, MetatablesOfApiValuesAreLocked) {
  EXPECT_EQ(errorOf(R"(
    for _, v in ipairs{sphere(1), camera{}, point_light{pos={0, 0, 1}}, scene{objects={box(1)}}} do
      assert(type(getmetatable(v)) == 'string', 'metatable reachable')
      assert(not pcall(setmetatable, v, {}), 'setmetatable allowed')
    end
    return sphere(1))"),
            "(no error)");
}

// Finalizers run with hooks off (no instruction budget) and can resurrect
// a collected solid; scripts get none.
TEST(Sandbox, FinalizersAreRefused) {
  for (const char* source : {
           "setmetatable({}, {__gc=function() while true do end end}) return sphere(1)",
           "local t = setmetatable({}, {__gc=function(t) saved = t.s end}) t.s = sphere(1) "
           "return sphere(1)",
       }) {
    std::string e = errorOf(source);
    EXPECT_NE(e.find("evil.lua:1: __gc metamethods are not available"), std::string::npos)
        << source << "\n  gave: " << e;
  }
  EXPECT_EQ(
      errorOf("local t = setmetatable({}, {__index={x=1}}) assert(t.x == 1) return sphere(1)"),
      "(no error)");
}

TEST(Sandbox, StringMetatableCannotReachDump) {
  EXPECT_EQ(errorOf("assert(('x').dump == nil) return sphere(1)"), "(no error)");
}

ScriptLimits smallLimits() {
  ScriptLimits limits;
  limits.instructions = 50'000'000;
  limits.memoryBytes = 64u << 20;
  return limits;
}

// Memory that solids hold, charged by a library call, stops the script
// with the line of that call: the abort's message still fits, however far
// the charge would have gone past the cap.
TEST(Sandbox, MemoryLimitNamesTheLineOfTheCall) {
  std::string e = errorOf(
      "local s = sphere(1)\n"
      "for i = 1, 12 do s = s + s:translate(1, 0, 0) end\n"
      "local t = {}\n"
      "for i = 1, 1000 do t[i] = s:translate(i, 0, 0) end\n"
      "return s",
      smallLimits());
  EXPECT_EQ(e, "evil.lua:4: script exceeded the memory limit of 64 MiB");
}

TEST(Sandbox, EndlessLoopEnds) {
  auto start = std::chrono::steady_clock::now();
  std::string e = errorOf("local x = 0\nwhile true do x = x + 1 end", smallLimits());
  EXPECT_NE(e.find("evil.lua:2: script exceeded the instruction budget"), std::string::npos) << e;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
}

TEST(Sandbox, EndlessLoopEndsInsidePcall) {
  for (const char* source : {
           "pcall(function() while true do end end) return sphere(1)",
           "while true do pcall(function() while true do end end) end",
           "xpcall(function() while true do end end, function(m) return m end) return sphere(1)",
           "local ok = pcall(pcall, function() while true do end end) return sphere(1)",
       }) {
    std::string e = errorOf(source, smallLimits());
    EXPECT_NE(e.find("script exceeded the instruction budget"), std::string::npos)
        << source << "\n  gave: " << e;
  }
}

TEST(Sandbox, MemoryBombEnds) {
  for (const char* source : {
           "local t = {} for i = 1, 1e9 do t[i] = i end",
           "local s = 'x' for i = 1, 64 do s = s .. s end",
           "local s = string.rep('x', 1 << 30)",
           "pcall(function() local t = {} for i = 1, 1e9 do t[i] = {i} end end) return sphere(1)",
           "pcall(string.rep, 'x', 1 << 30) return sphere(1)",
           "local t = {} for i = 1, 1e8 do t[i] = sphere(1) end",
       }) {
    std::string e = errorOf(source, smallLimits());
    EXPECT_NE(e.find("script exceeded the memory limit of 64 MiB"), std::string::npos)
        << source << "\n  gave: " << e;
  }
}

TEST(Sandbox, ScriptWithinLimitsRuns) {
  EXPECT_EQ(errorOf("local t = {} for i = 1, 1000 do t[i] = sphere(1):translate(i, 0, 0) end "
                    "return union(t)",
                    smallLimits()),
            "(no error)");
}

}  // namespace
}  // namespace csgray::detail
