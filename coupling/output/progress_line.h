#pragma once
// The live progress line of a long command: rewritten in place on a terminal (stderr), silent
// when stderr is not a terminal or progress is off, so logs and pipes never receive it.
#include <string>

namespace wear::coupling {

class ProgressLine {
public:
  /// Shows anything only when `enabled` and stderr is a terminal.
  explicit ProgressLine(bool enabled);
  /// Erases whatever the line still shows.
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool live() const { return live_; }
  /// Replaces the line's text.
  void show(const std::string& text);
  /// Ends the line, keeping its text on screen (the next output starts below it).
  void keep();
  /// Erases the line.
  void clear();

private:
  bool live_;
  std::size_t shown_ = 0; ///< characters on screen
};

/// printf-style formatting into a std::string (for progress and log lines).
std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

/// A duration for people: "42 s", "12 min 05 s", "3 h 24 min".
std::string human_duration(double seconds);

} // namespace wear::coupling
