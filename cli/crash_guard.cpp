#include "cli/crash_guard.h"

#include <signal.h>
#include <unistd.h>

#include <cstring>
#include <vector>

#include "export/cgal/mesh_boolean.h"

namespace csgray::detail {

namespace {

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE};
// The script's name, copied before the handler can run.
char scriptName[1024];
std::vector<char> alternateStack;

// Only async-signal-safe calls (POSIX.1-2017, 2.4.3): write and _exit. The
// description of the boolean in progress is a buffer that mesh_boolean
// fills before each boolean.
void say(const char* text) {
  ssize_t written = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)written;
}
void onCrash(int) {
  say("csgray: error: ");
  say(scriptName);
  say(": CGAL's boolean stopped with a crash in ");
  say(booleanInProgress());
  say("; move one of these operands by a hair, or export at another tolerance\n");
  ::_exit(1);
}

}  // namespace

CrashGuard::CrashGuard(const std::string& script) {
  std::strncpy(scriptName, script.c_str(), sizeof scriptName - 1);
  alternateStack.resize(std::size_t(1) << 16);
  stack_t stack{};
  stack.ss_sp = alternateStack.data();
  stack.ss_size = alternateStack.size();
  ::sigaltstack(&stack, nullptr);
  struct sigaction action {};
  action.sa_handler = onCrash;
  action.sa_flags = SA_ONSTACK;
  sigemptyset(&action.sa_mask);
  for (int signal : kSignals) ::sigaction(signal, &action, nullptr);
}

CrashGuard::~CrashGuard() {
  for (int signal : kSignals) ::signal(signal, SIG_DFL);
}

}  // namespace csgray::detail
