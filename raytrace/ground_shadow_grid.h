// The CAD look's ground shadow (raytrace/cad_look.h) on a grid over the
// ground rather than at every pixel: the shade is soft, so it is traced at
// the corners of square cells a few pixels wide and interpolated
// bilinearly between them. Each corner is traced once, by whichever
// thread needs it first, and kept; a pixel costs at most four lookups
// instead of 4 to 24 shadow rays through the part.
#pragma once

#include <atomic>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>

#include "engine/ray.h"

namespace csgray::detail {

using glm::dvec2;

class GroundShadowGrid {
 public:
  // Corners at lo + (i, j)·cell over the rectangle [lo, hi] of the ground
  // (x and y). No grid is made (made() is false) when it would take more
  // than maxCorners corners.
  GroundShadowGrid(const dvec2& lo, const dvec2& hi, double cell, std::size_t maxCorners);

  bool made() const { return corners_ != nullptr; }

  // The hidden share at ground point p, from the corners about its cell:
  // each corner traced (by `trace`, at every sky point) the first time it
  // is asked for, then each of the cell's corners smoothed as the mean of
  // the 3 × 3 corners about it, and those interpolated bilinearly. The
  // mean takes the grain out of the traced shares (each a sum over a few
  // sky points drawn per point, CadLook::skyPointsFor) and keeps a share
  // that changes linearly across the ground. A corner has one share
  // whichever pixel asks first, so the image does not depend on the order
  // pixels come in, nor on the threads. Nothing when p lies outside the
  // grid, or when smoothing moves two of the cell's corners by more than
  // kSharpStep each (a sharp edge of the shadow, a step of more than 0.3
  // beside them: the caller traces p itself).
  static constexpr double kSharpStep = 0.1;
  // Does the grid reach over ground point p?
  bool holds(const dvec3& p) const;
  std::optional<double> at(const dvec3& p, double groundZ,
                           const std::function<double(const dvec3&)>& trace) const;

 private:
  dvec2 lo_;
  double cell_;
  int nx_ = 0, ny_ = 0;  // corners along x and y
  // Per corner: the hidden share, or a negative number before it is traced.
  std::unique_ptr<std::atomic<float>[]> corners_;
};

}  // namespace csgray::detail
