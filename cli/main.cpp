// csgray: the command line over the modeler, ray tracer and io libraries.
// Each command is declared and run in its own file (cli/*_command.cpp);
// this puts them together and turns failures into exit statuses.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cli/commands.h"
#include "cli/warning.h"
#include "scene/value_checks.h"
#include "script/script.h"

using namespace csgray::detail;

namespace {

constexpr std::size_t kLongestError = 2000;

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

// One line on stderr, whatever a library said: line breaks become spaces.
// With cut, every word longer than a screen's share is cut to 60
// characters: CLI11's messages, and the commands' checks of options, echo
// the values given on the command line whole. No line is longer than a
// script's error may be.
int error(const std::string& message, int status, bool cut = false) {
  std::string line;
  std::size_t word = 0;
  for (std::size_t i = 0; i <= message.size(); ++i) {
    if (i < message.size() && message[i] != ' ' && message[i] != '\n' && message[i] != '\r')
      continue;
    const std::string_view text = std::string_view(message).substr(word, i - word);
    line += cut ? shownValue(text) : std::string(text);
    if (i < message.size()) line += ' ';
    word = i + 1;
  }
  std::cerr << "csgray: error: " << terminalLine(shownValue(line, kLongestError)) << "\n";
  return status;
}

// The first argument, when it is not an option and names no command.
const char* unknownCommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return nullptr;
  for (const CLI::App* command : app.get_subcommands({}))
    if (command->check_name(argv[1])) return nullptr;
  return argv[1];
}

// CLI11's words where they are hard to read: an option given twice is
// "--output: At Most 1 required but received 2".
std::string readableParseError(const std::string& message) {
  const std::string twice = ": At Most 1 required but received ";
  if (const std::size_t at = message.find(twice); at != std::string::npos)
    return message.substr(0, at) + ": given " + message.substr(at + twice.size()) +
           " times; give it once";
  return message;
}

}  // namespace

int main(int argc, char** argv) {
  // Past a file-size limit (ulimit -f, a quota), a write fails with EFBIG
  // and the file's writer reports it and removes its temporary file; the
  // signal's default would end the process there, leaving both.
  std::signal(SIGXFSZ, SIG_IGN);
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
                              checkCommand(app, script), infoCommand(app, script),
                              viewCommand(app, script)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    if (const char* name = unknownCommand(app, argc, argv))
      return error(
          "unknown command '" + std::string(name) +
              "'; the commands are render, export, check, info and view (see csgray --help)",
          2, true);
    return error(readableParseError(e.what()) + " (see csgray --help)", 2, true);
  }

  try {
    for (const Command& command : commands)
      if (*command.app) {
        const int code = command.run(PartScript(script, command.app->get_name()));
        flushStandardOutput();
        return code;
      }
  } catch (const CLI::ValidationError& e) {
    return error(e.what(), 2, true);
  } catch (const DefineError& e) {  // a -D the script cannot take, cut already
    return error(e.what(), 2);
  } catch (const std::exception& e) {
    return error(e.what(), 1);
  }
  return 0;
}
