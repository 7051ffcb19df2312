// Parts whose solids touch at a point, along an edge or over a face, or
// meet tangentially, export at the default tolerance to meshes that are
// closed, 2-manifold, outward and free of self-intersections, that pass
// csgray check, and whose volumes agree with the exact ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "check_support.h"
#include "engine/boolean.h"
#include "export/cgal/mesh_boolean.h"
#include "export/cgal/mesh_validity.h"
#include "io/scratch_folder.h"
#include "meshio/mesh_writer.h"
#include "script/script.h"
#include "tessellation/mesh_shells.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTolerance = 0.01;

SolidPtr part(const std::string& source) {
  const Scene scene = runScript(source, "part.lua", test::exampleOptions());
  return scene.objects.size() == 1 ? scene.objects[0] : unionOf(scene.objects);
}

// Exports at the default tolerance, expects a valid mesh within
// `volumeSlack` of `volume` (the chord error is within tolerance × area),
// and the check; returns the mesh.
// The export at the default tolerance, or nothing (and a failure) when
// meshOfSolid refuses it.
std::optional<TriangleMesh> exported(const Solid& solid) {
  try {
    return meshOfSolid(solid, kTolerance).mesh;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not exported: " << e.what();
    return std::nullopt;
  }
}

TriangleMesh exportsValid(const std::string& source, double volume, double volumeSlack) {
  SCOPED_TRACE(source);
  const SolidPtr solid = part(source);
  const std::optional<TriangleMesh> made = exported(*solid);
  if (!made) return {};
  const TriangleMesh& mesh = *made;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_NEAR(mesh.volume(), volume, volumeSlack);
  EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  return mesh;
}

// ---- Face to face ------------------------------------------------------------

TEST(ContactExport, StackedBoxesAreOneShell) {
  const TriangleMesh mesh =
      exportsValid("return box(10) + box(10):translate(0, 0, 10)", 2000.0, 1e-9);
  EXPECT_EQ(meshShells(mesh).count, 1u);
}

TEST(ContactExport, CylindersStackedFaceToFace) {
  // A shaft on a hub: r = 30, 60 high; the minimax polygon's area is within
  // tolerance × perimeter of the circle's.
  const double exact = kPi * 30 * 30 * 60;
  const TriangleMesh mesh =
      exportsValid("return cylinder{r=30, h=30} + cylinder{r=30, h=30}:translate(0, 0, 30)", exact,
                   kTolerance * (2 * kPi * 30 * 60 + 2 * kPi * 30 * 30));
  EXPECT_EQ(meshShells(mesh).count, 1u);
}

TEST(ContactExport, FrustumsStackedOnSharedRims) {
  // Volume of a frustum: πh(r1² + r1 r2 + r2²)/3.
  auto frustum = [](double r1, double r2, double h) {
    return kPi * h * (r1 * r1 + r1 * r2 + r2 * r2) / 3;
  };
  const double exact = frustum(30, 25, 10) + frustum(25, 28, 10);
  exportsValid(
      "return cylinder{r1=30, r2=25, h=10} + cylinder{r1=25, r2=28, h=10}:translate(0, 0, 10)",
      exact, kTolerance * 4000);
}

// ---- Along an edge, at a point --------------------------------------------------

TEST(ContactExport, SolidsStackedOnTheSameFacesAreGluedNotCorefined) {
  // A shaft on a hub of its radius (turned about its axis by 1° or not),
  // and two frustums on a shared rim of nearby radii (one rung of the
  // segment ladder): their faces in the plane of contact are the same
  // triangles, which the union drops.
  for (const char* source :
       {"return cylinder{r=30, h=30} + cylinder{r=30, h=30}:translate(0, 0, 30)",
        "return cylinder{r=8, h=10} + cylinder{r=8, h=10}:rotate(0, 0, 1):translate(0, 0, 10)",
        "return cylinder{r1=20, r2=20.5, h=2} + cylinder{r1=20.5, r2=21.5, h=2}:translate(0, 0, 2)",
        "return (cylinder{r=5, h=2} + cylinder{r=5, h=3}:translate(0, 0, 2)):rotate(90, 30, 0)"}) {
    SCOPED_TRACE(source);
    MeshBooleanStats stats;
    const SolidPtr solid = part(source);
    const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, nullptr, &stats).mesh;
    EXPECT_EQ(meshDefect(mesh).text, "");
    EXPECT_EQ(stats.glued, 1u);
    EXPECT_EQ(stats.corefinements, 0u);
    EXPECT_EQ(meshShells(mesh).count, 1u);
    EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  }
}

TEST(ContactExport, AGridOfCubesIsOneSolid) {
  // 12 × 12 cubes side by side, in rows along y 1 and 2 high by turns (of one
  // height, they would be one extrusion, export/prism_booleans.h): a slab
  // of volume 144 + 72, one shell, partly glued and partly corefined.
  const std::string source =
      "local cubes = {}\n"
      "for i = 0, 11 do for j = 0, 11 do\n"
      "  cubes[#cubes + 1] = box{size = {1, 1, 1 + i % 2}}:translate(i, j, 0)\n"
      "end end\n"
      "return union(cubes)";
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*part(source), kTolerance, nullptr, &stats).mesh;
  EXPECT_GT(stats.glued, 0u);
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_NEAR(mesh.volume(), 216.0, 1e-9);
  EXPECT_EQ(meshShells(mesh).count, 1u);
}

TEST(ContactExport, SolidsStackedOnFacesThatDifferAreCorefined) {
  // The same segments but another radius, a smaller box on a larger one,
  // a cylinder scaled a little across: the faces in the plane differ, so
  // the glue refuses and the corefinement makes the union.
  const double h = 10;
  struct Case {
    const char* source;
    double volume;
    double slack;
  };
  const Case cases[] = {
      {"return cylinder{r=30, h=10} + cylinder{r=29.9, h=10}:translate(0, 0, 10)",
       kPi * (30 * 30 + 29.9 * 29.9) * h, kTolerance * 4 * kPi * 30 * (30 + h)},
      {"return box(10) + box(4):translate(3, 3, 10)", 1000.0 + 64.0, 1e-9},
      {"return cylinder{r=8, h=10} + cylinder{r=8, h=10}:scale(1.01, 1, 1):translate(0, 0, 10)",
       kPi * 64 * 2.01 * h, kTolerance * 4 * kPi * 8 * (8 + h)},
  };
  for (const Case& c : cases) {
    MeshBooleanStats stats;
    SCOPED_TRACE(c.source);
    const TriangleMesh mesh = exportsValid(c.source, c.volume, c.slack);
    meshOfSolid(*part(c.source), kTolerance, nullptr, &stats);
    EXPECT_EQ(stats.glued, 0u);
    EXPECT_EQ(stats.corefinements, 1u);
    EXPECT_EQ(meshShells(mesh).count, 1u);
  }
}

TEST(ContactExport, SierpinskiTetrahedraThatMeetAtCornersAreSplitThere) {
  // Each level puts four tetrahedra of half the size at the corners, each
  // meeting the other three at one corner, where their irrational
  // coordinates agree only to rounding: level 1's are joined (their boxes
  // apart by a hair), the later levels' are united (boxes that overlap).
  // Each tetrahedron stays its own shell, half the volume per level.
  const double r = 50.0, edge = 4.0 * r / std::sqrt(6.0);
  const double whole = edge * edge * edge / (6.0 * std::sqrt(2.0));
  for (int level = 1; level <= 3; ++level) {
    const double volume = whole / std::pow(2.0, level);
    const TriangleMesh mesh = exportsValid(
        "return sierpinski_tetrahedron{level = " + std::to_string(level) + ", size = 100}", volume,
        1e-3 * volume);
    EXPECT_EQ(meshShells(mesh).count, std::size_t(1) << (2 * level));
  }
}

// Two of the four parts of level 6: Sierpinski tetrahedra of level 5, 1 024
// tetrahedra each, that meet one another at corners only. Their union
// keeps every tetrahedron, each its own shell: CGAL's corefinement lost one of the
// 2 048 where two corners were left a unit in the last place apart instead
// of made one. (Each contact pulls its corners a hair apart, which costs
// 0.12 % of the volume here.)
TEST(ContactExport, TwoSierpinskiTetrahedraOfLevelFiveKeepAllTheirTetrahedra) {
  const double r = 25.0, edge = 4.0 * r / std::sqrt(6.0);
  const double volume = 2.0 * edge * edge * edge / (6.0 * std::sqrt(2.0)) / 32.0;
  const std::string source = R"(
    -- Placed as the library places the parts of level 6, to the last bit.
    local part = sierpinski_tetrahedron{level = 5, size = 50}
    local c = 2 * math.sqrt(2) / 3
    return part:translate(0, 0, 25) +
           part:translate(c * math.cos(0) * 25, c * math.sin(0) * 25, -1 / 3 * 25))";
  const TriangleMesh mesh = exportsValid(source, volume, 2e-3 * volume);
  EXPECT_EQ(meshShells(mesh).count, 2048u);
}

TEST(ContactExport, BoxesTouchingAlongAnEdgeAreJoined) {
  // The union's operands grow by a hundredth of the tolerance: a bridge of
  // that width joins them along the edge, one shell.
  const TriangleMesh mesh =
      exportsValid("return box(10) + box(10):translate(10, 10, 0)", 2000.0, 1.0);
  EXPECT_EQ(meshShells(mesh).count, 1u);
}

TEST(ContactExport, BoxesTouchingAtAPointStayApartThere) {
  // CGAL gives each box its own vertex at (10, 10, 10); each is pulled a
  // hundredth of the tolerance into its own box (taking some 0.01 of volume
  // with the large triangles around it).
  const TriangleMesh mesh =
      exportsValid("return box(10) + box(10):translate(10, 10, 10)", 2000.0, 0.1);
  EXPECT_EQ(meshShells(mesh).count, 2u);
}

TEST(ContactExport, ATipOnAFaceIsSplit) {
  // An octahedron's tip on the middle of a box's top face, and of a cube's:
  // the tip was a unit in the last place short of the face, the two were
  // joined without a boolean, and the file's rounding made them touch
  // ("self-intersecting"). A point contact: two shells.
  const double octahedron = 4.0 / 3.0 * 1000.0;  // (4/3) R³
  const double side = 20.0 / std::sqrt(3.0);
  for (const auto& [source, volume] : std::vector<std::pair<std::string, double>>{
           {"return octahedron{r=10} + box{size={20, 20, 5}, center=true}:translate(0, 0, -12.5)",
            octahedron + 2000.0},
           {"return octahedron{r=10} + hexahedron{r=10}:translate(0, 0, -10 - 10 / math.sqrt(3))",
            octahedron + side * side * side}}) {
    const TriangleMesh mesh = exportsValid(source, volume, 0.1);
    EXPECT_EQ(meshShells(mesh).count, 2u) << source;
  }
}

TEST(ContactExport, ACutterWhoseTipTouchesTheFarFaceLeavesAWallThere) {
  // A countersink whose tip lies on the plate's far face, from either side,
  // and two pockets corner to corner: the part's empty sides touch at a
  // point. Each side's vertex there was moved into the part, as solids
  // that touch at a point are kept apart, and the two crossed ("faces
  // cross", "self-intersecting"). They move out of it: a wall of a
  // fiftieth of the tolerance closes the tip, and the pockets are cavities
  // of their own.
  const double cone = kPi * 16.0 * 5.0 / 3.0;  // π r² h / 3
  for (const char* source :
       {"return box{size={20, 20, 5}} - cone{r=4, h=5}:mirror(0, 0, 1):translate(10, 10, 5)",
        "return box{size={20, 20, 5}} - cone{r=4, h=5}:translate(10, 10, 0)"}) {
    // The cone's polygon lies within the tolerance of its side, π r l.
    const TriangleMesh mesh =
        exportsValid(source, 2000.0 - cone, kTolerance * kPi * 4 * std::sqrt(41.0));
    EXPECT_EQ(meshShells(mesh).count, 1u) << source;
  }
  const TriangleMesh mesh =
      exportsValid("return box(10) - box(2):translate(3, 3, 3) - box(2):translate(5, 5, 5)",
                   1000.0 - 16.0, 0.01);
  const MeshShells shells = meshShells(mesh);
  EXPECT_EQ(shells.count, 3u);
  EXPECT_EQ(shells.cavities, 2u);
}

TEST(ContactExport, SolidsStackedAtAHeightComputedInDoublesAreOneShell) {
  // 0.1 + 0.2 is 0.30000000000000004: the upper solid stood a unit in the
  // last place above the lower one's top, they were joined without a
  // boolean, and the file's rounding put the two faces in one place. So
  // too a tetrahedron on a cube of its circumradius, its base wider than
  // the cube's top (R/√3 + R/3 − R/3 is one unit above R/√3), and an
  // icosahedron turned onto a face, the box first; and such gaps beside
  // exact contacts.
  const double side = 20.0 / std::sqrt(3.0);
  const double tetrahedron = 8.0 * 1000.0 / (9.0 * std::sqrt(3.0));  // 8R³/(9√3)
  // (5/12)(3 + √5)a³, the edge a = R/sin(2π/5).
  const double edge = 10.0 / std::sin(2.0 * kPi / 5.0);
  const double icosahedron = 5.0 / 12.0 * (3.0 + std::sqrt(5.0)) * edge * edge * edge;
  for (const auto& [source, volume] : std::vector<std::pair<std::string, double>>{
           {"return box{size={10, 10, 0.3}} + box{size={4, 4, 1}}:translate(2, 2, 0.1 + 0.2)",
            30.0 + 16.0},
           {"return cylinder{r=5, h=0.3} + cylinder{r=3, h=1}:translate(0, 0, 0.1 + 0.2)",
            kPi * (25 * 0.3 + 9)},
           {"return hexahedron{r=10} + "
            "tetrahedron{r=10}:translate(0, 0, 10 / math.sqrt(3) + 10 / 3)",
            side * side * side + tetrahedron},
           // An icosahedron turned onto a face (its inradius above the box),
           // the face's corners a few units off the box's top.
           {"local rin = 10 * math.sqrt((5 + 2 * math.sqrt(5)) / 15)\n"
            "local turn = math.deg(math.acos(1 / math.sqrt(3)))\n"
            "return box{size={30, 30, 3}, center=true}:translate(0, 0, -1.5) + "
            "icosahedron{r=10}:rotate{angle=turn, axis={-1, 1, 0}}:translate(0, 0, rin)",
            2700.0 + icosahedron},
           // Gaps next to exact contacts: plates 0.1 thick at i·0.1 (the
           // one gap at 0.6, the rest glued face to face first), along z
           // and along x; three boxes, each half over the one below.
           {"local p = {}\nfor i = 0, 9 do p[#p + 1] = box{size={1, 1, 0.1}}:translate(0, 0, i * "
            "0.1) "
            "end\nreturn union(p)",
            1.0},
           {"local p = {}\nfor i = 0, 9 do p[#p + 1] = cylinder{r=1, h=0.1}:translate(0, 0, i * "
            "0.1) "
            "end\nreturn union(p)",
            kPi},
           {"local p = {}\nfor i = 0, 9 do p[#p + 1] = box{size={0.1, 1, 1}}:translate(i * 0.1, 0, "
            "0) "
            "end\nreturn union(p)",
            1.0},
           {"return box{size={1, 1, 0.3}} + box{size={1, 1, 0.3}}:translate(0.5, 0.5, 0.1 + 0.2) + "
            "box{size={1, 1, 0.3}}:translate(1, 1, 0.6000000000000001)",
            0.9}}) {
    const TriangleMesh mesh = exportsValid(source, volume, kTolerance * 1500.0);
    EXPECT_EQ(meshShells(mesh).count, 1u) << source;
  }
}

TEST(ContactExport, SolidsCloserThanTheFilesStepAreOneShell) {
  // Teeth 10⁻⁷ short of a plate's side at y = 10, where a float's step is
  // 9.5·10⁻⁷: their boxes are apart, and joined without a boolean, the
  // file's rounding put the facing sides in one place, crossing. The gap
  // is closed instead, and the check lets a gap narrower than a contact's
  // offset go. In doubles the gap stays: two shells.
  const std::string source =
      "local parts = {box{size = {10, 10, 2}}}\n"
      "for i = 0, 4 do parts[#parts + 1] = box{size = {1, 2, 2}}:translate(2 * i + 0.5, "
      "10 + 1e-7, 0) end\n"
      "return union(parts)";
  const SolidPtr solid = part(source);
  const TriangleMesh mesh =
      meshOfSolid(*solid, kTolerance, storedCoordinate(MeshFormat::Stl, false)).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_EQ(meshShells(mesh).count, 1u);
  EXPECT_NEAR(mesh.volume(), 200.0 + 5 * 4.0, 1e-4);
  EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  EXPECT_EQ(meshShells(meshOfSolid(*solid, kTolerance).mesh).count, 6u);
}

TEST(ContactExport, ACutWhosePiecesTouchAlongAnEdgeGoesThrough) {
  // Two cutters touch along the edge x = y = 5: the block's material that
  // meets there is cut apart, so that the mesh stays a 2-manifold.
  exportsValid(
      "return box(10) - (box{size={5, 5, 20}}:translate(0, 0, 5) + "
      "box{size={5, 5, 20}}:translate(5, 5, 5))",
      1000.0 - 2 * 125.0, 1.0);
}

TEST(ContactExport, ACutFlushWithAFaceThatAContactMovedLeavesNoSheet) {
  // The first two boxes touch along the edge y = 6, z = 2; the union moves
  // the faces there by a hundredth of the tolerance, and with them the
  // upper box's face y = 6, which the cutter (x 6..10, y 6..8, z 2..4) is
  // flush with. The cutter grows past the moved face: no sheet of the
  // upper box is left standing in the cut (8 of its 32 taken).
  exportsValid(
      "return (box{size={2,2,2}}:translate(6,4,0) + box{size={4,4,2}}:translate(4,6,2)) - "
      "box{size={4,2,2}}:translate(6,6,2)",
      8.0 + 24.0, 0.1);
}

TEST(ContactExport, ACutterThatAContactShrankStillCutsThroughAFlushFace) {
  // The paraboloid's vertex touches the clip box's floor at a point: the
  // intersection is made with the box shrunk by a hundredth of the
  // tolerance, its top too, which the block's top is flush with. The
  // cutter grows back past it: the cup is open, not sealed under a skin.
  // Volume: the block less the paraboloid x² + y² <= 4z up to z = 4,
  // 400 − ∫₀⁴ 4πz dz = 400 − 32π.
  exportsValid(
      "return box{size={10,10,4}}:translate(-5,-5,0) - "
      "clip(elliptic_paraboloid{a=2, b=2}, {lo={-5,-5,0}, hi={5,5,4}})",
      400.0 - 32.0 * kPi, 0.5);
}

TEST(ContactExport, APinInAHoleCutAgainMeetsItsWall) {
  // The ring's hole is cut again by a cylinder of its radius: the walls
  // lie in one place, and the cut is made with the cutter moved off the
  // wall, which widens the hole by a ten-thousandth. The pin of the same
  // radius grows past that gap where it meets the ring: one shell.
  // Volume: the ring π(10² − 5²)·4 and the pin π·5²·8.
  exportsValid(
      "local ring = linear_extrude{circle(10) - circle(5), height=4} - "
      "cylinder{r=5, h=10}:translate(0,0,-3)\n"
      "return ring + cylinder{r=5, h=8}",
      kPi * 75.0 * 4.0 + kPi * 25.0 * 8.0, 3.0);
}

// A script of a honeycomb of 4 × 4 hexagons of radius 2, their corners at
// (2 cos 60k°, 2 sin 60k°) about centres 3 apart, so that neighbours'
// corners meet only to rounding: `cell` makes a cell of the polygon `hex`
// and its centre x, y; the script returns `part`, made of the list
// `cells`. Their volume, 4 high: 16 · 6√3 · 4.
std::string honeycomb(const std::string& cell, const std::string& part) {
  return "local cells = {}\n"
         "for i = 0, 3 do for j = 0, 3 do\n"
         "  local hex = {}\n"
         "  for k = 0, 5 do hex[#hex + 1] = {2 * math.cos(math.rad(60 * k)), "
         "2 * math.sin(math.rad(60 * k))} end\n"
         "  local x, y = 3 * i, math.sqrt(3) * (2 * j + i % 2)\n"
         "  cells[#cells + 1] = " +
         cell + "\nend end\nreturn " + part;
}
const double kHoneycombVolume = 16.0 * 6.0 * std::sqrt(3.0) * 4.0;

TEST(ContactExport, AHoneycombOfCellsSideBySideIsOneShell) {
  // Welded in the plane, the region is one outline, and its sweep one
  // shell.
  exportsValid(honeycomb("polygon(hex):translate(x, y)",
                         "linear_extrude{union(table.unpack(cells)), height=4}"),
               kHoneycombVolume, 1e-6);
}

TEST(ContactExport, AHoneycombOfCellsExtrudedEachOnItsOwnIsOneShell) {
  // Each cell a linear_extrude of its own: the union in 3D left a crevice
  // where three cells meet (the check's fidelity failed); made as one
  // extrusion of their union, the walls they share are one.
  exportsValid(honeycomb("linear_extrude{polygon(hex), height=4}:translate(x, y, 0)",
                         "union(table.unpack(cells))"),
               kHoneycombVolume, 1e-6);
}

TEST(ContactExport, ALatticeOfBarsClippedToItsFrameIsOneExtrusion) {
  // A frame 40 × 40 × 3 (walls 4 wide) and two bars 2 wide and as thick
  // along its diagonals, clipped to its outline: every top and bottom face
  // coplanar. Area: the frame's, and in the opening two strips |x − y| ≤
  // √2 (the 32 × 32 square less two corner triangles of legs 32 − √2
  // each) less the square of side 2 where they cross.
  const double c = std::sqrt(2.0);
  exportsValid(
      "local frame = box{size = {40, 40, 3}} - box{size = {32, 32, 5}}:translate(4, 4, -1)\n"
      "local bar = box{size = {2, 80, 3}}:translate(-1, -40, 0)\n"
      "return frame + (bar:rotate(0, 0, 45) + bar:rotate(0, 0, -45)):translate(20, 20, 0) * "
      "box{size = {40, 40, 3}}",
      3.0 * (576.0 + 2.0 * (1024.0 - (32.0 - c) * (32.0 - c)) - 4.0), 1e-6);
  // A panel of 34 bars at ±45°: CGAL's booleans of the coplanar faces ran
  // past 180 s (export/prism_booleans.h).
  exportsValid(
      "local W, H, t = 80, 60, 3\n"
      "local frame = box{size = {W, H, t}} - box{size = {W - 8, H - 8, t + 2}}:translate(4, 4, "
      "-1)\n"
      "local bars = {}\n"
      "for i = -8, 8 do\n"
      "  for _, a in ipairs({45, -45}) do\n"
      "    bars[#bars + 1] = box{size = {2, 150, t}}:translate(-1, -75, 0):rotate(0, 0, a)"
      ":translate(i * 8, H / 2, 0)\n"
      "  end\n"
      "end\n"
      "return frame + union(bars) * box{size = {W, H, t}}",
      // More than the frame, less than the whole plate; the check compares
      // the mesh with the part point by point.
      3.0 * (80.0 * 60.0 + (80.0 * 60.0 - 72.0 * 52.0)) / 2.0, 3.0 * 72.0 * 52.0 / 2.0);
}

TEST(ContactExport, PixelsOfACodeOnTheirPlateAreOneExtrusion) {
  // A 16 × 16 code of unit pixels 1 high on a plate, listed in one union
  // with it, many of them corner to corner: the 3D booleans took seconds
  // (30 s at 50 × 50). The pixels are one extrusion, bridged where they
  // meet at a corner by a square a tenth of the tolerance wide, which adds
  // at most 10⁻⁶ each.
  const std::string source =
      "local parts, count = {}, 0\n"
      "for i = 0, 15 do for j = 0, 15 do\n"
      "  if (i * 7 + j * 5 + (i * j) % 3) % 4 < 2 then\n"
      "    parts[#parts + 1] = box{size = {1, 1, 1}}:translate(i, j, 0)\n"
      "  end\n"
      "end end\n"
      "parts[#parts + 1] = box{size = {16, 16, 2}}:translate(0, 0, -2)\n"
      "return union(parts)";
  int pixels = 0;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) pixels += (i * 7 + j * 5 + (i * j) % 3) % 4 < 2;
  MeshBooleanStats stats;
  const SolidPtr solid = part(source);
  const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, nullptr, &stats).mesh;
  EXPECT_EQ(stats.primitives, 2u);
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_NEAR(mesh.volume(), 512.0 + pixels, 256 * 1e-6);
  EXPECT_EQ(meshShells(mesh).count, 1u);
  EXPECT_TRUE(test::checksOut(*solid, kTolerance));
}

TEST(ContactExport, AThreadClippedFlushWithItsEndStaysOnItsPlate) {
  // A twisted square prism clipped by a box flush with its foot, standing
  // on a plate, or flush with its top, under a plate: the clip's faces lie
  // in the prism's, the intersection in doubles is made with the clip
  // moved, and a clip shrunk moved the end off the plate by 10⁻⁴ (two
  // shells). Volumes: the plate 200, the prism's square 16 (a twist keeps
  // its area) 8 high.
  const std::string thread =
      "local t = linear_extrude{square{size = 4, center = true}, height = 10, twist = 10}\n";
  for (const char* part : {"return box{size = {10, 10, 2}}:translate(-5, -5, -2) + "
                           "t * box{size = {8, 8, 8}}:translate(-4, -4, 0)",
                           "return box{size = {10, 10, 2}}:translate(-5, -5, 10) + "
                           "t * box{size = {8, 8, 8}}:translate(-4, -4, 2)"}) {
    const TriangleMesh mesh = exportsValid(thread + part, 328.0, kTolerance * 440.0);
    EXPECT_EQ(meshShells(mesh).count, 1u);
  }
}

TEST(ContactExport, WedgesAboutOneEdgeKeepTheirVolume) {
  // Eight wedges of 22.5° every 45°, each a linear_extrude of its own,
  // meet only along the axis. CGAL's repair of the crossings the contacts
  // left there dropped seven of them in one order of the union, and the
  // mesh, one wedge, was valid; such a repair is refused, and another
  // order makes the part whole. Volume: 8 · ½ · 10² · sin 22.5° · 2.
  exportsValid(
      "local parts = {}\n"
      "for i = 0, 7 do\n"
      "  local a, b = math.rad(45 * i), math.rad(45 * i + 22.5)\n"
      "  parts[#parts + 1] = linear_extrude{polygon({{0, 0}, {10 * math.cos(a), 10 * "
      "math.sin(a)}, {10 * math.cos(b), 10 * math.sin(b)}}), height = 2}\n"
      "end\n"
      "return union(table.unpack(parts))",
      8.0 * 100.0 * std::sin(kPi / 8.0), 1.0);
}

TEST(ContactExport, AHoleTangentToTheOutlineIsSweptApart) {
  // The plate's region touches itself where each hole meets the rim: its
  // sweep's mesh is no 2-manifold there, and the last try sweeps the
  // region's operands apart (a disc less two discs), which the booleans
  // resolve. Volume: 3π(20² − 2·2²).
  exportsValid(
      "return linear_extrude{circle(20) - circle(2):translate(18, 0) - "
      "circle(2):translate(-18, 0), height = 3}",
      3.0 * kPi * (400.0 - 8.0), 6.0);
}

TEST(ContactExport, PrismsCornerToCornerAreOpenedThere) {
  // Two squares' prisms that meet along one edge only: the union in 3D
  // fails there, and the last try sweeps their union opened at the corner
  // by a hundredth of the tolerance. Volume: 2 · 5² · 3.
  exportsValid(
      "return linear_extrude{square(5), height = 3} + "
      "linear_extrude{square(5):translate(5, 5), height = 3}",
      150.0, 0.05);
}

TEST(ContactExport, ABowtieBesideABoxTouchingItsCornersIsOpenedThere) {
  // A polygon through (2, 2) twice (two triangles corner to corner) swept,
  // beside a box that its two other corners touch: CGAL's corefinement,
  // given the pinched sweep, ran without end. The sweep is refused before
  // any boolean, and the last try opens it at the pinch. Volume: the two
  // triangles (4 each) and the box (16), 2 high.
  exportsValid(
      "return linear_extrude{polygon({{0, 0}, {4, 0}, {2, 2}, {4, 4}, {0, 4}, {2, 2}}), "
      "height = 2} + box{size = {4, 4, 2}}:translate(4, 0, 0)",
      48.0, 0.05);
}

TEST(ContactExport, OctahedraSharingAnEdgeAreJoinedAlongIt) {
  // Both grown by a hundredth of the tolerance, each octahedron's corner
  // at an end of the shared edge lay on the other's grown face, and the
  // file's floats put two vertices in one place there: the export failed.
  // Now one grows alone. Volume: two octahedra of r = 1, 4/3 each, and
  // the bridge.
  for (const char* source : {"return octahedron{r=1} + octahedron{r=1}:translate(1, 1, 0)",
                             "return octahedron{r=1} + octahedron{r=1}:translate(1, 0, 1)"}) {
    SCOPED_TRACE(source);
    const SolidPtr solid = part(source);
    const TriangleMesh mesh =
        meshOfSolid(*solid, kTolerance, storedCoordinate(MeshFormat::Stl, false)).mesh;
    EXPECT_EQ(meshDefect(mesh).text, "");
    EXPECT_EQ(meshShells(mesh).count, 1u);
    EXPECT_NEAR(mesh.volume(), 8.0 / 3.0, 0.01 * kTolerance * mesh.area() * 2);
    EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  }
}

TEST(ContactExport, ACheckerboardOfBoxesTouchingAlongEdges) {
  // Four boxes, every pair touching along an edge: the volume is the
  // boxes', plus the bridges (each union's operands grow by a hundredth
  // of the tolerance, at most twice here, over 600 of area).
  exportsValid(
      "return union(box(5), box(5):translate(5, 5, 0), box(5):translate(5, 0, 5), "
      "box(5):translate(0, 5, 5))",
      500.0, 3 * 0.01 * kTolerance * 600.0);
}

// ---- Concentric and tangent ---------------------------------------------------

TEST(ContactExport, ConcentricSpheresMakeAShell) {
  const double exact = 4.0 / 3.0 * kPi * (125.0 - 27.0);
  exportsValid("return sphere(5) - sphere(3)", exact, kTolerance * 4 * kPi * (25.0 + 9.0));
}

TEST(ContactExport, SpheresTangentAtAPoint) {
  const double exact = 2 * 4.0 / 3.0 * kPi * 125.0;
  exportsValid("return sphere(5) + sphere(5):translate(10, 0, 0)", exact,
               kTolerance * 2 * 4 * kPi * 25.0);
}

TEST(ContactExport, ASphereTangentToAPlane) {
  const double exact = 4.0 / 3.0 * kPi * 125.0 + 20 * 20 * 2;
  exportsValid(
      "return sphere(5):translate(0, 0, 5) + box{size={20, 20, 2}}:translate(-10, -10, -2)", exact,
      kTolerance * (4 * kPi * 25.0 + 2 * 400 + 160));
}

TEST(ContactExport, ATorusTangentToACylinder) {
  // The torus's inner equator (radius 12 − 2) lies on the cylinder's side:
  // the meshes fill the wedge between them as far as its sides are two
  // tolerances apart, which the check allows (docs/check.md, "Fidelity").
  // Volume: the cylinder's, and the torus's 2π²Rr².
  const double exact = kPi * 100 * 20 + 2 * kPi * kPi * 12 * 4;
  exportsValid("return cylinder{r=10, h=20} + torus{R=12, r=2}:translate(0, 0, 10)", exact,
               kTolerance * (2 * kPi * 10 * 20 + 2 * kPi * 100 + 4 * kPi * kPi * 12 * 2));
}

TEST(ContactExport, ABallInTheRodThatCutsItIsTakenWhole) {
  // A ball of radius 1 inside a rod of radius 1 that is cut away, tangent
  // to its side and caps: both meshes straddle their surfaces, so the
  // ball's vertices stand out of the rod's chords and the cut leaves
  // slivers of it, which the exact part does not hold and the export
  // removes. A plate 6 × 6 × 2 with the rod's hole: 72 − 2π.
  const std::string source =
      "return (box{size={6, 6, 2}}:translate(-3, -3, -1) + sphere(1))\n"
      "  - cylinder{r=1, h=2}:translate(0, 0, -1)";
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*part(source), kTolerance, nullptr, &stats).mesh;
  EXPECT_GE(stats.strayShells, 1u);
  EXPECT_EQ(meshShells(mesh).count, 1u);
  exportsValid(source, 72 - 2 * kPi, kTolerance * (2 * 36 + 4 * 12 + 2 * kPi * 2));
}

// The highest (or, with -1, lowest) coordinate of the mesh along axis.
double extreme(const TriangleMesh& mesh, int axis, double sign) {
  double most = -kInfinity;
  for (const dvec3& p : mesh.points) most = std::max(most, sign * p[axis]);
  return sign * most;
}

TEST(ContactExport, ABoxAsWideAsTheCylinderItHalvesLeavesNoFins) {
  // The box's sides touch the cylinder along four lines above z = 5; the
  // cylinder's mesh, whose points lie outside the circle, pokes past them,
  // and the cut kept those slivers as fins up to the top (z = 10), which
  // failed the check. The grazed sides are moved clear: the half cylinder,
  // nothing above z = 5. Also with the box taller than the cylinder, and
  // turned so that its sides touch between the mesh's points.
  const double exact = kPi * 25 * 5;
  const double slack = kTolerance * (2 * kPi * 5 * 5 + 2 * kPi * 25);
  for (const char* cutter :
       {"box{size={10, 10, 5}}:translate(-5, -5, 5)", "box{size={10, 10, 6}}:translate(-5, -5, 5)",
        "box{size={10, 10, 5}}:translate(-5, -5, 5):rotate(0, 0, 17)"}) {
    const std::string source = std::string("return cylinder{r=5, h=10} - ") + cutter;
    MeshBooleanStats stats;
    const TriangleMesh mesh = meshOfSolid(*part(source), kTolerance, nullptr, &stats).mesh;
    EXPECT_EQ(stats.grazes, 1u) << cutter;
    EXPECT_LE(extreme(mesh, 2, 1.0), 5.0) << cutter;
    exportsValid(source, exact, slack);
  }
}

TEST(ContactExport, AFlatFaceNearACuttersSideIsTheModelsNotAGraze) {
  // A pocket cut 10⁻³ short of the top (an epsilon with the wrong sign)
  // leaves a skin that thin over a closed cavity, and a box less itself
  // moved by 10⁻³ leaves a slab that thin. Both lie within the tolerance
  // past the cutter's side, as a curved part's mesh does where the side
  // only grazes it, and the side was moved out past them: the cavity
  // became a through hole, and the slab nothing ("the part is empty").
  // The exact part holds them, so the side stays.
  struct Case {
    const char* source;
    double volume;
    std::size_t shells;
  };
  for (const Case& c : {Case{"return box(10) - box{size={4, 4, 10 - 2e-3}}:translate(3, 3, 1e-3)",
                             1000.0 - 16.0 * (10.0 - 2e-3), 2u},
                        Case{"return box(10) - box(10):translate(1e-3, 0, 0)", 0.1, 1u}}) {
    SCOPED_TRACE(c.source);
    MeshBooleanStats stats;
    const TriangleMesh mesh = meshOfSolid(*part(c.source), kTolerance, nullptr, &stats).mesh;
    EXPECT_EQ(stats.grazes, 0u);
    EXPECT_EQ(meshDefect(mesh).text, "");
    EXPECT_EQ(meshShells(mesh).count, c.shells);
    EXPECT_NEAR(mesh.volume(), c.volume, 1e-9);
    EXPECT_TRUE(test::checksOut(*part(c.source), kTolerance));
  }
}

TEST(ContactExport, ASweptCircleMeetsACylinderOfItsRadiusOnItsPoints) {
  // A sweep flattened its circles by a rule of its own, and a cylinder of
  // the same radius beside it (a ring around a boss, a pin through a
  // swept plate's hole) left crevices between the two polygons, 0.005
  // wide and as deep as the sweep, which failed the check. Swept circles
  // now take the cylinder's rim polygon: also where the ring's arcs end in
  // corners (half a ring), where a step falls between them (turned 1°), and
  // off the origin.
  const double pi = kPi;
  struct Part {
    const char* source;
    double volume, area;
  };
  const Part parts[] = {
      {"local ring = circle(5):offset{r=2} - circle(5)\n"
       "return cylinder{r=5, h=5} + linear_extrude{ring, height=3}",
       125 * pi + 72 * pi, 2 * 25 * pi + 10 * pi * 5 + 2 * 24 * pi + 14 * pi * 3},
      {"local ring = circle(10):translate(3, 4) - circle(5):translate(3, 4)\n"
       "return cylinder{r=5, h=5}:translate(3, 4, 0) + linear_extrude{ring, height=3}",
       125 * pi + 225 * pi, 2 * 100 * pi + 20 * pi * 3 + 10 * pi * 2},
      {"local ring = (circle(8) - circle(5)) * square{size={20, 20}}:translate(-10, 0)\n"
       "return cylinder{r=5, h=6} + linear_extrude{ring, height=3}",
       150 * pi + 58.5 * pi, 2 * 25 * pi + 10 * pi * 6 + 39 * pi + 8 * pi * 3 + 18},
      {"local ring = (circle(8) - circle(5)) * square{size={20, 20}}:translate(-10, 0)\n"
       "return cylinder{r=5, h=6} + linear_extrude{ring:rotate(1), height=3}",
       150 * pi + 58.5 * pi, 2 * 25 * pi + 10 * pi * 6 + 39 * pi + 8 * pi * 3 + 18},
      {"local plate = linear_extrude{square{size={30, 30}, center=true} - circle(4), height=2}\n"
       "return plate + cylinder{r=4, h=10}:translate(0, 0, -4)",
       1800 + 128 * pi, 2 * 900 + 4 * 60 + 8 * pi * 8 + 2 * 16 * pi},
  };
  for (const Part& part : parts) exportsValid(part.source, part.volume, kTolerance * part.area);
}

TEST(ContactExport, PinsOnABoltCircleMeetTheirSweptHolesOnTheirPoints) {
  // Pins turned about their axes onto a bolt circle, each through a round
  // hole of a swept plate: a turned cylinder's rim was not the sweep's, and
  // the crevices between the two polygons failed the check (1 deep). Now
  // the sweep cuts a turned rim's points too, and walls a hair apart (each
  // placed by its own frame: the plate moved, the part turned as a whole)
  // are made flush. Volumes: the plate less its holes, and the pins. Pins
  // and plates mirrored so too.
  const double pi = kPi;
  auto boltCircle = [](int count, double r, double at, const char* placed) {
    return "local holes, pins = {}, {}\n"
           "for i = 0, " +
           std::to_string(count - 1) +
           " do\n"
           "  local turn = i * 360 / " +
           std::to_string(count) +
           "\n"
           "  holes[#holes + 1] = circle(" +
           std::to_string(r) + "):translate(" + std::to_string(at) +
           ", 0):rotate(turn)\n"
           "  pins[#pins + 1] = cylinder{r=" +
           std::to_string(r) + ", h=12}:translate(" + std::to_string(at) +
           ", 0, -3):rotate(0, 0, turn)\n"
           "end\n"
           "local plate = linear_extrude{circle(30) - union(table.unpack(holes)), height=5}\n"
           "return (plate" +
           placed + ") + (union(table.unpack(pins))" + placed + ")";
  };
  struct Part {
    int count;
    double r;
    const char* placed;
  };
  for (const Part& part : {Part{6, 3.0, ""}, Part{7, 3.0, ""}, Part{6, 2.5, ":translate(3, 4, 1)"},
                           Part{7, 3.0, ":rotate(30, 20, 10)"}}) {
    const double holes = part.count * part.r * part.r * pi;
    const double volume = (900.0 * pi - holes) * 5.0 + holes * 12.0;
    const double area = 2.0 * (900.0 * pi - holes) + 300.0 * pi +
                        part.count * (2.0 * pi * part.r * 7.0 + 2.0 * part.r * part.r * pi);
    exportsValid(boltCircle(part.count, part.r, 20.0, part.placed), volume, kTolerance * area);
  }
  // A pin mirrored onto the other side, and a plate mirrored upside down.
  exportsValid(
      "local plate = square{size={40, 20}, center=true} - circle(2):translate(-14, 0) - "
      "circle(2):translate(14, 0)\n"
      "local pin = cylinder{r=2, h=10}:translate(14, 0, -3)\n"
      "return linear_extrude{plate, height=4} + pin + pin:mirror(1, 0, 0)",
      3200.0 + 48.0 * pi, kTolerance * (2080.0 + 64.0 * pi));
  exportsValid(
      "local plate, pins = circle(20), {}\n"
      "for i = 0, 5 do\n"
      "  plate = plate - circle(2):translate(14, 0):rotate(i * 60 + 10)\n"
      "  pins[#pins + 1] = cylinder{r=2, h=8}:translate(14, 0, -3):rotate(0, 0, i * 60 + 10)\n"
      "end\n"
      "return linear_extrude{plate, height=3}:mirror(0, 0, 1):translate(0, 0, 3) + "
      "union(table.unpack(pins))",
      1320.0 * pi, kTolerance * 1040.0 * pi);
}

TEST(ContactExport, PinsInHolesNearerThanTheToleranceMeetTheirWalls) {
  // Two holes 0.005 apart, each with its pin: the holes' rim polygons,
  // which lie partly outside their circles, crossed there, and the sweep
  // took inscribed polygons instead, which left crevices between the pins
  // and the walls (the check found the mesh 1 off the part). The crossing
  // polygons are filled as they wind, and the holes keep the pins'
  // polygons. Volume: the plate and the pins' 5 outside it.
  exportsValid(
      "local prof = square{size={30, 16}}\nlocal pins = {}\n"
      "for _, x in ipairs({10, 14.005}) do\n"
      "  prof = prof - circle(2):translate(x, 8)\n"
      "  pins[#pins + 1] = cylinder{r=2, h=8}:translate(x, 8, -2)\n"
      "end\n"
      "return linear_extrude{prof, height=3} + union(pins)",
      30 * 16 * 3 + 2 * kPi * 4 * 5, kTolerance * 1500.0);
}

TEST(ContactExport, APinThroughTheBoreOfAnImportedTubeMeetsItsWall) {
  // A tube exported to STL and read back, with a pin of its bore's radius
  // through it: the bore's points are the file's floats, half a float's
  // step off the pin's polygon, and the walls crossed at a sliver's angle
  // (the export failed, "self-intersecting"). Walls that near are made
  // flush when a mesh's points are all floats. Volume: the tube and the
  // pin, which has nothing in common with it.
  const std::filesystem::path folder = csgray::test::scratchPathFor("csgray_contact_test_");
  std::filesystem::create_directories(folder);
  const std::string tube = (folder / "tube.stl").string();
  writeMeshFile(tube,
                meshOfSolid(*part("return cylinder{r=5, h=4} - "
                                  "cylinder{r=3, h=6}:translate(0, 0, -1)"),
                            kTolerance, storedCoordinate(MeshFormat::Stl, false)),
                false);
  ScriptOptions options = test::exampleOptions();
  options.folder = folder.string();
  const Scene scene =
      runScript("return mesh{file=\"tube.stl\"} + cylinder{r=3, h=6}:translate(0, 0, -1)",
                "part.lua", options);
  const TriangleMesh mesh =
      meshOfSolid(*scene.objects[0], kTolerance, storedCoordinate(MeshFormat::Stl, false)).mesh;
  std::filesystem::remove_all(folder);
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_EQ(meshShells(mesh).count, 1u);
  EXPECT_NEAR(mesh.volume(), kPi * (25 - 9) * 4 + kPi * 9 * 6, kTolerance * 400.0);
}

TEST(ContactExport, CuttersOfOneRadiusCrossingEachOtherAreCut) {
  // A diamond knurl's cutters: three cylinders of one radius, each axis
  // meeting the next one's inside the block. Their surfaces are tangent
  // where they cross, and the export failed as self-intersecting after
  // 80 s; the next two of a knurl took minutes. Every second one is now
  // made a thousandth of the tolerance wider (export/widened_cutters.h).
  const char* knurl =
      "local c = cylinder{r=0.7, h=40, center=true}\n"
      "local part = box{size={40, 40, 18}}:translate(-5, -20, 0)\n"
      "part = part - c:rotate(-30, 0, 0):translate(15, 0, 9)\n"
      "part = part - c:rotate(30, 0, 0):translate(15, 0, 9):rotate(0, 0, 15)\n"
      "part = part - c:rotate(-30, 0, 0):translate(15, 0, 9):rotate(0, 0, 30)\n";
  for (const std::string placed : {"return part", "return part:rotate(10, 20, 30)"}) {
    SCOPED_TRACE(placed);
    const SolidPtr solid = part(knurl + placed);
    const std::optional<TriangleMesh> mesh = exported(*solid);
    if (!mesh) continue;
    EXPECT_EQ(meshDefect(*mesh).text, "");
    EXPECT_EQ(meshShells(*mesh).count, 1u);
    EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  }
  // Two bores of one drill crossing square in a block: the block less
  // both, plus their Steinmetz solid of 16 r³ / 3 counted once.
  exportsValid(
      "local bore = cylinder{r=2, h=30, center=true}\n"
      "return box(20) - bore:rotate(0, 90, 0):translate(10, 10, 10)"
      " - bore:rotate(90, 0, 0):translate(10, 10, 10)",
      8000.0 - 2.0 * kPi * 4.0 * 20.0 + 16.0 * 8.0 / 3.0,
      kTolerance * 2.0 * (2400.0 + 4 * kPi * 20));
}

TEST(ContactExport, AnAxleInATurnedRingsBoreMeetsItOnItsPoints) {
  // A ring turned by rotate_extrude around an axle of its bore: the
  // ring's regular polygons and the axle's own polygon left crevices 1
  // deep. The axle now takes the ring's polygons, also turned about its
  // axis and with the whole part turned and moved. Volumes by Pappus.
  const double pi = kPi;
  exportsValid(
      "return rotate_extrude{square{size={10, 5}}:translate(6, 0)} + "
      "cylinder{r=6, h=15}:translate(0, 0, -5)",
      1640.0 * pi, kTolerance * 792.0 * pi);
  const char* wheel =
      "local wheel = rotate_extrude{square{size={14, 6}}:translate(6, 0) - "
      "circle(1.5):translate(16, 3)}\n"
      "local axle = cylinder{r=6, h=20}:translate(0, 0, -7):rotate(0, 0, 23)\n";
  for (const char* placed : {"", ":rotate(10, 20, 30):translate(1.1, 2.3, 0.7)"})
    exportsValid(std::string(wheel) + "return (wheel + axle)" + placed,
                 2904.0 * pi - 72.0 * pi * pi, kTolerance * (1208.0 * pi + 96.0 * pi * pi));
}

TEST(ContactExport, AnAxleInATurnedSectorsBoreMeetsItOnItsPoints) {
  // A sector turned through a share of a whole turn (270°, 90°, 100°)
  // around an axle of its inner radius: the axle kept its own polygon and
  // left crevices 1 deep. The sector's steps are now a multiple of the
  // share's numerator, those of a whole turn, whose polygon the axle
  // takes. Volume: the sector's share of the ring, and the axle.
  for (double degrees : {270.0, 90.0, 100.0}) {
    SCOPED_TRACE(degrees);
    const std::string source =
        "return rotate_extrude{polygon{{10, 0}, {20, 0}, {20, 5}, {10, "
        "5}}, angle = " +
        std::to_string(degrees) + "} + cylinder{r = 10, h = 5}";
    const double share = degrees / 360.0;
    exportsValid(source, 5 * kPi * (300 * share + 100),
                 kTolerance * (2 * kPi * (300 * share + 100) + 2 * kPi * 20 * 5 + 200));
  }
  // An angle too small to be such a share (it rounds to none of 360°)
  // keeps its own steps. Pappus: the square's area times its centre's path.
  const TriangleMesh tiny =
      meshOfSolid(*part("return rotate_extrude{polygon{{10, 0}, {20, 0}, {20, 5}, {10, 5}}, "
                        "angle = 1e-8}"),
                  kTolerance)
          .mesh;
  EXPECT_NEAR(tiny.volume(), 50.0 * 15.0 * 1e-8 * kPi / 180.0, 1e-12);
}

TEST(ContactExport, APipesStraightLegsMeetItsBendOnItsPoints) {
  // A bend of a rod (a circle turned through an angle) with a straight
  // leg of its radius on each end face: on an end face that lies in no
  // plane of the axes, the leg's own polygon and the bend's crossed a
  // hair apart, and the union was refused as self-intersecting after
  // half a minute (at 10° to 170°, all but 45°, 90° and 135°). A leg now
  // takes the bend's polygon of that circle and is glued to the bend
  // there; a flange across the leg then crosses plain walls, where it
  // met slivers of a corefinement before. Volume by Pappus: the
  // circle's area times its centre's path, and the legs.
  const double R = 30.0, r = 4.0, L = 12.0;
  auto elbow = [&](double degrees, double radius, double length) {
    const std::string a = std::to_string(degrees), rr = std::to_string(radius),
                      h = std::to_string(length);
    return "rotate_extrude{circle{r=" + rr + "}:translate(30, 0), angle=" + a + "}" +
           " + cylinder{r=" + rr + ", h=" + h + "}:rotate(90, 0, 0):translate(30, 0, 0)" +
           " + cylinder{r=" + rr + ", h=" + h + "}:rotate(-90, 0, 0):translate(30, 0, 0)" +
           ":rotate(0, 0, " + a + ")";
  };
  auto path = [&](double degrees) { return R * degrees * kPi / 180.0 + 2.0 * L; };
  for (double degrees : {30.0, 120.0, 157.5}) {
    SCOPED_TRACE(degrees);
    const double area = 2.0 * kPi * r * path(degrees) + 2.0 * kPi * r * r;
    exportsValid("return " + elbow(degrees, r, L), kPi * r * r * path(degrees), kTolerance * area);
  }
  // Turned and moved as a whole.
  exportsValid("return (" + elbow(70.0, r, L) + "):rotate(20, 30, 10):translate(5, 6, 7)",
               kPi * r * r * path(70.0), kTolerance * 2.0 * kPi * r * (path(70.0) + r));
  // A flange on the end of the slanted leg, placed as the leg is: its
  // faces cross the leg's walls, and its outer face is flush with the
  // leg's end.
  const double flange = 8.0, thick = 3.0;
  exportsValid("return " + elbow(50.0, r, L) + " + cylinder{r=" + std::to_string(flange) +
                   ", h=" + std::to_string(thick) + "}:rotate(-90, 0, 0):translate(30, " +
                   std::to_string(L - thick) + ", 0):rotate(0, 0, 50)",
               kPi * r * r * path(50.0) + kPi * (flange * flange - r * r) * thick,
               kTolerance * 2.0 * kPi * (r * path(50.0) + flange * (flange + thick)));
  // Hollow, as OpenSCAD users write it: the rod less a thinner rod whose
  // legs reach past the ends (a cylinder that cuts takes the polygon too).
  const double inner = 3.0;
  exportsValid("return (" + elbow(65.0, r, L) + ") - (" + elbow(65.0, inner, L + 1.0) + ")",
               kPi * (r * r - inner * inner) * path(65.0),
               kTolerance * 2.0 * kPi * (r + inner) * (path(65.0) + r));
}

TEST(ContactExport, SlantedTubesWithBoresFlushWithTheirEnds) {
  // A tube turned by 30° with a bore of its own length, beside a box that
  // comes first (so the part is not cut in the tube's frame): the bore's
  // ends and the tube's lie in one slanted plane only to rounding, and the
  // difference was refused as self-intersecting. The bore is now made a
  // tenth of the tolerance longer past each end. Volume: the ring's area
  // times the length, and the box.
  exportsValid(
      "return box(1):translate(0, -30, 0) + (cylinder{r=8, h=32}:rotate(30, 0, 0) - "
      "cylinder{r=6.5, h=32}:rotate(30, 0, 0))",
      1.0 + kPi * (64.0 - 42.25) * 32.0, kTolerance * 2.0 * kPi * (8.0 + 6.5) * (32.0 + 8.0));
  // A hollow elbow whose bore's legs end flush with the rod's (a Y or an
  // elbow cut so by OpenSCAD's users crashed CGAL or was refused).
  const double R = 25.0, ro = 7.0, ri = 5.5, leg = 15.0, path = R * 2.0 * kPi / 3.0 + 2.0 * leg;
  const std::string rod =
      "local function rod(r)\n"
      "  return rotate_extrude{circle{r=r}:translate(25, 0), angle=120}\n"
      "    + cylinder{r=r, h=15}:rotate(90, 0, 0):translate(25, 0, 0)\n"
      "    + cylinder{r=r, h=15}:rotate(-90, 0, 0):translate(25, 0, 0):rotate(0, 0, 120)\n"
      "end\n";
  exportsValid(rod + "return rod(7) - rod(5.5)", kPi * (ro * ro - ri * ri) * path,
               kTolerance * 2.0 * kPi * (ro + ri) * (path + ro));
  // A pin put back through a slanted bore of its radius in a block: the
  // bore's ends lie outside the block and it is not made longer (a first
  // version did, and the pin no longer met the bore's wall). Volume: the
  // block, and the pin outside the slab |z| <= 10, which it crosses over
  // 20 / cos of its tilt (cos 30° · cos 20°).
  const double slab = 20.0 / (std::cos(kPi / 6.0) * std::cos(kPi / 9.0));
  exportsValid(
      "local bore = cylinder{r=3, h=40, center=true}:rotate(30, 20, 0)\n"
      "return box{size={30, 30, 20}, center=true} - bore + bore",
      18000.0 + kPi * 9.0 * (40.0 - slab), kTolerance * (2.0 * 3300.0 + 2.0 * kPi * 3.0 * 40.0));
  // A hollow bend of 60°, a turn less a thinner turn of the same angle:
  // the thinner one now goes on past both end faces.
  const double bend = R * kPi / 3.0;
  exportsValid(
      "return rotate_extrude{circle{r=7}:translate(25, 0), angle=60} - "
      "rotate_extrude{circle{r=5.5}:translate(25, 0), angle=60}",
      kPi * (ro * ro - ri * ri) * bend, kTolerance * 2.0 * kPi * (ro + ri) * (bend + ro));
}

TEST(ContactExport, ABlockStandingOnAPlateCutFromARoundedBox) {
  // A plate cut from a rounded box by a box that shares its sides (the
  // intersection shrinks the box off them, by a hundredth of the
  // tolerance, the plate's top with it), and a block standing on its top
  // (embossed letters, on a name plate): the block's box no longer met the
  // plate's, the two were joined without a union, and the mesh fell into
  // two shells. Volume: half the rounded box (a − 2r)(b − 2r)(c − 2r) +
  // 2r·Σ(faces) + πr²·Σ(edges) + 4πr³/3, and the block.
  const double a = 80.0, b = 25.0, c = 6.0, r = 2.0;
  const double A = a - 2 * r, B = b - 2 * r, C = c - 2 * r;
  const double rounded = A * B * C + 2 * r * (A * B + A * C + B * C) + kPi * r * r * (A + B + C) +
                         4.0 / 3.0 * kPi * r * r * r;
  const TriangleMesh mesh = exportsValid(
      "return rounded_box{size={80, 25, 6}, r=2} * box{size={80, 25, 3}} + "
      "box{size={10, 10, 1.5}}:translate(30, 5, 3)",
      rounded / 2.0 + 150.0, kTolerance * 2.0 * (a * b + (a + b) * c));
  EXPECT_EQ(meshShells(mesh).count, 1u);
}

TEST(ContactExport, ARoundedPlateLessItsCornersCirclesIsSwept) {
  // offset{r=5} of a rectangle less circle(5) about each corner: the
  // region's arcs were a hair off the circles, and the sweep failed as
  // "its tessellation is not a 2-manifold". Its sides touch the circles
  // tangentially, so the plate is a hair thin at eight points.
  exportsValid(
      "local plate = square{size={40, 30}}:offset{r=5}\n"
      "for _, p in ipairs({{0, 0}, {40, 0}, {0, 30}, {40, 30}}) do\n"
      "  plate = plate - circle(5):translate(p[1], p[2])\n"
      "end\n"
      "return linear_extrude{plate, height=3}",
      3.0 * (1900.0 - 75.0 * kPi), kTolerance * (2.0 * 1700.0 + 3.0 * 300.0));
  // With cylinders standing in those notches, whose circles the sweep then
  // cuts on the cylinders' polygons: the polygon's points pushed out of the
  // circle crossed the side that runs into it tangentially, and the sweep
  // fell back to inscribed polygons that left crevices round the cylinders.
  exportsValid(
      "local plate = square{size={40, 30}}:offset{r=5}\n"
      "for _, p in ipairs({{0, 0}, {40, 0}, {0, 30}, {40, 30}}) do\n"
      "  plate = plate - circle(5):translate(p[1], p[2])\n"
      "end\n"
      "return linear_extrude{plate, height=3} + cylinder{r=5, h=6} + "
      "cylinder{r=5, h=6}:translate(40, 30, 0)",
      3.0 * (1900.0 - 75.0 * kPi) + 12.0 * 25.0 * kPi,
      kTolerance * (2.0 * 1700.0 + 3.0 * 300.0 + 2.0 * 250.0));
  exportsValid(
      "return linear_extrude{square{size={40, 30}}:offset{r=5} - circle(5), height=3} + "
      "cylinder{r=5, h=6}",
      5700.0 + 150.0 * kPi, kTolerance * (2.0 * 1900.0 + 3.0 * 300.0 + 250.0));
  // Where the side leaves the arc along its tangent (a rounded corner over a
  // cylinder), the turn point stays: without it the chord to the corner
  // sagged past the tolerance.
  exportsValid(
      "return linear_extrude{square{size={20, 20}}:offset{r=3}, height=3} + "
      "cylinder{r=3, h=6}:translate(0, 0, -6) + cylinder{r=3, h=6}:translate(20, 20, -6)",
      1920.0 + 135.0 * kPi, kTolerance * (2.0 * 670.0 + 3.0 * 100.0 + 250.0));
}

TEST(ContactExport, ARibTangentInsideASweptRingLeavesNoGap) {
  // A rib standing in a ring with its end on the inner circle: the ring's
  // inscribed polygon lies inside the circle, so the rib's end overlaps it
  // everywhere. A cylinder's rim polygon, outside the circle at its
  // points, left a gap along the end as deep as the ring, which is why a
  // sweep takes that polygon only where a cylinder stands on the circle.
  // The rib reaches x²/30 into the ring across its width of 2 (4 × 2/90).
  const double pi = kPi;
  exportsValid(
      "return linear_extrude{circle(20) - circle(15), height=4} + "
      "box{size={2, 10, 8}}:translate(-1, 5, 0)",
      pi * 175 * 4 + 160 - 4.0 * 2.0 / 90.0, kTolerance * (2 * 175 * pi + 140 * pi + 232));
}

// How many of the mesh's triangles the vertical line through p meets above
// height z: p inside a triangle's shadow on the xy plane by the signs of
// the three edge functions, at the height of the plane through it.
int facesAbove(const TriangleMesh& mesh, const dvec2& p, double z) {
  int count = 0;
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    auto edge = [&](const dvec3& u, const dvec3& v) {
      return (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
    };
    const double wa = edge(b, c), wb = edge(c, a), wc = edge(a, b), sum = wa + wb + wc;
    const bool within = (wa >= 0 && wb >= 0 && wc >= 0) || (wa <= 0 && wb <= 0 && wc <= 0);
    if (within && sum != 0.0 && (wa * a.z + wb * b.z + wc * c.z) / sum > z) ++count;
  }
  return count;
}

TEST(ContactExport, APocketCutFromARodsTangentPlaneByAnExtrusionLeavesNoSkin) {
  // OpenSCAD's translate([0, 0, R - d]) linear_extrude(d): a pocket whose
  // top is the plane tangent to a rod (r = 10, along x) at its highest
  // line. The rod's mesh reaches a little past that plane, and the cut
  // left a skin of it over the pocket, which failed the check; a box
  // there did not. A convex polygon's extrusion and an L's (the letters
  // of an engraving) now have the top moved clear as a box's side is.
  // Removed: ∫∫ (√(100 − y²) − 8) dx dy over the region placed at
  // (4, −2); G is the integral in y (a circle's area under a chord).
  auto g = [](double y) {
    return (y * std::sqrt(100.0 - y * y) + 100.0 * std::asin(y / 10.0)) / 2.0 - 8.0 * y;
  };
  struct Case {
    const char* region;
    double removed;
    dvec2 inside;  // a point of the region, placed
  };
  const Case cases[] = {
      {"square(4)", 4.0 * (g(2) - g(-2)), {6.0, 0.1}},
      {"polygon{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}}",
       4.0 * (g(-1) - g(-2)) + 1.0 * (g(2) - g(-1)),
       {4.5, 0.1}},
  };
  for (const Case& c : cases) {
    const std::string source = std::string("return cylinder{r=10, h=12}:rotate(0, 90, 0) - ") +
                               "linear_extrude{" + c.region + ", height=2}:translate(4, -2, 8)";
    MeshBooleanStats stats;
    const TriangleMesh mesh = meshOfSolid(*part(source), kTolerance, nullptr, &stats).mesh;
    EXPECT_EQ(stats.grazes, 1u) << source;
    // Nothing over the pocket's floor (z = 8) where the rod was highest.
    EXPECT_EQ(facesAbove(mesh, c.inside, 8.0 + 1e-9), 0) << source;
    exportsValid(source, kPi * 100.0 * 12.0 - c.removed,
                 kTolerance * (2 * kPi * 10 * 12 + 2 * kPi * 100));
  }
}

TEST(ContactExport, APocketTopJustInsideARodsTangentPlaneKeepsTheSkinOverIt) {
  // The same pockets with their top 0.002 inside the tangent plane: the
  // rod keeps a skin that thin over a strip of the pocket (0.4 wide), the
  // model's. The mesh's polygon bulges past the exact circle by more than
  // that, and the point halfway to its furthest point lay outside the rod,
  // so the top was moved through the skin (the check failed, a box's top
  // too). The face's own points under the bulge are asked as well.
  for (const char* cutter :
       {"box{4, 4, 2}", "linear_extrude{square(4), height=2}",
        "linear_extrude{polygon{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}}, height=2}"}) {
    const std::string source = std::string("return cylinder{r=10, h=12}:rotate(0, 90, 0) - ") +
                               cutter + ":translate(4, -2, 8 - 0.002)";
    MeshBooleanStats stats;
    const SolidPtr solid = part(source);
    meshOfSolid(*solid, kTolerance, nullptr, &stats);
    EXPECT_EQ(stats.grazes, 0u) << source;
    EXPECT_TRUE(test::checksOut(*solid, kTolerance)) << source;
  }
}

TEST(ContactExport, AHemisphereCutByABoxAsWideAsTheBall) {
  // The box's sides touch the ball's equator, and its bottom the south
  // pole: the ball's mesh, a little outside the sphere, kept slivers below
  // the equator there. Upper and lower halves, radius 1 and 5.
  for (const double r : {1.0, 5.0}) {
    for (const double sign : {1.0, -1.0}) {
      char source[200];
      std::snprintf(source, sizeof source,
                    "return sphere(%g) - box{size={%g, %g, %g}}:translate(%g, %g, %g)", r, 2 * r,
                    2 * r, r, -r, -r, sign > 0 ? -r : 0.0);
      MeshBooleanStats stats;
      const TriangleMesh mesh = meshOfSolid(*part(source), kTolerance, nullptr, &stats).mesh;
      EXPECT_EQ(stats.grazes, 1u) << source;
      // The half kept lies on its side of z = 0.
      EXPECT_GE(sign * extreme(mesh, 2, -sign), -1e-12) << source;
      exportsValid(source, 2.0 / 3.0 * kPi * r * r * r, kTolerance * 3 * kPi * r * r);
    }
  }
}

TEST(ContactExport, ABoxThatCutsIntoTheCylinderIsNotMoved) {
  // Sides 0.05 inside the cylinder, five tolerances: they cut it, and the
  // part keeps the two slivers of the circle they leave, up to the top.
  // Volume: the half cylinder and, above it, two circular segments of
  // height h = 0.05: r² acos((r − h)/r) − (r − h) √(2rh − h²) each.
  const double r = 5.0, h = 0.05;
  const double segment = r * r * std::acos((r - h) / r) - (r - h) * std::sqrt(2 * r * h - h * h);
  const std::string source =
      "return cylinder{r=5, h=10} - box{size={9.9, 10, 5}}:translate(-4.95, -5, 5)";
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*part(source), kTolerance, nullptr, &stats).mesh;
  EXPECT_EQ(stats.grazes, 1u);  // the sides at y = ±5 graze it
  EXPECT_EQ(extreme(mesh, 2, 1.0), 10.0);
  exportsValid(source, kPi * 25 * 5 + 2 * segment * 5,
               kTolerance * (2 * kPi * 5 * 10 + 2 * kPi * 25));
}

TEST(ContactExport, CrossingBoresAreCutAwayOneByOneInDoubles) {
  // Three equal tapered bores that cross at a ball's centre: their union
  // is not in general position (equal cones whose axes meet), too small
  // to be moved off, so CGAL unites them; the ball is then cut by each
  // bore in turn in doubles, rather than by that exact union in CGAL.
  // Valid, and in agreement with the model (volume, distance).
  const std::string source =
      "local bore = cylinder{r1=5, r2=2.5, h=30, center=true}\n"
      "return sphere(12) - bore - bore:rotate(90, 0, 0) - bore:rotate(0, 90, 0)";
  MeshBooleanStats stats;
  const SolidPtr solid = part(source);
  const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, nullptr, &stats).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  EXPECT_GE(stats.inDoubles, 3u);  // a cut for each bore
}

TEST(ContactExport, TheSamePartGivesTheSameMesh) {
  // examples/wall_hook.lua: its screw holes (a shank and a countersink,
  // united by CGAL) are cut in doubles, moved off the hook's faces.
  // CGAL's result came in an order that followed where its boxes lay in
  // memory, the moved holes followed that order, and the exported file
  // changed from run to run: the same part made again must give the same
  // mesh, point for point.
  const auto hook = [] {
    const Scene scene = runScriptFile(std::string(CSGRAY_SOURCE_DIR) + "/examples/wall_hook.lua",
                                      test::exampleOptions());
    return meshOfSolid(*unionOf(scene.objects), kTolerance).mesh;
  };
  const TriangleMesh first = hook();
  for (int again = 0; again < 4; ++again) {
    std::vector<std::unique_ptr<int>> clutter;  // the heap laid out otherwise
    for (int i = 0; i < 1000 * (again + 1); ++i) clutter.push_back(std::make_unique<int>(i));
    const TriangleMesh next = hook();
    ASSERT_EQ(next.points.size(), first.points.size());
    EXPECT_TRUE(next.points == first.points) << "try " << again;
    EXPECT_TRUE(next.triangles == first.triangles) << "try " << again;
  }
}

TEST(ContactExport, SeparatePiecesAndCavitiesAreKept) {
  // Two balls apart, thinner than the tolerance by the measure of a
  // sliver (volume under tolerance × area), so they are probed, and a box
  // with a ball's cavity: shells that the part does hold stay.
  MeshBooleanStats stats;
  TriangleMesh mesh = meshOfSolid(*part("return sphere(0.02) + sphere(0.02):translate(1, 0, 0)"),
                                  kTolerance, nullptr, &stats)
                          .mesh;
  EXPECT_EQ(meshShells(mesh).count, 2u);
  EXPECT_EQ(stats.strayShells, 0u);
  mesh = meshOfSolid(*part("return box(4) - sphere(1):translate(2, 2, 2)"), kTolerance, nullptr,
                     &stats)
             .mesh;
  EXPECT_EQ(meshShells(mesh).count, 2u);
  EXPECT_EQ(stats.strayShells, 0u);
}

TEST(ContactExport, AnExportThatFailsNamesTheScriptLinesNearTheTrouble) {
  // Boxes on a grid that meet corner to corner at (8, 8, 6), among others
  // that share faces and edges, less a box that removes exactly a cell:
  // the contacts resolved leave sheets a hundredth of the tolerance thick
  // that cross there (docs/cli.md, "Contacts"). If the export cannot be
  // made, the error names one of the two boxes by its line and a point
  // near the corner where the faces cross, not the box of the whole part.
  const std::string source =
      "return union{\n"
      "  box{size={2,2,2}}:translate(6,8,4),\n"
      "  cylinder{r=1, h=2}:translate(3,1,4),\n"
      "  box{size={2,2,2}}:translate(4,4,8),\n"
      "  box{size={4,2,2}}:translate(0,8,2),\n"
      "  box{size={4,2,2}}:translate(6,0,2),\n"
      "  box{size={4,2,2}}:translate(2,0,8),\n"
      "  box{size={4,2,2}}:translate(6,2,6),\n"
      "  box{size={2,2,2}}:translate(2,8,2),\n"
      "  box{size={4,2,2}}:translate(2,2,8),\n"
      "  sphere(1):translate(1,1,9),\n"
      "  sphere(1):translate(1,9,1),\n"
      "  box{size={2,2,2}}:translate(8,6,6)\n"
      "} - union{\n"
      "  sphere(1):translate(7,5,3),\n"
      "  cylinder{r=1, h=2}:translate(9,7,0),\n"
      "  box{size={4,2,2}}:translate(2,4,6)\n"
      "}\n";
  const SolidPtr solid = part(source);
  try {
    const TriangleMesh mesh = meshOfSolid(*solid, kTolerance).mesh;
    EXPECT_EQ(meshDefect(mesh).text, "");
    EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_TRUE(what.find("box (part.lua:2)") != std::string::npos ||
                what.find("box (part.lua:13)") != std::string::npos)
        << what;
    dvec3 at;
    const std::size_t open = what.find(" (", what.find("cross"));
    ASSERT_NE(open, std::string::npos) << what;
    ASSERT_EQ(std::sscanf(what.c_str() + open, " (%lf, %lf, %lf)", &at.x, &at.y, &at.z), 3) << what;
    EXPECT_LT(glm::length(at - dvec3(8, 8, 6)), 1.0) << what;
  }
}

// ---- Convex intersections ---------------------------------------------------------

TEST(ContactExport, ABoxCutByAHalfSpaceIsOneConvexPolytope) {
  // The unit cube below x + y + z = 1.5 is half of it, by symmetry; turned
  // and moved, it stays half. No corefinement: the planes' polytope.
  for (const char* source : {"return box(1) * half_space{normal={1, 1, 1}, offset=1.5}",
                             "return (box(1) * half_space{normal={1, 1, 1}, offset=1.5})"
                             ":rotate(10, 20, 30):translate(3, 4, 5)",
                             "return box(1) * half_space{normal={1, 1, 1}, offset=1.5} * box(2)"}) {
    SCOPED_TRACE(source);
    MeshBooleanStats stats;
    const TriangleMesh mesh = meshOfSolid(*part(source), kTolerance, nullptr, &stats).mesh;
    EXPECT_EQ(stats.corefinements, 0u);
    EXPECT_EQ(meshDefect(mesh).text, "");
    EXPECT_NEAR(mesh.volume(), 0.5, 1e-9);
    EXPECT_TRUE(test::checksOut(*part(source), kTolerance));
  }
  // Operands of two colours keep their faces' colours through CGAL.
  MeshBooleanStats stats;
  const std::string coloured =
      "return box(1):material{color={1, 0, 0}}"
      " * half_space{normal={1, 1, 1}, offset=1.5}:material{color={0, 0, 1}}";
  const PartMesh mesh = meshOfSolid(*part(coloured), kTolerance, nullptr, &stats);
  EXPECT_EQ(stats.corefinements, 1u);
  EXPECT_EQ(mesh.materials.size(), 2u);
  EXPECT_NEAR(mesh.mesh.volume(), 0.5, 1e-9);
}

TEST(ContactExport, AnEmptyConvexIntersectionIsNothing) {
  // A box above the half-space: the planes leave no volume.
  MeshBooleanStats stats;
  const PartMesh mesh =
      meshOfSolid(*part("return box(1):translate(0, 0, 2) * half_space{normal={0, 0, 1}, offset=1}"
                        " + sphere(1)"),
                  kTolerance, nullptr, &stats);
  EXPECT_EQ(meshDefect(mesh.mesh).text, "");
  EXPECT_NEAR(mesh.mesh.volume(), 4.0 / 3.0 * kPi, kTolerance * 4 * kPi);
}

// ---- Random parts ------------------------------------------------------------------

// A union of ten solids on a grid of 2: boxes 2 and 4 long that share
// faces, edges and corners, balls of radius 1 and cylinders r = 1, h = 2
// in the grid's cells, tangent to the boxes' faces, to each other and to
// the cells' walls; less two balls or rods placed anywhere.
std::string randomContactPart(unsigned seed) {
  std::mt19937 random(seed);
  auto cell = [&] { return 2 * int(random() % 4); };
  auto anywhere = [&](double lo, double hi) {
    return lo + (hi - lo) * std::uniform_real_distribution<double>(0.0, 1.0)(random);
  };
  std::string source = "return union{\n";
  char line[160];
  for (int k = 0; k < 10; ++k) {
    const int x = cell(), y = cell(), z = cell();
    switch (random() % 4) {
      case 0:
        std::snprintf(line, sizeof line, "  box(2):translate(%d, %d, %d),\n", x, y, z);
        break;
      case 1:
        std::snprintf(line, sizeof line, "  box{size={4, 2, 2}}:translate(%d, %d, %d),\n", x, y, z);
        break;
      case 2:
        std::snprintf(line, sizeof line, "  sphere(1):translate(%d, %d, %d),\n", x + 1, y + 1,
                      z + 1);
        break;
      default:
        std::snprintf(line, sizeof line, "  cylinder{r=1, h=2}:translate(%d, %d, %d),\n", x + 1,
                      y + 1, z);
    }
    source += line;
  }
  source += "} - union{\n";
  for (int k = 0; k < 2; ++k) {
    const double x = anywhere(0, 8), y = anywhere(0, 8), z = anywhere(0, 8);
    if (random() % 2)
      std::snprintf(line, sizeof line, "  sphere(%.3f):translate(%.3f, %.3f, %.3f),\n",
                    anywhere(0.5, 1.5), x, y, z);
    else
      std::snprintf(line, sizeof line, "  cylinder{r=%.3f, h=10}:translate(%.3f, %.3f, -1),\n",
                    anywhere(0.3, 1.0), x, y);
    source += line;
  }
  return source + "}\n";
}

TEST(ContactExport, RandomPartsWithSharedFacesAndTangenciesCheckOut) {
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const std::string source = randomContactPart(seed);
    SCOPED_TRACE(source);
    const SolidPtr solid = part(source);
    const std::optional<TriangleMesh> mesh = exported(*solid);
    if (!mesh) continue;
    EXPECT_EQ(meshDefect(*mesh).text, "");
    // Classification, the volume by ray grids against the mesh's, the
    // distance between the surfaces, and the shells.
    EXPECT_TRUE(test::checksOut(*solid, kTolerance, 5000));
  }
}

// Exports randomContactPart(seed) with its points stored so, expects a
// valid mesh that checks out against the model, and returns the order it
// was made in (MeshBooleanStats::reordered).
std::size_t reorderedAndValid(unsigned seed, StoredCoordinate stored) {
  const std::string source = randomContactPart(seed);
  SCOPED_TRACE(source);
  const SolidPtr solid = part(source);
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, stored, &stats).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_TRUE(test::checksOut(*solid, kTolerance, 5000));
  return stats.reordered;
}

TEST(ContactExport, RandomPartsThatNeedTheirUnionsInTheOtherOrder) {
  // Seeds of randomContactPart whose contacts, met in the script's order,
  // leave the mesh invalid, and in the reverse order come out valid: of
  // seeds 1 to 400, these five. (The seeds first found so, 70, 85, 130,
  // 157 and 203, where moved faces crossed near a corner that three
  // solids touch, or CGAL met solids touching at a corner, no longer need
  // it since boxes of one slab are made one extrusion in the plane where
  // the union's other operands lie off it, export/prism_booleans.h; 285
  // comes out valid in the script's order since caps that rounding turned
  // over are flipped back, flipCaps.)
  for (unsigned seed : {21u, 98u, 142u, 185u, 390u})
    EXPECT_EQ(reorderedAndValid(seed, nullptr), 1u);
}

TEST(ContactExport, RandomPartsThatNeedAShuffledOrder) {
  // Seeds of randomContactPart that fail in both the script's order and
  // the reverse one: their unions meet a corner where two solids touch
  // with a solid whose face runs through it (160, 175: CGAL's result on
  // such input is undefined, and it crashed now and then), or leave moved
  // faces crossing once rounded to an STL file's floats (245). One of the
  // shuffled orders makes them valid.
  const StoredCoordinate asStlStores = [](double x) { return double(float(x)); };
  for (unsigned seed : {160u, 175u, 245u}) EXPECT_GE(reorderedAndValid(seed, asStlStores), 2u);
}

TEST(ContactExport, AUnionThatCrossesItselfInsideTheOtherIsMadeInAnotherOrder) {
  // From randomContactPart(2809): the two boxes at (4, 4, 2) and (0, 6, 2)
  // meet at a corner, and united they cross themselves there; in the
  // script's order and the reverse one that union then met another
  // operand whose box, grown by a contact, holds that corner inside, and
  // CGAL's corefinement never returned. Such a union is refused until the
  // part goes ahead; a shuffled order makes the part.
  const SolidPtr solid = part(R"(
    return union{
      cylinder{r=1, h=2}:translate(3, 3, 6),
      box(2):translate(2, 4, 6),
      box{size={4, 2, 2}}:translate(0, 4, 6),
      box(2):translate(4, 4, 2),
      box{size={4, 2, 2}}:translate(0, 6, 2),
      box(2):translate(4, 2, 4),
      sphere(1):translate(3, 5, 3),
    })");
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, nullptr, &stats).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_GE(stats.reordered, 2u);
  EXPECT_TRUE(test::checksOut(*solid, kTolerance, 5000));
}

TEST(ContactExport, ACapThatRoundingTurnedOverIsFlippedBack) {
  // Of randomContactPart's seeds 1 to 400, 256 failed in every order: the
  // box grown where the ball touches it (a contact) has a face whose
  // diagonal runs through the corner of the box stacked on it, and the
  // face the booleans leave between them, flat, was turned over onto its
  // neighbour once rounded. Four of its solids fail so; its cap is flipped
  // across its long edge (flipCaps).
  const SolidPtr solid = part(R"(
    return union{
      sphere(1):translate(1, 3, 3),
      box(2):translate(4, 0, 6),
      sphere(1):translate(5, 1, 5),
      box{size={4, 2, 2}}:translate(0, 0, 4),
    })");
  const StoredCoordinate asStlStores = [](double x) { return double(float(x)); };
  for (const StoredCoordinate stored : {StoredCoordinate(nullptr), asStlStores}) {
    MeshBooleanStats stats;
    const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, stored, &stats).mesh;
    EXPECT_EQ(meshDefect(mesh).text, "");
    EXPECT_EQ(stats.reordered, 0u);
  }
  EXPECT_TRUE(test::checksOut(*solid, kTolerance, 5000));
  // And the part it came from, valid and holding to its model.
  reorderedAndValid(256, nullptr);
}

TEST(ContactExport, TiltedDiscsAboutACoreStayInDoubles) {
  // A thread made of thin discs, each tilted 4° and turned 22.5° more than
  // the one below, stacked about a core rod: the booleans in doubles left
  // a face turned over where two rims cross at a shallow angle, the mesh
  // failed its check, and the part was made again by CGAL alone (12 s for
  // these 48 discs, 78 s for 250). The cap is flipped back (flipCaps).
  const SolidPtr solid = part(R"(
    local parts = {cylinder{r=4.2, h=48 * 0.09375 + 1}}
    for i = 0, 47 do
      parts[#parts + 1] = cylinder{r=5, h=0.3, center=true}:rotate(4, 0, 0)
                            :rotate(0, 0, i * 22.5):translate(0, 0, 1 + i * 0.09375)
    end
    return union(parts))");
  // (As an STL file stores it: the face turned over in floats.)
  const StoredCoordinate asStlStores = [](double x) { return double(float(x)); };
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, asStlStores, &stats).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_EQ(meshShells(mesh).count, 1u);
  EXPECT_FALSE(stats.redoneByCgal);
  EXPECT_EQ(stats.inDoubles, stats.corefinements);
  EXPECT_TRUE(test::checksOut(*solid, kTolerance, 5000));
}

// ---- The same primitive twice ---------------------------------------------------

TEST(ContactExport, APrimitiveRepeatedIsExportedOnce) {
  // A union or intersection of a primitive with itself is the primitive:
  // the same mesh, with no boolean made.
  const SolidPtr once = part("return sphere(1)");
  const double volume = meshOfSolid(*once, kTolerance).mesh.volume();
  for (const char* source : {"return sphere(1) + sphere(1)", "return sphere(1) * sphere(1)",
                             "return union(sphere(1), box(1), sphere(1)) * sphere(1)"}) {
    SCOPED_TRACE(source);
    MeshBooleanStats stats;
    const SolidPtr solid = part(source);
    const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, nullptr, &stats).mesh;
    EXPECT_EQ(meshDefect(mesh).text, "");
    if (std::string(source).find("box") == std::string::npos) {
      EXPECT_EQ(stats.corefinements, 0u);
      EXPECT_EQ(mesh.volume(), volume);
    } else {
      EXPECT_EQ(stats.corefinements, 2u);  // the box into the sphere, and the intersection
    }
  }
}

TEST(ContactExport, SpokesTurnedAboutTheirCommonEdgeStayInDoubles) {
  // Seven bars turned about the z axis, each end face through it (a
  // candle stand's arms, a wheel's spokes): CGAL's union of two of them
  // puts crossings a hair's breadth apart on the axis, which rounding to
  // doubles merges. The faces between them are collapsed, and the union
  // kept in doubles, so that the ball's union after it is made in doubles
  // too (before, it stayed exact, and every boolean after it was CGAL's).
  const SolidPtr solid = part(R"(
    local spokes = {}
    for k = 0, 6 do
      spokes[#spokes + 1] = box{size={25, 3, 3}}:translate(0, -2, -1.5):rotate(0, 0, k * 360 / 7)
    end
    return union(spokes) + sphere{r=2}:translate(12.3, 0.4, 0.7))");
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, nullptr, &stats).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_EQ(meshShells(mesh).count, 1u);
  EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  EXPECT_FALSE(stats.redoneByCgal);
  EXPECT_GE(stats.inDoubles, 2u);
}

// ---- The parts of examples/ and bench/parts/ ---------------------------------------

TEST(ContactExport, TheRoundedBoxOfTangentParts) {
  // examples/rounded_box.lua, 40 × 30 × 20 with radius 3: the inner box
  // (a, b, c) grown by a ball of radius r, abc + 2r(ab + bc + ca) +
  // πr²(a + b + c) + 4πr³/3 (Steiner's formula).
  const double r = 3, a = 40 - 2 * r, b = 30 - 2 * r, c = 20 - 2 * r;
  const double exact = a * b * c + 2 * r * (a * b + b * c + c * a) + kPi * r * r * (a + b + c) +
                       4.0 / 3.0 * kPi * r * r * r;
  const Scene scene = runScriptFile(std::string(CSGRAY_SOURCE_DIR) + "/examples/rounded_box.lua",
                                    test::exampleOptions());
  const SolidPtr solid = scene.objects[0];
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*solid, kTolerance, nullptr, &stats).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_NEAR(mesh.volume(), exact, kTolerance * 2 * (40 * 30 + 30 * 20 + 40 * 20));
  EXPECT_EQ(meshShells(mesh).count, 1u);
  EXPECT_TRUE(test::checksOut(*solid, kTolerance));
  // Its parts are not in general position (a box's faces in another's
  // planes, a cylinder's generators in the boxes' faces and in the other
  // cylinders' caps): the large booleans are made in doubles with one
  // operand moved off the other, and only the first, of two boxes, by
  // CGAL (its result rounded to doubles for the next).
  EXPECT_GE(stats.perturbed, 1u);
  EXPECT_LE(stats.corefinements - stats.inDoubles, 1u);
  EXPECT_FALSE(stats.redoneByCgal);
}

TEST(ContactExport, AContactOfLargeMeshesIsNotMovedApartOrTogether) {
  // Two boxes with a ball on top, the boxes corner to corner at (10, 10,
  // 10): each boolean has hundreds of faces and the corner is not in
  // general position, but moving one operand off the other would join the
  // boxes there (grown) or not (shrunk): a contact, left to CGAL, and
  // split there as two boxes corner to corner are.
  const double ball = 4.0 / 3.0 * kPi * 27.0;
  MeshBooleanStats stats;
  const std::string source =
      "return union(box(10), sphere(3):translate(5, 5, 10), box(10):translate(10, 10, 10), "
      "sphere(3):translate(15, 15, 20))";
  const TriangleMesh mesh = meshOfSolid(*part(source), kTolerance, nullptr, &stats).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_NEAR(mesh.volume(), 2000.0 + ball, kTolerance * 4 * kPi * 9.0 * 2);
  EXPECT_EQ(meshShells(mesh).count, 2u);
  EXPECT_EQ(stats.perturbed, 0u);
}

TEST(ContactExport, FortyFrustumsStackedOnSharedRims) {
  // bench/parts/frustum_stack.lua: the volume of each frustum is
  // πh(r1² + r1 r2 + r2²)/3.
  const auto radius = [](int i) { return 20 + 6 * std::sin(i * 0.25); };
  double exact = 0.0, side = 0.0;
  for (int i = 0; i < 40; ++i) {
    const double r1 = radius(i), r2 = radius(i + 1);
    exact += kPi * 2 * (r1 * r1 + r1 * r2 + r2 * r2) / 3;
    side += kPi * (r1 + r2) * 2;
  }
  const Scene scene = runScriptFile(
      std::string(CSGRAY_SOURCE_DIR) + "/bench/parts/frustum_stack.lua", test::exampleOptions());
  MeshBooleanStats stats;
  const TriangleMesh mesh = meshOfSolid(*scene.objects[0], kTolerance, nullptr, &stats).mesh;
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_NEAR(mesh.volume(), exact, kTolerance * (side + 2 * kPi * 26 * 26));
  // Each rim is the polygon of its own radius, so neighbours meet on the
  // same points and are glued, but where the side between two rims of
  // different segments would stray past the tolerance.
  EXPECT_GE(stats.glued, 38u);
  EXPECT_EQ(stats.glued + stats.merges + stats.corefinements, 39u);
  EXPECT_EQ(meshShells(mesh).count, 1u);
  EXPECT_TRUE(test::checksOut(*scene.objects[0], kTolerance, 5000));
}

TEST(ContactExport, TheKnurledKnobsGroovesEndOnTheFilletsTangentLine) {
  // examples/knurled_knob.lua: a cylinder r = 15, 10 high, a cylinder
  // r = 13 on it to 12, a torus R = 13, r = 2 at 10 (the part of it outside
  // both: a quarter of its tube, turned at its centroid 13 + 4r/(3π),
  // Pappus), less 24 grooves r = 0.6, 10 high, centred on the side: each
  // takes the lens where its disc overlaps the knob's.
  const double a = 0.6, R = 15, d = 15;
  const double lens = a * a * std::acos((d * d + a * a - R * R) / (2 * d * a)) +
                      R * R * std::acos((d * d + R * R - a * a) / (2 * d * R)) -
                      0.5 * std::sqrt((-d + a + R) * (d + a - R) * (d - a + R) * (d + a + R));
  const double exact = kPi * 225 * 10 + kPi * 169 * 2 +
                       2 * kPi * (13 + 4 * 2 / (3 * kPi)) * (kPi * 4 / 4) - 24 * 10 * lens;
  const Scene scene = runScriptFile(std::string(CSGRAY_SOURCE_DIR) + "/examples/knurled_knob.lua",
                                    test::exampleOptions());
  const SolidPtr solid = scene.objects[0];
  for (double tolerance : {0.003, 0.005, kTolerance, 0.02}) {
    SCOPED_TRACE(tolerance);
    const TriangleMesh mesh = meshOfSolid(*solid, tolerance).mesh;
    EXPECT_EQ(meshDefect(mesh).text, "");
    // Area: the side and the top, the grooves' walls and the fillet.
    EXPECT_NEAR(mesh.volume(), exact,
                tolerance * (2 * kPi * 15 * 12 + 2 * kPi * 15 * 15 + 24 * 2 * kPi * 0.6 * 10));
    EXPECT_EQ(meshShells(mesh).count, 1u);
  }
  EXPECT_TRUE(test::checksOut(*solid, kTolerance));
}

// Sweeps of regions that touch themselves: meshed as one set of polygons
// they have an edge of four faces, or faces that cross, and failed; the
// export takes them apart into the sweeps of the region's operands, whose
// contacts are resolved as solids' are. Volumes by Pappus for the turned.
TEST(ContactExport, SweepsOfRegionsThatTouchThemselvesAreTakenApart) {
  struct Case {
    const char* source;
    double volume, area;
  } cases[] = {
      // Two squares corner to corner: an edge contact, joined by a bridge.
      {"return linear_extrude{square(1) + square(1):translate(1, 1), height=1}", 2.0, 10.0},
      // The same on a plate.
      {"return linear_extrude{square(1) + square(1):translate(1, 1), height=1}\n"
       "  + box{size={2, 2, 1}}:translate(0, 0, -1)",
       6.0, 20.0},
      // Two circles side by side: tangent along a line.
      {"return linear_extrude{circle(1) + circle(1):translate(2, 0), height=2}", 4 * kPi, 12 * kPi},
      // Turned: two tangent circles at 2 and 4 from the axis, 2π²ρr² each;
      // two squares corner to corner, 2πρ̄A each.
      {"return rotate_extrude{circle(1):translate(2, 0) + circle(1):translate(4, 0)}",
       2 * kPi * kPi * 6, 4 * kPi * kPi * 6},
      {"return rotate_extrude{square(1):translate(1, 0) + square(1):translate(2, 1)}",
       2 * kPi * (1.5 + 2.5), 2 * kPi * 4 * 4},
      // One polygon whose hole has a corner on the outline: a square of 16
      // less a triangle of 1, taken apart into its two loops.
      {"return linear_extrude{polygon{points={{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 0}, {3, 1}, "
       "{1, 1}}, paths={{0, 1, 2, 3}, {4, 5, 6}}}, height=1}",
       15.0, 2 * 16 + 16 + 5},
  };
  for (const Case& c : cases) {
    MeshBooleanStats stats;
    meshOfSolid(*part(c.source), kTolerance, nullptr, &stats);
    EXPECT_TRUE(stats.sweepsApart) << c.source;
    exportsValid(c.source, c.volume, kTolerance * c.area);
  }
}

TEST(ContactExport, ARegionThatTouchesTheAxisAtAPointIsRefusedSayingSo) {
  // A horn torus: pinched to a point on the axis, as torus{R=1, r=1} is.
  try {
    meshOfSolid(*part("return rotate_extrude{circle(1):translate(1, 0)}"), kTolerance);
    ADD_FAILURE() << "exported";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rotate_extrude: the region touches the axis at the one "
                                         "point"),
              std::string::npos)
        << e.what();
  }
}

TEST(ContactExport, HolesTurnedOntoABoltCircleFlushWithThePlatesFace) {
  // Cutters from z = -5 to the plate's face at 5, turned into place about
  // the plate's axis by angles whose turn once rounded z off its plane.
  // A cylinder r = 30, 5 high, less three holes r = 2.5 (their polygons
  // within the tolerance of the circle).
  const double exact = kPi * 5 * (30 * 30 - 3 * 2.5 * 2.5);
  exportsValid(
      "local plate = cylinder{r=30, h=5}\n"
      "local holes = {}\n"
      "for _, a in ipairs{95, 105, 125} do\n"
      "  holes[#holes + 1] = cylinder{r=2.5, h=10, center=true}:translate(22, 0, 0):rotate(0, 0, "
      "a)\n"
      "end\n"
      "return difference(plate, holes)",
      exact, kTolerance * 5 * 2 * kPi * (30 + 3 * 2.5));
}

TEST(ContactExport, CounterboresFlushWithTheTopOfATurnedPlate) {
  // A plate made by hull() of four upright cylinders (an extrusion of the
  // hull of their discs, placed by a quarter turn), less a counterbore
  // and a countersink whose tops are flush with its top face: the frames
  // were snapped to a grid of 2⁻³⁰ in the plate's frame, the counterbore's
  // 2.3 with them, and its top a hair off the face; the difference was
  // refused as self-intersecting. A quarter turn takes frames back
  // exactly, and they are no longer snapped. Volumes: the rounded
  // rectangle times its height, less a cylinder and a frustum.
  const double W = 134.0, D = 62.0, T = 4.0, R = 8.1;
  const double plate = (W * D - (4.0 - kPi) * R * R) * T;
  const double bore = kPi * 3.4 * 3.4 * 1.7;
  const double sink = kPi * 1.7 / 3.0 * (1.7 * 1.7 + 1.7 * 3.4 + 3.4 * 3.4);
  const std::string hull =
      "local c = {}\n"
      "for _, p in ipairs({{8.1, 8.1}, {125.9, 8.1}, {8.1, 53.9}, {125.9, 53.9}}) do\n"
      "  c[#c + 1] = cylinder{r=8.1, h=4}:translate(p[1], p[2], 0)\n"
      "end\n"
      "local plate = hull(c)\n";
  const double slack = kTolerance * 2.0 * (W * D + (W + D) * T);
  exportsValid(hull + "return plate - cylinder{r=3.4, h=1.7}:translate(20, 20, 2.3)", plate - bore,
               slack);
  exportsValid(hull + "return plate - cylinder{r1=1.7, r2=3.4, h=1.7}:translate(9.8, 9.8, 2.3)",
               plate - sink, slack);
  // A box turned a quarter by the script, with a pocket flush with its
  // top; and the part turned as a whole by other angles, where the grid
  // of 2⁻³⁰ moves the pocket's 2.3 too (the part is made again with its
  // places taken back as written).
  const double pocketed = 30 * 20 * 4 - kPi * 9 * 1.7;
  const double pocketSlack = kTolerance * 2.0 * (600 + 200 + 100 * 4);
  const std::string pocket = "cylinder{r=3, h=1.7}:translate(10, 10, 2.3)";
  exportsValid("return box{size={30, 20, 4}}:rotate(0, 0, 90) - " + pocket + ":rotate(0, 0, 90)",
               pocketed, pocketSlack);
  for (const char* turn : {"0, 0, 30", "17, 20, 0", "45, 0, 45"})
    exportsValid("return (box{size={30, 20, 4}} - " + pocket + "):rotate(" + turn + ")", pocketed,
                 pocketSlack);
}

TEST(ContactExport, AnAxleTurnedOrMirroredAgainstItsWheelFillsTheBore) {
  // A wheel (a rim r = 8 to 10 and two crossed spokes 2 wide, 3 thick, a
  // bore r = 2) and an axle of the bore's radius turned the other way, or
  // mirrored: the axle's polygon, mirrored, was a hair off the bore's, and
  // the union crossed itself (or crashed CGAL).
  const double spoke = 2.0 * (std::sqrt(63.0) + 64.0 * std::asin(1.0 / 8.0));  // |y| ≤ 1 in r ≤ 8
  const double boreOfSpokes = 2.0 * (2.0 * std::sqrt(3.0) + 4.0 * kPi / 3.0) - 4.0;
  const double wheel = 3.0 * (kPi * (100.0 - 64.0) + 2.0 * spoke - 4.0 - boreOfSpokes);
  const double axle = kPi * 4.0 * 10.0;  // the bore it fills is empty
  const std::string wheelSource =
      "local w = cylinder{r=10, h=3, center=true} - cylinder{r=8, h=10, center=true}\n"
      "w = w + box{size={18, 2, 3}, center=true} + box{size={2, 18, 3}, center=true}\n"
      "w = w - cylinder{r=2, h=10, center=true}\n";
  for (const char* assembly :
       {"return w:rotate(90, 0, 0) + cylinder{r=2, h=10}:rotate(-90, 0, 0)",
        "return w + cylinder{r=2, h=10}:mirror(0, 1, 0):translate(0, 0, -1)",
        "return w + cylinder{r=2, h=10}:mirror(0, 0, 1):translate(0, 0, 1)",
        "return w + cylinder{r=2, h=10}:rotate(0, 0, 180):translate(0, 0, -1)"})
    // The chord error over a surface of less than 1000.
    exportsValid(wheelSource + assembly, wheel + axle, kTolerance * 1000.0);
}

TEST(ContactExport, APinUpsideDownInASweptHoleMeetsItsWall) {
  // A plate 40 × 40 × 5 swept with a hole r = 3, and a pin 10 long turned
  // half a turn about x into it: the sweep's hole takes the pin's polygon
  // as the pin is cut, upright.
  exportsValid(
      "local plate = linear_extrude{square{size={40, 40}, center=true} - circle(3), height=5}\n"
      "return plate + cylinder{r=3, h=10}:rotate(180, 0, 0):translate(0, 0, 7)",
      40.0 * 40.0 * 5.0 + kPi * 9.0 * 5.0,
      kTolerance * (2 * 1600.0 + 4 * 40 * 5 + 2 * kPi * 3 * 10));
}

TEST(ContactExport, PinsTurnedOverOrAboutTheirAxesMeetTheirHolesWalls) {
  // A pin of a hole's radius that is turned another way than its hole:
  // a quarter about its own axis, or 33.3° or 95° (its polygon then left
  // crevices in the hole's), or mirrored across a diagonal; turned over,
  // then onto a bolt circle with the hole; mirrored, then so. Each
  // crossed its hole's faces or left crevices.
  for (const char* turn :
       {"rotate(0, 0, 90)", "rotate(0, 0, 33.3)", "rotate(0, 0, 95)", "mirror(1, 1, 0)"})
    exportsValid(
        "return box{size={10, 10, 2}, center=true} - cylinder{r=3, h=2, center=true}\n"
        "       + cylinder{r=3, h=4, center=true}:" +
            std::string(turn),
        200.0 + kPi * 9.0 * 2.0, kTolerance * (2 * 100.0 + 4 * 20.0 + 2 * kPi * 3 * 4));
  for (const char* pin : {"cylinder{r=3, h=8, center=true}:rotate(180, 0, 0)",
                          "cylinder{r=3, h=8, center=true}:mirror(1, 0, 0)"})
    exportsValid(
        "return box{size={20, 20, 4}, center=true}\n"
        "       - cylinder{r=3, h=4, center=true}:translate(5, 0, 0):rotate(0, 0, 60)\n"
        "       + " +
            std::string(pin) + ":translate(5, 0, 0):rotate(0, 0, 60)",
        1600.0 + kPi * 9.0 * 4.0, kTolerance * (2 * 400.0 + 4 * 80.0 + 2 * kPi * 3 * 8));
  // Turned to 135° and mirrored in x onto a hole turned to 45°: the
  // centres agree only where the two turns' sines and cosines do.
  exportsValid(
      "return box{size={20, 20, 4}, center=true}\n"
      "       - cylinder{r=3, h=4, center=true}:translate(5, 0, 0):rotate(0, 0, 45)\n"
      "       + cylinder{r=3, h=8, center=true}:translate(5, 0, 0):rotate(0, 0, 135)"
      ":mirror(1, 0, 0)",
      1600.0 + kPi * 9.0 * 4.0, kTolerance * (2 * 400.0 + 4 * 80.0 + 2 * kPi * 3 * 8));
  // A tee: a bore along x and a branch of its radius along +y from its
  // axis, turned there the other way; the branch leaves half of the two
  // bores' common 16 r³ / 3 (Steinmetz) to the through bore.
  exportsValid(
      "return box{size={20, 20, 20}}:translate(0, -10, -10)\n"
      "       - cylinder{r=3, h=20}:rotate(0, 90, 0)\n"
      "       - cylinder{r=3, h=10}:rotate(-90, 0, 0):translate(10, 0, 0)",
      8000.0 - kPi * 9.0 * 30.0 + 8.0 * 27.0 / 3.0, kTolerance * (6 * 400.0 + 2 * kPi * 3 * 30));
}

TEST(ContactExport, APinThroughABoreCutFlushWithBothFacesFillsIt) {
  // A tube r = 5, 2 long, its bore cut flush with both faces, and a pin
  // of the bore's radius through it from 1 below to 1 above: for bores
  // r = 1 and 3 no contact's offset made the union a 2-manifold. Also a
  // countersink refilled by its own frustum.
  for (double r : {1.0, 3.0}) {
    const std::string rs = std::to_string(r);
    exportsValid("return cylinder{r=5, h=2} - cylinder{r=" + rs + ", h=2}\n" +
                     "       + cylinder{r=" + rs + ", h=4}:translate(0, 0, -1)",
                 kPi * (25.0 * 2.0 + r * r * 2.0),
                 kTolerance * (2 * kPi * 25 + 2 * kPi * 5 * 2 + 2 * kPi * r * 4));
  }
  // A box 10 × 10 × 3 less a frustum r = 1 to 3 through it, plus that
  // frustum: the box.
  exportsValid(
      "return box{size={10, 10, 3}}:translate(-5, -5, 0) - cylinder{r1=1, r2=3, h=3}\n"
      "       + cylinder{r1=1, r2=3, h=3}",
      300.0, kTolerance * (2 * 100.0 + 4 * 30.0));
}

TEST(ContactExport, ABallTurnedOrMirroredInACupOfItsRadiusFillsIt) {
  // A plate 10 × 10 × 2 below z = 0 less a ball r = 3 about the origin,
  // and that ball turned or mirrored put back: the plate and the ball,
  // less the segment of the ball the plate held, π ∫₋₂⁰ (9 − z²) dz.
  const double exact = 200.0 + 4.0 / 3.0 * kPi * 27.0 - kPi * (18.0 - 8.0 / 3.0);
  for (const char* ball :
       {"sphere(3):rotate(180, 0, 0)", "sphere(3):mirror(1, 0, 0)", "sphere(3):rotate(0, 0, 37)"})
    exportsValid(std::string("return box{size={10, 10, 2}}:translate(-5, -5, -2) - sphere(3)\n"
                             "       + ") +
                     ball,
                 exact, kTolerance * (2 * 100.0 + 4 * 20.0 + 4 * kPi * 9));
}

TEST(ContactExport, APartScaledAsAWholeKeepsItsPinsInTheirHoles) {
  // A swept disc r = 20 with a hole r = 2 turned 10° onto a circle of 14,
  // 4 thick, and a pin through it from 3 below, all scaled by 1.5: the
  // sweep's hole takes the pin's rim as the two are placed, scaled.
  const double s = 1.5;
  exportsValid(
      "local disc = linear_extrude{circle(20) - circle(2):translate(14, 0):rotate(10), height=4}\n"
      "local pin = cylinder{r=2, h=10}:translate(14, 0, -3):rotate(0, 0, 10)\n"
      "return (disc + pin):scale(1.5)",
      s * s * s * kPi * (400.0 * 4.0 + 4.0 * 6.0),
      s * s * kTolerance * (2 * kPi * 400 + 2 * kPi * 20 * 4 + 2 * kPi * 2 * 10));
}

TEST(ContactExport, ThePixelKnobIsCutThroughWherePixelsMeet) {
  // examples/pixel_knob.lua: a knob r = 15, 10 high, less 13 pixels 2 × 2,
  // 1 deep.
  const Scene scene = runScriptFile(std::string(CSGRAY_SOURCE_DIR) + "/examples/pixel_knob.lua",
                                    test::exampleOptions());
  const double exact = kPi * 15 * 15 * 10 - 13 * 4.0;
  // In doubles, and as a binary STL stores it (floats): the vertices moved
  // apart where pixels meet at a corner must still be apart once rounded.
  for (StoredCoordinate stored :
       {StoredCoordinate(nullptr), storedCoordinate(MeshFormat::Stl, false)}) {
    const TriangleMesh mesh = meshOfSolid(*scene.objects[0], kTolerance, stored).mesh;
    EXPECT_EQ(meshDefect(mesh).text, "");
    EXPECT_NEAR(mesh.volume(), exact,
                kTolerance * (2 * kPi * 15 * 10 + 2 * kPi * 15 * 15 + 13 * 12));
  }
}

}  // namespace
}  // namespace csgray::detail
