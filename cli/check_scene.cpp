#include "cli/check_scene.h"

#include <cstdio>

#include "check/part_check.h"
#include "cli/crash_guard.h"
#include "cli/heap_reserve.h"
#include "cli/warning.h"

namespace csgray::detail {

int checkScene(const Scene& scene, const CheckCommandOptions& options) {
  // The export's booleans, as in csgray export (cli/heap_reserve.h).
  reserveHugePageHeap(std::size_t(512) << 20);
  const CheckReport report = [&] {
    const CrashGuard guard(options.script);
    return checkPrintedPart(scene, options.script, options.check, printWarning);
  }();
  if (options.checked) options.checked();
  const std::string text = options.json ? checkReportJson(report, options.script)
                                        : checkReportText(report, options.script);
  std::fputs(text.c_str(), stdout);
  return report.ok() ? 0 : 1;
}

}  // namespace csgray::detail
