// The script library (graphs, parametric surfaces, fractal mountains and
// compounds): analytic volumes and areas, the closed meshes they make,
// the same mountain for the same seed, and one-line errors at the
// script's line, also for a call in a return statement (a tail call).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "engine/primitive.h"
#include "export/cgal/mesh_validity.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

using test::scriptError;
using test::solidOf;

// The library's meshes are polyhedra: one primitive whose mesh is its
// tessellation.
TriangleMesh meshOf(const SolidPtr& s) {
  return dynamic_cast<const Primitive&>(*s).tessellate(0.01, Bounds::everything());
}
double meshVolume(const SolidPtr& s) { return meshOf(s).volume(); }

TEST(ScriptLibrary, AGraphHoldsTheIntegralUnderIt) {
  // ∫∫ (x² + y² + 1) over [−1, 1]² = 8/3 + 4: the paraboloid above a base
  // at z = −1. The triangles lie within the tolerance (0.01) of the graph
  // in z, so the volume within 0.01 × the area (4).
  SolidPtr g = solidOf(
      "return graph{f=function(x, y) return x * x + y * y end, x={-1, 1}, y={-1, 1}, base=-1}");
  EXPECT_EQ(meshDefect(meshOf(g)).text, "");
  EXPECT_NEAR(meshVolume(g), 20.0 / 3.0, 0.04);
  // A finer tolerance: closer.
  SolidPtr fine = solidOf(
      "return graph{f=function(x, y) return x * x + y * y end, x={-1, 1}, y={-1, 1}, base=-1, "
      "tolerance=0.0005}");
  EXPECT_NEAR(meshVolume(fine), 20.0 / 3.0, 0.002);
  // The rays see the same solid: the volume from spans.
  EXPECT_NEAR(test::gridVolume(*g, g->bounds(), 200), meshVolume(g), 0.01);
  // A plane needs no refinement: the grid, exactly.
  SolidPtr flat =
      solidOf("return graph{f=function(x, y) return 2 + x end, x={0, 3}, y={0, 2}, base=0}");
  EXPECT_NEAR(meshVolume(flat), 2 * 3 * 3.5, 1e-9);
}

TEST(ScriptLibrary, ParametricSurfacesCloseUpIntoSolids) {
  // A sphere of radius 1 by its angles: the poles are one point each.
  const std::string sphere =
      "return parametric{f=function(u, v) return {math.sin(v) * math.cos(u), "
      "math.sin(v) * math.sin(u), math.cos(v)} end, u={0, 2 * math.pi}, v={0, math.pi}, "
      "closed_u=true, resolution=";
  const double coarse = meshVolume(solidOf(sphere + "{32, 16}}"));
  const double fine = meshVolume(solidOf(sphere + "{128, 64}}"));
  // Inscribed: below the ball's volume, and closer the finer.
  EXPECT_LT(coarse, fine);
  EXPECT_LT(fine, 4.0 / 3.0 * kPi);
  EXPECT_NEAR(fine, 4.0 / 3.0 * kPi, 0.005 * 4.0 / 3.0 * kPi);
  // A torus, closed both ways: Pappus, 2π²Rr².
  SolidPtr torus = solidOf(
      "return parametric{f=function(u, v) return {(3 + math.cos(v)) * math.cos(u), "
      "(3 + math.cos(v)) * math.sin(u), math.sin(v)} end, u={0, 2 * math.pi}, "
      "v={0, 2 * math.pi}, closed_u=true, closed_v=true, resolution={256, 128}}");
  EXPECT_EQ(meshDefect(meshOf(torus)).text, "");
  EXPECT_NEAR(meshVolume(torus), 2 * kPi * kPi * 3, 0.002 * 2 * kPi * kPi * 3);
  // Left open: refused, with the place of an open edge.
  const std::string open = scriptError(
      "local s = parametric{f=function(u, v) return {u, v, u * v} end, u={0, 1}, v={0, 1}}");
  EXPECT_NE(open.find("part.lua:1: parametric: the surface does not close up into a solid"),
            std::string::npos)
      << open;
}

TEST(ScriptLibrary, AMountainIsTheSameForTheSameSeed) {
  auto points = [](int seed) {
    return meshOf(
        solidOf("return fractal_mountain{size=10, levels=4, seed=" + std::to_string(seed) + "}"));
  };
  const TriangleMesh a = points(3), again = points(3), other = points(4);
  EXPECT_EQ(a.points, again.points);
  EXPECT_NE(a.points, other.points);
  EXPECT_EQ(meshDefect(a).text, "");
  // A (2^4 + 1)² grid on top: 2·16² triangles, and the walls and base.
  EXPECT_EQ(a.triangles.size(), 2u * 16 * 16 + 4u * 16 * 2 + 4u * 16);
  // Roughness 0: no bumps after the first level; the corners stay at 0.
  SolidPtr smooth = solidOf("return fractal_mountain{size=10, levels=3, roughness=0, base=-5}");
  EXPECT_NEAR(smooth->bounds().lo.z, -5.0, 1e-12);
}

TEST(ScriptLibrary, FractalCompoundsHaveTheirAreasAndVolumes) {
  // The Sierpinski triangle: (3/4)^level of the triangle's area.
  EXPECT_EQ(scriptError("local t = sierpinski_triangle{level=3, size=10}\n"
                        "assert(math.abs(t:area() - 25 * math.sqrt(3) * 0.75 ^ 3) < 1e-9)\n"
                        "return box(1)"),
            "(no error)");
  // The Pythagoras tree: each level adds the trunk's area (cos² + sin² = 1).
  EXPECT_EQ(scriptError("local t = pythagoras_tree{level=2, size=3, angle=30}\n"
                        "assert(math.abs(t:area() - 3 * 9) < 1e-9)\nreturn box(1)"),
            "(no error)");
  // The Sierpinski tetrahedron: half the volume per level.
  const double r = 5, edge = 4 * r / std::sqrt(6.0),
               first = edge * edge * edge / (6 * std::sqrt(2));
  SolidPtr tetra = solidOf("return sierpinski_tetrahedron{level=2, size=10}");
  EXPECT_NEAR(test::gridVolume(*tetra, tetra->bounds(), 300), first / 4, 0.01 * first / 4);
  // The cube tree: the trunk and two cubes of sides cos and sin of 45°,
  // each sunk a hundredth of its side into the trunk (so less at most the
  // slab of that depth under it).
  const double c = std::cos(kPi / 4), whole = 1000 * (1 + 2 * c * c * c);
  SolidPtr cubes = solidOf("return pythagoras_tree_3d{level=1, size=10}");
  const double v = test::gridVolume(*cubes, cubes->bounds(), 300);
  EXPECT_LT(v, whole + 2.0);
  EXPECT_GT(v, whole - 2 * 1000 * 0.01 * c * c * c - 2.0);
  EXPECT_EQ(solidOf("return pythagoras_tree_3d{level=0, size=10}")->bounds().hi.z, 10.0);
}

TEST(ScriptLibrary, ErrorsNameTheScriptsLine) {
  EXPECT_EQ(scriptError("-- a graph\nreturn graph{f=1}"),
            "part.lua:2: graph: f must be a function of x and y");
  EXPECT_EQ(scriptError("local g = graph{f=function(x, y) return 0 end, x={1, 0}, y={0, 1}}"),
            "part.lua:1: graph: x must run from a smaller number to a larger one (got {1, 0})");
  EXPECT_EQ(scriptError("return graph{f=function(x, y) return 0 / 0 end, x={0, 1}, y={0, 1}}")
                .rfind("part.lua:1: graph: f(0.0, 0.0) gave ", 0),
            0u);
  EXPECT_EQ(scriptError("return fractal_mountain{levels=12}"),
            "part.lua:1: fractal_mountain: levels must be a whole number from 1 to 9 (got 12)");
  EXPECT_EQ(
      scriptError("return sierpinski_tetrahedron{level=-1}"),
      "part.lua:1: sierpinski_tetrahedron: level must be a whole number from 0 to 10 (got -1)");
  // A base at or above the lowest point leaves no solid under it.
  EXPECT_EQ(
      scriptError("local g = graph{f=function(x, y) return x end, x={0, 1}, y={0, 1}, base=0}"),
      "part.lua:1: graph: base must lie below the lowest point of the graph (0.0)");
  EXPECT_EQ(scriptError("\nreturn fractal_mountain{size=10, levels=2, base=1e9}")
                .rfind("part.lua:2: fractal_mountain: base must lie below the lowest point of the "
                       "mountain (",
                       0),
            0u);
  // An error in the script's own function keeps its own line.
  EXPECT_EQ(scriptError("return graph{f=function(x, y)\n  return nil + x\nend, x={0, 1}, y={0, 1}}")
                .rfind("part.lua:2: ", 0),
            0u);
  // A shape the library made names the line that asked for it.
  SolidPtr s = solidOf("-- x\nreturn sierpinski_tetrahedron{level=1, size=2}");
  EXPECT_EQ(s->children()[0]->origin().text(), "part.lua:2");
}

}  // namespace
}  // namespace csgray::detail
