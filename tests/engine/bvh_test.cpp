// The bounding volume hierarchy: it visits exactly the items whose boxes a
// ray meets, and boolean nodes that traverse it give the same span lists
// as the plain fold of every operand's spans, on random rays and windows.
#include "engine/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/sphere.h"
#include "raytrace/renderer.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::randomDirection;
using test::randomPoint;

const Bounds kWorld{dvec3(-10.0), dvec3(10.0)};

std::vector<Bounds> randomBoxes(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> size(0.01, 2.0);
  std::vector<Bounds> boxes;
  for (int i = 0; i < n; ++i) {
    dvec3 lo = randomPoint(rng, kWorld);
    boxes.push_back({lo, lo + dvec3(size(rng), size(rng), size(rng))});
  }
  return boxes;
}

// n random boxes, then an empty one (never visited) at n, an unbounded
// one (always visited) at n + 1 and one unbounded along z at n + 2.
std::vector<Bounds> randomBoxesAndOthers(std::mt19937_64& rng, int n) {
  std::vector<Bounds> boxes = randomBoxes(rng, n);
  boxes.push_back(Bounds{});
  boxes.push_back(Bounds::everything());
  boxes.push_back({dvec3(0, 0, -kInfinity), dvec3(1, 1, kInfinity)});
  return boxes;
}

Ray randomRay(std::mt19937_64& rng) {
  return Ray(randomPoint(rng, Bounds{dvec3(-15.0), dvec3(15.0)}), randomDirection(rng));
}

TEST(Bvh, VisitsExactlyTheItemsWhoseBoxesTheRayMeets) {
  std::mt19937_64 rng(1);
  for (int n : {1, 2, 3, 7, 64, 1000}) {
    const std::vector<Bounds> boxes = randomBoxesAndOthers(rng, n);
    Bvh bvh(boxes);
    for (int r = 0; r < 300; ++r) {
      Ray ray = randomRay(rng);
      ray.tMin = r % 3 == 0 ? -kInfinity : 0.0;
      ray.tMax = r % 5 == 0 ? 12.0 : kInfinity;
      std::set<std::uint32_t> expected, visited;
      for (std::uint32_t i = 0; i < boxes.size(); ++i)
        if (boxes[i].finite() && boxEntry(boxes[i], ray, ray.tMin, ray.tMax) != kInfinity)
          expected.insert(i);
      double tMax = ray.tMax;
      bvh.traverse(ray, tMax, [&](std::uint32_t item, double) {
        EXPECT_TRUE(visited.insert(item).second) << "item " << item << " visited twice";
        return true;
      });
      EXPECT_TRUE(visited.count(std::uint32_t(n + 1))) << "the unbounded item is always visited";
      EXPECT_FALSE(visited.count(std::uint32_t(n))) << "the empty box is never visited";
      visited.erase(std::uint32_t(n + 1));
      visited.erase(std::uint32_t(n + 2));
      ASSERT_EQ(visited, expected) << "n = " << n << ", ray " << r;
    }
  }
}

TEST(Bvh, VisitsExactlyTheItemsWhoseBoxesHoldAPoint) {
  std::mt19937_64 rng(11);
  for (int n : {1, 2, 3, 7, 64, 1000}) {
    const std::vector<Bounds> boxes = randomBoxesAndOthers(rng, n);
    Bvh bvh(boxes);
    for (int r = 0; r < 300; ++r) {
      // Points anywhere, and on a box's corner (held: boxes are closed).
      const dvec3 p = r % 4 == 0 ? boxes[r % n].hi : randomPoint(rng, kWorld);
      std::set<std::uint32_t> expected, visited;
      // Unbounded items are visited whatever the point, the empty box never.
      for (std::uint32_t i = 0; i < boxes.size(); ++i)
        if (i != std::uint32_t(n) && (!boxes[i].finite() || boxes[i].contains(p)))
          expected.insert(i);
      bvh.forEachHolding(p, 0.0, [&](std::uint32_t item) {
        EXPECT_TRUE(visited.insert(item).second) << "item " << item << " visited twice";
        return true;
      });
      ASSERT_EQ(visited, expected) << "n = " << n << ", point " << r;
    }
  }
}

// Trees of one to five boxes (one bounded box takes a path of its own)
// visit a box with the entry t of its slab test, also for rays parallel to
// an axis that run in the plane of a face (0·inf in the test).
TEST(Bvh, EntryIsTheBoxsSlabTest) {
  std::mt19937_64 rng(5);
  int met = 0;
  for (int n = 1; n <= 5; ++n) {
    const std::vector<Bounds> boxes = randomBoxes(rng, n);
    const Bvh bvh(boxes);
    for (int r = 0; r < 400; ++r) {
      Ray ray = randomRay(rng);
      if (r % 4 == 0) {  // along y, in the plane of box 0's low x face
        ray = Ray(dvec3(boxes[0].lo.x, -15.0, boxes[0].center().z), dvec3(0, 1, 0));
      }
      double tMax = ray.tMax;
      std::set<std::uint32_t> visited;
      bvh.traverse(ray, tMax, [&](std::uint32_t item, double t) {
        EXPECT_EQ(t, boxEntry(boxes[item], ray, ray.tMin, ray.tMax)) << n << " " << r;
        visited.insert(item);
        return true;
      });
      for (std::uint32_t i = 0; i < boxes.size(); ++i)
        EXPECT_EQ(visited.count(i) == 1, boxEntry(boxes[i], ray, ray.tMin, ray.tMax) != kInfinity)
            << n << " " << r << " " << i;
      met += int(visited.size());
    }
  }
  EXPECT_GT(met, 300);
}

TEST(Bvh, PruningByTMaxFindsTheNearestBox) {
  std::mt19937_64 rng(2);
  std::vector<Bounds> boxes = randomBoxes(rng, 500);
  Bvh bvh(boxes);
  for (int r = 0; r < 500; ++r) {
    Ray ray = randomRay(rng);
    double nearest = kInfinity;
    for (const Bounds& b : boxes) nearest = std::min(nearest, boxEntry(b, ray, 0.0, kInfinity));
    double tMax = kInfinity, found = kInfinity;
    bvh.traverse(ray, tMax, [&](std::uint32_t item, double) {
      double t = boxEntry(boxes[item], ray, 0.0, tMax);
      EXPECT_LE(t, tMax);
      found = std::min(found, t);
      tMax = found;  // like a first-hit query: nothing beyond the best
      return true;
    });
    ASSERT_EQ(found, nearest) << "ray " << r;
  }
}

TEST(Bvh, IdenticalCentresStillMakeSmallLeaves) {
  // SAH cannot split boxes with one centre; the build halves them anyway.
  std::vector<Bounds> boxes(1000, Bounds{dvec3(0.0), dvec3(1.0)});
  Bvh bvh(boxes);
  int visited = 0;
  double tMax = kInfinity;
  bvh.traverse(Ray(dvec3(0.5, 0.5, -5), dvec3(0, 0, 1)), tMax, [&](std::uint32_t, double) {
    ++visited;
    return true;
  });
  EXPECT_EQ(visited, 1000);
  EXPECT_GT(bvh.memoryBytes(), 1000 * sizeof(Bounds));
}

TEST(Bvh, BoxesNearTheLargestDoubleAreBuiltAndFound) {
  // A box about 1e308 from its neighbours: the sum of its corners
  // overflows, so its centre was infinite, its bin's index int() of NaN,
  // and the build wrote far outside its bins (a sphere moved by 1e308 in a
  // union crashed the render). Every box is still found by a point in it.
  std::vector<Bounds> boxes;
  for (int i = 0; i < 10; ++i) boxes.push_back({dvec3(3.0 * i, 0, 0), dvec3(3.0 * i + 1, 1, 1)});
  boxes.push_back({dvec3(1.7e308, 0, 0), dvec3(1.79e308, 1, 1)});
  boxes.push_back({dvec3(-1.79e308, 0, 0), dvec3(-1.7e308, 1, 1)});
  EXPECT_TRUE(std::isfinite(boxes[10].center().x));
  EXPECT_EQ(boxes[1].center(), dvec3(3.5, 0.5, 0.5));
  const Bvh bvh(boxes);
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    std::set<std::uint32_t> visited;
    bvh.forEachHolding(boxes[i].center(), 0.0, [&](std::uint32_t item) {
      visited.insert(item);
      return true;
    });
    EXPECT_EQ(visited, std::set<std::uint32_t>{i}) << "box " << i;
  }
}

// Random solids: spheres, boxes, cylinders, and now and then a half-space.
std::vector<SolidPtr> randomSolids(std::mt19937_64& rng, int n, bool withHalfSpaces) {
  std::uniform_real_distribution<double> u(0.2, 1.5);
  std::vector<SolidPtr> solids;
  for (int i = 0; i < n; ++i) {
    Affine at = Affine::translation(randomPoint(rng, Bounds{dvec3(-8.0), dvec3(8.0)}));
    switch (i % 3) {
      case 0:
        solids.push_back(Primitive::create<Sphere>(u(rng))->transformed(at));
        break;
      case 1:
        solids.push_back(Primitive::create<Box>(dvec3(u(rng), u(rng), u(rng)))->transformed(at));
        break;
      default:
        solids.push_back(Primitive::create<Cylinder>(u(rng), u(rng), u(rng))->transformed(at));
    }
    if (withHalfSpaces && i % 50 == 25)
      solids.push_back(Primitive::create<HalfSpace>(randomDirection(rng), u(rng)));
  }
  return solids;
}

// The plain fold over every operand, without boxes, BVH or windows.
SpanList referenceSpans(Boolean::Op op, const std::vector<SolidPtr>& operands, const Ray& line) {
  SpanList out, operand, merged;
  operands[0]->spans(line, out);
  for (std::size_t i = 1; i < operands.size(); ++i) {
    operands[i]->spans(line, operand);
    if (op == Boolean::Op::Union) unite(out, operand, merged);
    if (op == Boolean::Op::Difference) subtract(out, operand, merged);
    if (op == Boolean::Op::Intersection) intersect(out, operand, merged);
    out = merged;
  }
  return out;
}

// Within [t0, t1] the two span lists are the same: the same stretches, and
// the same boundaries (t, primitive, flip) wherever a boundary lies inside
// the window. (Outside a window a span may end elsewhere: see solid.h.)
void expectSameWithin(const SpanList& actual, const SpanList& expected, double t0, double t1) {
  auto clipped = [&](const SpanList& list) {
    std::vector<Span> kept;
    for (Span s : list) {
      if (s.out.t < t0 || s.in.t > t1) continue;
      if (s.in.t < t0) s.in = Boundary{t0};
      if (s.out.t > t1) s.out = Boundary{t1};
      kept.push_back(s);
    }
    return kept;
  };
  std::vector<Span> a = clipped(actual), e = clipped(expected);
  ASSERT_EQ(a.size(), e.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (auto [x, y] : {std::pair{a[i].in, e[i].in}, std::pair{a[i].out, e[i].out}}) {
      EXPECT_EQ(x.t, y.t);
      EXPECT_EQ(x.primitive, y.primitive);
      EXPECT_EQ(x.flip, y.flip);
    }
  }
}

TEST(BooleanBvh, SpansEqualThePlainFoldOnRandomRays) {
  std::mt19937_64 rng(3);
  for (Boolean::Op op : {Boolean::Op::Union, Boolean::Op::Difference}) {
    for (int n : {3, 6, 40, 400}) {
      std::vector<SolidPtr> operands = randomSolids(rng, n, op == Boolean::Op::Union);
      if (op == Boolean::Op::Difference)  // a big first operand, many cutters
        operands.insert(
            operands.begin(),
            Primitive::create<Box>(dvec3(14.0))->transformed(Affine::translation(dvec3(-7.0))));
      Boolean node(op, operands);
      for (int r = 0; r < 400; ++r) {
        Ray ray = randomRay(rng);
        Ray line(ray.origin, ray.dir, -kInfinity, kInfinity);
        SpanList expected = referenceSpans(op, operands, line);
        // The whole line, and a window that starts or ends inside solids.
        SpanList actual;
        node.spans(line, actual);
        ASSERT_TRUE(actual.valid());
        expectSameWithin(actual, expected, -kInfinity, kInfinity);
        Ray window(ray.origin, ray.dir, 3.0, 15.0);
        node.spans(window, actual);
        ASSERT_TRUE(actual.valid());
        expectSameWithin(actual, expected, 3.0, 15.0);
        if (::testing::Test::HasFailure())
          FAIL() << "op " << int(op) << ", n = " << n << ", ray " << r;
      }
    }
  }
}

TEST(BooleanBvh, ContainsEqualsThePlainFoldAtRandomPoints) {
  // A union, and a difference of many cutters, asked through the tree,
  // against every operand asked in turn.
  std::mt19937_64 rng(12);
  for (Boolean::Op op : {Boolean::Op::Union, Boolean::Op::Difference}) {
    for (int n : {3, 40, 400}) {
      std::vector<SolidPtr> operands = randomSolids(rng, n, op == Boolean::Op::Union);
      if (op == Boolean::Op::Difference)
        operands.insert(
            operands.begin(),
            Primitive::create<Box>(dvec3(14.0))->transformed(Affine::translation(dvec3(-7.0))));
      Boolean node(op, operands);
      int inside = 0;
      for (int r = 0; r < 2000; ++r) {
        const dvec3 p = randomPoint(rng, kWorld);
        bool expected = op == Boolean::Op::Difference && operands[0]->contains(p);
        for (std::size_t i = op == Boolean::Op::Difference ? 1 : 0; i < operands.size(); ++i)
          if (operands[i]->contains(p)) expected = op == Boolean::Op::Union;
        ASSERT_EQ(node.contains(p), expected)
            << "op " << int(op) << ", n = " << n << ", point " << r;
        inside += expected;
      }
      // (The union's half-spaces may fill the whole box.)
      EXPECT_GT(inside, 0);
      if (op == Boolean::Op::Difference) {
        EXPECT_LT(inside, 2000);
      }
    }
  }
}

TEST(BooleanBvh, IntersectionWindowsEqualThePlainFold) {
  std::mt19937_64 rng(4);
  std::vector<SolidPtr> operands;
  for (int i = 0; i < 8; ++i)
    operands.push_back(Primitive::create<Sphere>(6.0)->transformed(
        Affine::translation(randomPoint(rng, Bounds{dvec3(-1.5), dvec3(1.5)}))));
  Boolean node(Boolean::Op::Intersection, operands);
  for (int r = 0; r < 1000; ++r) {
    Ray ray = randomRay(rng);
    Ray line(ray.origin, ray.dir, -kInfinity, kInfinity);
    SpanList actual;
    node.spans(line, actual);
    expectSameWithin(actual, referenceSpans(Boolean::Op::Intersection, operands, line), -kInfinity,
                     kInfinity);
  }
}

// The first boundary within [ray.tMin, ray.tMax] after tMin, and whether
// the ray enters there; none if the window holds no boundary.
std::optional<std::pair<Boundary, bool>> firstBoundary(const SpanList& spans, const Ray& ray) {
  for (const Span& s : spans) {
    bool entering = s.in.t > ray.tMin;
    const Boundary& b = entering ? s.in : s.out;
    if (b.t <= ray.tMin) continue;
    if (b.t > ray.tMax) break;
    return std::pair{b, entering};
  }
  return std::nullopt;
}

TEST(BooleanBvh, FirstBoundaryQueriesAgreeWithTheWholeSpans) {
  std::mt19937_64 rng(6);
  auto bigBox = [] {
    return Primitive::create<Box>(dvec3(14.0))->transformed(Affine::translation(dvec3(-7.0)));
  };
  // Holes given one by one (a BVH over them), as one union (the union's
  // BVH), with an intersection among them, and with a difference among
  // them, whose spans beyond a window are not its own: the plain path.
  std::vector<SolidPtr> cutters = randomSolids(rng, 200, false);
  std::vector<SolidPtr> listed{bigBox()};
  listed.insert(listed.end(), cutters.begin(), cutters.end());
  std::vector<SolidPtr> lens = randomSolids(rng, 2, false);
  std::vector<SolidPtr> mixed = cutters;
  mixed.push_back(intersectionOf(lens));
  std::vector<SolidPtr> notched = cutters;
  notched.push_back(differenceOf({Primitive::create<Sphere>(4.0), Primitive::create<Sphere>(3.0)}));
  // Overlapping holes, so that a cut moves the start into the next one.
  std::vector<SolidPtr> foam;
  for (double x = -6.0; x <= 6.0; x += 1.5)
    for (double y = -6.0; y <= 6.0; y += 1.5)
      for (double z = -6.0; z <= 6.0; z += 1.5)
        foam.push_back(Primitive::create<Sphere>(0.9)->transformed(
            Affine::translation(dvec3(x, y, z) + 0.3 * randomDirection(rng))));
  std::vector<SolidPtr> foamListed{bigBox()};
  foamListed.insert(foamListed.end(), foam.begin(), foam.end());
  std::vector<SolidPtr> parts{
      differenceOf({bigBox(), unionOf(foam)}),
      differenceOf(foamListed),
      differenceOf(listed),
      differenceOf({unionOf({bigBox(), unionOf(randomSolids(rng, 100, false))}), unionOf(cutters)}),
      differenceOf({bigBox(), unionOf(mixed)}),
      differenceOf({bigBox(), unionOf(notched)}),
      differenceOf({Primitive::create<Sphere>(6.0), Primitive::create<Sphere>(6.0)->transformed(
                                                        Affine::translation(dvec3(0, 0, 6)))}),
      // Unions: of many primitives (a BVH), of a few, of differences, and
      // with a half-space, which every ray from one side starts inside.
      unionOf(cutters),
      unionOf(lens),
      unionOf({differenceOf(listed), differenceOf({bigBox(), unionOf(foam)}),
               Primitive::create<Sphere>(3.0)->transformed(Affine::translation(dvec3(9, 0, 0)))}),
      unionOf({unionOf(randomSolids(rng, 30, false)),
               Primitive::create<HalfSpace>(dvec3(0, 0, 1), -8.0)}),
  };
  EXPECT_TRUE(unionOf(cutters)->insideBeyondWindow());
  EXPECT_TRUE(unionOf(mixed)->insideBeyondWindow());
  EXPECT_FALSE(unionOf(notched)->insideBeyondWindow());
  EXPECT_FALSE(parts[0]->insideBeyondWindow());
  EXPECT_TRUE(unionOf(foam)->insideBeyondWindow());
  std::uniform_real_distribution<double> u(0.0, 20.0);
  int hits = 0, entries = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    for (int r = 0; r < 2000; ++r) {
      // Rays from outside and from inside the parts, over windows that
      // start and end anywhere.
      Ray ray = randomRay(rng);
      if (r % 2) ray = Ray(randomPoint(rng, Bounds{dvec3(-7.0), dvec3(7.0)}), ray.dir);
      if (r % 3 == 1) ray.tMin = u(rng);
      if (r % 5 == 2) ray.tMax = ray.tMin + u(rng);
      SpanList whole, first;
      parts[k]->spans(ray, whole);
      parts[k]->spansToFirstBoundary(ray, first);
      auto expected = firstBoundary(whole, ray), actual = firstBoundary(first, ray);
      ASSERT_EQ(actual.has_value(), expected.has_value()) << "part " << k << ", ray " << r;
      if (!expected) continue;
      ++hits;
      entries += expected->second;
      EXPECT_EQ(actual->first.t, expected->first.t) << "part " << k << ", ray " << r;
      EXPECT_EQ(actual->first.primitive, expected->first.primitive);
      EXPECT_EQ(actual->first.face, expected->first.face);
      EXPECT_EQ(actual->first.flip, expected->first.flip);
      EXPECT_EQ(actual->second, expected->second);
    }
  }
  // Most rays meet a part, both entering it and leaving it first.
  EXPECT_GT(hits, 3000);
  EXPECT_GT(entries, 500);
  EXPECT_LT(entries, hits - 1000);
}

// The renderer's BVH over the scene's objects finds the nearest surface
// that testing every object finds.
TEST(SceneBvh, FirstHitIsTheNearestOfAllObjects) {
  std::mt19937_64 rng(5);
  Scene scene;
  scene.objects = randomSolids(rng, 300, false);
  scene.surfaces.push_back(Surface::plane(dvec3(0, 0, -9), dvec3(0, 0, 1)));
  scene.camera = CameraSpec{dvec3(0, -30, 0), dvec3(0), dvec3(0, 0, 1), 45.0};
  Renderer renderer(scene, {16, 16, 1});
  for (int r = 0; r < 2000; ++r) {
    Ray ray = randomRay(rng);
    double nearest = kInfinity;
    for (const SolidPtr& s : scene.objects) {
      SpanList spans;
      s->spans(ray, spans);
      for (const Span& span : spans) {
        double t = span.in.t > ray.tMin ? span.in.t : span.out.t;
        if (t > ray.tMin) {
          nearest = std::min(nearest, t);
          break;
        }
      }
    }
    if (std::optional<double> t = scene.surfaces[0]->hit(ray)) nearest = std::min(nearest, *t);
    std::optional<SurfaceHit> hit = renderer.firstHit(ray);
    if (nearest == kInfinity) {
      EXPECT_FALSE(hit) << "ray " << r;
    } else {
      ASSERT_TRUE(hit) << "ray " << r;
      EXPECT_EQ(hit->t, nearest) << "ray " << r;
    }
  }
}

}  // namespace
}  // namespace csgray::detail
