// The public plain values as the internal ones and back. Those the user
// gives are checked on the way in, as a script's are (scene/).
#pragma once

#include <glm/mat4x4.hpp>
#include <optional>

#include "csgray/material.h"
#include "csgray/scene.h"
#include "csgray/solid.h"
#include "engine/bounds.h"
#include "scene/light.h"
#include "scene/material.h"
#include "scene/scene.h"

namespace csgray::detail {

inline dvec3 toDetail(const Vec3& v) { return {v.x, v.y, v.z}; }
inline Vec3 toPublic(const dvec3& v) { return {v.x, v.y, v.z}; }
inline csgray::Bounds toPublic(const Bounds& b) { return {toPublic(b.lo), toPublic(b.hi)}; }
inline std::optional<dvec3> toDetail(const std::optional<Vec3>& v) {
  return v ? std::optional<dvec3>(toDetail(*v)) : std::nullopt;
}

// Rows to glm's columns.
inline glm::dmat4 toDetail(const Matrix4& rows) {
  glm::dmat4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = rows[r][c];
  return m;
}

// Checked: "material: ambient must be in [0, 1]".
MaterialPtr toDetail(const csgray::Material& material);
csgray::Material toPublic(const Material& material);

// The parameters of the light's script function; makeLight checks them.
LightParams toDetail(const csgray::Light& light);
csgray::Light toPublic(const Light& light);

// Checked: "camera: eye and look_at are the same point".
CameraSpec toDetail(const csgray::Camera& camera);
csgray::Camera toPublic(const CameraSpec& camera);

}  // namespace csgray::detail
