// check(): `csgray check` and the script's check() (check/part_check.h),
// its report as plain data.
#include "csgray/check.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "api/access.h"
#include "api/convert.h"
#include "api/errors.h"
#include "check/part_check.h"

namespace csgray {

using detail::toPublic;

namespace {

// The ranges of the script's check(): the same messages.
void checkRange(const char* key, double value, double lo, double hi, bool whole) {
  if (value >= lo && value <= hi && (!whole || std::floor(value) == value)) return;
  if (whole)
    throw std::invalid_argument("check: " + std::string(key) + " must be a whole number from " +
                                std::to_string(static_cast<long long>(lo)) + " to " +
                                std::to_string(static_cast<long long>(hi)));
  throw std::invalid_argument("check: " + std::string(key) + " must be from " + std::to_string(lo) +
                              " to " + std::to_string(hi));
}

detail::CheckOptions optionsOf(const CheckOptions& o) {
  using Limits = detail::CheckOptions;
  checkRange("samples", double(o.samples), 0, double(Limits::kMaxSamples), true);
  checkRange("grid", o.grid, 2, Limits::kMaxGrid, true);
  checkRange("seed", double(o.seed), 0, 9e15, true);
  checkRange("tolerance", o.tolerance, 1e-6, 1e3, false);
  checkRange("min_wall", o.minWall, 0.0, 1e6, false);
  checkRange("min_gap", o.minGap, 0.0, 1e6, false);
  detail::CheckOptions made;
  made.samples = o.samples;
  made.grid = o.grid;
  made.seed = o.seed;
  made.tolerance = o.tolerance;
  made.minWall = o.minWall;
  made.minGap = o.minGap;
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
  made.mesh = {r.meshOk(), r.triangles, r.meshDefect, r.shells, r.modelPieces};
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
  return detail::guarded(
      [&] { return reportOf(detail::checkPart(*detail::Access::of(solid), optionsOf(options))); });
}

}  // namespace csgray
