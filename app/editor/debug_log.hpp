#pragma once
// The editor's debug log (--debug-log or AMLS_EDITOR_DEBUG_LOG): one line per
// frame and per event, each with the seconds since start, flushed at once so
// that a test driving the editor can follow it. Does nothing without a path.
#include <chrono>
#include <concepts>
#include <fstream>
#include <string>

namespace amls::editor {

class DebugLog {
 public:
  explicit DebugLog(const std::string& path);
  bool enabled() const { return out_.is_open(); }
  // Writes "t=<seconds> <text>".
  void line(const std::string& text);
  // The same with the text made by `text()` (returning a std::string) only
  // when the log is on: lines logged every frame cost nothing otherwise.
  template <typename MakeText>
  requires std::invocable<MakeText&>
  void line(MakeText&& text) {
    if (enabled()) line(std::string(text()));
  }

 private:
  std::ofstream out_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace amls::editor
