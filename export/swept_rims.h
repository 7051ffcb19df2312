// The circles of a part's extrusions that its cylinders stand on.
//
// A cylinder's mesh turns on a polygon pushed a little outside its circle
// (circlePolygon), an extrusion's on polygons inscribed in its region's
// circles. Where the two meet on one circle (a ring swept around a boss of
// its inner radius, a pin through a swept plate's round hole), the two
// polygons cross, and the union keeps the slivers between them: crevices
// a hundredth wide and as deep as the sweep, which `csgray check` rightly
// fails. So the exporter hands each straight extrusion the circles of its
// region that a cylinder of the part stands on, in the extrusion's plane,
// and the extrusion cuts those on the cylinder's own rim polygon
// (LinearExtrusion::withRims, flatten()). Only those: a rim polygon lies
// partly outside its circle, and a flat face tangent to it from the inside
// of a round hole (a rib standing in a ring) would then leave a gap where
// the inscribed polygon leaves none.
//
// A rotate_extrude's rings are regular polygons of its own step count, so
// there the cylinder gives way: a cylinder standing in a turn's wall of
// its radius takes that turn's rings (turnedWallPolygon), and where the
// turn is not whole, those of the whole turn whose share it is
// (Revolution::wallSteps: 270°, three quarters of one). A cylinder
// standing square on an end face of a turn that is not whole, on a circle
// of its region (a pipe's straight leg on its bend), takes that circle's
// polygon in the turn's mesh (Revolution::circleLoop), so that the leg's
// end and the bend's face meet point for point to rounding, in whatever
// plane the face lies; the union then glues them there
// (export/cgal/glued_caps.h).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <unordered_set>
#include <vector>

#include "engine/affine.h"
#include "engine/solid.h"
#include "primitives/cylinder.h"
#include "primitives/linear_extrusion.h"
#include "primitives/revolution.h"

namespace csgray::detail {

class SweptRims {
 public:
  // The part's cylinders (not cones) that do not only cut, each as
  // `placed` gives it (as the export tessellates it: in the evaluation's
  // frame, upright and unmirrored where it can be, export/upright_cylinders.h).
  SweptRims(const Solid& part,
            const std::function<std::shared_ptr<const Primitive>(const Primitive&)>& placed);

  // The rims, in the extrusion's plane, of the cylinders whose frame
  // differs from the extrusion's (which must be placed as the cylinders
  // are) by a move, a turn about the extrusion's axis (a bolt circle's
  // pins) and a mirror: a cylinder tilted against the extrusion, or
  // scaled, has no rim in its plane, and is left out.
  std::vector<CircleRim> of(const LinearExtrusion& sweep) const;

  // The polygon a cylinder of the part (placed as the part's primitives
  // are) takes where it stands in a wall of a turn of the part (a
  // rotate_extrude's ring around an axle of its bore): that turn's rings,
  // turned as the cylinder is, so that the two meet on the same points to
  // rounding (the union then makes their walls flush: aligned_walls.h).
  // The cylinder must share the turn's axis, upright and not mirrored
  // against it; nothing otherwise, for a cone, or for a cylinder that
  // only cuts. `original` is the part's primitive that `cylinder` places.
  std::optional<CirclePolygon> turnedWallPolygon(const Primitive& original,
                                                 const Cylinder& cylinder, double tolerance) const;

  // The polygon a cylinder of the part takes where one of its ends lies
  // on an end face of a turn that is not whole (a pipe's straight leg on
  // its bend), on a circle of the turn's region: that circle's polygon in
  // the turn's mesh (Revolution::circleLoop), turned as the cylinder is,
  // so that the cylinder's end and the turn's face have the same points
  // to rounding (the union glues them: export/cgal/glued_caps.h). The
  // cylinder must stand square on the face, outside the turn's wedge,
  // unscaled; nothing otherwise, or for a cone. (A cylinder that cuts
  // takes it too: the bore of a pipe's leg, united with the bend's bore.)
  // `cylinder` is placed as the part's primitives are.
  std::optional<CirclePolygon> turnedEndPolygon(const Cylinder& cylinder, double tolerance) const;

  bool empty() const { return cylinders_.empty(); }

 private:
  struct Rim {
    glm::dmat4 worldFromObject;
    double radius;
  };
  std::vector<Rim> cylinders_;             // those that do not only cut
  std::unordered_set<const Solid*> kept_;  // the same, by the part's primitive
  // The part's turns, whole or not, each placed as the part's primitives are.
  std::vector<std::shared_ptr<const Revolution>> turns_;
};

}  // namespace csgray::detail
