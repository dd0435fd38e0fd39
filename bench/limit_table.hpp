// The measured limits written by bench_limit (data/bench/limit.tsv), read back by the
// other benchmarks to report each rate as a fraction of the limit that applies.
#pragma once
#include <cmath>
#include <filesystem>
#include <string>

#include "gpm/io/tsv.hpp"

namespace bench {

struct Limit {
  double rate = NAN;      // wall-clock rate (all threads)
  double rate_cpu = NAN;  // from the threads' CPU time (robust to a shared machine)
  bool found() const { return std::isfinite(rate); }
};

class LimitTable {
 public:
  // An empty or absent path gives a table without rows (every lookup not found).
  explicit LimitTable(const std::string& path) {
    if (!path.empty() && std::filesystem::exists(path)) {
      t_ = gpm::TsvTable::load(path);
      loaded_ = true;
    }
  }
  bool loaded() const { return loaded_; }
  Limit get(const std::string& test, int threads) const {
    const int ct = t_.column("test"), cn = t_.column("threads"), cr = t_.column("rate"),
              cc = t_.column("rate_cpu");
    if (ct < 0 || cn < 0 || cr < 0) return {};
    for (std::size_t i = 0; i < t_.rows.size(); ++i)
      if (t_.text(i, ct) == test && t_.text(i, cn) == std::to_string(threads))
        return {t_.number(i, cr), cc >= 0 && !t_.text(i, cc).empty() ? t_.number(i, cc) : NAN};
    return {};
  }

 private:
  gpm::TsvTable t_;
  bool loaded_ = false;
};

}  // namespace bench

#include <fstream>

namespace bench {

// "family F model M" of the first CPU in /proc/cpuinfo (the model name alone, e.g. "AMD
// EPYC" in a VM, does not say which generation).
inline std::string cpu_family_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, fam, mod;
  while (std::getline(in, line)) {
    auto val = [&] { return line.substr(line.find(':') + 2); };
    if (fam.empty() && line.rfind("cpu family", 0) == 0) fam = val();
    if (mod.empty() && line.rfind("model", 0) == 0 && line.rfind("model name", 0) != 0) mod = val();
  }
  return "family " + fam + " model " + mod;
}

// The 1-minute load average: above the number of cores, other jobs shared the machine.
inline std::string loadavg() {
  std::ifstream in("/proc/loadavg");
  std::string a;
  in >> a;
  return a;
}

}  // namespace bench
