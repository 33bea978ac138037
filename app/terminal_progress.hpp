#pragma once
// Progress of long runs on stderr, only when stderr is a terminal.
#include <cstddef>

namespace amls::app {

class TerminalProgress {
 public:
  TerminalProgress();
  ~TerminalProgress();
  // One line, rewritten in place, at most a few times a second.
  void update(std::size_t step, std::size_t steps, double t, std::size_t points);

 private:
  bool enabled_;
  bool drawn_ = false;
  double last_ = -1.0;
};

}  // namespace amls::app
