#include "cli/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace csgray::detail {

ProgressBar::ProgressBar(const char* label)
    : label_(label),
      terminal_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  if (shown_) std::fprintf(stderr, "\r%*s\r", 60, "");
}

void ProgressBar::update(double fraction) {
  if (!terminal_) return;
  // Quick renders stay silent: the bar appears after the first second.
  if (std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
  int percent = std::clamp(int(fraction * 100.0), 0, 100);
  std::lock_guard lock(mutex_);
  if (percent == lastPercent_) return;
  lastPercent_ = percent;
  shown_ = true;
  constexpr int kWidth = 30;
  char bar[kWidth + 1];
  int filled = percent * kWidth / 100;
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = '\0';
  std::fprintf(stderr, "\rcsgray: %s [%s] %3d%%", label_, bar, percent);
  std::fflush(stderr);
}

}  // namespace csgray::detail
