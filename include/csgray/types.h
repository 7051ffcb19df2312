// csgray's library: the plain values its other headers share, and the mark
// of what the shared library exports.
#pragma once

#include <cmath>
#include <memory>

#if defined(__GNUC__)
#define CSGRAY_API __attribute__((visibility("default")))
#else
#define CSGRAY_API
#endif

namespace csgray {

namespace detail {

// The internal value behind a Solid, a Surface or a Texture, shared by
// their copies: they are immutable, so a copy costs a reference count. A
// move copies too, so that a value moved from still holds what it held
// rather than nothing (using it was a null dereference).
template <class T>
class Shared {
 public:
  explicit Shared(std::shared_ptr<const T> p) : p_(std::move(p)) {}
  Shared(const Shared&) = default;
  Shared(Shared&& other) noexcept : p_(other.p_) {}
  Shared& operator=(const Shared&) = default;
  Shared& operator=(Shared&& other) noexcept {
    p_ = other.p_;
    return *this;
  }
  const T* operator->() const { return p_.get(); }
  const T& operator*() const { return *p_; }
  const std::shared_ptr<const T>& pointer() const { return p_; }

 private:
  std::shared_ptr<const T> p_;
};

}  // namespace detail

// A point or a vector of the plane, in model units (a 2D region's).
struct Vec2 {
  double x = 0.0, y = 0.0;
};

inline bool operator==(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(const Vec2& a, const Vec2& b) { return !(a == b); }

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
