#pragma once
// Wall-clock timing of a phase (steady clock, so a changed system time does not disturb it);
// one definition shared by every module's timing figures.
#include <chrono>

namespace wear::meshes {

class Stopwatch {
public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  /// [s] since construction or the last restart().
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  void restart() { start_ = std::chrono::steady_clock::now(); }

private:
  std::chrono::steady_clock::time_point start_;
};

} // namespace wear::meshes
