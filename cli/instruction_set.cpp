// A build for x86-64-v3 (CMakeLists.txt, CSGRAY_ARCH) started on a processor
// without AVX2, FMA or BMI2 would die of SIGILL at its first such
// instruction, with no word why. This check runs before any of that code:
// it is compiled for plain x86-64 (cli/CMakeLists.txt), and as a
// constructor of priority 101 it runs before the executable's other static
// initialisers, which may already use the instructions.
#if defined(CSGRAY_X86_64_V3)
#include <unistd.h>

namespace {

__attribute__((constructor(101))) void requireX8664V3() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64-v3")) return;
  static const char kMessage[] =
      "csgray: this build uses x86-64-v3 instructions (AVX2, FMA, BMI2), which this "
      "processor lacks; build it here, or with cmake -DCSGRAY_ARCH=portable\n";
  // write(2) and _exit: nothing of the C++ runtime, which may not be set up.
  [[maybe_unused]] ssize_t written = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  ::_exit(1);
}

}  // namespace
#endif
