// What `csgray check` and the script's check() find when they hold a part's
// exported mesh against its exact model: plain data, with its text and
// JSON forms. docs/check.md explains every figure. The check itself is in
// check/part_check.h; the report lives here so that the script API, which
// does not link the mesh code, can hand it to a script as a table.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/ray.h"

namespace csgray::detail {

struct CheckOptions {
  // Limits that keep a check within memory and minutes.
  static constexpr std::size_t kMaxSamples = 10'000'000;
  static constexpr int kMaxGrid = 1024;

  std::size_t samples = 100'000;  // random points classified both ways
  double tolerance = 0.01;        // of the export (model units)
  double minWall = 0.4;           // thinner solid stretches are warned of
  double minGap = 0.4;            // narrower empty stretches are warned of
  int grid = 128;                 // rays per side of each of the three ray grids
  std::uint64_t seed = 1;         // of the random points: the same each run
  bool strict = false;            // warnings fail the check too
};

// Sets the numeric option that the script's check() calls key ("samples",
// "grid", "seed", "tolerance", "min_wall" or "min_gap") to value, within
// the range that both the script's check() and the library's allow: else
// throws std::invalid_argument, naming it as the script does ("check: grid
// must be a whole number from 2 to 1024").
void setCheckOption(CheckOptions& options, const std::string& key, double value);

// Distances to the exact surface are measured along lines (docs/check.md):
// exact on flat faces, a few percent off where a face curves tightly
// within the tolerance (by δ²/2r for a face of radius r). A point this
// share past what is allowed still passes.
inline constexpr double kCheckEstimateSlack = 0.05;

// Something that does not make the mesh wrong but may make the part so:
// faces of two operands that coincide, a wall too thin to print, ...
struct CheckWarning {
  std::string kind;     // "coincident faces", "touching faces", "zero-length span",
                        // "thin wall", "narrow gap"
  std::string message;  // one line, naming the operands and their script lines
  dvec3 location{0.0};
  std::size_t rays = 1;  // grid rays that found it
};

// A measured stretch (wall or gap): its thickness and where it is.
struct Stretch {
  double thickness = 0.0;
  dvec3 location{0.0};
};

struct CheckReport {
  CheckOptions options;
  // The export: made at all (else `failure` says why), and valid.
  std::string failure;     // the part could not be meshed, or the check not run
  std::string meshDefect;  // empty: closed, 2-manifold, outward, no self-intersections
  std::size_t triangles = 0;
  // Separate shells of the mesh, those of them that bound cavities, and
  // the pieces the model is meant to be: its objects, and the operands of
  // a union whose boxes keep apart. More shells than pieces, cavities
  // aside, warn of a cut that goes through (docs/check.md).
  std::size_t shells = 0;
  std::size_t cavities = 0;
  std::size_t modelPieces = 0;

  // Random points in the box, classified by the exact model and by CGAL.
  std::size_t points = 0;
  std::size_t agree = 0;
  std::size_t inBand = 0;            // differing, but within the tolerance band: set aside
  std::vector<dvec3> disagreements;  // differing outside the band (the first few)
  std::size_t disagreementCount = 0;

  // Volumes: the exact one from ray grids along x, y and z, and the mesh's.
  double volumeAlong[3] = {0.0, 0.0, 0.0};
  double gridSpread = 0.0;   // the difference of the two furthest apart for their sampling
  double gridAllowed = 0.0;  // five standard deviations of those two grids' sampling
  double exactVolume = 0.0;  // their mean
  double meshVolume = 0.0;
  double meshArea = 0.0;
  double volumeAllowed = 0.0;  // tolerance × area, plus five deviations of the mean

  // The distance between the two boundaries at the sampled point where it
  // is largest for what is allowed there (the tolerance, or more where
  // faces meet at a crease), and where that is.
  double fidelity = 0.0;
  double fidelityAllowed = 0.0;
  dvec3 fidelityAt{0.0};
  bool fidelityFromMesh = false;  // measured from a mesh point (else from an exact one)

  std::optional<Stretch> thinnestWall, narrowestGap;
  std::vector<CheckWarning> warnings;
  std::size_t warningsLeftOut = 0;  // past the first 20 of the boolean warnings

  bool meshOk() const { return failure.empty() && meshDefect.empty(); }
  // Every point was classified, and none disagrees.
  bool classificationOk() const {
    return meshOk() && points == options.samples && disagreementCount == 0;
  }
  bool gridsAgree() const { return gridSpread <= gridAllowed; }
  bool volumeOk() const;
  bool fidelityOk() const;
  // All of the above hold (and, when strict, there are no warnings).
  bool ok() const;
};

// A point as the report and its messages give one: "(x, y, z)", six
// digits each.
std::string pointText(const dvec3& p);

// The report as a few aligned lines, ending in the verdict; `name` (the
// script) heads it.
std::string checkReportText(const CheckReport& report, const std::string& name);
// The same as one JSON object.
std::string checkReportJson(const CheckReport& report, const std::string& name);

}  // namespace csgray::detail
