// csgray check's three ray grids, one along each axis: n × n rays, one at a
// random point of each cell, each traced through the exact model and the
// mesh. They measure the volume three ways, the distances between the two
// surfaces, the thinnest wall and the narrowest gap, and find where
// operands of a boolean share or touch faces.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "check/check_report.h"
#include "check/exact_distance.h"
#include "engine/solid.h"
#include "export/cgal/mesh_probe.h"
#include "tessellation/triangle_mesh.h"

namespace csgray::detail {

// What the rays of one row of a grid found; rows are merged in order, so
// that the figures do not depend on the threads.
struct GridTally {
  // The sampled point furthest from the other boundary for what is
  // allowed there.
  double fidelity = 0.0, fidelityAllowed = 1.0;
  dvec3 fidelityAt{0.0};
  bool fidelityFromMesh = false;
  std::optional<Stretch> wall, gap;
  bool unbounded = false;
  // Warnings by what they say but where: one for each pair of script
  // lines, however many faces and rays show it.
  std::map<std::string, CheckWarning> warnings;

  // Would a point d away where `allowed` is allowed be the worst so far?
  bool worse(double d, double allowed) const { return d * fidelityAllowed > fidelity * allowed; }
  void distance(double d, double allowed, const dvec3& at, bool fromMesh) {
    if (worse(d, allowed)) {
      fidelity = d;
      fidelityAllowed = allowed;
      fidelityAt = at;
      fidelityFromMesh = fromMesh;
    }
  }
  static void thinnest(std::optional<Stretch>& best, double thickness, const dvec3& at) {
    if (!best || thickness < best->thickness) best = Stretch{thickness, at};
  }
  void warn(const std::string& kind, const std::string& what, const dvec3& at) {
    auto [it, added] = warnings.try_emplace(kind + ": " + what);
    if (added) {
      it->second.kind = kind;
      it->second.message = what + ", at " + pointText(at);
      it->second.location = at;
    } else {
      ++it->second.rays;
    }
  }
  void merge(const GridTally& other) {
    distance(other.fidelity, other.fidelityAllowed, other.fidelityAt, other.fidelityFromMesh);
    if (other.wall) thinnest(wall, other.wall->thickness, other.wall->location);
    if (other.gap) thinnest(gap, other.gap->thickness, other.gap->location);
    unbounded = unbounded || other.unbounded;
    for (const auto& [key, w] : other.warnings) {
      auto [it, added] = warnings.try_emplace(key, w);
      if (!added) it->second.rays += w.rays;
    }
  }
};

// The three grids over the box: the volume along each axis (the report's
// volumeAlong, exactVolume, gridSpread, gridAllowed and volumeAllowed,
// which needs its meshArea), and in tally what their rays found.
void traceGrids(const Solid& solid, const MeshProbe& probe, const ExactDistance& exact,
                const TriangleMesh& mesh, const Bounds& box, const CheckOptions& options,
                CheckReport& report, GridTally& tally);

}  // namespace csgray::detail
