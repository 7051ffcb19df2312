// What a render shows: solids and open surfaces, lights, a camera and a
// background, as a script's scene{} describes them (docs/script.md,
// Scenes). Scene checks what it is given as the script does, and throws
// csgray::Error (InvalidArgument) with the same message.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "csgray/material.h"
#include "csgray/solid.h"
#include "csgray/types.h"

namespace csgray {

namespace detail {
class Surface;
struct Access;
}  // namespace detail

// A surface that is not a solid: planar (a floor, a wall) or an open mesh
// of triangles (a graph's sheet, a landscape). It encloses no volume, so
// it takes no part in booleans and is not exported, but it renders, seen
// from both sides. An immutable value like Solid.
class CSGRAY_API Surface {
 public:
  // The infinite plane normal · p = offset.
  static Surface plane(const Vec3& normal = {0, 0, 1}, double offset = 0.0);
  // A disc of radius r about center.
  static Surface disc(double r, const Vec3& center = {}, const Vec3& normal = {0, 0, 1});
  static Surface triangle(const Vec3& a, const Vec3& b, const Vec3& c);
  // origin + s·u + t·v for s, t in [0, 1].
  static Surface parallelogram(const Vec3& origin, const Vec3& u, const Vec3& v);
  // In the xy plane from the origin (centred on it with center), facing +z.
  static Surface rectangle(double width, double height, bool center = false);
  static Surface square(double size, bool center = false);
  // A 2D region shown flat in the xy plane, facing +z, as a script's
  // region placed in a scene is: an open surface, not a solid.
  static Surface region(const Region& region);
  // An open surface of triangles: faces of three point indices (from 0,
  // in either order), shaded smooth with one normal per point (none, or a
  // zero one: averaged from the triangles around the point), or flat with
  // smooth = false. Triangles with no area are left out.
  static Surface mesh(const std::vector<Vec3>& points,
                      const std::vector<std::vector<std::int64_t>>& faces,
                      const std::vector<Vec3>& normals = {}, bool smooth = true);

  Surface translate(const Vec3& offset) const;
  Surface rotate(const Vec3& degrees) const;
  Surface rotate(double degrees, const Vec3& axis) const;
  Surface scale(const Vec3& factors) const;
  Surface mirror(const Vec3& normal) const;
  Surface transform(const Matrix4& m) const;
  Surface material(const Material& material) const;

  // "plane", "disc", ...
  std::string kind() const;
  Bounds bounds() const;

 private:
  explicit Surface(std::shared_ptr<const detail::Surface> impl);
  detail::Shared<detail::Surface> impl_;
  friend struct detail::Access;
};

// A light: each kind uses its own fields and the common ones. Messages name
// the script function of its kind (point_light, spot_light, area_light,
// sphere_light).
struct Light {
  enum class Kind { Point, Spot, Area, Sphere };
  Kind kind = Kind::Point;
  Vec3 position;  // the point, or the centre of an area light
  Vec3 color{1.0, 1.0, 1.0};
  double intensity = 1.0;
  bool falloff = false;  // divide by the squared distance
  // Spot: aimed at lookAt or along direction (one of them; neither: down
  // -z), lighting angle degrees off its axis (0 to 90) by cos^exponent.
  std::optional<Vec3> lookAt, direction;
  double angle = 30.0;
  // Spot: full light within inner degrees, fading smoothly to none at
  // angle (POV-Ray's radius and falloff); none: a hard edge at angle.
  std::optional<double> inner;
  double exponent = 1.0;
  Vec3 u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0};  // Area: the rectangle's edges
  double radius = 1.0;                      // Sphere
  int samples = 16;                         // Area and Sphere: shadow rays, 1 to 1024

  static Light point(const Vec3& position) {
    Light light;
    light.position = position;
    return light;
  }
  static Light spot(const Vec3& position, const Vec3& lookAt, double angle = 30.0) {
    Light light = point(position);
    light.kind = Kind::Spot;
    light.lookAt = lookAt;
    light.angle = angle;
    return light;
  }
  static Light area(const Vec3& center, const Vec3& u, const Vec3& v) {
    Light light = point(center);
    light.kind = Kind::Area;
    light.u = u;
    light.v = v;
    return light;
  }
  static Light sphere(const Vec3& center, double radius) {
    Light light = point(center);
    light.kind = Kind::Sphere;
    light.radius = radius;
    return light;
  }
};

struct Camera {
  enum class Projection { Perspective, Orthographic };
  Vec3 eye{0.0, -10.0, 0.0};
  Vec3 lookAt{0.0, 0.0, 0.0};
  Vec3 up{0.0, 0.0, 1.0};
  double fov = 45.0;  // perspective: the horizontal view angle in degrees
  Projection projection = Projection::Perspective;
  // Orthographic only: the width of the view in model units; none fits
  // the scene.
  std::optional<double> width = std::nullopt;
  // Perspective only: focal blur. A lens `aperture` wide (0: a pinhole,
  // sharp everywhere) in focus on the plane through focalPoint (none:
  // lookAt) square to the view; each pixel takes at least blurSamples rays
  // (1 to 1024) through the lens.
  double aperture = 0.0;
  std::optional<Vec3> focalPoint = std::nullopt;
  int blurSamples = 16;
};

// Fog of constant density in the air: along a way of length d a ray keeps
// exp(-d / distance) of what it sees and takes the rest from the colour.
// With an altitude > 0, ground fog: that density up to the height
// z = offset, thinning above it as 1 / (1 + (z - offset) / altitude)².
struct Fog {
  Vec3 color{0.5, 0.5, 0.5};
  double distance = 1.0;  // > 0
  double offset = 0.0;
  double altitude = 0.0;  // >= 0; 0: of constant density
};

class CSGRAY_API Scene {
 public:
  Scene();
  // A scene of one solid, as a script that returns a solid gives: drawn in
  // the default look (docs/script.md, "The default look").
  explicit Scene(const Solid& part);
  Scene(const Scene& other);
  Scene& operator=(const Scene& other);
  Scene(Scene&& other);  // leaves other empty
  Scene& operator=(Scene&& other) noexcept;
  ~Scene();

  Scene& add(const Solid& object);
  Scene& add(const Surface& surface);
  Scene& add(const Light& light);
  // Whether a scene without lights gets one beside the camera (the
  // default, true). Off, it is lit only by ambient light and emission, as
  // a script's scene{lights={}}.
  Scene& setDefaultLight(bool enabled);
  Scene& setCamera(const Camera& camera);
  // Ends the default look: the scene's own background is drawn.
  Scene& setBackground(const Vec3& color);
  // A background by direction (a sky): a ray that meets nothing sees the
  // texture at its unit direction. Ends the default look too.
  Scene& setBackground(const Texture& sky);
  // The default look of a bare part (Scene(part), a script that returns a
  // solid): a light gradient behind it, three lights about the camera (or
  // the scene's own, when it has some), a shadow on the ground, and 9 rays
  // at the pixels on its edges when render's samples are 0. Off, the
  // scene is drawn as a scene{} of the script is.
  Scene& setDefaultLook(bool enabled);
  // At most this many reflected or refracted rays in a chain (0 to 64),
  // and none whose share of a pixel is below minWeight (0 to 1).
  Scene& setMaxDepth(int depth);
  Scene& setMinWeight(double weight);
  // Diffuse inter-reflection by path tracing: `samples` rays (1 to 4096)
  // scatter from each surface the camera sees, `bounces` (0 to 64) bounces
  // before Russian roulette; samples 0 turns it off (docs/script.md, Scenes).
  Scene& setIndirectLight(int samples, int bounces = 2);
  // Ambient occlusion: the ambient term dimmed by the share of `samples`
  // rays that meet something within `distance` (0: a tenth of the scene's
  // size); samples 0 turns it off.
  Scene& setAmbientOcclusion(int samples, double distance = 0.0);
  // Fog between the camera and the surfaces, and between surfaces (not
  // inside transparent solids); none turns it off.
  Scene& setFog(const std::optional<Fog>& fog);

  std::vector<Solid> objects() const;
  std::vector<Surface> surfaces() const;
  // None: a default light beside the camera, unless defaultLight() is off.
  std::vector<Light> lights() const;
  bool defaultLight() const;
  bool defaultLook() const;
  // None: the camera frames the objects' bounds.
  std::optional<Camera> camera() const;
  Vec3 background() const;
  // The background texture, when setBackground gave one (it is drawn in
  // place of background()).
  std::optional<Texture> backgroundTexture() const;
  int maxDepth() const;
  double minWeight() const;
  int indirectSamples() const;
  int indirectBounces() const;
  int ambientOcclusionSamples() const;
  double ambientOcclusionDistance() const;
  std::optional<Fog> fog() const;
  // Of the objects and the bounded surfaces.
  Bounds bounds() const;
  // What would be printed: the objects, their union when there are several.
  // Error (InvalidArgument) when there is none.
  Solid part() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  friend struct detail::Access;
};

}  // namespace csgray
