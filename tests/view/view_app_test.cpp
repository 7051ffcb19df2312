// csgray view as a whole, with a server that returns at once: what the
// terminal says before the page can be served.
#include "view/view_app.h"

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>

namespace csgray::detail {
namespace {

class ReturningServer : public HttpServer {
 public:
  int port() const override { return 1; }
  std::string url() const override { return "http://127.0.0.1:1/"; }
  void run() override {}
  void start() override {}
  void stop() override {}
};

std::string viewOutput(const std::string& source, double slowRunSeconds, std::string& printed) {
  const std::string script = testing::TempDir() + "/view_app_part.lua";
  std::ofstream(script) << source;
  ViewOptions options;
  options.script = script;
  options.threads = 1;
  options.slowRunSeconds = slowRunSeconds;
  options.makeServer = [](ViewService&, const std::string&, int) {
    return std::make_unique<ReturningServer>();
  };
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  serveView(options);
  printed = testing::internal::GetCapturedStdout();
  return testing::internal::GetCapturedStderr();
}

TEST(ViewApp, ASlowFirstRunSaysSoBeforeThePageIsServed) {
  // The terminal was silent until a slow script had run. A run past the
  // time (here none: every run is past it) says so; one within it (here an
  // hour) says nothing of it.
  std::string printed;
  const std::string slow = viewOutput("return sphere(1)\n", 0.0, printed);
  EXPECT_NE(slow.find("view_app_part.lua; the page is served once it has run"), std::string::npos)
      << slow;
  EXPECT_NE(printed.find("csgray: viewing"), std::string::npos) << printed;
  const std::string quick = viewOutput("return sphere(1)\n", 3600.0, printed);
  EXPECT_EQ(quick.find("running"), std::string::npos) << quick;
  EXPECT_NE(printed.find("csgray: viewing"), std::string::npos) << printed;
}

}  // namespace
}  // namespace csgray::detail
