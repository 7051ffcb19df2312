// csgray: the command line over the modeler, ray tracer and io libraries.
// Each command is declared and run in its own file (cli/*_command.cpp);
// this puts them together and turns failures into exit statuses.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli/commands.h"

using namespace csgray::detail;

namespace {

// Standard output holds what info and check report, and what render and
// export wrote: lost there (> /dev/full, a full disk), it is an error, as
// a file that cannot be written is.
void flushStandardOutput() {
  errno = 0;
  std::cout.flush();
  if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout)
    throw std::runtime_error(std::string("cannot write the standard output: ") +
                             (errno != 0 ? std::strerror(errno) : "the write failed"));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"csgray: exact CSG ray tracing of parts written in Lua"};
  // The version and the instruction set the build is for (CMakeLists.txt,
  // CSGRAY_ARCH): a v3 binary runs only on processors that have it.
#if defined(CSGRAY_X86_64_V3)
  app.set_version_flag("--version", std::string(CSGRAY_VERSION) + " (x86-64-v3)");
#else
  app.set_version_flag("--version", std::string(CSGRAY_VERSION) + " (portable)");
#endif
  app.require_subcommand(1);

  ScriptArguments script;
  const Command commands[] = {renderCommand(app, script), exportCommand(app, script),
                              checkCommand(app, script), infoCommand(app, script)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    std::cerr << "csgray: error: " << e.what() << " (see csgray --help)\n";
    return 2;
  }

  try {
    const PartScript part(script);
    for (const Command& command : commands)
      if (*command.app) {
        const int code = command.run(part);
        flushStandardOutput();
        return code;
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
