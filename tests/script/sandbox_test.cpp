// The Lua sandbox: nothing that reaches files, processes or the VM's
// internals is reachable, and runaway scripts end with a clear error even
// when they try to catch it.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <new>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/convex_polyhedron.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/mesh_solid.h"
#include "primitives/quadric.h"
#include "primitives/sphere.h"
#include "primitives/torus.h"
#include "scene/surface.h"
#include "script/held_objects.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

std::string errorOf(const std::string& source, const ScriptLimits& limits = {},
                    ScriptOptions options = {}) {
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
      "local t = {}\n"
      "for i = 1, 4096 do t[i] = sphere(1):translate(i, 0, 0) end\n"
      "local s, u = union(t), {}\n"
      "for i = 1, 1000 do u[i] = s:material{color = {1, 0, 0}} end\n"
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

// The memory limit ends the script as the instruction budget does, with
// the line where it was reached: no pcall or xpcall catches it, nor does a
// __close that raises an error of its own as the memory error passes.
TEST(Sandbox, MemoryLimitCannotBeCaught) {
  struct Case {
    const char* source;
    int line;
  } cases[] = {
      {"local ok = pcall(string.rep, 'x', 1 << 30)\nreturn sphere(1)", 1},
      {"local t = {}\nfor i = 1, 40 do t[i] = string.rep('x', 1 << 20) .. i end\n"
       "local ok = pcall(table.concat, t)\nreturn sphere(1)",
       3},
      {"local s = string.rep('x', 30 << 20)\nlocal ok = pcall(string.format, '%s%s', s, s)\n"
       "return sphere(1)",
       2},
      {"local ok = xpcall(function()\n  return string.rep('x', 1 << 30)\nend, "
       "function(m) return m end)\nreturn sphere(1)",
       2},
      {"local ok = pcall(function()\n"
       "  local guard <close> = setmetatable({}, {__close = function() error('hidden') end})\n"
       "  return string.rep('x', 1 << 30)\nend)\nreturn sphere(1)",
       3},
      {"local ok = pcall(function()\n  local t = {}\n  for i = 1, 1e9 do t[i] = {i} end\nend)\n"
       "return sphere(1)",
       3},
      {"local ok = pcall(function()\n  local t = {}\n"
       "  for i = 1, 1e7 do t[i] = sphere(1):translate(i, 0, 0) end\nend)\nreturn sphere(1)",
       3},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(errorOf(c.source, smallLimits()),
              "evil.lua:" + std::to_string(c.line) + ": script exceeded the memory limit of 64 MiB")
        << c.source;
  }
}

// A height map is charged at what building its mesh takes, before it is
// built: one past the limit stops at the call, without taking the memory
// first, though the finished mesh would be within it.
TEST(Sandbox, AHeightMapPastTheMemoryLimitStopsBeforeItsMesh) {
  ScriptOptions options;
  int loads = 0;
  options.loadImage = [&](const std::string&) {
    ++loads;
    TextureImage image;
    image.width = image.height = 180;  // 4·179² triangles: 100 MB to build, 26 MB built
    image.rgb.assign(std::size_t(180) * 180 * 3, 0.5f);
    return image;
  };
  // The image is read through loadImage; the file need only be there.
  const std::string folder = testing::TempDir() + "/height_map_limit";
  std::filesystem::create_directories(folder);
  std::ofstream(folder + "/hill.png", std::ios::binary)
      << "\x89PNG\r\n\x1a\n";  // loadImage reads it
  options.limits = smallLimits();
  options.folder = folder;
  const auto error = [&](const std::string& source) {
    return test::scriptError(source, options, "evil.lua");
  };
  // A map that could not be built within the limit even alone names its
  // file and what it would take.
  EXPECT_EQ(error("local s = sphere(1)\nreturn height_map{file='hill.png'}"),
            "evil.lua:2: height_map: hill.png: a map of 180 x 180 heights takes about 98 MiB to "
            "build, more than the script's memory limit of 64 MiB");
  EXPECT_EQ(loads, 1);
  options.loadImage = [](const std::string&) {
    TextureImage image;
    image.width = image.height = 60;  // some 11 MB
    image.rgb.assign(std::size_t(60) * 60 * 3, 0.5f);
    return image;
  };
  EXPECT_EQ(error("return height_map{file='hill.png'}"), "(no error)");
}

// A C++ allocation that fails (here in the programs that read meshes and
// check parts) ends the script too, rather than giving pcall an error.
TEST(Sandbox, FailedAllocationEndsTheScript) {
  ScriptOptions options;
  options.loadMesh = [](const std::string&, bool, std::string&) -> TriangleMesh {
    throw std::bad_alloc();
  };
  options.checkSolid = [](const Solid&, const CheckOptions&) -> CheckReport {
    throw std::bad_alloc();
  };
  for (const char* source : {"local ok = pcall(mesh, {file='part.stl'})\nreturn sphere(1)",
                             "local ok = pcall(check, sphere(1))\nreturn sphere(1)"}) {
    EXPECT_EQ(errorOf(source, {}, options),
              "evil.lua:1: script exceeded the memory limit of 1024 MiB")
        << source;
  }
}

// Work that runs few instructions but takes long counts against the
// budget: errors caught by the thousand (a recursion that doubles under
// pcall until the C stack overflows, again and again), a recursion that
// overflows Lua's stack (hundreds of thousands of frames to unwind), and
// allocations (string.rep in a loop).
TEST(Sandbox, SlowWorkCountsAgainstTheBudget) {
  for (const char* source : {
           "local function f() pcall(f) pcall(f) end\nf()\nreturn sphere(1)",
           "local function f() xpcall(f, f) xpcall(f, f) end\nf()\nreturn sphere(1)",
           "local function f() f() end\nfor i = 1, 1e6 do pcall(f) end\nreturn sphere(1)",
           "local function f() return 1 + f() end\nwhile true do pcall(f) end",
           "for i = 1, 1e6 do local s = string.rep('x', 1e6) end\nreturn sphere(1)",
       }) {
    ScriptLimits limits;  // memory enough for Lua's stack to overflow
    limits.instructions = 50'000'000;
    std::string e = errorOf(source, limits);
    EXPECT_NE(e.find("script exceeded the instruction budget of 50000000"), std::string::npos)
        << source << "\n  gave: " << e;
  }
}

// What the C++ objects of solids hold stays counted while any value shares
// them, also when the value that made them is collected. (A moved union is
// a use of it, not a copy: doubling a part by moved uses stays small and
// meets the limit on primitives, which counts uses.)
TEST(Sandbox, SharedNodesStayCounted) {
  EXPECT_EQ(errorOf("local s = sphere(1)\nfor i = 1, 30 do s = s + s:translate(1, 0, 0) end\n"
                    "return s",
                    smallLimits())
                .rfind("evil.lua:2: union: the part would have more than 2000000 primitives", 0),
            0u);
  // The copies in a list are collected once the union holds them; the
  // unions kept hold 100 000 spheres, about 100 MB.
  EXPECT_EQ(errorOf("local kept = {}\nfor k = 1, 1000 do\n  local t = {}\n"
                    "  for i = 1, 100 do t[i] = sphere(1):translate(i, k, 0) end\n"
                    "  kept[k] = union(t)\nend\nreturn union(kept)",
                    smallLimits()),
            "evil.lua:4: script exceeded the memory limit of 64 MiB");
  // Dead values give back what they held: a long loop of copies that are
  // dropped at once runs within the limit.
  EXPECT_EQ(errorOf("local s = box(1)\nfor i = 1, 200000 do local t = s:translate(i, 0, 0) end\n"
                    "return s",
                    smallLimits()),
            "(no error)");
}

// s = s - hole in a loop shares one operand list along the chain
// (engine/operand_list.h): 100 000 steps run within 64 MiB, each charged
// for its node and the list once. Branches off such a chain copy the list,
// and each copy is charged: a thousand of them, 3 GB, end at the limit.
TEST(Sandbox, AChainsSharedListIsCountedOnceAndEachCopyOfIt) {
  const std::string chain =
      "local h = sphere(1)\nlocal s = box(1)\nfor i = 1, 100000 do s = s - h end\n";
  EXPECT_EQ(errorOf(chain + "return s", smallLimits()), "(no error)");
  EXPECT_EQ(errorOf(chain + "local kept = {}\nfor i = 1, 1000 do kept[i] = s - h end\nreturn s",
                    smallLimits()),
            "evil.lua:5: script exceeded the memory limit of 64 MiB");
}

// The sizes a solid's nodes are counted at cover what they take: the
// object, its shared pointer's control block and the allocator's header.
TEST(Sandbox, ChargesCoverTheObjects) {
  constexpr std::size_t overhead = 4 * sizeof(void*);
  for (std::size_t size :
       {sizeof(Sphere), sizeof(Box), sizeof(Cylinder), sizeof(HalfSpace), sizeof(Quadric),
        sizeof(Torus), sizeof(ConvexPolyhedron), sizeof(MeshSolid), sizeof(Surface)})
    EXPECT_LE(size + overhead, kBytesPerShape);
  EXPECT_LE(sizeof(Boolean) + overhead, kBytesPerBoolean);
}

}  // namespace
}  // namespace csgray::detail
