#include "app/terminal_progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace amls::app {

namespace {
double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

TerminalProgress::TerminalProgress() : enabled_(isatty(STDERR_FILENO) == 1) {}

TerminalProgress::~TerminalProgress() {
  if (drawn_) std::fputs("\r\033[K", stderr);
}

void TerminalProgress::update(std::size_t step, std::size_t steps, double t, std::size_t points) {
  if (!enabled_) return;
  const double now = now_seconds();
  if (step != steps && now - last_ < 0.2) return;
  last_ = now;
  drawn_ = true;
  std::fprintf(stderr, "\r\033[Kstep %zu/%zu  t = %.3f  points = %zu", step, steps, t, points);
  std::fflush(stderr);
}

}  // namespace amls::app
