// csgray check: the exported mesh held against the exact model. Random
// points are classified by both, volumes and boundaries are compared along
// three jittered ray grids, and the grids also find where operands of a
// boolean share or touch faces and where walls and gaps are thin.
// docs/check.md says what each figure means.
#pragma once

#include <functional>
#include <string>

#include "check/check_report.h"
#include "engine/solid.h"
#include "scene/scene.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// Makes the export of the solid in memory (meshOfSolid at the options'
// tolerance, rounded to floats as an STL file holds it) and checks it. A part that cannot be
// meshed gives a report whose `failure` says why.
CheckReport checkPart(const Solid& solid, const CheckOptions& options);

// checkPart of the scene's printed part (export/printed_part.h: its
// solids' union); warn gets what is left out. Throws std::runtime_error,
// naming the script, when there is no solid.
CheckReport checkPrintedPart(const Scene& scene, const std::string& script,
                             const CheckOptions& options,
                             const std::function<void(const std::string& message)>& warn);

// Checks a given mesh against the solid, as if it were the solid's export
// at the options' tolerance: a mesh read back from a file, or one broken on
// purpose in a test.
CheckReport checkMeshAgainstSolid(const Solid& solid, const TriangleMesh& mesh,
                                  const CheckOptions& options);

}  // namespace csgray::detail
