// Shared checks for the test suites: the span-list invariants, the
// agreement of spans with contains() and the outward normals, which every
// solid must satisfy, and running scripts.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "check/part_check.h"
#include "engine/primitive.h"
#include "engine/solid.h"
#include "export/solid_projection.h"
#include "io/image_file.h"
#include "meshio/mesh_import.h"
#include "script/script.h"

namespace csgray::detail::test {

// The scripts in examples/, sorted: every one is rendered and exported.
inline std::vector<std::string> exampleScripts() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(CSGRAY_SOURCE_DIR "/examples"))
    if (entry.path().extension() == ".lua") paths.push_back(entry.path().string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

// What the command line gives a script: image and mesh files, and check().
inline ScriptOptions exampleOptions() {
  ScriptOptions options;
  options.loadImage = readTextureImage;
  options.loadMesh = importMesh;
  options.checkSolid = checkPart;
  options.projectSolid = solidProjection;
  return options;
}

// The error a script stops with, or "(no error)" if it runs.
inline std::string scriptError(const std::string& source, const ScriptOptions& options = {},
                               const std::string& name = "part.lua") {
  try {
    runScript(source, name, options);
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "(no error)";
}

// The one object of a script's scene.
inline SolidPtr solidOf(const std::string& source, const ScriptOptions& options = {}) {
  Scene scene = runScript(source, "part.lua", options);
  EXPECT_EQ(scene.objects.size(), 1u) << source;
  return scene.objects.at(0);
}

// A test name from a script's path: its stem, other characters as '_'.
inline std::string exampleName(const std::string& path) {
  std::string name = std::filesystem::path(path).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// The spans of a ray, as a value.
// The primitives of a solid's tree (the leaves of its booleans).
inline int primitivesOf(const Solid& solid) {
  if (solid.children().empty()) return 1;
  int n = 0;
  for (const SolidPtr& child : solid.children()) n += primitivesOf(*child);
  return n;
}

inline SpanList spansOf(const Solid& solid, const Ray& ray) {
  SpanList out;
  solid.spans(ray, out);
  return out;
}

inline void expectVecNear(const dvec3& actual, const dvec3& expected, double tol) {
  EXPECT_NEAR(actual.x, expected.x, tol);
  EXPECT_NEAR(actual.y, expected.y, tol);
  EXPECT_NEAR(actual.z, expected.z, tol);
}

// A random unit vector, uniform on the sphere.
inline dvec3 randomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  dvec3 d;
  do d = dvec3(n(rng), n(rng), n(rng));
  while (glm::length(d) < 1e-6);
  return glm::normalize(d);
}

// A random point in the box.
inline dvec3 randomPoint(std::mt19937_64& rng, const Bounds& box) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return box.lo + dvec3(u(rng), u(rng), u(rng)) * box.size();
}

// A ray in a random direction through a random point of the solid (or,
// one time in four, of its box), starting 200 units before that point.
inline Ray randomRayThrough(std::mt19937_64& rng, const Solid& solid) {
  dvec3 p = randomPoint(rng, solid.bounds());
  if (rng() % 4 != 0)
    while (!solid.contains(p)) p = randomPoint(rng, solid.bounds());
  const dvec3 d = randomDirection(rng);
  return Ray(p - 200.0 * d, d);
}

// The spans of the whole line through the ray must be a valid span list,
// and contains() must agree with them: the middle of every span is inside,
// the middle of every gap between spans is outside. A line (tMin = -inf)
// is used so that unbounded spans are tested too.
inline void expectSpansAgreeWithContains(const Solid& solid, const Ray& line) {
  SpanList spans;
  solid.spans(line, spans);
  ASSERT_TRUE(spans.valid());
  auto midpoint = [](double a, double b) {
    if (std::isinf(a) && std::isinf(b)) return 0.0;
    if (std::isinf(a)) return b - 1.0 - std::abs(b);
    if (std::isinf(b)) return a + 1.0 + std::abs(a);
    return 0.5 * (a + b);
  };
  for (const Span& s : spans) {
    if (s.length() < 1e-9) continue;
    double t = midpoint(s.in.t, s.out.t);
    EXPECT_TRUE(solid.contains(line.at(t))) << "span [" << s.in.t << ", " << s.out.t << "] t=" << t;
  }
  for (uint32_t i = 0; i <= spans.size(); ++i) {
    double a = i == 0 ? -kInfinity : spans[i - 1].out.t;
    double b = i == spans.size() ? kInfinity : spans[i].in.t;
    if (a == b || b - a < 1e-9) continue;  // a == b: no gap before a span from -inf
    double t = midpoint(a, b);
    EXPECT_FALSE(solid.contains(line.at(t))) << "gap [" << a << ", " << b << "] t=" << t;
  }
}

// Many random lines through points near the solid's bounds (or near the
// origin for an unbounded solid).
inline void expectSpansAgreeWithContainsOnRandomLines(const Solid& solid, int count = 2000,
                                                      unsigned seed = 1) {
  std::mt19937_64 rng(seed);
  Bounds box = solid.bounds();
  if (!box.finite()) box = Bounds{dvec3(-5.0), dvec3(5.0)};
  dvec3 pad = 0.1 * box.size();
  Bounds around{box.lo - pad, box.hi + pad};
  for (int i = 0; i < count; ++i) {
    Ray line(randomPoint(rng, around), randomDirection(rng), -kInfinity, kInfinity);
    expectSpansAgreeWithContains(solid, line);
    if (::testing::Test::HasFailure()) return;
  }
}

// The first boundary within [ray.tMin, ray.tMax] after tMin, and whether
// the ray enters there (as the renderer takes it); none if there is none.
inline std::optional<std::pair<Boundary, bool>> firstBoundary(const SpanList& spans,
                                                              const Ray& ray) {
  for (const Span& s : spans) {
    const bool entering = s.in.t > ray.tMin;
    const Boundary& b = entering ? s.in : s.out;
    if (b.t <= ray.tMin) continue;
    if (b.t > ray.tMax) break;
    return std::pair{b, entering};
  }
  return std::nullopt;
}

// How many rays met the solid, and how many of those entered it first.
struct FirstBoundaryCounts {
  int hits = 0, entries = 0;
};

// spansToFirstBoundary gives the first boundary of the whole spans, bit for
// bit, on rays from around the solid through a point of its box and from
// such a point in any direction, over windows that start and end anywhere.
inline FirstBoundaryCounts expectFirstBoundaryAgreesWithTheWholeSpans(const Solid& solid, int count,
                                                                      unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Bounds box = solid.bounds();
  const dvec3 pad = 0.5 * box.size();
  FirstBoundaryCounts counts;
  for (int r = 0; r < count; ++r) {
    const dvec3 from = randomPoint(rng, Bounds{box.lo - pad, box.hi + pad});
    const dvec3 through = randomPoint(rng, box);
    if (from == through) continue;
    Ray ray(from, glm::normalize(through - from));
    // Every other ray from a point of the box (inside the solid or not).
    if (r % 2) ray = Ray(through, randomDirection(rng));
    const double reach = glm::length(box.size());
    if (r % 3 == 1) ray.tMin = 2.0 * reach * u(rng);
    if (r % 5 == 2) ray.tMax = ray.tMin + 2.0 * reach * u(rng);
    SpanList whole, first;
    solid.spans(ray, whole);
    solid.spansToFirstBoundary(ray, first);
    const auto expected = firstBoundary(whole, ray), actual = firstBoundary(first, ray);
    EXPECT_EQ(actual.has_value(), expected.has_value()) << "ray " << r;
    if (!expected || !actual) continue;
    ++counts.hits;
    counts.entries += expected->second;
    EXPECT_EQ(actual->first.t, expected->first.t) << "ray " << r;
    EXPECT_EQ(actual->first.primitive, expected->first.primitive);
    EXPECT_EQ(actual->first.face, expected->first.face);
    EXPECT_EQ(actual->second, expected->second);
  }
  return counts;
}

// Volume from span lengths on a grid of parallel rays along z through the
// box (the midpoint rule in x and y, exact along z).
inline double gridVolume(const Solid& solid, const Bounds& box, int n) {
  double dx = box.size().x / n, dy = box.size().y / n;
  double volume = 0.0;
  SpanList spans;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      dvec3 o(box.lo.x + (i + 0.5) * dx, box.lo.y + (j + 0.5) * dy, box.lo.z - 1.0);
      Ray ray(o, dvec3(0, 0, 1), -kInfinity, kInfinity);
      solid.spans(ray, spans);
      // The ray starts at z = lo.z - 1, so t = z - lo.z + 1: clip in t.
      volume += spans.lengthWithin(0.0, box.size().z + 2.0) * dx * dy;
    }
  }
  return volume;
}

// On random lines, every finite boundary names the primitive and its normal
// there is a unit vector facing against the ray where it enters and along
// the ray where it leaves (outward normals), up to slack.
inline void expectOutwardUnitNormals(const Primitive& p, double slack = 1e-9, int count = 500,
                                     unsigned seed = 7) {
  std::mt19937_64 rng(seed);
  Bounds box = p.bounds();
  if (!box.finite()) box = Bounds{dvec3(-5.0), dvec3(5.0)};
  for (int i = 0; i < count; ++i) {
    Ray line(randomPoint(rng, box), randomDirection(rng), -kInfinity, kInfinity);
    for (const Span& s : spansOf(p, line)) {
      if (s.length() < 1e-9) continue;  // tangent: the normal is perpendicular
      for (bool entering : {true, false}) {
        const Boundary& b = entering ? s.in : s.out;
        if (std::isinf(b.t)) {
          EXPECT_EQ(b.primitive, nullptr);
          continue;
        }
        ASSERT_EQ(b.primitive, &p);
        dvec3 n = p.normal(line.at(b.t), b.face);
        EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
        double along = glm::dot(n, line.dir);
        if (entering) {
          EXPECT_LE(along, slack) << "entering at t=" << b.t << " face " << int(b.face);
        } else {
          EXPECT_GE(along, -slack) << "leaving at t=" << b.t << " face " << int(b.face);
        }
      }
    }
    if (::testing::Test::HasFailure()) return;
  }
}

// The 4 × 4 matrix with x, y, z, w on its diagonal.
inline glm::dmat4 diagonal(double x, double y, double z, double w) {
  glm::dmat4 m(0.0);
  m[0][0] = x;
  m[1][1] = y;
  m[2][2] = z;
  m[3][3] = w;
  return m;
}

// Is t inside one of the spans (ends included)?
inline bool member(const SpanList& spans, double t) {
  for (const Span& s : spans)
    if (s.in.t <= t && t <= s.out.t) return true;
  return false;
}

// Lines whose origin is exactly the special point p (an apex, a point of a
// rim, a corner), where the surface is not smooth. The spans must be a valid
// list, and contains() must agree with them at probes on both sides of p
// and in the middle of every span and gap, away from span ends.
inline void expectAgreementOnLinesThrough(const Solid& solid, const dvec3& p, int count = 500,
                                          unsigned seed = 3) {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < count; ++i) {
    Ray line(p, randomDirection(rng), -kInfinity, kInfinity);
    SpanList spans = spansOf(solid, line);
    ASSERT_TRUE(spans.valid());
    std::vector<double> probes = {-3.0, -1.0, -0.25, 0.25, 1.0, 3.0};
    for (uint32_t k = 0; k < spans.size(); ++k) {
      if (std::isfinite(spans[k].length()))
        probes.push_back(0.5 * (spans[k].in.t + spans[k].out.t));
      if (k > 0) probes.push_back(0.5 * (spans[k - 1].out.t + spans[k].in.t));
    }
    for (double t : probes) {
      bool nearEnd = false;
      for (const Span& s : spans)
        nearEnd = nearEnd || std::abs(t - s.in.t) < 1e-9 || std::abs(t - s.out.t) < 1e-9;
      if (nearEnd) continue;
      EXPECT_EQ(solid.contains(line.at(t)), member(spans, t))
          << "t=" << t << " dir=(" << line.dir.x << ", " << line.dir.y << ", " << line.dir.z << ")";
    }
    if (::testing::Test::HasFailure()) return;
  }
}

// A camera on −y, 50 from the origin, looking at it along +y with z up,
// orthographic over `width` model units: pixel columns map straight to x.
inline CameraSpec frontOrthographicCamera(double width) {
  CameraSpec front;
  front.eye = {0.0, -50.0, 0.0};
  front.lookAt = {0.0, 0.0, 0.0};
  front.up = {0.0, 0.0, 1.0};
  front.orthographic = true;
  front.orthoWidth = width;
  return front;
}

}  // namespace csgray::detail::test
