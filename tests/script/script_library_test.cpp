// The script library (graphs, parametric surfaces, fractal mountains and
// compounds): analytic volumes and areas, the closed meshes they make,
// the same mountain for the same seed, and one-line errors at the
// script's line, also for a call in a return statement (a tail call).
// As open surfaces: rays meet them where the functions say, with the
// analytic normals, from both sides; a mountain's surface is its solid's
// top.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <string>

#include "engine/primitive.h"
#include "export/cgal/mesh_validity.h"
#include "primitives/mesh_solid.h"
#include "raytrace/renderer.h"
#include "scene/surface_mesh.h"
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

// The one surface of a script's scene.
SurfacePtr surfaceOf(const std::string& source) {
  Scene scene = runScript(source, "part.lua", {});
  EXPECT_EQ(scene.surfaces.size(), 1u) << source;
  return scene.surfaces.at(0);
}

// The angle between two lines, in degrees (the sign of a normal tells
// only the side).
double degreesBetween(const dvec3& a, const dvec3& b) {
  const double c = std::abs(glm::dot(glm::normalize(a), glm::normalize(b)));
  return std::acos(std::min(1.0, c)) * 180.0 / kPi;
}

TEST(ScriptLibrary, AGraphSurfaceLiesOnTheGraphWithItsNormals) {
  // z = x² + y² over [−1, 1]²: vertical rays meet the sheet within the
  // tolerance (0.01) of f, from above and from below, and the shading
  // normal is within a degree of (−2x, −2y, 1).
  const SurfacePtr sheet = surfaceOf(
      "return graph{f=function(x, y) return x * x + y * y end, x={-1, 1}, y={-1, 1}, "
      "surface=true}");
  EXPECT_EQ(sheet->shape(), Surface::Shape::Mesh);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> in(-0.999, 0.999);
  double worst = 0.0;
  for (int k = 0; k < 500; ++k) {
    const double x = in(rng), y = in(rng), f = x * x + y * y;
    for (double dir : {-1.0, 1.0}) {
      const Ray ray(dvec3(x, y, dir < 0 ? 5.0 : -5.0), dvec3(0, 0, dir));
      int face = -1;
      const std::optional<double> t = sheet->hit(ray, &face);
      ASSERT_TRUE(t) << x << ", " << y;
      const dvec3 p = ray.at(*t);
      // The triangles' corners are on the graph and it is convex: the sheet lies above it.
      EXPECT_GE(p.z, f - 1e-12);
      EXPECT_LE(p.z, f + 0.01);
      worst = std::max(worst, degreesBetween(sheet->normalAt(p, face), dvec3(-2 * x, -2 * y, 1)));
    }
  }
  EXPECT_LT(worst, 1.0);
  // Beside the rectangle: nothing.
  EXPECT_FALSE(sheet->hit(Ray(dvec3(1.01, 0, 5), dvec3(0, 0, -1))));
  // The sheet refines as the solid does: the same top.
  const SolidPtr solid =
      solidOf("return graph{f=function(x, y) return x * x + y * y end, x={-1, 1}, y={-1, 1}}");
  const auto& top = sheet->mesh()->points();
  const auto& all = dynamic_cast<const MeshSolid&>(*solid).points();
  ASSERT_LT(top.size(), all.size());
  EXPECT_TRUE(std::equal(top.begin(), top.end(), all.begin()));
}

TEST(ScriptLibrary, OpenParametricPatchesAreWhereTheirFunctionsPutThem) {
  // The saddle z = u·v over [0, 1]²: each grid cell's two triangles lie
  // within h²/4 of it (h = 1/16), and the normal is (−v, −u, 1).
  const SurfacePtr saddle = surfaceOf(
      "return parametric{f=function(u, v) return {u, v, u * v} end, u={0, 1}, v={0, 1}, "
      "resolution=16, surface=true}");
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> in(0.001, 0.999);
  double worst = 0.0;
  for (int k = 0; k < 300; ++k) {
    const double x = in(rng), y = in(rng);
    const Ray ray(dvec3(x, y, -3), dvec3(0, 0, 1));
    int face = -1;
    const std::optional<double> t = saddle->hit(ray, &face);
    ASSERT_TRUE(t);
    EXPECT_NEAR(ray.at(*t).z, x * y, 1.0 / (4 * 16 * 16) + 1e-12);
    worst = std::max(worst, degreesBetween(saddle->normalAt(ray.at(*t), face), dvec3(-y, -x, 1)));
  }
  EXPECT_LT(worst, 1.0);
  // A helicoid of one turn, (u cos v, u sin v, v) for u in [0.2, 1]: above
  // the point at angle θ from the x axis it is at height θ, and nowhere
  // inside the radius 0.2 nor beyond 1.
  const SurfacePtr helicoid = surfaceOf(
      "return parametric{f=function(u, v) return {u * math.cos(v), u * math.sin(v), v} end, "
      "u={0.2, 1}, v={0, 2 * math.pi}, resolution={8, 256}, surface=true}");
  for (int k = 0; k < 300; ++k) {
    const double theta = 2 * kPi * in(rng), r = 0.21 + 0.78 * in(rng);
    const Ray ray(dvec3(r * std::cos(theta), r * std::sin(theta), 10), dvec3(0, 0, -1));
    const std::optional<double> t = helicoid->hit(ray);
    ASSERT_TRUE(t) << r << ", " << theta;
    EXPECT_NEAR(ray.at(*t).z, theta, 0.01);
  }
  EXPECT_FALSE(helicoid->hit(Ray(dvec3(0.1, 0.05, 10), dvec3(0, 0, -1))));
  EXPECT_FALSE(helicoid->hit(Ray(dvec3(0.9, 0.5, 10), dvec3(0, 0, -1))));
}

TEST(ScriptLibrary, AMountainSurfaceIsItsSolidsTop) {
  const std::string mountain = "return fractal_mountain{size=10, levels=4, seed=";
  auto surface = [&](int seed) {
    return surfaceOf(mountain + std::to_string(seed) + ", surface=true}");
  };
  const SurfacePtr a = surface(3), again = surface(3), other = surface(4);
  EXPECT_EQ(a->mesh()->points(), again->mesh()->points());
  EXPECT_NE(a->mesh()->points(), other->mesh()->points());
  EXPECT_EQ(a->mesh()->triangles().size(), 2u * 16 * 16);
  // Rays from above meet the surface where they enter the solid.
  const SolidPtr solid = solidOf(mountain + "3}");
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> in(0.0, 10.0);
  for (int k = 0; k < 300; ++k) {
    const Ray ray(dvec3(in(rng), in(rng), 20), dvec3(0, 0, -1));
    const SpanList spans = test::spansOf(*solid, ray);
    const std::optional<double> t = a->hit(ray);
    ASSERT_FALSE(spans.empty());
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, spans.begin()->in.t, 1e-9);
  }
}

TEST(ScriptLibrary, ASheetIsSeenAndCastsShadowsFromBothSides) {
  // A flat graph sheet in z = 0 shades as a plane there does, from above
  // and from below, lit from the side the eye is on, also where it mirrors
  // and lets through light (a ball on each side to be seen in it and
  // through it); and it shades a point behind it from a light on the
  // other side as the plane does: wholly when opaque, by its transparency
  // when not.
  const std::string rest =
      "sphere(0.4):translate(-0.1, 0.2, 1), sphere(0.4):translate(0.5, -0.1, -1)}, "
      "lights={point_light{pos={0.3, 0.2, 5}}, point_light{pos={-0.2, 0.1, -5}}}, "
      "camera=camera{eye={0, -3, 3}}}";
  for (const std::string material :
       {"{color={0.8, 0.5, 0.2}, specular=0.3}",
        "{color={0.8, 0.5, 0.2}, specular=0.3, reflection=0.3, transparency=0.4}"}) {
    SCOPED_TRACE(material);
    const Scene sheet = runScript(
        "return scene{objects={graph{f=function(x, y) return 0 end, x={-2, 2}, y={-2, 2}, "
        "surface=true}:material" +
            material + ", " + rest,
        "part.lua", {});
    const Scene plane = runScript("return scene{objects={plane{}:material" + material + ", " + rest,
                                  "part.lua", {});
    const Renderer withSheet(sheet, RenderOptions(8, 8)), withPlane(plane, RenderOptions(8, 8));
    for (double side : {1.0, -1.0}) {
      for (const dvec3& aim : {dvec3(0.25, -0.14, 0), dvec3(-0.1, 0.2, 0), dvec3(0.5, -0.1, 0)}) {
        const dvec3 eye(0.1, -0.8, 3 * side);
        const Ray ray(eye, aim - eye);
        const dvec3 seen = withSheet.trace(ray);
        EXPECT_GT(seen.x, 0.1) << side;
        test::expectVecNear(seen, withPlane.trace(ray), 1e-9);
      }
      // From below the upper light is dimmed or hidden by the sheet, and
      // the other way round.
      const dvec3 from(0.1, 0.1, -side), to(0.1, 0.1, 4 * side);
      EXPECT_EQ(withSheet.transmittance(from, to), withPlane.transmittance(from, to));
      EXPECT_LT(withSheet.transmittance(from, to).x, 0.5);
    }
  }
}

TEST(ScriptLibrary, SurfacesOfTheLibraryAreNoSolids) {
  const std::string sheet =
      "graph{f=function(x, y) return x * y end, x={0, 1}, y={0, 1}, surface=true}";
  EXPECT_NE(scriptError("return " + sheet + " + box(1)").find("is a surface, not a solid"),
            std::string::npos);
  EXPECT_NE(scriptError("local b = " + sheet + ":bounds()").find("surface"), std::string::npos);
  EXPECT_EQ(scriptError("return graph{f=function(x, y) return 0 end, x={0, 1}, y={0, 1}, "
                        "surface=true, base=-1}"),
            "part.lua:1: graph: a surface (surface=true) has no base: give one or the other");
  EXPECT_EQ(scriptError("return fractal_mountain{smooth=false}"),
            "part.lua:1: fractal_mountain: smooth is for a surface (surface=true); a solid's "
            "faces are flat");
  EXPECT_EQ(scriptError("return parametric{f=function(u, v) return {u, v, 0} end, u={0, 1}, "
                        "v={0, 1}, surface=1}"),
            "part.lua:1: parametric: surface must be true or false");
  EXPECT_EQ(scriptError("\nreturn mesh_surface{points={{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, "
                        "faces={{0, 1, 3}}}"),
            "part.lua:2: mesh_surface: face 0: point index 3 is out of range (there are 3 "
            "points, numbered from 0)");
  // Flat: each triangle's own normal.
  const SurfacePtr flat = surfaceOf(
      "return graph{f=function(x, y) return x * x end, x={0, 1}, y={0, 1}, surface=true, "
      "smooth=false}");
  int face = -1;
  const Ray ray(dvec3(0.3, 0.4, 5), dvec3(0, 0, -1));
  const std::optional<double> t = flat->hit(ray, &face);
  ASSERT_TRUE(t);
  test::expectVecNear(flat->normalAt(ray.at(*t), face), flat->faceNormal(face), 0.0);
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
