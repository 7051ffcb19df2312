// What a script describes: solids to show, and how to look at them. The
// renderer turns this into pixels; the exporter uses only the solids.
#pragma once

#include <optional>
#include <vector>

#include "modeler/solid.h"

namespace csgray {

// A pinhole camera (seed 001, 2.1.1): eye point, the point looked at, the
// up direction and the horizontal view angle in degrees.
struct CameraSpec {
  dvec3 eye{0.0, -10.0, 0.0};
  dvec3 lookAt{0.0};
  dvec3 up{0.0, 0.0, 1.0};
  double fovDegrees = 45.0;
};

// A point light of any colour (seed 001, 2.4) and intensity.
struct PointLight {
  dvec3 position{0.0};
  dvec3 color{1.0};
  double intensity = 1.0;
};

struct Scene {
  std::vector<SolidPtr> objects;
  std::optional<CameraSpec> camera;  // none: frame the objects' bounds
  std::vector<PointLight> lights;    // none: a default light beside the camera
  dvec3 background{0.05, 0.05, 0.08};

  // The union of the objects' bounds.
  Bounds bounds() const;
};

// A camera that looks at the box from the front-right-top and sees all of
// it at the given aspect ratio (width / height). Throws std::invalid_argument
// for an empty or unbounded box.
CameraSpec frameBounds(const Bounds& box, double aspect, double fovDegrees = 45.0);

// The light used when a scene names none: above and behind the eye, to the left.
PointLight defaultLight(const CameraSpec& camera);

}  // namespace csgray
