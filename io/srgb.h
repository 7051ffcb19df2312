// The sRGB transfer function (IEC 61966-2-1) and its inverse: 8-bit images
// hold sRGB code values, the renderer works in linear light.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace csgray::detail {

inline float encodeSrgb(float linear) {
  float v = std::clamp(linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

inline float decodeSrgb(float encoded) {
  float v = std::clamp(encoded, 0.0f, 1.0f);
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// The 8-bit code of a linear value, round(255 · encodeSrgb(v)), without a
// pow per value: a table over [0, 1] in kBuckets buckets gives the code at
// each bucket's start, and since codes lie more than a bucket apart in
// linear light, one comparison with the next step finishes the job. The
// closest codes are those of the linear segment near black, 1 / (255 ·
// 12.92) = 3.0e-4 apart; a bucket is 1 / 4095 = 2.4e-4 wide.
class SrgbEncoder {
 public:
  static constexpr int kBuckets = 4096;

  SrgbEncoder();
  std::uint8_t operator()(float linear) const {
    if (!(linear > 0.0f)) return 0;  // also NaN
    float v = std::min(linear, 1.0f);
    int code = start_[int(v * float(kBuckets - 1))];
    return std::uint8_t(v > steps_[code] ? code + 1 : code);
  }

 private:
  std::array<float, 256> steps_;  // steps_[k]: where the code goes from k to k + 1
  std::array<std::uint8_t, kBuckets> start_;
};

}  // namespace csgray::detail
