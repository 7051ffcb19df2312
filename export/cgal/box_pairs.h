// The pairs of boxes that meet, among a mesh's faces: CGAL's box
// intersection, split along the boxes' longest spread so that both cores
// share the work without doing it twice.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace csgray::detail {

// A face's closed bounding box, with the face's index and the mesh it is
// in (0 or 1: faces of two meshes may have one index).
struct FaceBox {
  double lo[3], hi[3];
  std::uint32_t face;
  std::uint32_t mesh = 0;
};

// The box of the triangle with corners p, q, r (anything with [0..2]).
template <class Point>
FaceBox faceBox(const Point& p, const Point& q, const Point& r, std::uint32_t face,
                std::uint32_t mesh = 0) {
  FaceBox box{{}, {}, face, mesh};
  for (int d = 0; d < 3; ++d) {
    box.lo[d] = std::min({double(p[d]), double(q[d]), double(r[d])});
    box.hi[d] = std::max({double(p[d]), double(q[d]), double(r[d])});
  }
  return box;
}

// Calls report(f, g) once for each unordered pair of boxes that meet
// (closed: boxes that only touch meet), f and g their faces. Reports may
// come from several threads at once and in any order. The boxes are
// reordered.
void forEachMeetingPair(std::vector<FaceBox>& boxes,
                        const std::function<void(std::uint32_t, std::uint32_t)>& report);

// A face of mesh 0 and a face of mesh 1.
using FacePair = std::pair<std::uint32_t, std::uint32_t>;

// The pairs (f, g) of a box of a (mesh 0, face f) and a box of b (mesh 1,
// face g) that meet, each once, found on several threads but in an order
// fixed by the boxes given (the same vectors give the same order, however
// many threads). The boxes are reordered. Throws Cancelled once the calling
// thread's cancel flag is set (engine/cancellation.h).
std::vector<FacePair> meetingPairs(std::vector<FaceBox>& a, std::vector<FaceBox>& b);

}  // namespace csgray::detail
