#include "gpm/profile.hpp"

#include <fstream>
#include <string>

#include "gpm/error.hpp"

namespace gpm {

Profile parse_profile(const std::string& name) {
  if (name == "quick") return Profile::quick;
  if (name == "paper") return Profile::paper;
  throw InputError("unknown profile '" + name + "'; valid: quick, paper");
}

std::string profile_name(Profile p) { return p == Profile::quick ? "quick" : "paper"; }

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
