// csgray check as a function: the exported mesh of a part held against its
// exact model (docs/check.md says what each figure means).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "csgray/solid.h"
#include "csgray/types.h"

namespace csgray {

struct CheckOptions {
  std::size_t samples = 100'000;  // random points classified both ways: 0 to 10⁷
  double tolerance = 0.01;        // of the export: 1e-6 to 1000
  double minWall = 0.4;           // thinner walls are warned of: 0 to 10⁶
  double minGap = 0.4;            // narrower gaps are warned of: 0 to 10⁶
  int grid = 128;                 // rays per side of each of the three grids: 2 to 1024
  std::uint64_t seed = 1;         // of the random points and rays
  bool strict = false;            // warnings fail the check too
  // Set by another thread, stops the check: check throws Error with
  // ErrorCode::Cancelled at its next step: one of the export's (see
  // ExportOptions::cancel), a row of a ray grid, a sample point.
  const std::atomic<bool>* cancel = nullptr;
};

// Something that does not make the mesh wrong but may make the part so:
// faces of two operands that coincide, a wall too thin to print, ...
struct CheckWarning {
  std::string kind;  // "coincident faces", "thin wall", ...
  std::string message;
  Vec3 at;
  std::size_t rays = 1;  // grid rays that found it
};

// A wall's or a gap's thickness, and where it is.
struct Stretch {
  double thickness = 0.0;
  Vec3 at;
};

struct CheckReport {
  bool ok = false;      // the verdict: every item below passed
  std::string failure;  // why the part could not be meshed or checked; then nothing else is set
  std::string summary;  // what `csgray check` prints

  struct MeshItem {
    bool ok = false;
    std::size_t triangles = 0;
    std::string defect;  // empty: closed, 2-manifold, outward, no self-intersections
    std::size_t shells = 0;
    std::size_t cavities = 0;  // of the shells, those that face inwards: walls of cavities
    std::size_t modelPieces = 0;
  } mesh;
  struct ClassificationItem {
    bool ok = false;
    std::size_t points = 0, agree = 0, inBand = 0, disagree = 0;
    std::vector<Vec3> disagreements;  // the first few points where the mesh and model differ
  } classification;
  struct VolumeItem {
    bool ok = false;
    double exact = 0.0;                // the mean of the three grids'
    double x = 0.0, y = 0.0, z = 0.0;  // along each axis
    double mesh = 0.0, meshArea = 0.0;
    double allowed = 0.0;  // the largest difference of exact and mesh allowed
  } volume;
  struct FidelityItem {
    bool ok = false;
    double distance = 0.0, allowed = 0.0;  // the largest for what is allowed there
    Vec3 at;
  } fidelity;
  std::optional<Stretch> thinnestWall, narrowestGap;
  std::vector<CheckWarning> warnings;
  std::size_t warningsLeftOut = 0;
};

CSGRAY_API CheckReport check(const Solid& solid, const CheckOptions& options = {});

}  // namespace csgray
