#include "check/report_findings.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace csgray::detail {

namespace {

constexpr std::size_t kWarningKinds = 20;

}  // namespace

void reportFindings(const GridTally& tally, const TriangleMesh& mesh, const MeshShells& shells,
                    const CheckOptions& options, CheckReport& report) {
  report.fidelity = tally.fidelity;
  // (With no distance found above zero, nothing more than the tolerance was allowed.)
  report.fidelityAllowed = tally.fidelity > 0.0 ? tally.fidelityAllowed : options.tolerance;
  report.fidelityAt = tally.fidelityAt;
  report.fidelityFromMesh = tally.fidelityFromMesh;
  report.thinnestWall = tally.wall;
  report.narrowestGap = tally.gap;

  // Warnings: the degenerate booleans the rays met, most often met first,
  // then walls and gaps below what a printer makes.
  std::vector<CheckWarning> found;
  for (const auto& [key, w] : tally.warnings) found.push_back(w);
  std::stable_sort(found.begin(), found.end(),
                   [](const CheckWarning& a, const CheckWarning& b) { return a.rays > b.rays; });
  if (found.size() > kWarningKinds) {
    report.warningsLeftOut = found.size() - kWarningKinds;
    found.resize(kWarningKinds);
  }
  report.warnings = std::move(found);
  auto thin = [&](const std::optional<Stretch>& s, double limit, const char* kind,
                  const char* what) {
    if (!s || s->thickness >= limit) return;
    std::ostringstream m;
    m << what << " " << s->thickness << " thick at " << pointText(s->location) << ", under "
      << limit;
    report.warnings.push_back({kind, m.str(), s->location, 1});
  };
  // A cavity's shell is the inside of a piece, not a piece.
  if (const std::size_t pieces = report.shells - report.cavities; pieces > report.modelPieces) {
    const ShellApproach near = nearestShells(mesh, shells);
    std::ostringstream m;
    m << "the export falls into " << pieces << " separate pieces, more than the "
      << report.modelPieces << " piece" << (report.modelPieces == 1 ? "" : "s")
      << " the model is made of: two come within " << near.distance << " of each other at "
      << pointText(0.5 * (near.a + near.b))
      << ": a cut goes through there, or the model's pieces meet in an edge or a point";
    report.warnings.insert(report.warnings.begin(),
                           {"separate shells", m.str(), 0.5 * (near.a + near.b), 1});
  }
  thin(report.thinnestWall, options.minWall, "thin wall", "a wall");
  thin(report.narrowestGap, options.minGap, "narrow gap", "a gap");
}

}  // namespace csgray::detail
