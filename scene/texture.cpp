#include "scene/texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "scene/rotation.h"
#include "scene/value_checks.h"

namespace csgray::detail {

dvec3 Texture::colorAt(const dvec3& p, const dvec3& n) const {
  if (placement_.isIdentity()) return pattern(p, n);
  // placement maps pattern frame → texture space, so points go back through
  // its inverse; normals go back through the inverse transpose of that
  // inverse, i.e. the transpose of the forward linear part.
  dvec3 local = placement_.pointToObject(p);
  dvec3 localNormal = glm::transpose(glm::dmat3(placement_.worldFromObject())) * n;
  return pattern(local, localNormal);
}

namespace {

double fract(double x) { return x - std::floor(x); }

dvec3 mix(const dvec3& a, const dvec3& b, double t) { return a + (b - a) * t; }

// ------------------------------------------------------------------ checker

class CheckerTexture final : public Texture {
 public:
  CheckerTexture(const dvec3& a, const dvec3& b, double size) : a_(a), b_(b), size_(size) {}

 protected:
  dvec3 pattern(const dvec3& p, const dvec3&) const override {
    // The parity of each cell index, without converting to an integer
    // (which would overflow far from the origin); NaN counts as odd. The
    // millionth of a cell added keeps a face that lies on a cell boundary
    // (a floor at z = 0) in one cell: its hit points round to either side.
    // The parity of the whole number k is k − 2·floor(k/2), each step exact
    // in doubles (halving, floor, doubling; the difference is 0 or 1), so
    // it equals fmod(k, 2) (NaN and ±inf give NaN: odd) without a call
    // into libm, which took 3 % of the glass scene's render.
    auto odd = [this](double c) {
      const double k = std::floor(c / size_ + 1e-6);
      return k - 2.0 * std::floor(0.5 * k) != 0.0;
    };
    return (odd(p.x) != odd(p.y)) != odd(p.z) ? b_ : a_;
  }

 private:
  dvec3 a_, b_;
  double size_;
};

// -------------------------------------------------------------------- image

class ImageTexture final : public Texture {
 public:
  ImageTexture(std::shared_ptr<const TextureImage> image, ImageMapping mapping)
      : image_(std::move(image)), mapping_(mapping) {}

 protected:
  dvec3 pattern(const dvec3& p, const dvec3& n) const override {
    constexpr double kTwoPi = 2.0 * std::numbers::pi;
    double u = 0.0, v = 0.0;
    switch (mapping_) {
      case ImageMapping::Planar:
        u = p.x, v = p.y;
        break;
      case ImageMapping::Spherical: {
        double r = glm::length(p);
        u = std::atan2(p.y, p.x) / kTwoPi + 0.5;
        v = r > 0.0 ? 0.5 + std::asin(std::clamp(p.z / r, -1.0, 1.0)) / std::numbers::pi : 0.5;
        break;
      }
      case ImageMapping::Cylindrical:
        u = std::atan2(p.y, p.x) / kTwoPi + 0.5, v = p.z;
        break;
      case ImageMapping::Box: {
        // The face whose axis is the largest normal component; ties go to
        // the earlier axis so that the choice is deterministic.
        dvec3 m = glm::abs(n);
        if (m.x >= m.y && m.x >= m.z)
          u = p.y, v = p.z;
        else if (m.y >= m.z)
          u = p.x, v = p.z;
        else
          u = p.x, v = p.y;
        break;
      }
    }
    return lookup(u, v);
  }

 private:
  // Bilinear filtering between the four nearest texel centres. Texel
  // (x, row) has its centre at u = (x + 0.5) / width, v = 1 - (row + 0.5) /
  // height: v = 0 is the bottom of the image. u always repeats; v repeats
  // except for spherical mapping, where v = 0 and 1 are the poles and
  // wrapping would blend the bottom row into the north pole (and the top
  // row into the south pole), so there v is clamped to the edge rows.
  dvec3 lookup(double u, double v) const {
    const TextureImage& img = *image_;
    bool wrapV = mapping_ != ImageMapping::Spherical;
    if (!std::isfinite(u)) u = 0.0;
    if (!std::isfinite(v)) v = 0.0;
    // After fract (which may round up to 1) or clamp, s and t lie in
    // [-0.5, size - 0.5], so the casts below stay in range.
    double s = fract(u) * img.width - 0.5;
    double t = (1.0 - (wrapV ? fract(v) : std::clamp(v, 0.0, 1.0))) * img.height - 0.5;
    double s0 = std::floor(s), t0 = std::floor(t);
    double fs = s - s0, ft = t - t0;
    auto wrap = [](int i, int size) { return ((i % size) + size) % size; };
    auto edge = [](int i, int size) { return std::clamp(i, 0, size - 1); };
    int x0 = wrap(static_cast<int>(s0), img.width), x1 = wrap(x0 + 1, img.width);
    int y0 = static_cast<int>(t0), y1 = y0 + 1;
    if (wrapV)
      y0 = wrap(y0, img.height), y1 = wrap(y1, img.height);
    else
      y0 = edge(y0, img.height), y1 = edge(y1, img.height);
    dvec3 top = mix(img.at(x0, y0), img.at(x1, y0), fs);
    dvec3 bottom = mix(img.at(x0, y1), img.at(x1, y1), fs);
    return mix(top, bottom, ft);
  }

  std::shared_ptr<const TextureImage> image_;
  ImageMapping mapping_;
};

// -------------------------------------------------------------------- noise

// Ken Perlin's permutation of 0..255 from "Improving noise" (SIGGRAPH 2002)
// and its reference implementation, so that the noise is the published one.
constexpr std::array<unsigned char, 256> kPermutation = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

constexpr bool isPermutation(const std::array<unsigned char, 256>& p) {
  std::array<bool, 256> seen{};
  for (unsigned char v : p) {
    if (seen[v]) return false;
    seen[v] = true;
  }
  return true;
}
static_assert(isPermutation(kPermutation));

// The paper's 12 gradients, the midpoints of the edges of the cube, padded
// to 16 with (1,1,0), (-1,1,0), (0,-1,1), (0,-1,-1) so that a hash picks one
// with & 15; in the order of the reference implementation's grad().
constexpr int kGradients[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1}};

// The hash of a lattice point: the permutation applied per coordinate, as
// P[P[P[i] + j] + k] with indices taken mod 256.
int latticeHash(int i, int j, int k) {
  return kPermutation[(kPermutation[(kPermutation[i & 255] + j) & 255] + k) & 255];
}

// The gradient of lattice point (i, j, k) dotted with the offset d from it.
double gradientDot(int i, int j, int k, double dx, double dy, double dz) {
  const int* g = kGradients[latticeHash(i, j, k) & 15];
  return g[0] * dx + g[1] * dy + g[2] * dz;
}

// The paper's fade curve 6t^5 - 15t^4 + 10t^3: zero first and second
// derivatives at 0 and 1, so the noise is C2 across cell faces.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

double lerp(double t, double a, double b) { return a + t * (b - a); }

// The lattice cell index (the floor of a coordinate) mod 256, all the hash
// needs; reduced in floating point so that large coordinates do not
// overflow an int.
int cellIndex(double floorC) {
  return static_cast<int>(floorC - 256.0 * std::floor(floorC / 256.0));
}

class GradientTexture final : public Texture {
 public:
  GradientTexture(const ColorMap& colors, const dvec3& from, const dvec3& to)
      : colors_(colors), from_(from), step_((to - from) / glm::dot(to - from, to - from)) {}

 protected:
  dvec3 pattern(const dvec3& p, const dvec3&) const override {
    // The share of the way from `from` to `to` that p's projection lies at.
    return colors_.at(glm::dot(p - from_, step_));
  }

 private:
  ColorMap colors_;
  dvec3 from_, step_;
};

class NoiseTexture final : public Texture {
 public:
  NoiseTexture(NoiseKind kind, const ColorMap& colors, int octaves, double strength)
      : kind_(kind), colors_(colors), octaves_(octaves), strength_(strength) {}

 protected:
  dvec3 pattern(const dvec3& p, const dvec3&) const override {
    double t = 0.0;
    switch (kind_) {
      case NoiseKind::Perlin:
        t = 0.5 * (perlinNoise(p) + 1.0);
        break;
      case NoiseKind::Turbulence:
        t = std::clamp(turbulence(p, octaves_), 0.0, 1.0);
        break;
      case NoiseKind::Marble:
        // Perlin's marble (SIGGRAPH 1985, "An image synthesizer"): stripes
        // of sin(x) bent by turbulence.
        t = 0.5 + 0.5 * std::sin(p.x + strength_ * turbulence(p, octaves_));
        break;
      case NoiseKind::Wood: {
        // Rings about z, one per unit of radius. Turbulence shifts the radius
        // by 0.1 · strength per unit of turbulence (which is < 2), so the
        // default strength 4 bends the rings without breaking them up.
        double r = std::sqrt(p.x * p.x + p.y * p.y) + 0.1 * strength_ * turbulence(p, octaves_);
        t = fract(r);
        break;
      }
    }
    return colors_.at(t);
  }

 private:
  NoiseKind kind_;
  ColorMap colors_;
  int octaves_;
  double strength_;
};

class FractalTexture final : public Texture {
 public:
  FractalTexture(FractalKind kind, const ColorMap& colors, const dvec3& inside, int iterations,
                 double cx, double cy)
      : kind_(kind), colors_(colors), inside_(inside), iterations_(iterations), cx_(cx), cy_(cy) {}

 protected:
  dvec3 pattern(const dvec3& p, const dvec3&) const override {
    double zx = p.x, zy = p.y, cx = cx_, cy = cy_;
    if (kind_ == FractalKind::Mandelbrot) cx = p.x, cy = p.y, zx = 0.0, zy = 0.0;
    // A point whose orbit leaves radius 2 escapes to infinity; iterating
    // on to radius 2⁸ makes the smooth count below nearly independent of
    // where the orbit crossed radius 2.
    constexpr double kBailout = 256.0;
    for (int n = 0; n < iterations_; ++n) {
      const double xx = zx * zx, yy = zy * zy;
      if (xx + yy > kBailout * kBailout) {
        // The smooth (renormalised) escape count n + 1 − log₂ log₂ |z|
        // (Vepstas, "Renormalizing the Mandelbrot Escape", 1997), as a
        // fraction of the iterations; its square root spreads the many
        // points that escape early over more of the blend.
        const double smooth = n + 1.0 - std::log2(std::log2(std::sqrt(xx + yy)));
        return colors_.at(std::sqrt(std::clamp(smooth / iterations_, 0.0, 1.0)));
      }
      zy = 2.0 * zx * zy + cy;
      zx = xx - yy + cx;
    }
    return inside_;
  }

 private:
  FractalKind kind_;
  ColorMap colors_;
  dvec3 inside_;
  int iterations_;
  double cx_, cy_;
};

}  // namespace

double perlinNoise(const dvec3& p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0.0;
  // Improved noise after Perlin, "Improving noise", SIGGRAPH 2002: the
  // gradients of the eight corners of the lattice cell, dotted with the
  // offsets to p, blended trilinearly by the fade curve.
  double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
  int i = cellIndex(fx), j = cellIndex(fy), k = cellIndex(fz);
  double x = p.x - fx, y = p.y - fy, z = p.z - fz;
  double u = fade(x), v = fade(y), w = fade(z);
  double x00 = lerp(u, gradientDot(i, j, k, x, y, z), gradientDot(i + 1, j, k, x - 1, y, z));
  double x10 =
      lerp(u, gradientDot(i, j + 1, k, x, y - 1, z), gradientDot(i + 1, j + 1, k, x - 1, y - 1, z));
  double x01 =
      lerp(u, gradientDot(i, j, k + 1, x, y, z - 1), gradientDot(i + 1, j, k + 1, x - 1, y, z - 1));
  double x11 = lerp(u, gradientDot(i, j + 1, k + 1, x, y - 1, z - 1),
                    gradientDot(i + 1, j + 1, k + 1, x - 1, y - 1, z - 1));
  double n = lerp(w, lerp(v, x00, x10), lerp(v, x01, x11));
  // With these gradients the sum peaks near ±1.036 at a few points (found by
  // local search); clamp to the documented range.
  return std::clamp(n, -1.0, 1.0);
}

double turbulence(const dvec3& p, int octaves) {
  // Perlin 1985: the sum of |noise| over octaves of doubling frequency and
  // halving amplitude; at most Σ 1/2^i < 2.
  double sum = 0.0, scale = 1.0;
  for (int i = 0; i < octaves; ++i, scale *= 2.0) sum += std::abs(perlinNoise(scale * p)) / scale;
  return sum;
}

TexturePtr checkerTexture(const dvec3& a, const dvec3& b, double size) {
  if (!(size > 0.0) || !std::isfinite(size))
    throw std::invalid_argument("checker size must be a finite number > 0");
  return std::make_shared<CheckerTexture>(a, b, size);
}

TexturePtr gradientTexture(const ColorMap& colors, const dvec3& from, const dvec3& to) {
  const double squared = glm::dot(to - from, to - from);
  if (!(squared > 0.0 && std::isfinite(squared)))
    throw std::invalid_argument("gradient from and to must be distinct points, not too far apart");
  return std::make_shared<GradientTexture>(colors, from, to);
}

TexturePtr imageTexture(std::shared_ptr<const TextureImage> image, ImageMapping mapping) {
  if (!image || image->width <= 0 || image->height <= 0)
    throw std::invalid_argument("texture image is empty");
  if (image->rgb.size() != static_cast<std::size_t>(image->width) * image->height * 3)
    throw std::invalid_argument("texture image has " + std::to_string(image->rgb.size()) +
                                " values, not width · height · 3");
  return std::make_shared<ImageTexture>(std::move(image), mapping);
}

TexturePtr noiseTexture(NoiseKind kind, const ColorMap& colors, int octaves, double strength) {
  if (octaves < 1 || octaves > 16)
    throw std::invalid_argument("noise octaves must be between 1 and 16, not " +
                                std::to_string(octaves));
  if (!(strength >= 0.0) || !std::isfinite(strength))
    throw std::invalid_argument("noise strength must be a finite number >= 0");
  return std::make_shared<NoiseTexture>(kind, colors, octaves, strength);
}

TexturePtr fractalTexture(FractalKind kind, const ColorMap& colors, const dvec3& inside,
                          int iterations, double cx, double cy) {
  if (iterations < 1 || iterations > 10000)
    throw std::invalid_argument("fractal iterations must be between 1 and 10000, not " +
                                std::to_string(iterations));
  if (!std::isfinite(cx) || !std::isfinite(cy))
    throw std::invalid_argument("a Julia set's c must be finite");
  return std::make_shared<FractalTexture>(kind, colors, inside, iterations, cx, cy);
}

// ---- Textures as users give them ------------------------------------------

namespace {

void checkColors(const char* function, const ColorPair& colors) {
  checkColor(function, "colors", colors.first);
  checkColor(function, "colors", colors.second);
}

void checkColors(const char* function, const ColorMap& colors) {
  for (const ColorStop& stop : colors.stops()) checkColor(function, "colors", stop.color);
}

// The placement's map, with a singular scale reported under the texture's
// name ("checker: transform is singular").
Affine placementOf(const char* function, const TexturePlacement& p) {
  try {
    Affine placement;
    if (p.scale) placement = Affine::scaling(*p.scale);
    if (p.rotate) placement = placement.then(rotationDegrees(*p.rotate));
    if (p.translate) placement = placement.then(Affine::translation(*p.translate));
    return placement;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(function) + ": " + e.what());
  }
}

// The factory's texture, not yet shared with anything, placed.
TexturePtr placed(TexturePtr texture, const Affine& placement) {
  std::const_pointer_cast<Texture>(texture)->setPlacement(placement);
  return texture;
}

}  // namespace

TexturePtr placedChecker(const std::optional<ColorPair>& colors, double size,
                         const TexturePlacement& placement) {
  const ColorPair c = colors.value_or(ColorPair(dvec3(1.0), dvec3(0.1)));
  checkColors("checker", c);
  checkPositive("checker", "size", size);
  const Affine frame = placementOf("checker", placement);
  return placed(checkerTexture(c.first, c.second, size), frame);
}

TexturePtr placedGradient(const std::optional<ColorMap>& colors, const dvec3& from, const dvec3& to,
                          const TexturePlacement& placement) {
  const ColorMap c = colors.value_or(ColorMap(dvec3(1.0), dvec3(0.1)));
  checkColors("gradient", c);
  checkFinite("gradient", "from", from);
  checkFinite("gradient", "to", to);
  if (from == to) throw std::invalid_argument("gradient: from and to are the same point");
  const dvec3 way = to - from;
  if (!(glm::dot(way, way) > 0.0 && std::isfinite(glm::dot(way, way))))
    throw std::invalid_argument("gradient: from and to are too close or too far apart");
  return placed(gradientTexture(c, from, to), placementOf("gradient", placement));
}

TexturePtr placedNoise(NoiseKind kind, const std::optional<ColorMap>& colors, double octaves,
                       double strength, const TexturePlacement& placement) {
  const char* name = noiseName(kind);
  const ColorMap c = colors.value_or(kind == NoiseKind::Wood
                                         ? ColorMap(dvec3(0.55, 0.33, 0.16), dvec3(0.3, 0.16, 0.07))
                                         : ColorMap(dvec3(0.9, 0.9, 0.88), dvec3(0.2, 0.2, 0.25)));
  checkColors(name, c);
  const int count = kind == NoiseKind::Perlin ? 1 : checkWhole(name, "octaves", octaves, 1, 16);
  checkNonNegative(name, "strength", strength);
  const Affine frame = placementOf(name, placement);
  return placed(noiseTexture(kind, c, count, strength), frame);
}

TexturePtr placedImage(std::shared_ptr<const TextureImage> image, ImageMapping mapping,
                       const TexturePlacement& placement) {
  const Affine frame = placementOf("image_texture", placement);
  return placed(imageTexture(std::move(image), mapping), frame);
}

TexturePtr placedFractal(FractalKind kind, const std::optional<ColorMap>& colors,
                         const std::optional<dvec3>& inside, double iterations, double cx,
                         double cy, const TexturePlacement& placement) {
  const char* name = kind == FractalKind::Mandelbrot ? "mandelbrot" : "julia";
  const ColorMap c = colors.value_or(ColorMap(dvec3(0.05, 0.1, 0.4), dvec3(1.0, 0.85, 0.3)));
  checkColors(name, c);
  const dvec3 in = inside.value_or(dvec3(0.0));
  checkColor(name, "inside", in);
  const int count = checkWhole(name, "iterations", iterations, 1, 10000);
  const Affine frame = placementOf(name, placement);
  return placed(fractalTexture(kind, c, in, count, cx, cy), frame);
}

const char* noiseName(NoiseKind kind) {
  switch (kind) {
    case NoiseKind::Perlin:
      return "perlin";
    case NoiseKind::Turbulence:
      return "turbulence";
    case NoiseKind::Marble:
      return "marble";
    case NoiseKind::Wood:
      return "wood";
  }
  return "noise";
}

}  // namespace csgray::detail
