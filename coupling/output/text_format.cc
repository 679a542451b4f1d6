// Text for people in log lines (text_format.h): printf into a string, durations in s, min, h.
#include "coupling/output/text_format.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace wear::coupling {

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
