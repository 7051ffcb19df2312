#include "export/triangle_filters.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <initializer_list>

namespace csgray::detail {

namespace {

// The sign of orient3d(p, q, r, s), the side of the plane through p, q, r
// that s is on, when the double evaluation certainly has it; 0 when it
// cannot tell. The bound is Shewchuk's errboundA for orient3d, (7 + 56ε)ε
// times the permanent (J. R. Shewchuk, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", Discrete & Computational
// Geometry 18, 1997, section 4). It holds without underflow: a permanent
// below 1e-200 is not trusted.
int orientation(const dvec3& p, const dvec3& q, const dvec3& r, const dvec3& s) {
  const dvec3 a = p - s, b = q - s, c = r - s;
  const double bc = b.y * c.z - b.z * c.y, ca = c.y * a.z - c.z * a.y, ab = a.y * b.z - a.z * b.y;
  const double det = a.x * bc + b.x * ca + c.x * ab;
  const double permanent = std::abs(a.x) * (std::abs(b.y * c.z) + std::abs(b.z * c.y)) +
                           std::abs(b.x) * (std::abs(c.y * a.z) + std::abs(c.z * a.y)) +
                           std::abs(c.x) * (std::abs(a.y * b.z) + std::abs(a.z * b.y));
  constexpr double kBound = 7.771561172376103e-16;  // (7 + 56ε)ε, ε = 2⁻⁵³
  if (!(permanent > 1e-200)) return 0;
  if (det > kBound * permanent) return 1;
  if (det < -kBound * permanent) return -1;
  return 0;
}

// The same in the plane: the side of the line p → q that r is on. The
// bound is Shewchuk's ccwerrboundA, (3 + 16ε)ε (ibid.).
int orientation(double px, double py, double qx, double qy, double rx, double ry) {
  const double left = (px - rx) * (qy - ry), right = (py - ry) * (qx - rx);
  const double det = left - right;
  constexpr double kBound = 3.3306690738754716e-16;  // (3 + 16ε)ε
  const double permanent = std::abs(left) + std::abs(right);
  if (!(permanent > 1e-200)) return 0;
  if (det > kBound * permanent) return 1;
  if (det < -kBound * permanent) return -1;
  return 0;
}

// All of `points` strictly on one side of the plane of t.
bool strictlyOnOneSide(const dvec3 t[3], const dvec3* points, int count) {
  const int first = orientation(t[0], t[1], t[2], points[0]);
  if (first == 0) return false;
  for (int k = 1; k < count; ++k)
    if (orientation(t[0], t[1], t[2], points[k]) != first) return false;
  return true;
}

// Some edge line of t has all of other strictly on the side away from t's
// third corner, in the projection that drops coordinate `drop`: the
// shadows are apart, and so are the triangles.
bool edgeSeparates(const dvec3 t[3], const dvec3 other[3], int drop) {
  const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
  const int turn = orientation(t[0][u], t[0][v], t[1][u], t[1][v], t[2][u], t[2][v]);
  if (turn == 0) return false;
  for (int k = 0; k < 3; ++k) {
    const dvec3 &p = t[k], &q = t[(k + 1) % 3];
    bool apart = true;
    for (int j = 0; j < 3 && apart; ++j)
      apart = orientation(p[u], p[v], q[u], q[v], other[j][u], other[j][v]) == -turn;
    if (apart) return true;
  }
  return false;
}

// Triangles t and other share corner t[0] == other[0]: one of t's edges at
// that corner has other's two far corners strictly on the side away from
// t's third corner, in the projection that drops coordinate `drop`. Then
// the shadows meet only at the shared corner's shadow, and since t's
// shadow is a proper triangle (its turn is not 0), t has one point there,
// the corner itself: the triangles meet only at it. (Faces in one plane,
// a flat cap's fan, are the pairs this answers.)
bool cornerEdgeSeparates(const dvec3 t[3], const dvec3 other[3], int drop) {
  const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
  const int turn = orientation(t[0][u], t[0][v], t[1][u], t[1][v], t[2][u], t[2][v]);
  if (turn == 0) return false;
  // The edges t0 → t1 and t2 → t0, each with t's third corner on side turn.
  for (int k : {0, 2}) {
    const dvec3 &p = t[k], &q = t[(k + 1) % 3];
    if (orientation(p[u], p[v], q[u], q[v], other[1][u], other[1][v]) == -turn &&
        orientation(p[u], p[v], q[u], q[v], other[2][u], other[2][v]) == -turn)
      return true;
  }
  return false;
}

// The coordinate along which t's normal is largest: dropping it keeps t's
// shadow from being thin.
int dominantAxis(const dvec3 t[3]) {
  const dvec3 m = glm::abs(glm::cross(t[1] - t[0], t[2] - t[0]));
  return m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
}

}  // namespace

bool certainlyApart(const dvec3 a[3], const dvec3 b[3]) {
  if (strictlyOnOneSide(a, b, 3) || strictlyOnOneSide(b, a, 3)) return true;
  // Shadows on the coordinate plane most nearly parallel to a (any
  // projection would do).
  const int drop = dominantAxis(a);
  return edgeSeparates(a, b, drop) || edgeSeparates(b, a, drop);
}

bool certainlyMeetOnlyAtCorner(const dvec3 a[3], const dvec3 b[3]) {
  // If b's far corners are strictly on one side of a's plane, b meets that
  // plane only at the shared corner, and so meets a only there.
  if (strictlyOnOneSide(a, b + 1, 2) || strictlyOnOneSide(b, a + 1, 2)) return true;
  const int drop = dominantAxis(a);
  return cornerEdgeSeparates(a, b, drop) || cornerEdgeSeparates(b, a, drop);
}

bool certainlyNotFolded(const dvec3 a[3], const dvec3 b[3]) {
  // The normals' dot product, against a bound far above its rounding error
  // (a few ε times the product of the edge lengths that made it).
  const dvec3 ea = a[1] - a[0], fa = a[2] - a[0], eb = b[1] - b[0], fb = b[2] - b[0];
  const double dot = glm::dot(glm::cross(ea, fa), glm::cross(eb, fb));
  const double scale = glm::length(ea) * glm::length(fa) * glm::length(eb) * glm::length(fb);
  return std::isfinite(scale) && dot > 1e-10 * scale;
}

}  // namespace csgray::detail
