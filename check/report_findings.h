// The last step of csgray check: what the grids' rays found, written into
// the report as its figures and warnings.
#pragma once

#include "check/check_report.h"
#include "check/ray_grids.h"
#include "tessellation/mesh_shells.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// Sets the report's fidelity (the worst distance between mesh and model
// for what is allowed there, and where), its thinnest wall and narrowest
// gap, and its warnings: the degenerate booleans the rays met, most often
// met first (at most a few kinds, the rest counted), then a mesh of more
// shells than the model has pieces (report.shells, report.modelPieces),
// then walls and gaps below what a printer makes.
void reportFindings(const GridTally& tally, const TriangleMesh& mesh, const MeshShells& shells,
                    const CheckOptions& options, CheckReport& report);

}  // namespace csgray::detail
