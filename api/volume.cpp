#include "api/volume.h"

#include <tbb/parallel_for.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "engine/span_list.h"
#include "scene/value_checks.h"

namespace csgray::detail {

namespace {

// splitmix64 (Steele, Lea and Flood, OOPSLA 2014), as the check uses it: a
// jitter per ray that does not depend on which thread traces it, so that
// every call gives the same volume.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
double unit(std::uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

}  // namespace

double gridVolume(const Solid& solid, int grid) {
  checkWhole("volume", "grid", grid, 1, 4096);
  const Bounds box = solid.bounds();
  if (box.empty()) return 0.0;
  if (!box.finite()) throw std::invalid_argument("volume: the solid is unbounded");
  solid.prepare();
  const int n = grid;
  double sum = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const double du = box.size()[u] / n, dv = box.size()[v] / n;
    const double depth = box.size()[axis];
    dvec3 along(0.0);
    along[axis] = 1.0;
    std::vector<double> rows(n, 0.0);
    tbb::parallel_for(0, n, [&](int i) {
      SpanList spans;
      for (int j = 0; j < n; ++j) {
        const std::uint64_t key =
            mix(1 ^ mix((std::uint64_t(axis) << 60) ^ (std::uint64_t(i) << 30) ^ j));
        dvec3 origin = box.lo;
        origin[u] += (i + unit(key)) * du;
        origin[v] += (j + unit(mix(key))) * dv;
        solid.spans(Ray(origin, along, -kInfinity, kInfinity), spans);
        rows[i] += spans.lengthWithin(0.0, depth);
      }
    });
    double length = 0.0;
    for (double row : rows) length += row;  // in order: the same sum on any threads
    sum += length * du * dv;
  }
  return sum / 3.0;
}

}  // namespace csgray::detail
