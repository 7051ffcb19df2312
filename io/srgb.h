// The sRGB transfer function (IEC 61966-2-1) and its inverse: 8-bit images
// hold sRGB code values, the renderer works in linear light.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace csgray {

inline float encodeSrgb(float linear) {
  float v = std::clamp(linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

inline float decodeSrgb(float encoded) {
  float v = std::clamp(encoded, 0.0f, 1.0f);
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// The 8-bit code of a linear value, rounded as round(255 · encodeSrgb(v))
// but without a pow per value: the linear values where the code steps up
// are computed once, and a value's code is found by binary search.
std::uint8_t srgbByte(float linear);

}  // namespace csgray
