// check(solid, {samples=, tolerance=, ...}): the report of `csgray check`
// as a table, so that a script, or a user's test, can assert that a part's
// booleans are sound and its export agrees with it (docs/check.md).
#include <optional>
#include <stdexcept>

#include "scene/modifiers.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

void setNumber(lua_State* L, const char* key, double value) {
  lua_pushnumber(L, value);
  lua_setfield(L, -2, key);
}
void setInteger(lua_State* L, const char* key, std::size_t value) {
  lua_pushinteger(L, static_cast<lua_Integer>(value));
  lua_setfield(L, -2, key);
}
void setBoolean(lua_State* L, const char* key, bool value) {
  lua_pushboolean(L, value);
  lua_setfield(L, -2, key);
}
void setString(lua_State* L, const char* key, const std::string& value) {
  lua_pushlstring(L, value.data(), value.size());
  lua_setfield(L, -2, key);
}
void setPoint(lua_State* L, const char* key, const dvec3& p) {
  pushVec3(L, p);
  lua_setfield(L, -2, key);
}
void setStretch(lua_State* L, const char* key, const std::optional<Stretch>& s) {
  if (!s) return;  // nil: none found
  lua_createtable(L, 0, 2);
  setNumber(L, "thickness", s->thickness);
  setPoint(L, "at", s->location);
  lua_setfield(L, -2, key);
}

void pushReport(lua_State* L, const CheckReport& r) {
  lua_createtable(L, 0, 12);
  setBoolean(L, "ok", r.ok());
  // What csgray check prints, for assert(report.ok, report.summary).
  setString(L, "summary", checkReportText(r, "check()"));
  if (!r.failure.empty()) {
    setString(L, "failure", r.failure);
    return;
  }
  lua_createtable(L, 0, 3);
  setBoolean(L, "ok", r.meshOk());
  setInteger(L, "triangles", r.triangles);
  setString(L, "defect", r.meshDefect);
  lua_setfield(L, -2, "mesh");

  lua_createtable(L, 0, 5);
  setBoolean(L, "ok", r.classificationOk());
  setInteger(L, "points", r.points);
  setInteger(L, "agree", r.agree);
  setInteger(L, "in_band", r.inBand);
  setInteger(L, "disagree", r.disagreementCount);
  lua_setfield(L, -2, "classification");

  lua_createtable(L, 0, 8);
  setBoolean(L, "ok", r.volumeOk());
  setNumber(L, "exact", r.exactVolume);
  setNumber(L, "x", r.volumeAlong[0]);
  setNumber(L, "y", r.volumeAlong[1]);
  setNumber(L, "z", r.volumeAlong[2]);
  setNumber(L, "mesh", r.meshVolume);
  setNumber(L, "mesh_area", r.meshArea);
  setNumber(L, "allowed", r.volumeAllowed);
  lua_setfield(L, -2, "volume");

  lua_createtable(L, 0, 3);
  setBoolean(L, "ok", r.fidelityOk());
  setNumber(L, "distance", r.fidelity);
  setNumber(L, "allowed", r.fidelityAllowed);
  setPoint(L, "at", r.fidelityAt);
  lua_setfield(L, -2, "fidelity");

  setStretch(L, "thinnest_wall", r.thinnestWall);
  setStretch(L, "narrowest_gap", r.narrowestGap);

  lua_createtable(L, static_cast<int>(r.warnings.size()), 0);
  for (std::size_t k = 0; k < r.warnings.size(); ++k) {
    const CheckWarning& w = r.warnings[k];
    lua_createtable(L, 0, 4);
    setString(L, "kind", w.kind);
    setString(L, "message", w.message);
    setPoint(L, "at", w.location);
    setInteger(L, "rays", w.rays);
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  lua_setfield(L, -2, "warnings");
  setInteger(L, "warnings_left_out", r.warningsLeftOut);
}

int check(lua_State* L) {
  checkArgumentCount(L, "check", 2);
  const SolidPtr& solid =
      checkValue<SolidPtr>(L, 1, "check: the first argument", "be checked as a part");
  LuaArgs args(L, 2, "check");
  CheckOptions options;
  // Read and checked in this order, so that the first bad one is named.
  for (const char* key : {"samples", "grid", "seed", "tolerance", "min_wall", "min_gap"})
    if (std::optional<double> value = args.number(key)) setCheckOption(options, key, *value);
  options.strict = args.boolean("strict").value_or(false);
  args.finish();
  const ScriptOptions& script = scriptOptionsOf(L);
  if (!script.checkSolid) throw std::invalid_argument("check: this program cannot check solids");
  // The model's part: not its ghosts or disabled solids (scene/modifiers.h).
  SolidPtr model = modelOf(solid);
  if (!model)
    throw std::invalid_argument(
        "check: nothing is left to check: the solid is disabled or a ghost");
  pushReport(L, script.checkSolid(*model, options));
  return 1;
}

}  // namespace

void registerCheckApi(lua_State* L) { lua_register(L, "check", guarded<check>); }

}  // namespace csgray::detail
