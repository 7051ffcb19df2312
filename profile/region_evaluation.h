// A region evaluated into one profile whose loops neither cross nor touch
// along an edge (they may touch at a point, and a loop may pass through a
// point twice: a bow tie is one loop or two): outer loops counterclockwise,
// holes clockwise. What offsets, hulls, areas, outlines (SVG, DXF) and the
// tessellation of sweeps start from. Booleans of segments and circular arcs
// are exact (CGAL's general polygon sets with circle-segment traits); an
// arc of an ellipse that is not a circle is first replaced by a polygon
// within `ellipseTolerance`, and so is a Bézier curve (booleans, offsets
// and hulls of letters are within that tolerance, not exact). Its arcs are circles (axes r·I),
// angle1 > angle0 for counterclockwise ones; each edge's `from` is the previous one's `to` exactly.
// Every function here throws std::invalid_argument for a coordinate, distance or tolerance that is
// not a finite number (and a tolerance that is not positive), with a message that says which.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "profile/region.h"

namespace csgray::detail {

Profile evaluate(const Region& region, double ellipseTolerance);

// The box of the region's own points (Region::bounds() may be looser: a
// boolean's is its operands'), from its evaluation within
// evaluationTolerance: exact for segments and circular arcs. What
// OpenSCAD's resize of a 2D shape measures.
ProfileBounds tightBounds(const Region& region);

// The points about which directed segments wind a non-zero number of times
// (the non-zero rule), as an evaluated profile. The segments must make
// closed chains (every point left as often as it is reached); they may
// cross, touch and overlap, and segments of no length are left out. Exact:
// the arrangement of the segments, each edge counting the segments along
// it by their direction.
Profile nonZeroFill(std::span<const std::array<dvec2, 2>> segments);
// The same for the points about which they wind a positive number of
// times: counterclockwise outlines less clockwise holes, where the holes
// may reach past the outlines.
Profile positiveFill(std::span<const std::array<dvec2, 2>> segments);

// The tolerance to evaluate a region within (its offsets, hulls and area)
// when the user gives none: a ten-millionth of its size, at which an
// ellipse's polygon is invisible; a hundred-thousandth where it holds
// Bézier curves (letters). An offset of a letter works on its polygons,
// one strip and one corner per side, and Wang's bound makes 10 times fewer
// sides at 100 times the tolerance: an offset of a "B" took 11 s at 10⁻⁷,
// 0.4 s at 10⁻⁵ (a tenth of a micron on 10 mm letters).
double evaluationTolerance(const Region& region);

// Signed area of an evaluated profile (or of any profile whose loops
// neither cross nor nest: a glyph's): positive for counterclockwise loops,
// exact for every kind of edge.
double area(const Profile& evaluated);

// A circle of the plane whose arcs flatten() cuts on the polygon a
// cylinder standing on it has (circlePolygon): its centre, its radius, and
// the cylinder's x and y axes in the plane, which place the polygon's
// points (the identity unless the cylinder is turned about its axis; a
// turn as the cylinder's frame holds it, to rounding).
struct CircleRim {
  dvec2 center{0.0};
  double radius = 0.0;
  dmat2 axes{1.0};
};

// Each loop as a polygon within `tolerance` of the exact edges (the sagitta
// rule of the cylinders' tessellation for arcs); a loop's first point is
// not repeated at its end. An arc of a circle that is one of `rims` (its
// centre and radius within 10⁻⁹ of the radius, the centre also within
// 10⁻⁹ of its distance from the origin or 2⁻³⁰) instead takes the points of
// that cylinder's rim polygon at rimTolerance that lie on it, between its
// ends, so that a swept circle meets the cylinder on the same points: a
// ring swept around a cylinder leaves no crevice between their polygons.
std::vector<std::vector<dvec2>> flatten(const Profile& profile, double tolerance,
                                        std::span<const CircleRim> rims = {},
                                        double rimTolerance = 0.0);

// OpenSCAD's offset(r = r): every point within |r| of the region (r > 0)
// or the points of the region at least -r from its outside (r < 0); the
// corners it makes round are true arcs.
Profile offsetRounded(const Region& region, double r, double ellipseTolerance);
// OpenSCAD's offset(delta = d, chamfer = c): the edges moved by d along
// their normals (arcs to concentric arcs); the corners that turn towards
// the offset's side mitred, or with chamfer cut flat by the line at
// distance |d| from the corner across the mitre's bisector (Clipper's
// square join, which OpenSCAD uses: a square of side a grows to
// (a + 2d)² − 4(3 − 2√2)d²).
Profile offsetDelta(const Region& region, double delta, bool chamfer, double ellipseTolerance);
// The convex hull of the regions: segments and arcs of their circles (an
// empty profile for no regions, or for a hull without area).
Profile hull(std::span<const RegionPtr> regions, double ellipseTolerance);
// The Minkowski sum a ⊕ b (every sum of a point of a and one of b), exact
// where one is a circle (the other's rounded offset, moved by the
// centre), both are convex and one is a polygon (the hull of copies of
// the other at its corners), or one is convex and the other a polygon
// (that one moved, with each of its edges swept over the convex one);
// where that other has arcs, they are cut into segments within a part in
// 10⁴ of its size first. Two shapes neither of which is convex are
// refused.
Profile minkowskiSum(const RegionPtr& a, const RegionPtr& b, double ellipseTolerance);

}  // namespace csgray::detail
