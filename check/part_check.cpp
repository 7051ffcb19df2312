#include "check/part_check.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "check/exact_distance.h"
#include "check/model_pieces.h"
#include "check/point_classification.h"
#include "check/ray_grids.h"
#include "check/report_findings.h"
#include "engine/boolean.h"
#include "engine/cancellation.h"
#include "engine/instance.h"
#include "export/cgal/mesh_boolean.h"
#include "export/cgal/mesh_probe.h"
#include "export/cgal/mesh_validity.h"
#include "export/printed_part.h"
#include "meshio/mesh_writer.h"
#include "tessellation/mesh_shells.h"

namespace csgray::detail {

CheckReport checkMeshAgainstSolid(const Solid& solid, const TriangleMesh& mesh,
                                  const CheckOptions& options) {
  // The distances to the surface read each primitive's frame: instances
  // multiplied out.
  if (solid.hasInstances())
    return checkMeshAgainstSolid(*flattened(solid.shared_from_this()), mesh, options);
  CheckReport report;
  report.options = options;
  report.triangles = mesh.size();
  if (solid.bounds().empty()) {
    report.failure = "the part is empty: it has no mesh to check";
    return report;
  }
  if (!solid.bounds().finite()) {
    report.failure = "the part is unbounded: it has no mesh to check";
    return report;
  }
  if (mesh.empty()) {
    report.failure = "the mesh is empty";
    return report;
  }
  if (options.grid < 2 || options.grid > CheckOptions::kMaxGrid ||
      options.samples > CheckOptions::kMaxSamples || !(options.tolerance > 0.0)) {
    report.failure = "the grid must have 2 to " + std::to_string(CheckOptions::kMaxGrid) +
                     " rays a side, the samples be at most " +
                     std::to_string(CheckOptions::kMaxSamples) + ", and the tolerance be positive";
    return report;
  }
  report.meshDefect = meshDefect(mesh).text;
  stopIfCancelled();  // between its steps (engine/cancellation.h)
  const MeshShells shells = meshShells(mesh);
  report.shells = shells.count;
  report.cavities = shells.cavities;
  solid.prepare();
  // Shells within twice the tolerance of each other are solids that
  // touch; a point that deep inside a face lies inside its solid.
  report.modelPieces = modelPieces(solid, mesh, shells, 2.0 * options.tolerance);
  stopIfCancelled();
  const MeshProbe probe(mesh);
  report.meshVolume = probe.volume();
  report.meshArea = probe.area();

  // The box holds both: the mesh may lie up to the tolerance outside.
  Bounds box = solid.bounds();
  box.include(mesh.bounds());
  const dvec3 margin(2.0 * options.tolerance + 1e-6 * glm::length(box.size()));
  box = Bounds{box.lo - margin, box.hi + margin};

  const ExactDistance exact(solid, options, box);
  GridTally tally;
  traceGrids(solid, probe, exact, mesh, box, options, report, tally);
  if (tally.unbounded) {
    report.failure = "the part is unbounded along a grid ray: it has no mesh to check";
    return report;
  }
  if (probe.canClassify()) classifyPoints(solid, probe, exact, box, options, report);
  stopIfCancelled();
  reportFindings(tally, mesh, shells, options, report);
  return report;
}

CheckReport checkPrintedPart(const Scene& scene, const std::string& script,
                             const CheckOptions& options,
                             const std::function<void(const std::string& message)>& warn) {
  const SolidPtr part = printedPart(scene, script, "check", warn);
  // Refused as the export refuses it, before a mesh that floats cannot
  // hold is made (a ball of radius 10¹⁸: 20 s and 1.3 GB to learn so).
  checkFloatPrecision(*part, options.tolerance, script);
  return checkPart(*part, options);
}

CheckReport checkPart(const Solid& solid, const CheckOptions& options) {
  TriangleMesh mesh;
  try {
    // Rounded to floats, as STL, OBJ, OFF and PLY files store them.
    mesh = meshOfSolid(solid, options.tolerance, storedCoordinate(MeshFormat::Stl, false)).mesh;
  } catch (const std::exception& e) {
    CheckReport report;
    report.options = options;
    report.failure = std::string("the part cannot be exported: ") + e.what();
    return report;
  }
  return checkMeshAgainstSolid(solid, mesh, options);
}

}  // namespace csgray::detail
