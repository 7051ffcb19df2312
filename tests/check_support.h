// The one-line check for our own tests: a solid is valid, and its export
// agrees with it (csgray check, check/part_check.h):
//   EXPECT_TRUE(test::checksOut(*part));
// On failure the whole report is the message.
#pragma once

#include <gtest/gtest.h>

#include "check/part_check.h"

namespace csgray::detail::test {

inline ::testing::AssertionResult checksOut(const Solid& solid, double tolerance = 0.01,
                                            std::size_t samples = 20'000) {
  CheckOptions options;
  options.tolerance = tolerance;
  options.samples = samples;
  const CheckReport report = checkPart(solid, options);
  if (report.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << checkReportText(report, solid.kind());
}

}  // namespace csgray::detail::test
