// The first half of csgray check: random points of the box, each classified
// by the mesh (inside, outside or on it) and by the exact model. Where the
// two disagree the point may still lie within what the mesh may be off the
// exact surface (in band); otherwise it is a disagreement.
#pragma once

#include "check/check_report.h"
#include "check/exact_distance.h"
#include "engine/solid.h"
#include "export/cgal/mesh_probe.h"

namespace csgray::detail {

// Fills the report's points, agree, inBand, disagreementCount and the
// first disagreements, for options.samples points drawn from options.seed.
void classifyPoints(const Solid& solid, const MeshProbe& probe, const ExactDistance& distances,
                    const Bounds& box, const CheckOptions& options, CheckReport& report);

}  // namespace csgray::detail
