// csgray::Texture: the script's textures (scene/texture.h), with the same
// checks.
#include "api/access.h"
#include "api/convert.h"
#include "api/errors.h"
#include "csgray/material.h"
#include "io/image_file.h"

namespace csgray {

using detail::Access;
using detail::guarded;
using detail::toDetail;

namespace {

detail::TexturePlacement placementOf(const Texture::Placement& p) {
  return {toDetail(p.scale), toDetail(p.rotate), toDetail(p.translate)};
}

// A checker's two colours.
std::optional<detail::ColorPair> colorsOf(const std::optional<Texture::Colors>& colors) {
  if (!colors) return std::nullopt;
  if (!colors->stops.empty())
    throw std::invalid_argument("checker: colors must be two colours, not stops");
  return detail::ColorPair(toDetail(colors->first), toDetail(colors->second));
}

// A blending pattern's colours: the stops when given.
std::optional<detail::ColorMap> colorMapOf(const std::optional<Texture::Colors>& colors,
                                           const char* function) {
  if (!colors) return std::nullopt;
  if (colors->stops.empty())
    return detail::ColorMap(toDetail(colors->first), toDetail(colors->second));
  std::vector<detail::ColorStop> stops;
  for (const Texture::Stop& s : colors->stops) stops.push_back({s.at, toDetail(s.color)});
  return detail::ColorMap(std::move(stops), function);
}

detail::NoiseKind noiseOf(Texture::Noise kind) {
  switch (kind) {
    case Texture::Noise::Perlin:
      return detail::NoiseKind::Perlin;
    case Texture::Noise::Turbulence:
      return detail::NoiseKind::Turbulence;
    case Texture::Noise::Marble:
      return detail::NoiseKind::Marble;
    case Texture::Noise::Wood:
      return detail::NoiseKind::Wood;
  }
  return detail::NoiseKind::Perlin;
}

detail::ImageMapping mappingOf(Texture::Mapping mapping) {
  switch (mapping) {
    case Texture::Mapping::Planar:
      return detail::ImageMapping::Planar;
    case Texture::Mapping::Spherical:
      return detail::ImageMapping::Spherical;
    case Texture::Mapping::Cylindrical:
      return detail::ImageMapping::Cylindrical;
    case Texture::Mapping::Box:
      return detail::ImageMapping::Box;
  }
  return detail::ImageMapping::Planar;
}

}  // namespace

Texture::Texture(std::shared_ptr<const detail::Texture> impl) : impl_(std::move(impl)) {}

Texture Texture::checker(const std::optional<Colors>& colors, double size,
                         const Placement& placement) {
  return guarded([&] {
    return Texture(detail::placedChecker(colorsOf(colors), size, placementOf(placement)));
  });
}

Texture Texture::gradient(const std::optional<Colors>& colors, const Vec3& from, const Vec3& to,
                          const Placement& placement) {
  return guarded([&] {
    return Texture(detail::placedGradient(colorMapOf(colors, "gradient"), detail::toDetail(from),
                                          detail::toDetail(to), placementOf(placement)));
  });
}

Texture Texture::noise(Noise kind, const std::optional<Colors>& colors, int octaves,
                       double strength, const Placement& placement) {
  return guarded([&] {
    const detail::NoiseKind noise = noiseOf(kind);
    return Texture(detail::placedNoise(noise, colorMapOf(colors, detail::noiseName(noise)), octaves,
                                       strength, placementOf(placement)));
  });
}

Texture Texture::fractal(Fractal kind, const std::optional<Colors>& colors, const Vec3& inside,
                         int iterations, double cx, double cy, const Placement& placement) {
  return guarded([&] {
    const bool mandelbrot = kind == Fractal::Mandelbrot;
    return Texture(detail::placedFractal(
        mandelbrot ? detail::FractalKind::Mandelbrot : detail::FractalKind::Julia,
        colorMapOf(colors, mandelbrot ? "mandelbrot" : "julia"), toDetail(inside), iterations, cx,
        cy, placementOf(placement)));
  });
}

Texture Texture::image(const std::string& path, Mapping mapping, const Placement& placement) {
  // readTextureImage's errors (a missing or unreadable file) are IoError.
  auto image = guarded(ErrorCode::IoError, [&] {
    return std::make_shared<detail::TextureImage>(detail::readTextureImage(path));
  });
  return guarded([&] {
    return Texture(
        detail::placedImage(std::move(image), mappingOf(mapping), placementOf(placement)));
  });
}

Vec3 Texture::colorAt(const Vec3& point, const Vec3& normal) const {
  return detail::toPublic(impl_->colorAt(toDetail(point), toDetail(normal)));
}

}  // namespace csgray
