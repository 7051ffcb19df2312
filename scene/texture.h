// Textures: colours that vary over a surface, as
// functions of a point in texture space. Texture space is the world as it
// was when the material was given to a solid or surface, so a texture moves
// with the part when the part is moved later. Each texture also has its
// own placement (scale, rotation, translation) within texture space.
#pragma once

#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "engine/affine.h"
#include "scene/color_map.h"

namespace csgray::detail {

// A bitmap in linear RGB floats, row-major from the top left.
struct TextureImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // width · height · 3
  dvec3 at(int x, int y) const {
    const float* p = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    return {p[0], p[1], p[2]};
  }
};

class Texture {
 public:
  virtual ~Texture() = default;
  // Colour at a point of texture space; n is the surface normal there
  // (box mapping picks the face by it).
  dvec3 colorAt(const dvec3& p, const dvec3& n) const;

  // placement maps the pattern's own frame into texture space.
  void setPlacement(const Affine& placement) { placement_ = placement; }
  const Affine& placement() const { return placement_; }

 protected:
  // The colour at a point of the pattern's own frame.
  virtual dvec3 pattern(const dvec3& p, const dvec3& n) const = 0;

 private:
  Affine placement_;
};

using TexturePtr = std::shared_ptr<const Texture>;

// A 3D checkerboard of cubes of edge size: colour a where
// floor(x/size) + floor(y/size) + floor(z/size) is even, else b.
TexturePtr checkerTexture(const dvec3& a, const dvec3& b, double size);

// A linear gradient: colour a at `from`, b at `to`, blending along the
// line between them and constant beyond (an SVG linearGradient's "pad").
TexturePtr gradientTexture(const ColorMap& colors, const dvec3& from, const dvec3& to);

// How a bitmap is wrapped onto points (u, v in [0, 1), repeating):
enum class ImageMapping {
  Planar,       // u = x, v = y: one copy of the image per unit square of the xy plane
  Spherical,    // u = longitude about z, v = latitude, about the origin
  Cylindrical,  // u = angle about z, v = z (one copy per unit of height)
  Box,          // planar onto the face of the unit cube that the normal picks
};
TexturePtr imageTexture(std::shared_ptr<const TextureImage> image, ImageMapping mapping);

// Fractal noise after Perlin ("Improving noise", SIGGRAPH 2002):
enum class NoiseKind {
  Perlin,      // noise(p) in [-1, 1] blends a (-1) to b (+1)
  Turbulence,  // Σ |noise(2^i p)| / 2^i over octaves
  Marble,      // veins: sin(x + turbulence(p)·strength)
  Wood,        // rings about the z axis, one per unit of radius, disturbed by turbulence
};
TexturePtr noiseTexture(NoiseKind kind, const ColorMap& colors, int octaves = 6,
                        double strength = 4.0);
inline TexturePtr noiseTexture(NoiseKind kind, const dvec3& a, const dvec3& b, int octaves = 6,
                               double strength = 4.0) {
  return noiseTexture(kind, ColorMap(a, b), octaves, strength);
}

// Escape-time fractals in the xy plane of the pattern's frame: each point
// c = x + iy (Mandelbrot) or start z = x + iy (Julia, with the given c)
// iterates z ← z² + c. Points that stay within radius 2 for `iterations`
// steps take `inside`; the others blend a (escaped at once) to b (escaped
// late) by their smooth escape count.
enum class FractalKind { Mandelbrot, Julia };
TexturePtr fractalTexture(FractalKind kind, const ColorMap& colors, const dvec3& inside,
                          int iterations, double cx = 0.0, double cy = 0.0);

// ---- Textures as users give them ------------------------------------------

// Where a pattern sits in texture space: scaled, then rotated (degrees about
// x, then y, then z), then translated.
struct TexturePlacement {
  std::optional<dvec3> scale, rotate, translate;
};

// The two colours of a pattern; none: the pattern's own defaults. The
// patterns that blend (all but the checker) take a ColorMap of more.
using ColorPair = std::pair<dvec3, dvec3>;

// The textures of the script's checker{}, perlin{}, turbulence{}, marble{},
// wood{} and image_texture{}, with their checks and messages ("checker:
// size must be > 0"). Perlin noise has one octave: octaves is not used.
TexturePtr placedChecker(const std::optional<ColorPair>& colors, double size,
                         const TexturePlacement& placement);
// The script's gradient{}: from and to default to the origin and +z.
TexturePtr placedGradient(const std::optional<ColorMap>& colors, const dvec3& from, const dvec3& to,
                          const TexturePlacement& placement);
TexturePtr placedNoise(NoiseKind kind, const std::optional<ColorMap>& colors, double octaves,
                       double strength, const TexturePlacement& placement);
TexturePtr placedImage(std::shared_ptr<const TextureImage> image, ImageMapping mapping,
                       const TexturePlacement& placement);
// The script's mandelbrot{} and julia{}: c is Julia's constant.
TexturePtr placedFractal(FractalKind kind, const std::optional<ColorMap>& colors,
                         const std::optional<dvec3>& inside, double iterations, double cx,
                         double cy, const TexturePlacement& placement);
// The script function of a noise: "perlin", "turbulence", "marble", "wood".
const char* noiseName(NoiseKind kind);

// Improved Perlin noise in [-1, 1] (Perlin 2002) and its turbulence sum;
// exposed for tests.
double perlinNoise(const dvec3& p);
double turbulence(const dvec3& p, int octaves);

}  // namespace csgray::detail
