// Random numbers for sampling that do not depend on thread scheduling: each
// pixel seeds its own generator from its coordinates, so a render is the
// same on any number of threads and from run to run.
#pragma once

#include <cstdint>

namespace csgray::detail {

class Sampler {
 public:
  Sampler(std::uint32_t x, std::uint32_t y, std::uint32_t pass = 0)
      : state_(mix((std::uint64_t(x) << 32 | y) ^ (std::uint64_t(pass) << 56))) {}

  // Uniform in [0, 1).
  double next() {
    state_ += 0x9E3779B97F4A7C15ull;
    return double(mix(state_) >> 11) * 0x1.0p-53;
  }

 private:
  // SplitMix64's finaliser (Steele, Lea and Flood, OOPSLA 2014).
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  std::uint64_t state_;
};

}  // namespace csgray::detail
