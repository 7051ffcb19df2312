// Textures: the checker's cells lie where its formula puts them and move
// with the placement; each image mapping fetches the expected texel
// (upright, repeating, filtered between texel centres); the noise is
// Perlin's improved noise (zero on the lattice, bounded, continuous, equal
// to the reference implementation); and texture images read back from
// files as linear RGB, with one-line errors naming the file.
#include "scene/texture.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/image_file.h"
#include "io/scratch_folder.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

using test::expectVecNear;

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const dvec3 kA(1.0, 0.0, 0.0);
const dvec3 kB(0.0, 0.0, 1.0);
const dvec3 kUp(0.0, 0.0, 1.0);

// The factories hand out const textures; they are created non-const, so
// placing one through a const_pointer_cast is well defined.
TexturePtr placed(TexturePtr texture, const Affine& placement) {
  std::const_pointer_cast<Texture>(texture)->setPlacement(placement);
  return texture;
}

// ------------------------------------------------------------------ checker

// A linear gradient: a at `from`, b at `to`, the share t = (p − from)·(to −
// from) / |to − from|² of the way between, constant past either end and
// across the line.
TEST(GradientTexture, BlendsAlongTheLineAndPadsBeyond) {
  const dvec3 a(1, 0, 0), b(0, 0, 1), from(1, 2, 3), to(3, 2, 3);
  const TexturePtr t = placedGradient(ColorPair(a, b), from, to, {});
  const dvec3 n(0, 0, 1);
  expectVecNear(t->colorAt(from, n), a, 1e-15);
  expectVecNear(t->colorAt(to, n), b, 1e-15);
  expectVecNear(t->colorAt(dvec3(1.5, 2, 3), n), 0.75 * a + 0.25 * b, 1e-15);
  expectVecNear(t->colorAt(dvec3(1.5, -7, 40), n), 0.75 * a + 0.25 * b, 1e-15);  // across
  expectVecNear(t->colorAt(dvec3(-5, 2, 3), n), a, 0.0);
  expectVecNear(t->colorAt(dvec3(50, 2, 3), n), b, 0.0);
  EXPECT_THROW(placedGradient(std::nullopt, from, from, {}), std::invalid_argument);
  EXPECT_THROW(placedGradient(std::nullopt, dvec3(-1e300, 0, 0), dvec3(1e300, 0, 0), {}),
               std::invalid_argument);
}

TEST(CheckerTexture, CellCentresFollowTheParityOfTheCellIndices) {
  TexturePtr checker = checkerTexture(kA, kB, 1.0);
  for (int i = -3; i <= 2; ++i)
    for (int j = -3; j <= 2; ++j)
      for (int k = -3; k <= 2; ++k) {
        dvec3 centre(i + 0.5, j + 0.5, k + 0.5);
        dvec3 expected = (i + j + k) % 2 == 0 ? kA : kB;
        EXPECT_EQ(checker->colorAt(centre, kUp), expected) << i << " " << j << " " << k;
      }
}

TEST(CheckerTexture, OneCellStepAlongAnyAxisSwapsTheColour) {
  TexturePtr checker = checkerTexture(kA, kB, 1.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-20.0, 20.0);
  const dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int n = 0; n < 200; ++n) {
    // A cell centre, so that the step never lands on a boundary.
    dvec3 p = glm::floor(dvec3(coord(rng), coord(rng), coord(rng))) + 0.5;
    dvec3 here = checker->colorAt(p, kUp);
    for (const dvec3& axis : axes) {
      EXPECT_NE(checker->colorAt(p + axis, kUp), here);
      EXPECT_NE(checker->colorAt(p - axis, kUp), here);
      EXPECT_EQ(checker->colorAt(p + 2.0 * axis, kUp), here);
    }
  }
}

TEST(CheckerTexture, ColourIsConstantWithinACell) {
  TexturePtr checker = checkerTexture(kA, kB, 1.0);
  // Cell (0, 0, 0) is a, cell (-1, 0, 0) is b, near their shared face.
  EXPECT_EQ(checker->colorAt({0.01, 0.5, 0.5}, kUp), kA);
  EXPECT_EQ(checker->colorAt({0.99, 0.01, 0.99}, kUp), kA);
  EXPECT_EQ(checker->colorAt({-0.01, 0.5, 0.5}, kUp), kB);
  EXPECT_EQ(checker->colorAt({-0.99, 0.99, 0.01}, kUp), kB);
}

TEST(CheckerTexture, SizeScalesTheCells) {
  const double size = 2.5;
  TexturePtr checker = checkerTexture(kA, kB, size);
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      dvec3 centre = size * dvec3(i + 0.5, j + 0.5, 0.5);
      EXPECT_EQ(checker->colorAt(centre, kUp), (i + j) % 2 == 0 ? kA : kB) << i << " " << j;
    }
  // 1.2 and 2.4 lie in the same cell of size 2.5, though not of size 1.
  EXPECT_EQ(checker->colorAt({1.2, 0.5, 0.5}, kUp), checker->colorAt({2.4, 0.5, 0.5}, kUp));
}

TEST(CheckerTexture, FarFromTheOriginStillAlternates) {
  TexturePtr checker = checkerTexture(kA, kB, 1.0);
  // Cell indices beyond the range of int: parity is taken in floating point.
  double x = 1e12 + 0.5;
  EXPECT_EQ(checker->colorAt({x, 0.5, 0.5}, kUp), kA);
  EXPECT_EQ(checker->colorAt({x + 1.0, 0.5, 0.5}, kUp), kB);
  EXPECT_EQ(checker->colorAt({-x, 0.5, 0.5}, kUp), kB);  // cell -1e12 - 1 is odd
}

// The parity is the one fmod(k, 2) gives for the cell index k, wherever
// the point is: beyond 2^53 (where every double is even), at ±0, and off
// to infinity or NaN (odd).
TEST(CheckerTexture, ParityIsTheRemainderOfTheCellIndexEverywhere) {
  TexturePtr checker = checkerTexture(kA, kB, 1.0);
  auto expected = [](double x) {
    const double k = std::floor(x + 1e-6);
    return std::fmod(k, 2.0) != 0.0 ? kB : kA;
  };
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> exponent(-3.0, 300.0);
  std::vector<double> xs = {0.0,
                            -0.0,
                            0.5,
                            -0.5,
                            9007199254740992.0,
                            9007199254740994.0,
                            -9007199254740993.5,
                            1e300,
                            -1e300,
                            std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::quiet_NaN()};
  for (int n = 0; n < 2000; ++n) xs.push_back((n % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng)));
  int odd = 0;
  for (double x : xs) {
    const dvec3 colour = checker->colorAt({x, 0.5, 0.5}, kUp);
    EXPECT_EQ(colour, expected(x)) << x;
    odd += colour == kB;
  }
  EXPECT_GT(odd, 3);  // both parities occur (small indices alternate)
}

TEST(CheckerTexture, TranslationMovesThePattern) {
  TexturePtr checker = placed(checkerTexture(kA, kB, 1.0), Affine::translation({0.5, 0.0, 0.0}));
  // The cell boundaries are now at x = k + 0.5: x in (0.5, 1.5) is cell 0.
  EXPECT_EQ(checker->colorAt({1.0, 0.5, 0.5}, kUp), kA);
  EXPECT_EQ(checker->colorAt({0.25, 0.5, 0.5}, kUp), kB);
  EXPECT_EQ(checker->colorAt({0.75, 0.5, 0.5}, kUp), kA);
  EXPECT_EQ(checker->colorAt({1.75, 0.5, 0.5}, kUp), kB);
  // Unplaced, 0.25 and 0.75 share cell 0.
  TexturePtr plain = checkerTexture(kA, kB, 1.0);
  EXPECT_EQ(plain->colorAt({0.25, 0.5, 0.5}, kUp), kA);
}

TEST(CheckerTexture, ScalingPlacementEnlargesTheCells) {
  TexturePtr checker = placed(checkerTexture(kA, kB, 1.0), Affine::scaling({3.0, 1.0, 1.0}));
  // Cells are 3 long in x, still 1 in y.
  EXPECT_EQ(checker->colorAt({0.5, 0.5, 0.5}, kUp), kA);
  EXPECT_EQ(checker->colorAt({2.9, 0.5, 0.5}, kUp), kA);
  EXPECT_EQ(checker->colorAt({3.1, 0.5, 0.5}, kUp), kB);
  EXPECT_EQ(checker->colorAt({2.9, 1.5, 0.5}, kUp), kB);
}

TEST(CheckerTexture, RotationPlacementTurnsThePattern) {
  // Rotated 45° about z, cells are diamonds: points on the x axis at
  // distance d lie at pattern coordinates (d/√2, -d/√2).
  TexturePtr checker =
      placed(checkerTexture(kA, kB, 1.0), Affine::rotation(kPi / 4.0, {0.0, 0.0, 1.0}));
  double s = std::sqrt(2.0);
  EXPECT_EQ(checker->colorAt({0.5 * s, 0.0, 0.5}, kUp), kB);  // pattern (0.5, -0.5)
  EXPECT_EQ(checker->colorAt({0.0, 0.5 * s, 0.5}, kUp), kA);  // pattern (0.5, 0.5)
  EXPECT_EQ(checker->colorAt({1.5 * s, 0.0, 0.5}, kUp), kB);  // pattern (1.5, -1.5)
}

TEST(CheckerTexture, RefusesBadSizes) {
  for (double size : {0.0, -1.0, kNaN, std::numeric_limits<double>::infinity()})
    EXPECT_THROW(checkerTexture(kA, kB, size), std::invalid_argument) << size;
}

// -------------------------------------------------------------------- image

// A 4x2 image whose texel (x, row) is (x, row, 10 + x + 4 row): every texel
// distinct, and each channel linear in the texel indices.
std::shared_ptr<TextureImage> testImage() {
  auto image = std::make_shared<TextureImage>();
  image->width = 4;
  image->height = 2;
  for (int row = 0; row < 2; ++row)
    for (int x = 0; x < 4; ++x) {
      image->rgb.push_back(static_cast<float>(x));
      image->rgb.push_back(static_cast<float>(row));
      image->rgb.push_back(static_cast<float>(10 + x + 4 * row));
    }
  return image;
}

dvec3 texel(int x, int row) { return {x, row, 10 + x + 4 * row}; }

// Texture coordinates of the centre of texel (x, row): v = 0 is the bottom.
double uOf(int x) { return (x + 0.5) / 4.0; }
double vOf(int row) { return 1.0 - (row + 0.5) / 2.0; }

constexpr double kTol = 1e-9;

TEST(ImageTexture, PlanarFetchesTexelsUpright) {
  TexturePtr tex = imageTexture(testImage(), ImageMapping::Planar);
  for (int row = 0; row < 2; ++row)
    for (int x = 0; x < 4; ++x)
      expectVecNear(tex->colorAt({uOf(x), vOf(row), 0.0}, kUp), texel(x, row), kTol);
  // Image row 0 is the top: it is at the larger y.
  expectVecNear(tex->colorAt({uOf(0), 0.75, 0.0}, kUp), texel(0, 0), kTol);
  expectVecNear(tex->colorAt({uOf(0), 0.25, 0.0}, kUp), texel(0, 1), kTol);
}

TEST(ImageTexture, PlanarRepeatsEveryUnitAndIgnoresZ) {
  TexturePtr tex = imageTexture(testImage(), ImageMapping::Planar);
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j)
      for (int row = 0; row < 2; ++row)
        for (int x = 0; x < 4; ++x)
          expectVecNear(tex->colorAt({uOf(x) + i, vOf(row) + j, 3.7 * i - j}, kUp), texel(x, row),
                        kTol);
}

TEST(ImageTexture, FiltersBilinearlyBetweenTexelCentres) {
  TexturePtr tex = imageTexture(testImage(), ImageMapping::Planar);
  // Half-way between texels 1 and 2 of the bottom row.
  expectVecNear(tex->colorAt({0.5, vOf(1), 0.0}, kUp), 0.5 * (texel(1, 1) + texel(2, 1)), kTol);
  // The middle of four texel centres.
  expectVecNear(tex->colorAt({0.5, 0.5, 0.0}, kUp),
                0.25 * (texel(1, 0) + texel(2, 0) + texel(1, 1) + texel(2, 1)), kTol);
  // A quarter of the way from texel 0 to texel 1.
  expectVecNear(tex->colorAt({uOf(0) + 0.25 / 4.0, vOf(0), 0.0}, kUp),
                0.75 * texel(0, 0) + 0.25 * texel(1, 0), kTol);
  // At u = 0 the filter wraps: half of texel 3 and half of texel 0.
  expectVecNear(tex->colorAt({0.0, vOf(0), 0.0}, kUp), 0.5 * (texel(3, 0) + texel(0, 0)), kTol);
  // At v = 0 too: half of the bottom row and half of the top.
  expectVecNear(tex->colorAt({uOf(2), 0.0, 0.0}, kUp), 0.5 * (texel(2, 1) + texel(2, 0)), kTol);
  // And continuously across the seam.
  dvec3 below = tex->colorAt({-1e-9, vOf(0), 0.0}, kUp);
  dvec3 above = tex->colorAt({1e-9, vOf(0), 0.0}, kUp);
  expectVecNear(below, above, 1e-6);
}

// A point at longitude lon (about z, from +x) and latitude lat, radius r.
dvec3 onSphere(double lon, double lat, double r) {
  return r * dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
}

// u = atan2(y, x)/2π + 0.5: texel x is centred at longitude (uOf(x) - 0.5)·2π,
// i.e. -135°, -45°, 45°, 135°.
double longitudeOf(int x) { return (uOf(x) - 0.5) * 2.0 * kPi; }

TEST(ImageTexture, SphericalFetchesByLongitudeAndLatitude) {
  TexturePtr tex = imageTexture(testImage(), ImageMapping::Spherical);
  // v = 0.5 + lat/π: the top row is centred at 45° north, the bottom at 45° south.
  for (double r : {0.5, 1.0, 7.0})
    for (int x = 0; x < 4; ++x) {
      expectVecNear(tex->colorAt(onSphere(longitudeOf(x), kPi / 4, r), kUp), texel(x, 0), kTol);
      expectVecNear(tex->colorAt(onSphere(longitudeOf(x), -kPi / 4, r), kUp), texel(x, 1), kTol);
    }
  // Longitude -135° is the -x,-y quadrant: u = 0.125, texel 0.
  expectVecNear(tex->colorAt({-1.0, -1.0, std::sqrt(2.0)}, kUp), texel(0, 0), kTol);
  // Longitude 0 (+x) is u = 0.5, half-way between texels 1 and 2.
  expectVecNear(tex->colorAt(onSphere(0.0, -kPi / 4, 1.0), kUp), 0.5 * (texel(1, 1) + texel(2, 1)),
                kTol);
}

TEST(ImageTexture, SphericalPolesTakeTheEdgeRowsOnly) {
  TexturePtr tex = imageTexture(testImage(), ImageMapping::Spherical);
  // Within half a texel of a pole, v does not wrap to the other pole's row.
  expectVecNear(tex->colorAt(onSphere(longitudeOf(2), 0.45 * kPi, 1.0), kUp), texel(2, 0), kTol);
  expectVecNear(tex->colorAt(onSphere(longitudeOf(2), -0.45 * kPi, 1.0), kUp), texel(2, 1), kTol);
  // Exactly at the north pole atan2(0, 0) = 0 gives u = 0.5.
  expectVecNear(tex->colorAt({0.0, 0.0, 2.0}, kUp), 0.5 * (texel(1, 0) + texel(2, 0)), kTol);
  expectVecNear(tex->colorAt({0.0, 0.0, -2.0}, kUp), 0.5 * (texel(1, 1) + texel(2, 1)), kTol);
  // The centre has no direction; it still gives a finite colour.
  dvec3 centre = tex->colorAt({0.0, 0.0, 0.0}, kUp);
  EXPECT_TRUE(std::isfinite(centre.x) && std::isfinite(centre.y) && std::isfinite(centre.z));
}

TEST(ImageTexture, CylindricalFetchesByAngleAndHeight) {
  TexturePtr tex = imageTexture(testImage(), ImageMapping::Cylindrical);
  for (double r : {0.3, 1.0, 5.0})
    for (int k = -2; k <= 2; ++k)
      for (int row = 0; row < 2; ++row)
        for (int x = 0; x < 4; ++x) {
          dvec3 p(r * std::cos(longitudeOf(x)), r * std::sin(longitudeOf(x)), vOf(row) + k);
          expectVecNear(tex->colorAt(p, kUp), texel(x, row), kTol);
        }
}

TEST(ImageTexture, BoxPicksTheFaceByTheNormal) {
  TexturePtr tex = imageTexture(testImage(), ImageMapping::Box);
  for (int row = 0; row < 2; ++row)
    for (int x = 0; x < 4; ++x) {
      double u = uOf(x), v = vOf(row);
      dvec3 want = texel(x, row);
      // x faces: (y, z); y faces: (x, z); z faces: (x, y); the unused
      // coordinate and the sign of the normal do not matter.
      expectVecNear(tex->colorAt({0.3, u, v}, {1.0, 0.0, 0.0}), want, kTol);
      expectVecNear(tex->colorAt({-4.0, u, v}, {-1.0, 0.0, 0.0}), want, kTol);
      expectVecNear(tex->colorAt({u, 2.2, v}, {0.0, 1.0, 0.0}), want, kTol);
      expectVecNear(tex->colorAt({u, -0.6, v}, {0.0, -1.0, 0.0}), want, kTol);
      expectVecNear(tex->colorAt({u, v, 9.0}, {0.0, 0.0, 1.0}), want, kTol);
      expectVecNear(tex->colorAt({u, v, -1.5}, {0.0, 0.0, -1.0}), want, kTol);
      // Oblique normals pick the largest component.
      expectVecNear(tex->colorAt({0.3, u, v}, {-0.8, 0.5, 0.3}), want, kTol);
      expectVecNear(tex->colorAt({u, 0.3, v}, {0.4, -0.7, 0.6}), want, kTol);
      expectVecNear(tex->colorAt({u, v, 0.3}, {0.1, 0.5, 0.55}), want, kTol);
      // Repeating in both directions.
      expectVecNear(tex->colorAt({u - 3.0, v + 2.0, 0.3}, {0.0, 0.0, 1.0}), want, kTol);
    }
}

TEST(ImageTexture, BoxFaceFollowsARotatedPlacement) {
  // The pattern turned 90° about z: its x axis lies along texture-space y,
  // so a texture-space normal along y selects the pattern's x face.
  TexturePtr tex = placed(imageTexture(testImage(), ImageMapping::Box),
                          Affine::rotation(kPi / 2.0, {0.0, 0.0, 1.0}));
  Affine turn = Affine::rotation(kPi / 2.0, {0.0, 0.0, 1.0});
  for (int row = 0; row < 2; ++row)
    for (int x = 0; x < 4; ++x) {
      dvec3 local(0.3, uOf(x), vOf(row));  // on the pattern's x face
      dvec3 p = turn.pointToWorld(local);
      expectVecNear(tex->colorAt(p, {0.0, 1.0, 0.0}), texel(x, row), kTol);
    }
}

TEST(ImageTexture, PlacementScalesTheImage) {
  // Scaled by 2: one copy of the image per 2x2 square.
  TexturePtr tex =
      placed(imageTexture(testImage(), ImageMapping::Planar), Affine::scaling({2.0, 2.0, 1.0}));
  for (int row = 0; row < 2; ++row)
    for (int x = 0; x < 4; ++x)
      expectVecNear(tex->colorAt({2.0 * uOf(x), 2.0 * vOf(row), 0.0}, kUp), texel(x, row), kTol);
}

TEST(ImageTexture, RefusesEmptyOrInconsistentImages) {
  EXPECT_THROW(imageTexture(nullptr, ImageMapping::Planar), std::invalid_argument);
  EXPECT_THROW(imageTexture(std::make_shared<TextureImage>(), ImageMapping::Planar),
               std::invalid_argument);
  auto short_ = testImage();
  short_->rgb.pop_back();
  EXPECT_THROW(imageTexture(short_, ImageMapping::Planar), std::invalid_argument);
  auto zeroWide = testImage();
  zeroWide->width = 0;
  EXPECT_THROW(imageTexture(zeroWide, ImageMapping::Planar), std::invalid_argument);
}

TEST(ImageTexture, NonFiniteCoordinatesGiveAFiniteColour) {
  TexturePtr tex = imageTexture(testImage(), ImageMapping::Planar);
  dvec3 c = tex->colorAt({kNaN, std::numeric_limits<double>::infinity(), 0.0}, kUp);
  EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
}

// -------------------------------------------------------------------- noise

TEST(PerlinNoise, IsZeroAtLatticePoints) {
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j)
      for (int k = -5; k <= 5; ++k) EXPECT_EQ(perlinNoise(dvec3(i, j, k)), 0.0);
  EXPECT_EQ(perlinNoise({1e6, -3e7, 123456789.0}), 0.0);
}

TEST(PerlinNoise, MatchesPerlinsReferenceImplementation) {
  // ImprovedNoise.java (Perlin 2002) gives noise(3.14, 42, 7) =
  // 0.13691995878400012.
  EXPECT_NEAR(perlinNoise({3.14, 42.0, 7.0}), 0.13691995878400012, 1e-15);
}

TEST(PerlinNoise, StaysInRangeAndVaries) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-100.0, 100.0);
  double lo = 0.0, hi = 0.0, sumAbs = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    double v = perlinNoise({coord(rng), coord(rng), coord(rng)});
    ASSERT_GE(v, -1.0);
    ASSERT_LE(v, 1.0);
    lo = std::min(lo, v), hi = std::max(hi, v), sumAbs += std::abs(v);
  }
  // Not degenerate: it swings both ways and is not mostly zero.
  EXPECT_LT(lo, -0.7);
  EXPECT_GT(hi, 0.7);
  EXPECT_GT(sumAbs / n, 0.1);
}

TEST(PerlinNoise, IsClampedWhereTheSumOvershoots) {
  // Near this point the unclamped sum of the improved noise reaches 1.0358
  // (found by local search); the documented range is [-1, 1].
  EXPECT_EQ(perlinNoise({56.492, 171.648, 103.49}), 1.0);
  EXPECT_GT(perlinNoise({56.492, 171.648, 103.49 + 0.05}), 0.9);
}

TEST(PerlinNoise, IsContinuous) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> coord(-50.0, 50.0);
  const double h = 1e-6;
  for (int i = 0; i < 20000; ++i) {
    dvec3 p(coord(rng), coord(rng), coord(rng));
    dvec3 d = test::randomDirection(rng);
    // The gradient is bounded by a few units, so a step of h changes the
    // value by at most a small multiple of h.
    EXPECT_LE(std::abs(perlinNoise(p + h * d) - perlinNoise(p)), 10.0 * h);
  }
  // Also across the faces of lattice cells, where the corner set changes.
  for (int i = 0; i < 2000; ++i) {
    dvec3 p(std::round(coord(rng)), coord(rng), coord(rng));
    dvec3 step(1e-9, 0.0, 0.0);
    EXPECT_NEAR(perlinNoise(p - step), perlinNoise(p + step), 1e-7);
    dvec3 q(coord(rng), coord(rng), std::round(coord(rng)));
    dvec3 stepZ(0.0, 0.0, 1e-9);
    EXPECT_NEAR(perlinNoise(q - stepZ), perlinNoise(q + stepZ), 1e-7);
  }
}

TEST(PerlinNoise, IsDeterministicAndRepeatsEvery256) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  for (int i = 0; i < 1000; ++i) {
    dvec3 p(coord(rng), coord(rng), coord(rng));
    double v = perlinNoise(p);
    EXPECT_EQ(perlinNoise(p), v);
    EXPECT_NEAR(perlinNoise(p + dvec3(256.0, 0.0, 0.0)), v, 1e-9);
    EXPECT_NEAR(perlinNoise(p + dvec3(0.0, -512.0, 256.0)), v, 1e-9);
  }
}

TEST(PerlinNoise, NonFinitePointsGiveZero) {
  EXPECT_EQ(perlinNoise({kNaN, 0.5, 0.5}), 0.0);
  EXPECT_EQ(perlinNoise({0.5, std::numeric_limits<double>::infinity(), 0.5}), 0.0);
}

TEST(Turbulence, IsNonNegativeAndBoundedByTheOctaveSum) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> coord(-30.0, 30.0);
  for (int octaves = 1; octaves <= 16; ++octaves) {
    double bound = 0.0;
    for (int i = 0; i < octaves; ++i) bound += 1.0 / std::ldexp(1.0, i);
    for (int i = 0; i < 500; ++i) {
      double t = turbulence({coord(rng), coord(rng), coord(rng)}, octaves);
      EXPECT_GE(t, 0.0);
      EXPECT_LE(t, bound);
    }
  }
}

TEST(Turbulence, IsTheSumOfOctavesOfAbsoluteNoise) {
  dvec3 p(1.37, -4.21, 0.66);
  EXPECT_DOUBLE_EQ(turbulence(p, 1), std::abs(perlinNoise(p)));
  EXPECT_NEAR(turbulence(p, 3),
              std::abs(perlinNoise(p)) + std::abs(perlinNoise(2.0 * p)) / 2.0 +
                  std::abs(perlinNoise(4.0 * p)) / 4.0,
              1e-15);
}

// Is c on the segment from a to b, and at which fraction?
double fractionOnSegment(const dvec3& c, const dvec3& a, const dvec3& b) {
  dvec3 ab = b - a;
  double t = glm::dot(c - a, ab) / glm::dot(ab, ab);
  expectVecNear(c, a + t * ab, 1e-12);
  return t;
}

const dvec3 kLight(0.9, 0.8, 0.3);
const dvec3 kDark(0.1, 0.4, 0.3);

TEST(NoiseTexture, PerlinAndTurbulenceBlendByTheirFormulas) {
  TexturePtr perlin = noiseTexture(NoiseKind::Perlin, kDark, kLight);
  TexturePtr turb = noiseTexture(NoiseKind::Turbulence, kDark, kLight, 3);
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  for (int i = 0; i < 500; ++i) {
    dvec3 p(coord(rng), coord(rng), coord(rng));
    EXPECT_NEAR(fractionOnSegment(perlin->colorAt(p, kUp), kDark, kLight),
                0.5 * (perlinNoise(p) + 1.0), 1e-12);
    EXPECT_NEAR(fractionOnSegment(turb->colorAt(p, kUp), kDark, kLight),
                std::min(turbulence(p, 3), 1.0), 1e-12);
  }
  // At a lattice point the noise is 0: half-way.
  expectVecNear(perlin->colorAt({2.0, -3.0, 5.0}, kUp), 0.5 * (kDark + kLight), 1e-12);
}

TEST(NoiseTexture, MarbleAndWoodStayBetweenTheirColours) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  for (NoiseKind kind : {NoiseKind::Marble, NoiseKind::Wood, NoiseKind::Turbulence})
    for (double strength : {0.0, 1.0, 4.0, 20.0}) {
      TexturePtr tex = noiseTexture(kind, kDark, kLight, 6, strength);
      for (int i = 0; i < 300; ++i) {
        double t = fractionOnSegment(tex->colorAt({coord(rng), coord(rng), coord(rng)}, kUp), kDark,
                                     kLight);
        EXPECT_GE(t, -1e-12);
        EXPECT_LE(t, 1.0 + 1e-12);
      }
    }
}

TEST(NoiseTexture, MarbleWithoutTurbulenceIsASineOfX) {
  TexturePtr marble = noiseTexture(NoiseKind::Marble, kDark, kLight, 4, 0.0);
  for (double x : {-2.0, 0.0, 0.7, kPi / 2.0, 3.0}) {
    dvec3 c = marble->colorAt({x, 1.3, -0.4}, kUp);
    EXPECT_NEAR(fractionOnSegment(c, kDark, kLight), 0.5 + 0.5 * std::sin(x), 1e-12);
  }
  // With turbulence the veins bend: it is no longer a function of x alone.
  TexturePtr veined = noiseTexture(NoiseKind::Marble, kDark, kLight, 4, 4.0);
  bool differs = false;
  for (double y = 0.1; y < 3.0; y += 0.37)
    differs |= glm::length(veined->colorAt({0.3, y, 0.2}, kUp) -
                           veined->colorAt({0.3, 0.1, 0.2}, kUp)) > 1e-3;
  EXPECT_TRUE(differs);
}

TEST(NoiseTexture, WoodRingsRepeatEveryUnitOfRadius) {
  TexturePtr wood = noiseTexture(NoiseKind::Wood, kDark, kLight, 6, 0.0);
  for (double r : {0.1, 0.25, 0.6, 0.9})
    for (double angle : {0.0, 1.0, 2.5, -2.0})
      for (double z : {-1.0, 0.0, 3.3}) {
        dvec3 dir(std::cos(angle), std::sin(angle), 0.0);
        dvec3 at = wood->colorAt(r * dir + dvec3(0.0, 0.0, z), kUp);
        // t = fract(r), whatever the angle and height, period 1 in radius.
        EXPECT_NEAR(fractionOnSegment(at, kDark, kLight), r, 1e-12);
        for (int k = 1; k <= 3; ++k)
          expectVecNear(wood->colorAt((r + k) * dir + dvec3(0.0, 0.0, z), kUp), at, 1e-9);
      }
}

TEST(NoiseTexture, RefusesBadOctavesAndStrength) {
  for (int octaves : {0, -1, 17, 1000}) {
    try {
      noiseTexture(NoiseKind::Marble, kDark, kLight, octaves, 1.0);
      ADD_FAILURE() << "octaves " << octaves << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("octaves"), std::string::npos) << e.what();
    }
  }
  for (double strength : {-0.1, kNaN, std::numeric_limits<double>::infinity()}) {
    try {
      noiseTexture(NoiseKind::Wood, kDark, kLight, 6, strength);
      ADD_FAILURE() << "strength " << strength << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("strength"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(noiseTexture(NoiseKind::Perlin, kDark, kLight, 1, 0.0));
  EXPECT_NO_THROW(noiseTexture(NoiseKind::Perlin, kDark, kLight, 16, 100.0));
}

// ------------------------------------------------------------ image reading

// sRGB code value of a linear value (IEC 61966-2-1), as writeImage encodes.
double encodeSrgb(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

class ReadTextureImage : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = csgray::test::scratchPathFor("csgray_texture_test_");
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  std::string path(const std::string& name) const { return (folder_ / name).string(); }

  // Writes a uint8 image with OIIO directly (any channel count).
  void writeBytes(const std::string& file, int w, int h, int channels,
                  const std::vector<unsigned char>& bytes) {
    auto out = OIIO::ImageOutput::create(file);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // bytes as given, alpha or not
    ASSERT_TRUE(out->open(file, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, bytes.data()));
    ASSERT_TRUE(out->close());
  }

  // The error of readTextureImage(file), which must throw.
  std::string errorOf(const std::string& file) {
    try {
      readTextureImage(file);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    ADD_FAILURE() << file << " was read";
    return "";
  }

  std::filesystem::path folder_;
};

TEST_F(ReadTextureImage, PngRoundTripsWithin8BitRounding) {
  const int w = 3, h = 2;
  std::vector<float> linear = {0.0f,  0.5f, 1.0f,  0.2f,  0.01f, 0.8f, 0.002f, 0.3f, 0.9f,
                               0.05f, 0.7f, 0.15f, 0.99f, 0.0f,  1.0f, 0.45f,  0.6f, 0.001f};
  std::string file = path("tiny.png");
  writeImage(file, w, h, linear.data());
  TextureImage image = readTextureImage(file);
  ASSERT_EQ(image.width, w);
  ASSERT_EQ(image.height, h);
  ASSERT_EQ(image.rgb.size(), linear.size());
  // Compared as sRGB code values: within half a step of 1/255, plus slack
  // for float arithmetic. Row-major from the top, as written.
  for (size_t i = 0; i < linear.size(); ++i)
    EXPECT_NEAR(encodeSrgb(image.rgb[i]), encodeSrgb(linear[i]), 0.5 / 255.0 + 1e-5) << i;
  // And the end points are exact.
  EXPECT_EQ(image.rgb[0], 0.0f);
  EXPECT_NEAR(image.rgb[2], 1.0f, 1e-6);
}

TEST_F(ReadTextureImage, ExrKeepsLinearValues) {
  std::vector<float> linear = {0.0f, 0.25f, 4.5f, 1e-3f, 17.0f, 0.75f};
  std::string file = path("tiny.exr");
  writeImage(file, 2, 1, linear.data());
  TextureImage image = readTextureImage(file);
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 1);
  ASSERT_EQ(image.rgb.size(), linear.size());
  for (size_t i = 0; i < linear.size(); ++i) EXPECT_FLOAT_EQ(image.rgb[i], linear[i]) << i;
}

TEST_F(ReadTextureImage, GreyIsReplicatedAndDecoded) {
  std::string file = path("grey.png");
  // 2x2 grey, top row 0 and 255, bottom row 128 and 64.
  writeBytes(file, 2, 2, 1, {0, 255, 128, 64});
  TextureImage image = readTextureImage(file);
  ASSERT_EQ(image.rgb.size(), 12u);
  const double codes[4] = {0, 255, 128, 64};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(encodeSrgb(image.rgb[i * 3 + c]) * 255.0, codes[i], 1e-3) << i << " " << c;
}

TEST_F(ReadTextureImage, AlphaIsDropped) {
  std::string file = path("rgba.png");
  writeBytes(file, 2, 1, 4, {255, 0, 51, 0, 10, 200, 30, 255});
  TextureImage image = readTextureImage(file);
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.rgb.size(), 6u);
  const double codes[6] = {255, 0, 51, 10, 200, 30};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(encodeSrgb(image.rgb[i]) * 255.0, codes[i], 1e-3) << i;
}

TEST_F(ReadTextureImage, ErrorsAreOneLineAndNameTheFile) {
  std::string missing = path("missing.png");
  std::string text = path("notes.txt");
  std::string fakePng = path("fake.png");
  std::string folder = path("a_folder.png");
  std::ofstream(text) << "not an image\nat all\n";
  std::ofstream(fakePng) << "this is text, not a PNG\n";
  std::filesystem::create_directories(folder);
  for (const std::string& file : {missing, text, fakePng, folder}) {
    std::string message = errorOf(file);
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_NE(errorOf(missing).find("no such file"), std::string::npos);
}

TEST_F(ReadTextureImage, ReadsIntoATextureThatFetchesThePixels) {
  // End to end: a 2x2 PNG on the xy plane, upright.
  std::string file = path("quad.png");
  writeBytes(file, 2, 2, 3, {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255});
  auto image = std::make_shared<TextureImage>(readTextureImage(file));
  TexturePtr tex = imageTexture(image, ImageMapping::Planar);
  expectVecNear(tex->colorAt({0.25, 0.75, 0.0}, kUp), {1.0, 0.0, 0.0}, 1e-6);  // top left
  expectVecNear(tex->colorAt({0.75, 0.75, 0.0}, kUp), {0.0, 1.0, 0.0}, 1e-6);  // top right
  expectVecNear(tex->colorAt({0.25, 0.25, 0.0}, kUp), {0.0, 0.0, 1.0}, 1e-6);  // bottom left
  expectVecNear(tex->colorAt({0.75, 0.25, 0.0}, kUp), {1.0, 1.0, 1.0}, 1e-6);  // bottom right
}

}  // namespace
}  // namespace csgray::detail
