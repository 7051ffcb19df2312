// projection(solid, {cut = true}): OpenSCAD's projection() in scripts, a
// solid's section by the plane z = 0 or its shadow on it as a region.
// Reference: docs/script.md, "Projections". The work is the exporter's
// (ScriptOptions::projectSolid: export/solid_projection.h).
#include <new>
#include <stdexcept>
#include <string>

#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

int projection(lua_State* L) {
  checkArgumentCount(L, "projection", 2);
  const SolidPtr& solid = checkValue<SolidPtr>(L, 1, "projection: the first argument",
                                               "be projected (only solids have a section)");
  LuaArgs args(L, 2, "projection");
  const bool cut = args.boolean("cut").value_or(false);
  args.finish();
  const ScriptOptions& options = scriptOptionsOf(L);
  if (!options.projectSolid)
    throw std::invalid_argument("projection: this program cannot project solids");
  Profile flat;
  try {
    flat = options.projectSolid(solid, cut);
  } catch (const std::bad_alloc&) {
    throw;  // the sandbox's own message
  } catch (const std::exception& e) {
    // The exporter's words (an unbounded solid, a boolean it cannot make),
    // said of this call.
    throw std::invalid_argument(std::string("projection: ") + e.what());
  }
  pushRegion(L, Region::leaf(std::move(flat)));
  return 1;
}

}  // namespace

void registerProjectionApi(lua_State* L) { lua_register(L, "projection", guarded<projection>); }

}  // namespace csgray::detail
