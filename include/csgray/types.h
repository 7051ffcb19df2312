// csgray's library: the plain values its other headers share, and the mark
// of what the shared library exports.
#pragma once

#include <cmath>

#if defined(__GNUC__)
#define CSGRAY_API __attribute__((visibility("default")))
#else
#define CSGRAY_API
#endif

namespace csgray {

// A point or a vector in model units (millimetres for a printed part), or a
// linear RGB colour with components from 0 (black) up.
struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, const Vec3& v) { return {s * v.x, s * v.y, s * v.z}; }
inline bool operator==(const Vec3& a, const Vec3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}
inline bool operator!=(const Vec3& a, const Vec3& b) { return !(a == b); }

// An axis-aligned box from lo to hi. Empty when lo > hi on some axis; an
// unbounded solid has infinite coordinates on the axes where it goes on.
struct Bounds {
  Vec3 lo, hi;

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  bool finite() const {
    return !empty() && std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(lo.z) &&
           std::isfinite(hi.x) && std::isfinite(hi.y) && std::isfinite(hi.z);
  }
  Vec3 size() const { return hi - lo; }
  Vec3 center() const { return 0.5 * (lo + hi); }
};

}  // namespace csgray
