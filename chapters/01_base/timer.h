/// \file
/// A wall-clock timer for the command line's JSON lines (benchmarks use Google Benchmark).
#pragma once

#include <chrono>

namespace rtk {

/// Measures elapsed wall-clock time from construction or the last reset().
class Timer {
 public:
  Timer() : start_(Clock::now()) {}
  void reset() { start_ = Clock::now(); }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

}  // namespace rtk
