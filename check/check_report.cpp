#include "check/check_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace csgray::detail {

namespace {

// A numeric option of check(): its range, and where it goes.
struct NumberOption {
  const char* key;
  double lo, hi;
  bool whole;
  void (*set)(CheckOptions&, double);
};

constexpr NumberOption kNumberOptions[] = {
    {"samples", 0, double(CheckOptions::kMaxSamples), true,
     [](CheckOptions& o, double v) { o.samples = std::size_t(v); }},
    {"grid", 2, CheckOptions::kMaxGrid, true, [](CheckOptions& o, double v) { o.grid = int(v); }},
    {"seed", 0, 9e15, true, [](CheckOptions& o, double v) { o.seed = std::uint64_t(v); }},
    {"tolerance", 1e-6, 1e3, false, [](CheckOptions& o, double v) { o.tolerance = v; }},
    {"min_wall", 0.0, 1e6, false, [](CheckOptions& o, double v) { o.minWall = v; }},
    {"min_gap", 0.0, 1e6, false, [](CheckOptions& o, double v) { o.minGap = v; }},
};

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string jsonNumber(double x) {
  if (!std::isfinite(x)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return text;
}

std::string jsonPoint(const dvec3& p) {
  return "[" + jsonNumber(p.x) + ", " + jsonNumber(p.y) + ", " + jsonNumber(p.z) + "]";
}

const char* mark(bool ok) { return ok ? "ok    " : "FAILED"; }

}  // namespace

std::string pointText(const dvec3& p) {
  return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
}

void setCheckOption(CheckOptions& options, const std::string& key, double value) {
  for (const NumberOption& option : kNumberOptions) {
    if (key != option.key) continue;
    const bool inRange = value >= option.lo && value <= option.hi;
    if (option.whole && !(inRange && std::floor(value) == value))
      throw std::invalid_argument("check: " + key + " must be a whole number from " +
                                  std::to_string(static_cast<long long>(option.lo)) + " to " +
                                  std::to_string(static_cast<long long>(option.hi)));
    if (!inRange) {
      // %g: "1e-06 to 1000", not std::to_string's "0.000001 to 1000.000000".
      char range[64];
      std::snprintf(range, sizeof range, "%g to %g", option.lo, option.hi);
      throw std::invalid_argument("check: " + key + " must be from " + range);
    }
    option.set(options, value);
    return;
  }
  throw std::invalid_argument("check: unknown parameter '" + key + "'");
}

bool CheckReport::volumeOk() const {
  return failure.empty() && gridsAgree() && std::abs(meshVolume - exactVolume) <= volumeAllowed;
}

bool CheckReport::fidelityOk() const {
  return failure.empty() && fidelity <= fidelityAllowed * (1.0 + kCheckEstimateSlack);
}

bool CheckReport::ok() const {
  return meshOk() && classificationOk() && volumeOk() && fidelityOk() &&
         !(options.strict && !warnings.empty());
}

std::string checkReportText(const CheckReport& r, const std::string& name) {
  std::ostringstream s;
  s << "csgray check: " << name << " at tolerance " << number(r.options.tolerance) << "\n";
  if (!r.failure.empty()) {
    s << "  " << r.failure << "\n"
      << "verdict: FAILED\n";
    return s.str();
  }
  s << "  mesh            " << mark(r.meshOk()) << "  " << r.triangles << " triangles: "
    << (r.meshDefect.empty() ? "closed, 2-manifold, outward, no self-intersections" : r.meshDefect)
    << "\n";
  s << "  shells                  " << r.shells;
  if (r.cavities > 0)
    s << ", " << r.cavities << (r.cavities == 1 ? " of them a cavity" : " of them cavities");
  s << " (the model is " << r.modelPieces << " piece" << (r.modelPieces == 1 ? "" : "s") << ")\n";
  if (r.points == 0 && r.options.samples > 0) {
    s << "  classification  " << mark(false)
      << "  not done: the mesh is not a closed 2-manifold, so it has no inside\n";
  } else {
    s << "  classification  " << mark(r.classificationOk()) << "  " << r.points
      << " points: " << r.agree << " agree, " << r.inBand
      << " differ within the tolerance band (set aside), " << r.disagreementCount << " disagree\n";
    for (const dvec3& p : r.disagreements)
      s << "                          disagree at " << pointText(p) << "\n";
  }
  s << "  volume          " << mark(r.volumeOk()) << "  exact " << number(r.exactVolume) << " (x "
    << number(r.volumeAlong[0]) << ", y " << number(r.volumeAlong[1]) << ", z "
    << number(r.volumeAlong[2]) << "; spread " << number(r.gridSpread)
    << (r.gridsAgree() ? " <= " : " > ") << number(r.gridAllowed) << "), mesh "
    << number(r.meshVolume) << ": off by " << number(std::abs(r.meshVolume - r.exactVolume))
    << (std::abs(r.meshVolume - r.exactVolume) <= r.volumeAllowed ? " <= " : " > ")
    << number(r.volumeAllowed) << "\n";
  const bool crease = r.fidelityAllowed > r.options.tolerance;
  s << "  fidelity        " << mark(r.fidelityOk()) << "  " << number(r.fidelity)
    << (r.fidelityOk() ? " <= " : " > ")
    << (crease ? number(r.fidelityAllowed) + " allowed at a crease" : "the tolerance") << ", from "
    << (r.fidelityFromMesh ? "a mesh" : "an exact") << " point at " << pointText(r.fidelityAt)
    << "\n";
  auto stretch = [&](const char* label, const std::optional<Stretch>& st) {
    s << label;
    if (st)
      s << number(st->thickness) << " at " << pointText(st->location) << "\n";
    else
      s << "none found\n";
  };
  stretch("  thinnest wall           ", r.thinnestWall);
  stretch("  narrowest gap           ", r.narrowestGap);
  for (const CheckWarning& w : r.warnings) {
    s << "  warning: " << w.kind << ": " << w.message;
    if (w.rays > 1) s << " (" << w.rays << " rays)";
    s << "\n";
  }
  if (r.warningsLeftOut > 0)
    s << "  (" << r.warningsLeftOut << " more warnings of coinciding faces left out)\n";
  const bool warned = r.options.strict && !r.warnings.empty();
  s << "verdict: " << (r.ok() ? "ok" : "FAILED") << (warned ? " (strict: there are warnings)" : "")
    << "\n";
  return s.str();
}

std::string checkReportJson(const CheckReport& r, const std::string& name) {
  std::ostringstream s;
  s << "{\n  \"script\": " << jsonString(name) << ",\n  \"ok\": " << (r.ok() ? "true" : "false")
    << ",\n  \"tolerance\": " << jsonNumber(r.options.tolerance);
  if (!r.failure.empty()) {
    s << ",\n  \"failure\": " << jsonString(r.failure) << "\n}\n";
    return s.str();
  }
  s << ",\n  \"mesh\": {\"ok\": " << (r.meshOk() ? "true" : "false")
    << ", \"triangles\": " << r.triangles << ", \"defect\": " << jsonString(r.meshDefect)
    << ", \"shells\": " << r.shells << ", \"cavities\": " << r.cavities
    << ", \"model_pieces\": " << r.modelPieces << "}";
  s << ",\n  \"classification\": {\"ok\": " << (r.classificationOk() ? "true" : "false")
    << ", \"points\": " << r.points << ", \"agree\": " << r.agree << ", \"in_band\": " << r.inBand
    << ", \"disagree\": " << r.disagreementCount << ", \"disagreements\": [";
  for (std::size_t k = 0; k < r.disagreements.size(); ++k)
    s << (k ? ", " : "") << jsonPoint(r.disagreements[k]);
  s << "]}";
  s << ",\n  \"volume\": {\"ok\": " << (r.volumeOk() ? "true" : "false")
    << ", \"exact\": " << jsonNumber(r.exactVolume) << ", \"x\": " << jsonNumber(r.volumeAlong[0])
    << ", \"y\": " << jsonNumber(r.volumeAlong[1]) << ", \"z\": " << jsonNumber(r.volumeAlong[2])
    << ", \"grid_spread\": " << jsonNumber(r.gridSpread)
    << ", \"grid_allowed\": " << jsonNumber(r.gridAllowed)
    << ", \"mesh\": " << jsonNumber(r.meshVolume) << ", \"mesh_area\": " << jsonNumber(r.meshArea)
    << ", \"allowed\": " << jsonNumber(r.volumeAllowed) << "}";
  s << ",\n  \"fidelity\": {\"ok\": " << (r.fidelityOk() ? "true" : "false")
    << ", \"distance\": " << jsonNumber(r.fidelity)
    << ", \"allowed\": " << jsonNumber(r.fidelityAllowed) << ", \"at\": " << jsonPoint(r.fidelityAt)
    << ", \"from\": " << (r.fidelityFromMesh ? "\"mesh\"" : "\"exact\"") << "}";
  auto stretch = [&](const char* key, const std::optional<Stretch>& st) {
    s << ",\n  \"" << key << "\": ";
    if (st)
      s << "{\"thickness\": " << jsonNumber(st->thickness)
        << ", \"at\": " << jsonPoint(st->location) << "}";
    else
      s << "null";
  };
  stretch("thinnest_wall", r.thinnestWall);
  stretch("narrowest_gap", r.narrowestGap);
  s << ",\n  \"warnings\": [";
  for (std::size_t k = 0; k < r.warnings.size(); ++k) {
    const CheckWarning& w = r.warnings[k];
    s << (k ? ",\n    " : "\n    ") << "{\"kind\": " << jsonString(w.kind)
      << ", \"message\": " << jsonString(w.message) << ", \"at\": " << jsonPoint(w.location)
      << ", \"rays\": " << w.rays << "}";
  }
  s << (r.warnings.empty() ? "]" : "\n  ]") << ",\n  \"warnings_left_out\": " << r.warningsLeftOut
    << "\n}\n";
  return s.str();
}

}  // namespace csgray::detail
