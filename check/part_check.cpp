#include "check/part_check.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <numeric>
#include <string>
#include <vector>

#include "check/exact_distance.h"
#include "check/point_classification.h"
#include "check/ray_grids.h"
#include "check/report_findings.h"
#include "engine/boolean.h"
#include "engine/instance.h"
#include "export/cgal/mesh_boolean.h"
#include "export/cgal/mesh_probe.h"
#include "export/cgal/mesh_validity.h"
#include "export/printed_part.h"
#include "meshio/mesh_writer.h"
#include "primitives/profile_sweep.h"
#include "profile/region_evaluation.h"
#include "tessellation/mesh_shells.h"

namespace csgray::detail {

namespace {

// The pieces a sweep is: its region's outer loops once evaluated (the
// letters of a word, cells apart), each counterclockwise.
std::size_t sweptPieces(const Solid& solid) {
  auto* sweep = dynamic_cast<const RegionSweep*>(&solid);
  if (sweep == nullptr) return 1;
  const Region& region = *sweep->sweptRegion();
  std::size_t outer = 0;
  Profile loop;
  for (const ProfileLoop& each : evaluate(region, evaluationTolerance(region)).loops) {
    loop.loops = {each};
    outer += area(loop) > 0.0;
  }
  return std::max<std::size_t>(outer, 1);
}

// The pieces a part is meant to be: a union's operands (unions within it
// looked through) joined where their boxes overlap, and a sweep alone in
// its group as many as its region has; any other solid is one.
std::size_t modelPieces(const Solid& solid) {
  std::vector<Bounds> boxes;
  std::vector<const Solid*> solids;
  std::vector<const Solid*> pending = {&solid};
  while (!pending.empty()) {
    const Solid* s = pending.back();
    pending.pop_back();
    auto* node = dynamic_cast<const Boolean*>(s);
    if (node && node->op() == Boolean::Op::Union) {
      for (const SolidPtr& child : node->children()) pending.push_back(child.get());
    } else if (!s->bounds().empty()) {
      boxes.push_back(s->bounds());
      solids.push_back(s);
    }
  }
  // Groups of overlapping boxes, by union-find.
  std::vector<std::size_t> parent(boxes.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::size_t pieces = boxes.size();
  std::vector<std::size_t> members(boxes.size(), 1);
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j]) && root(i) != root(j)) {
        members[root(i)] += members[root(j)];
        parent[root(j)] = root(i);
        --pieces;
      }
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (root(i) == i && members[i] == 1) pieces += sweptPieces(*solids[i]) - 1;
  return std::max<std::size_t>(pieces, 1);
}

}  // namespace

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
  const MeshShells shells = meshShells(mesh);
  report.shells = shells.count;
  report.modelPieces = modelPieces(solid);
  solid.prepare();
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
  reportFindings(tally, mesh, shells, options, report);
  return report;
}

CheckReport checkPrintedPart(const Scene& scene, const std::string& script,
                             const CheckOptions& options,
                             const std::function<void(const std::string& message)>& warn) {
  return checkPart(*printedPart(scene, script, "check", warn), options);
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
