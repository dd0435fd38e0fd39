#include "gpm/profile.hpp"

#include <cmath>
#include <fstream>
#include <string>

#include "gpm/args.hpp"
#include "gpm/error.hpp"
#include "gpm/tsv.hpp"

namespace gpm {

Profile parse_profile(const std::string& name) {
  if (name == "quick") return Profile::quick;
  if (name == "paper") return Profile::paper;
  throw InputError("unknown profile '" + name + "'; valid: quick, paper");
}

std::string profile_name(Profile p) { return p == Profile::quick ? "quick" : "paper"; }

std::vector<int> levels_option(const Args& a, Profile p, const std::vector<int>& quick,
                               const std::vector<int>& paper, int lo, int hi) {
  if (a.str("levels").empty()) return pick(p, quick, paper);
  std::vector<int> levels;
  for (double v : a.nums("levels")) {
    if (v != std::floor(v) || v < lo || v > hi)
      throw InputError("--levels: " + fmt(v) + " is not an integer in [" + std::to_string(lo) +
                       ", " + std::to_string(hi) + "]");
    levels.push_back(static_cast<int>(v));
  }
  if (levels.empty()) throw InputError("--levels: no level given");
  return levels;
}

double peak_rss_mib() {
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmHWM:") {
      double kb = 0;
      in >> kb;
      return kb / 1024.0;
    }
    std::string rest;
    std::getline(in, rest);
  }
  return 0;
}

}  // namespace gpm
