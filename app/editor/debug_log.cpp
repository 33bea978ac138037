#include "app/editor/debug_log.hpp"

#include <cstdio>

namespace amls::editor {

DebugLog::DebugLog(const std::string& path) {
  if (!path.empty()) out_.open(path, std::ios::trunc);
}

void DebugLog::line(const std::string& text) {
  if (!out_.is_open()) return;
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "t=%.4f ", t);
  out_ << stamp << text << '\n';
  out_.flush();
}

}  // namespace amls::editor
