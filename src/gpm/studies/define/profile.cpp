#include "gpm/studies/define/profile.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"

namespace gpm {

Profile parse_profile(const std::string& name) {
  if (name == "quick") return Profile::quick;
  if (name == "paper") return Profile::paper;
  throw InputError("unknown profile '" + name + "'; valid: quick, paper");
}

std::string profile_name(Profile p) { return p == Profile::quick ? "quick" : "paper"; }

std::vector<int> levels_option(const Args& a, Profile p, const std::vector<int>& quick,
                               const std::vector<int>& paper, int lo, int hi) {
  // Absent: the profile's levels; given but empty (--levels "") is a mistake, never "all".
  if (!a.has("levels")) return pick(p, quick, paper);
  if (a.str("levels").empty()) throw InputError("--levels: empty; name the levels, e.g. --levels 5,6");
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

namespace {

// The value of a "Key:   N kB" line of a /proc file, in kB (0 if absent).
double proc_kb(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string k;
  while (in >> k) {
    if (k == key) {
      double kb = 0;
      in >> kb;
      return kb;
    }
    std::string rest;
    std::getline(in, rest);
  }
  return 0;
}

}  // namespace

double peak_rss_mib() { return proc_kb("/proc/self/status", "VmHWM:") / 1024.0; }

double machine_memory_bytes() { return proc_kb("/proc/meminfo", "MemTotal:") * 1024.0; }

namespace {
std::string gib(double bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return b;
}
}  // namespace

double grid_particle_estimate(double dx) {
  const double per_axis = std::floor(Domain{}.side() / dx) + 1;
  return per_axis * per_axis;
}

void require_grid_fits_memory(double dx, double bytes_per_particle, const std::string& option) {
  require_positive(dx, option);
  if (dx >= 0.5)
    throw InputError(option + " " + fmt(dx) + " is too coarse: no grid node would lie inside "
                              "Omega = (0,1)^2 (dx must be < 0.5)");
  const double n = grid_particle_estimate(dx), need = n * bytes_per_particle;
  const double have = machine_memory_bytes();
  if (have > 0 && !(need <= have)) {
    char count[32];
    std::snprintf(count, sizeof count, "%.3g", n);
    throw InputError(option + " " + fmt(dx) + " needs about " + count + " particles and " +
                     gib(need) + " of memory; this machine has " + gib(have) + " (MemTotal)");
  }
}

double pde_bytes_per_particle(double h, double dx, LaplacianStorage storage, double max_bytes) {
  const double nnz_bytes =
      kAssembledBytesPerNonzero * 3.14159265358979323846 * (h / dx) * (h / dx) / Domain{}.area_H();
  const double matrix_bytes = storage == LaplacianStorage::matrix_free ? 0
                              : storage == LaplacianStorage::assembled
                                  ? nnz_bytes
                                  : std::min(nnz_bytes, max_bytes / grid_particle_estimate(dx));
  return 400 + matrix_bytes;
}

void require_pde_levels_fit_memory(const std::vector<int>& levels, const std::vector<HRule>& h_rules,
                                   LaplacianStorage storage, double max_bytes) {
  for (int k : levels)
    for (const auto& rule : h_rules) {
      const double dx = std::ldexp(1.0, -k);
      require_grid_fits_memory(dx, pde_bytes_per_particle(pde_h(rule, dx), dx, storage, max_bytes),
                               "--levels: level " + std::to_string(k) + ", dx =");
    }
}

}  // namespace gpm
