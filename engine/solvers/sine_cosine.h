// The sine and cosine of one angle together, for the paths that turn a
// point at every step of a root search (a twisted extrusion: millions of
// angles a render). The C library's sincos costs about 190 instructions a
// call here, most of them saving and restoring the rounding mode; this
// one about 40, within one unit in the last place of the exact values.
//
// The angle is reduced to r = x − k·π/2, |r| <= π/4, with π/2 split in
// three doubles (Cody and Waite, "Software Manual for the Elementary
// Functions", 1980, ch. 8): the first product is exact under a fused
// multiply-add, since x and k·P1 lie on a common grid of 2⁻⁵³ (or k is 0)
// and their difference is below 1. On [−π/4, π/4] the Taylor series of
// sin to r¹⁷ and of cos to r¹⁸ are exact to 1e-19 (the first term left
// out bounds the error: (π/4)¹⁹/19! and (π/4)²⁰/20!).
#pragma once

#include <cmath>

namespace csgray::detail {

struct SineCosine {
  double sin, cos;
};

inline SineCosine sineCosine(double x) {
  // Beyond this the reduction's k·P2 would lose bits; no caller's angle
  // comes near (a twist is at most 1 000 turns, 6 284 radians).
  constexpr double kLargest = 1e5;
  if (!(std::abs(x) <= kLargest)) return {std::sin(x), std::cos(x)};
  constexpr double kTwoOverPi = 0.6366197723675814;
  // π/2 = P1 + P2 + P3, each the double nearest what is left.
  constexpr double P1 = 1.5707963267948966;
  constexpr double P2 = 6.123233995736766e-17;
  constexpr double P3 = -1.4973849048591698e-33;
  const double k = std::nearbyint(x * kTwoOverPi);
  double r = std::fma(-k, P1, x);
  r = std::fma(-k, P2, r);
  r = std::fma(-k, P3, r);
  const double r2 = r * r;
  // Horner's scheme in r², the coefficients ±1/n!.
  double s = 2.8114572543455206e-15;    //  1/17!
  s = s * r2 - 7.647163731819816e-13;   // −1/15!
  s = s * r2 + 1.6059043836821613e-10;  //  1/13!
  s = s * r2 - 2.505210838544172e-08;   // −1/11!
  s = s * r2 + 2.7557319223985893e-06;  //  1/9!
  s = s * r2 - 0.0001984126984126984;   // −1/7!
  s = s * r2 + 0.008333333333333333;    //  1/5!
  s = s * r2 - 0.16666666666666666;     // −1/3!
  const double sine = r + r * r2 * s;
  double c = 1.5619206968586225e-16;    //  1/18!
  c = c * r2 - 4.779477332387385e-14;   // −1/16!
  c = c * r2 + 1.1470745597729725e-11;  //  1/14!
  c = c * r2 - 2.08767569878681e-09;    // −1/12!
  c = c * r2 + 2.755731922398589e-07;   //  1/10!
  c = c * r2 - 2.48015873015873e-05;    // −1/8!
  c = c * r2 + 0.001388888888888889;    //  1/6!
  c = c * r2 - 0.041666666666666664;    // −1/4!
  c = c * r2 + 0.5;                     //  1/2!
  const double cosine = 1.0 - r2 * c;
  // The quadrant k mod 4 (k may be negative).
  switch (static_cast<long long>(k) & 3) {
    case 0:
      return {sine, cosine};
    case 1:
      return {cosine, -sine};
    case 2:
      return {-sine, -cosine};
    default:
      return {-cosine, sine};
  }
}

// The sine and cosine of a + e from those of a (sc): the angle sum
// formulas, with e's own from their Taylor series where |e| <= 1/8 (to e⁹
// and e¹⁰: the first terms left out, (1/8)¹¹/11! and (1/8)¹²/12!, are below
// 1e-19), through sineCosine beyond. A root search along a short stretch
// of a twisted path turns its points by angles a little apart: this costs
// a third of sineCosine, and is as exact but for the sum's two roundings.
inline SineCosine sineCosineBeside(const SineCosine& sc, double e) {
  double se, ce;
  if (std::abs(e) <= 0.125) {
    const double e2 = e * e;
    se = e - e * e2 * (1.0 / 6.0) *
                 (1.0 - e2 * (1.0 / 20.0) * (1.0 - e2 * (1.0 / 42.0) * (1.0 - e2 * (1.0 / 72.0))));
    ce = 1.0 - e2 * 0.5 *
                   (1.0 - e2 * (1.0 / 12.0) *
                              (1.0 - e2 * (1.0 / 30.0) *
                                         (1.0 - e2 * (1.0 / 56.0) * (1.0 - e2 * (1.0 / 90.0)))));
  } else {
    const SineCosine own = sineCosine(e);
    se = own.sin;
    ce = own.cos;
  }
  return {sc.sin * ce + sc.cos * se, sc.cos * ce - sc.sin * se};
}

}  // namespace csgray::detail
