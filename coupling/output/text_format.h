#pragma once
// Text for people in log lines: printf-style formatting and durations.
#include <string>

namespace wear::coupling {

/// printf-style formatting into a std::string (for log lines).
std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

/// A duration for people: "42 s", "12 min 05 s", "3 h 24 min".
std::string human_duration(double seconds);

} // namespace wear::coupling
