// The live progress line: carriage return, the text, padding over what the previous text left
// on screen. Only on a terminal, so redirected logs stay clean.
#include "coupling/output/progress_line.h"

#include <unistd.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace wear::coupling {

ProgressLine::ProgressLine(bool enabled) : live_(enabled && ::isatty(STDERR_FILENO)) {}

ProgressLine::~ProgressLine() {
  clear();
}

void ProgressLine::show(const std::string& text) {
  if (!live_)
    return;
  const int pad = shown_ > text.size() ? int(shown_ - text.size()) : 0;
  std::fprintf(stderr, "\r%s%*s", text.c_str(), pad, "");
  std::fflush(stderr);
  shown_ = text.size() + std::size_t(pad);
}

void ProgressLine::keep() {
  if (!live_ || shown_ == 0)
    return;
  std::fprintf(stderr, "\n");
  shown_ = 0;
}

void ProgressLine::clear() {
  if (!live_ || shown_ == 0)
    return;
  std::fprintf(stderr, "\r%*s\r", int(shown_), "");
  std::fflush(stderr);
  shown_ = 0;
}

std::string format(const char* fmt, ...) {
  char b[1024];
  va_list a;
  va_start(a, fmt);
  std::vsnprintf(b, sizeof b, fmt, a);
  va_end(a);
  return b;
}

std::string human_duration(double s) {
  if (s < 60)
    return format("%.0f s", s);
  if (s < 3600)
    return format("%.0f min %02.0f s", std::floor(s / 60), std::fmod(s, 60));
  return format("%.0f h %02.0f min", std::floor(s / 3600), std::floor(std::fmod(s, 3600) / 60));
}

} // namespace wear::coupling
