// csgray: the command line over the modeler, ray tracer and io libraries.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include "cli/watchdog.h"
#include "io/image_file.h"
#include "modeler/primitive.h"
#include "modeler/script/script.h"
#include "raytrace/renderer.h"

using namespace csgray;

namespace {

constexpr int kMaxSide = 16384;
constexpr long kMaxPixels = 64L * 1024 * 1024;

// "1024x768" to width and height; throws CLI::ValidationError.
std::pair<int, int> parseSize(const std::string& text) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,6})[xX](\d{1,6}))")))
    throw CLI::ValidationError("--size",
                               "expected WIDTHxHEIGHT, e.g. 1024x768, got '" + text + "'");
  int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1 || w > kMaxSide || h > kMaxSide || long(w) * h > kMaxPixels)
    throw CLI::ValidationError("--size", "image size " + text + " is out of range (1 to " +
                                             std::to_string(kMaxSide) + " per side, at most " +
                                             std::to_string(kMaxPixels) + " pixels)");
  return {w, h};
}

// -D name=value pairs.
std::vector<std::pair<std::string, std::string>> parseDefines(
    const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, std::string>> defines;
  for (const std::string& item : items) {
    size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw CLI::ValidationError("-D", "expected name=value, got '" + item + "'");
    defines.emplace_back(item.substr(0, eq), item.substr(eq + 1));
  }
  return defines;
}

std::string formatPoint(const dvec3& p) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "[%g, %g, %g]", p.x, p.y, p.z);
  return buffer;
}

void printInfo(const std::string& script, const Scene& scene) {
  TreeStats stats;
  for (const SolidPtr& object : scene.objects) {
    TreeStats s = treeStats(*object);
    stats.primitives += s.primitives;
    stats.booleans += s.booleans;
  }
  Bounds b = scene.bounds();
  std::cout << script << "\n";
  if (b.empty()) {
    std::cout << "  bounds:        empty\n";
  } else {
    std::cout << "  bounds:        " << formatPoint(b.lo) << " .. " << formatPoint(b.hi) << "\n";
    if (b.finite()) std::cout << "  size:          " << formatPoint(b.size()) << "\n";
  }
  std::cout << "  objects:       " << scene.objects.size() << "\n"
            << "  primitives:    " << stats.primitives << "\n"
            << "  boolean nodes: " << stats.booleans << "\n"
            << "  lights:        " << scene.lights.size()
            << (scene.lights.empty() ? " (default)" : "") << "\n"
            << "  camera:        " << (scene.camera ? "set" : "framed from bounds") << "\n";
}

}  // namespace

// 0 (no limit) up to about eleven days; NaN is refused.
const CLI::Validator timeoutRange(
    [](const std::string& text) -> std::string {
      double v = std::strtod(text.c_str(), nullptr);
      return v >= 0.0 && v <= 1e6 ? "" : "must be a number of seconds from 0 to 1e6";
    },
    "SECONDS");

int main(int argc, char** argv) {
  CLI::App app{"csgray: exact CSG ray tracing of parts written in Lua"};
  app.set_version_flag("--version", std::string(CSGRAY_VERSION));
  app.require_subcommand(1);

  std::string script, output, size = "800x600";
  std::vector<std::string> defineItems;
  int threads = 0;
  double scriptTimeout = 60.0;

  CLI::App* render = app.add_subcommand("render", "Ray trace a part script to an image");
  render->add_option("script", script, "Lua part script")->required();
  render
      ->add_option("-o,--output", output,
                   "Image file; its extension picks the format (.png, .exr, ...)")
      ->required();
  render->add_option("--size", size, "Image size WIDTHxHEIGHT")->capture_default_str();
  render->add_option("--threads", threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  render->add_option("-D", defineItems, "Set a script global before it runs: name=value");
  render->add_option("--script-timeout", scriptTimeout, "Seconds the script may run (0: no limit)")
      ->check(timeoutRange)
      ->capture_default_str();

  CLI::App* info = app.add_subcommand("info", "Print the bounds and tree size of a part script");
  info->add_option("script", script, "Lua part script")->required();
  info->add_option("-D", defineItems, "Set a script global before it runs: name=value");
  info->add_option("--script-timeout", scriptTimeout, "Seconds the script may run (0: no limit)")
      ->check(timeoutRange)
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    std::cerr << "csgray: error: " << e.what() << " (see csgray --help)\n";
    return 2;
  }

  try {
    ScriptOptions scriptOptions;
    scriptOptions.defines = parseDefines(defineItems);
    // Runs the script under the watchdog: nothing is written meanwhile.
    auto runScript = [&] {
      char limit[32];
      std::snprintf(limit, sizeof limit, "%g", scriptTimeout);
      Watchdog watchdog(scriptTimeout, script + ": the script did not finish within " + limit +
                                           " s (--script-timeout)");
      return runScriptFile(script, scriptOptions);
    };
    if (*render) {
      auto [width, height] = parseSize(size);
      // Refuse an unwritable format before spending time on the render.
      std::error_code same;
      if (std::filesystem::equivalent(script, output, same))
        throw std::runtime_error("cannot write " + output + ": it is the script itself");
      if (std::string problem = imageOutputProblem(output); !problem.empty())
        throw std::runtime_error("cannot write " + output + ": " + problem);
      auto start = std::chrono::steady_clock::now();
      Scene scene = runScript();
      RenderOptions options{width, height, threads};
      Image image = [&] {
        try {
          return Renderer(scene, options).render();
        } catch (const std::invalid_argument& e) {  // e.g. nothing to frame
          throw std::runtime_error(script + ": " + e.what());
        }
      }();
      writeImage(output, image.width, image.height, image.rgb.data());
      std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
      std::printf("csgray: wrote %s (%dx%d) in %.2f s\n", output.c_str(), width, height,
                  seconds.count());
    } else if (*info) {
      printInfo(script, runScript());
    }
  } catch (const CLI::ValidationError& e) {
    std::cerr << "csgray: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::string message = e.what();
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';  // one line, whatever a library said
    std::cerr << "csgray: error: " << message << "\n";
    return 1;
  }
  return 0;
}
