// check(): `csgray check` and the script's check() (check/part_check.h),
// its report as plain data.
#include "csgray/check.h"

#include "api/access.h"
#include "api/convert.h"
#include "api/errors.h"
#include "check/part_check.h"
#include "engine/cancellation.h"

namespace csgray {

using detail::toPublic;

namespace {

// Checked as the script's check() checks them, with the same messages.
detail::CheckOptions optionsOf(const CheckOptions& o) {
  detail::CheckOptions made;
  detail::setCheckOption(made, "samples", double(o.samples));
  detail::setCheckOption(made, "grid", o.grid);
  detail::setCheckOption(made, "seed", double(o.seed));
  detail::setCheckOption(made, "tolerance", o.tolerance);
  detail::setCheckOption(made, "min_wall", o.minWall);
  detail::setCheckOption(made, "min_gap", o.minGap);
  made.strict = o.strict;
  return made;
}

std::optional<Stretch> stretchOf(const std::optional<detail::Stretch>& s) {
  if (!s) return std::nullopt;
  return Stretch{s->thickness, toPublic(s->location)};
}

CheckReport reportOf(const detail::CheckReport& r) {
  CheckReport made;
  made.ok = r.ok();
  made.summary = detail::checkReportText(r, "check()");
  made.failure = r.failure;
  if (!r.failure.empty()) return made;
  made.mesh = {r.meshOk(), r.triangles, r.meshDefect, r.shells, r.cavities, r.modelPieces};
  made.classification.ok = r.classificationOk();
  made.classification.points = r.points;
  made.classification.agree = r.agree;
  made.classification.inBand = r.inBand;
  made.classification.disagree = r.disagreementCount;
  for (const detail::dvec3& p : r.disagreements)
    made.classification.disagreements.push_back(toPublic(p));
  made.volume = {r.volumeOk(),     r.exactVolume, r.volumeAlong[0], r.volumeAlong[1],
                 r.volumeAlong[2], r.meshVolume,  r.meshArea,       r.volumeAllowed};
  made.fidelity = {r.fidelityOk(), r.fidelity, r.fidelityAllowed, toPublic(r.fidelityAt)};
  made.thinnestWall = stretchOf(r.thinnestWall);
  made.narrowestGap = stretchOf(r.narrowestGap);
  for (const detail::CheckWarning& w : r.warnings)
    made.warnings.push_back({w.kind, w.message, toPublic(w.location), w.rays});
  made.warningsLeftOut = r.warningsLeftOut;
  return made;
}

}  // namespace

CheckReport check(const Solid& solid, const CheckOptions& options) {
  return detail::guarded([&] {
    const detail::CancelScope scope(options.cancel);
    try {
      return reportOf(detail::checkPart(*detail::Access::of(solid), optionsOf(options)));
    } catch (const detail::Cancelled&) {
      throw Error(ErrorCode::Cancelled, "check: cancelled");
    }
  });
}

}  // namespace csgray
