// OpenSCAD 2021.01's own polyhedra of linear_extrude (with twist or a
// scale per axis) and rotate_extrude, for `--facets openscad`: the flat
// slices and turning steps OpenSCAD cuts the sweeps into, so that an
// export has OpenSCAD's volume (docs/openscad.md, "Curves"). The exact
// sweeps are primitives/linear_extrusion.h and primitives/revolution.h.
//
// The counts follow OpenSCAD's src/calc.cc (get_fragments_from_r,
// get_helix_slices, get_conical_helix_slices, get_diagonal_slices) and
// the polyhedra its src/GeometryEvaluator.cc (extrudePolygon, add_slice,
// rotatePolygon), as OpenSCAD 2021.01 has them.
#pragma once

#include <optional>

#include "engine/solid.h"
#include "primitives/profile_sweep_tessellation.h"

namespace csgray::detail {

// Refuses a polyhedron of OpenSCAD's polygons of more triangles than a
// tessellation may have (kMaxTessellationTriangles): throws
// std::invalid_argument, to which the importer adds the node.
void requireOpenScadTriangles(double triangles);

// OpenSCAD's special variables of a node.
struct OpenScadResolution {
  double fn = 0.0, fa = 12.0, fs = 2.0;
};

struct OpenScadLinearExtrude {
  double height = 100.0;
  bool center = false;
  double twistDegrees = 0.0;
  dvec2 scale{1.0, 1.0};
  std::optional<int> slices;  // OpenSCAD's slices=, when given (> 0)
};

// The number of slices OpenSCAD cuts the extrusion of these loops into:
// slices= when given; with a twist, the steps of a helix through the
// point farthest from the axis (a conical helix under a uniform scale)
// by $fn, $fa and $fs, at least one per 120° of twist; with a scale per
// axis and no twist, the longest path of a point between the ends by
// $fs (or $fn slices); otherwise one.
int openscadExtrudeSlices(const SweepLoops& loops, const OpenScadLinearExtrude& extrude,
                          const OpenScadResolution& resolution);

// The extrusion of the loops (outer ones counter-clockwise, holes
// clockwise, sweepLoops' order) as OpenSCAD builds it: the loops turned
// by −twist·k/N and scaled at each of the N + 1 levels k, each side quad
// cut into two triangles along its shorter diagonal in the plane (ties
// by the twist's sense), caps at the ends, and with a scale of 0 on both
// axes an apex. Throws std::invalid_argument for a scale of 0 on one axis
// only (the top would be a segment) or past the triangle budget.
SolidPtr openscadLinearExtrusion(const SweepLoops& loops, const OpenScadLinearExtrude& extrude,
                                 const OpenScadResolution& resolution);

// The number of steps OpenSCAD turns a profile reaching `reach` from the
// axis by, over angleDegrees: its fragments of a circle of that radius
// times the fraction of a turn, rounded down, at least one.
int openscadRevolutionSteps(double reach, double angleDegrees,
                            const OpenScadResolution& resolution);

// The loops (in the (x, z) half plane x >= 0) turned about the z axis from
// +x counter-clockwise over angleDegrees (in (0, 360]) in
// openscadRevolutionSteps steps: a ring of the loops' points at each step,
// quads between them, the loops themselves as flat faces at both ends of
// a partial turn. A point on the axis is one vertex. Throws
// std::invalid_argument past the triangle budget.
SolidPtr openscadRevolution(const SweepLoops& loops, double angleDegrees,
                            const OpenScadResolution& resolution);

}  // namespace csgray::detail
