// What a script describes: solids to show, and how to look at them. The
// renderer turns this into pixels; the exporter uses only the solids.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "engine/solid.h"
#include "scene/light.h"
#include "scene/surface.h"

namespace csgray::detail {

// A camera: eye point, the point looked at and the up direction. A
// perspective camera is the pinhole with a horizontal
// view angle in degrees; an orthographic one sends parallel rays along the
// view direction from a screen orthoWidth wide (what a CAD preview shows).
// A perspective camera with an aperture is a thin lens instead: sharp on
// the plane through focalPoint square to the view, blurred before and
// behind it (raytrace/renderer.cpp), each pixel taking at least
// blurSamples rays through points of the lens.
struct CameraSpec {
  dvec3 eye{0.0, -10.0, 0.0};
  dvec3 lookAt{0.0};
  dvec3 up{0.0, 0.0, 1.0};
  double fovDegrees = 45.0;
  bool orthographic = false;
  double orthoWidth = 10.0;
  double aperture = 0.0;                           // the lens's diameter; 0: a pinhole
  std::optional<dvec3> focalPoint = std::nullopt;  // none: lookAt
  int blurSamples = 16;

  bool blurs() const { return aperture > 0.0; }
};

// Bounds on recursion (two mirrors facing each other would reflect
// forever): at most maxDepth reflected or refracted rays in a chain,
// and none whose share of the pixel falls below minWeight.
struct TraceLimits {
  int maxDepth = 8;
  double minWeight = 1.0 / 512.0;
};

// Diffuse inter-reflection, by path tracing (docs/theory.md, "Indirect
// light"): off while samples is 0. At a surface that the camera sees,
// `samples` rays scatter diffusely; each later bounce sends one, and past
// `bounces` of them Russian roulette decides whether a path goes on.
struct IndirectLight {
  int samples = 0;
  int bounces = 2;
};

// Ambient occlusion: the ambient term of each point dimmed by the share of
// `samples` diffusely scattered rays that meet something within
// `distance` (0: a tenth of the scene's size). Off while samples is 0.
struct AmbientOcclusion {
  int samples = 0;
  double distance = 0.0;
};

// Fog in the air between surfaces (POV-Ray's fog of constant density):
// along a stretch of length d a ray keeps exp(−d / distance) of what it
// sees and takes the rest from the fog's colour, so a ray that meets
// nothing sees the colour alone. Off while distance is 0. With an
// altitude, ground fog (POV-Ray's fog_type 2): that density up to the
// height z = offset, thinning above it as 1 / (1 + (z − offset) /
// altitude)² (raytrace/fog.h).
struct Fog {
  dvec3 color{0.5};
  double distance = 0.0;
  double offset = 0.0;
  double altitude = 0.0;  // 0: of constant density

  bool ground() const { return altitude > 0.0; }
};

struct Scene {
  std::vector<SolidPtr> objects;
  std::vector<SurfacePtr> surfaces;  // open surfaces: planes, discs, triangles, ...
  // OpenSCAD's modifiers (scene/modifiers.h): ghosts (`%`) are shown
  // see-through and are not part of the model (not exported, not checked);
  // highlighted solids (`#`) are parts of objects, drawn again over the
  // image. A viewer may empty either list to hide them.
  std::vector<SolidPtr> ghosts;
  std::vector<SolidPtr> highlights;
  std::optional<CameraSpec> camera;  // none: frame the objects' bounds
  std::vector<Light> lights;
  // With no lights, one beside the camera (defaultLight below). A scene
  // that names its lights, even as an empty list, turns it off and is lit
  // only by ambient light and emission.
  bool defaultLight = true;
  dvec3 background{0.05, 0.05, 0.08};
  // When set, the background by direction instead (POV-Ray's sky_sphere):
  // a ray that meets nothing sees this texture at its unit direction.
  TexturePtr sky;
  TraceLimits limits;
  // A bare solid's scene (the script returned a solid, a surface or a
  // region, not scene{}): it gets the look of raytrace/cad_look.h, in place
  // of the background and of the default light when it has no lights.
  bool cadLook = false;
  // Draw edge lines (raytrace/edge_lines.h): scene{edges=true}.
  bool edges = false;
  IndirectLight indirect;
  AmbientOcclusion ambientOcclusion;
  Fog fog;

  // The union of the objects', the ghosts' and the bounded surfaces' bounds.
  Bounds bounds() const;
  // What a camera without a place frames, and what the CAD look's ground
  // lies under: bounds() with each object and ghost by its own points' box
  // (tightBounds, some 50 000 rays each), so that a part cut flat by a
  // difference stands on its ground; one the rays meet nothing of (an
  // empty difference) is left out. part: the objects' partBounds, where
  // found already and the rays met them.
  Bounds framedBounds(const std::optional<Bounds>& part = std::nullopt) const;
  // framedBounds() found once for a scene rendered many times (csgray
  // view's frames), or none: the renderer finds it.
  std::optional<Bounds> framedBox;
  // The objects' alone, each its own points' box (tightBounds): the part an
  // export writes, without ghosts, nor objects the rays meet nothing of.
  // metNothing, if given, says whether they met none (the part is empty,
  // or all of it narrower than their spacing), the box then being the
  // objects' loose one.
  Bounds partBounds(bool* metNothing = nullptr) const;
  // Takes the modifiers' marks out of the objects (resolveModifiers of
  // scene/modifiers.h), filling ghosts and highlights.
  void resolveModifiers();
};

// A camera that looks at the box from the front-right-top and sees all of
// it at the given aspect ratio (width / height). Throws std::invalid_argument
// for an empty or unbounded box.
CameraSpec frameBounds(const Bounds& box, double aspect, double fovDegrees = 45.0);

// The light used when a scene names none: above and behind the eye, to the left.
Light defaultLight(const CameraSpec& camera);

// ---- The checks of the script's scene{}, which the library's scene makes too

// Counts the primitives and surfaces of a scene's objects as they are added,
// a shared part once for each use: the objects are drawn together, so they
// share the limit on the primitives of a part (Boolean::kMaxPrimitives),
// and a list of millions of uses of one part stops there.
class ObjectTally {
 public:
  // Throws std::invalid_argument naming what ("scene: objects[3]") when
  // count more would take the scene past the limit.
  void add(std::size_t count, const std::string& what);

 private:
  std::size_t total_ = 0;
};

// Each throws std::invalid_argument with the script's message.
void checkBackground(const dvec3& color);                // components >= 0
void checkIndirectLight(const IndirectLight& indirect);  // samples 0 to 4096, bounces 0 to 64
// Colour components >= 0, distance > 0, offset finite, altitude >= 0.
void checkFog(const Fog& fog);
void checkAmbientOcclusion(const AmbientOcclusion& occlusion);  // samples 0 to 4096, distance >= 0
int checkedMaxDepth(double depth);                              // a whole number from 0 to 64
void checkMinWeight(double weight);                             // in [0, 1]
void checkHasObjects(const Scene& scene);                       // a solid or a surface

}  // namespace csgray::detail
