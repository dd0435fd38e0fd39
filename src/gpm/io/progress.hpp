// Progress lines on stderr for long runs: level, fraction done, rate and ETA.
// At most one line every `interval` seconds (plus the final one), so logs stay short.
#pragma once
#include <chrono>
#include <string>

namespace gpm {

class Progress {
 public:
  Progress(std::string label, double total_work, const char* unit = "pairs",
           double interval_s = 5.0);
  // Report that `done` units (cumulative) are finished; prints if the interval elapsed.
  void update(double done);
  // Final line with total time and mean rate; returns elapsed seconds.
  double finish();
  double elapsed() const;

 private:
  std::string label_;
  double total_;
  const char* unit_;
  double interval_;
  std::chrono::steady_clock::time_point start_, last_;
};

// Wall time since construction: a data file's `wall_time_s`.
class Stopwatch {
 public:
  double seconds() const;

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace gpm
