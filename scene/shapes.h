// The shapes a part is made of, from the parameters a user gives them: the
// script's sphere{}, box{}, cylinder{}, ... and the library's Solid
// factories make them here, so that a bad parameter gets the same message
// from both ("sphere: r must be > 0 (got -1)"). Each throws
// std::invalid_argument. Optional parameters are those a script may leave
// out; a missing one that is needed is an error that says so.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/boolean.h"
#include "primitives/blob.h"
#include "primitives/mesh_solid.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// A radius given as r or as a diameter d (as in OpenSCAD), or neither:
// checked (> 0, or >= 0 when zero is allowed) under the name the user gave.
std::optional<double> radiusOf(const std::string& function, const char* rKey,
                               std::optional<double> r, const char* dKey, std::optional<double> d,
                               bool zeroAllowed);

SolidPtr sphereShape(std::optional<double> r, std::optional<double> d);
// A unit sphere under a non-uniform scale: exact, normals by inverse transpose.
SolidPtr ellipsoidShape(const std::optional<dvec3>& radii);
// From the origin to size, or centred on the origin.
SolidPtr boxShape(const std::optional<dvec3>& size, bool center);

// A cylinder or cone frustum along +z from 0 to h (centred on the origin
// with center): radius r, or r1 at the bottom and r2 at the top, each also
// as a diameter.
struct CylinderParams {
  std::optional<double> h, r, d, r1, d1, r2, d2;
  bool center = false;
};
// function is "cylinder", whose r2 is r1 unless given, or "cone", whose r2
// is 0 unless given.
SolidPtr cylinderShape(const char* function, const CylinderParams& params);

// normal·p <= offset.
SolidPtr halfSpaceShape(const std::optional<dvec3>& normal, double offset);
// About the z axis: R from the axis to the centre of the tube, r the tube's
// radius. Any R >= 0 is a solid.
SolidPtr torusShape(std::optional<double> R, std::optional<double> r);
// About the origin: radii along x, y and z, e the exponent of the sections
// across z, n of the profile along it (both from 0.001 to 2).
// Balls whose fields add up (primitives/blob.h): the solid where the sum
// reaches threshold.
SolidPtr blobShape(std::vector<BlobBall> balls, std::optional<double> threshold);
SolidPtr superellipsoidShape(const std::optional<dvec3>& radii, std::optional<double> e,
                             std::optional<double> n);

// "union", "intersection" or "difference".
const char* booleanName(Boolean::Op op);
// The operation on the operands; one operand is that solid itself.
SolidPtr booleanShape(Boolean::Op op, std::vector<SolidPtr> operands);

// A closed triangle mesh (counter-clockwise faces seen from outside, as
// mesh files and exports have them) as a solid; the checks' messages begin
// with name (a file name) where MeshSolid's begin with "polyhedron".
std::shared_ptr<MeshSolid> meshShape(const TriangleMesh& mesh, const std::string& name);

}  // namespace csgray::detail
