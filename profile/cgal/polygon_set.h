// Regions as CGAL's general polygon sets over segments and circular arcs
// (2D Regularized Boolean Set-Operations, "Gps_circle_segment_traits_2"):
// exact booleans of rational segments and circles with rational centres
// and rational squared radii. Included only by the files of profile/cgal/.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_circle_segment_traits_2.h>

#include <vector>

#include "profile/corner_weld.h"
#include "profile/region.h"

namespace csgray::detail {

using PlaneKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using CircleSegmentTraits = CGAL::Gps_circle_segment_traits_2<PlaneKernel>;
using ArcPolygonSet = CGAL::General_polygon_set_2<CircleSegmentTraits>;
using ArcPolygon = CircleSegmentTraits::Polygon_2;
using ArcPolygonWithHoles = CircleSegmentTraits::Polygon_with_holes_2;
// A segment or a circular arc, not necessarily x-monotone.
using CircleSegment = CircleSegmentTraits::Curve_2;

// The exact point of a double's value.
PlaneKernel::Point_2 exactPoint(const dvec2& p);

// The closed curves of loops (each a list of segments and arcs whose ends
// join) as a polygon set by the even-odd rule: a point is in the set when
// it is enclosed by an odd number of the curves. The curves may cross,
// touch and overlap; overlapping pieces cancel in pairs.
ArcPolygonSet evenOddSet(const std::vector<std::vector<CircleSegment>>& loops);

// A leaf's loops as exact curves: segments and circular arcs as they are
// (an arc through its two ends and its middle point, so that loops close
// exactly), arcs of ellipses that are not circles as polygons within
// ellipseTolerance. Throws std::invalid_argument for a coordinate that is
// not a finite number.
// With a weld, the corners between two of its straight edges that it
// moves are taken where it moves them (profile/corner_weld.h).
std::vector<std::vector<CircleSegment>> exactLoops(const Profile& profile, double ellipseTolerance,
                                                   const CornerWeld* weld = nullptr);

// The region's set, its corners welded (profile/corner_weld.h).
ArcPolygonSet polygonSetOf(const Region& region, double ellipseTolerance);

// The points about which closed chains of curves (each point left as
// often as it is reached) wind a positive number of times, each curve
// counted the way it runs, as a profile (profileOf's conventions).
Profile positiveWindingFill(const std::vector<CircleSegment>& curves);

// The set's boundary as a profile: outer loops counterclockwise, holes
// clockwise; pieces of one segment or circle that follow each other joined
// into one edge; edges too short for doubles to tell apart dropped.
Profile profileOf(const ArcPolygonSet& set);

}  // namespace csgray::detail
