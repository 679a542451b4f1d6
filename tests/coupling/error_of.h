#pragma once
// The message of the exception `f` throws, "" when it throws none: tests check that bad
// input is refused and named.
#include <exception>
#include <functional>
#include <string>

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}
