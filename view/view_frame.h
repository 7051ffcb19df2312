// A frame the page asks for, from the query of GET /frame or GET /pick:
//
//   camera=ex,ey,ez,tx,ty,tz,ux,uy,uz   eye, target, up (none: the scene's
//                                       camera, or the bounds framed)
//   fov=45 | ortho=W                    perspective angle (degrees) or the
//                                       orthographic screen's width
//   size=WxH                            the full frame's size in pixels
//   pass=0|1|2                          0: a quarter of each side, 1: full,
//                                       2: full, 4 rays a pixel at edges
//   section=nx,ny,nz,d                  cut the part by the plane, keeping
//                                       the side nx·x + ny·y + nz·z <= d
//   ghosts=0, highlights=0              leave out the script's ghosts
//                                       (s:ghost()), its highlights
//                                       (s:highlight()); 1 (the default)
//                                       shows them
#pragma once

#include <map>
#include <optional>
#include <string>

#include "raytrace/section_plane.h"
#include "scene/scene.h"

namespace csgray::detail {

struct FrameRequest {
  std::optional<CameraSpec> camera;
  int width = 800, height = 600;
  int pass = 1;
  std::optional<SectionPlane> section;
  bool ghosts = true, highlights = true;

  // The scene as this frame shows it: its camera, without the ghosts or
  // highlights it leaves out.
  void applyTo(Scene& scene) const;

  // The size a pass renders at.
  int passWidth() const;
  int passHeight() const;
  int samples() const { return pass >= 2 ? 4 : 1; }
};

// From the query's parameters; throws std::invalid_argument with a
// one-line message naming the parameter.
FrameRequest parseFrameRequest(const std::multimap<std::string, std::string>& query);

// What a ray through a pixel meets first.
struct PickResult {
  bool hit = false;
  dvec3 point{0.0};
  dvec3 normal{0.0};
  std::string kind;    // "box", "sphere", "plane", ...
  std::string source;  // "part.lua:12", or "" when unknown
};

}  // namespace csgray::detail
