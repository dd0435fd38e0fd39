#include "gpm/io/progress.hpp"

#include <cstdio>

namespace gpm {

Progress::Progress(std::string label, double total_work, const char* unit, double interval_s)
    : label_(std::move(label)), total_(total_work), unit_(unit), interval_(interval_s),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

double Stopwatch::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(double done) {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_) return;
  last_ = now;
  const double t = elapsed();
  const double rate = t > 0 ? done / t : 0;
  const double eta = rate > 0 ? (total_ - done) / rate : 0;
  std::fprintf(stderr, "[%s] %5.1f%%  %.3g %s/s  elapsed %.0fs  ETA %.0fs\n", label_.c_str(),
               total_ > 0 ? 100.0 * done / total_ : 100.0, rate, unit_, t, eta);
}

double Progress::finish() {
  const double t = elapsed();
  std::fprintf(stderr, "[%s] done in %.2fs (%.3g %s/s)\n", label_.c_str(), t,
               t > 0 ? total_ / t : 0.0, unit_);
  return t;
}

}  // namespace gpm
