// core_voronoi: Voronoi decomposition of Ω_H for the plain and the jittered grid, level by
// level: the cell areas (they must tile Ω_H), the covering radius r_c (imoto eq. (5),
// thesis (1.5)) against the plain-grid formula and the two documents' statements about it
// (imoto §5: r_N ≤ √2(1+1/4)Δx/2; thesis Ch. 4: 1.4Δx ≤ r_c ≤ 1.8Δx), and the time and
// peak memory of the computation.
//
// One row per (level, seed, distribution).  The plain grid does not depend on the seed: it
// is computed once per level and its row repeated for every seed.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <tuple>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/run/runner.hpp"

using namespace gpm;

namespace {

// Levels per profile and the default seeds: voronoi_study() (catalog.hpp).
const VoronoiStudy& kStudy = voronoi_study();

// Resets the peak-RSS mark (VmHWM) to the current RSS so that the next reading is the
// peak of the next computation only (Linux ≥ 4.0).  Returns false where unsupported.
bool reset_peak_rss() {
  std::ofstream f("/proc/self/clear_refs");
  if (!f) return false;
  f << "5";
  f.flush();
  return static_cast<bool>(f);
}

struct Row {
  std::size_t n = 0, n_in = 0;
  double area_sum = 0, r_c = 0, r_c_omega = 0, amin = 0, amax = 0, wx = 0, wy = 0;
  double time_s = 0, rss = 0;
};

Row measure(const Particles& p, const Domain& dom, double dx, bool rss_reset) {
  if (rss_reset) reset_peak_rss();
  const auto t0 = std::chrono::steady_clock::now();
  const VoronoiCells c = voronoi_cells(p, dom, false);
  Row r;
  r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.rss = peak_rss_mib();
  r.n = p.size();
  r.n_in = p.count_in_omega();
  r.area_sum = c.area_sum;
  r.r_c = c.covering_radius;
  r.wx = p.x[c.worst];
  r.wy = p.y[c.worst];
  r.amin = *std::min_element(c.area.begin(), c.area.end()) / (dx * dx);
  r.amax = *std::max_element(c.area.begin(), c.area.end()) / (dx * dx);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.in_omega[i]) r.r_c_omega = std::max(r.r_c_omega, c.cover[i]);
  return r;
}

// The program: the options read once; run() opens the cached data file and measures every
// level it lacks, one unit each (the registry's: a level, its plain grid and every seed).
class CoreVoronoi {
 public:
  CoreVoronoi(int argc, char** argv)
      : run_(study_registry().study("core_voronoi"),
             "Voronoi cells of Omega_H for the plain and the jittered grid: area sum, covering\n"
             "radius r_c vs the grid formula and the documents' claims, time and peak memory\n"
             "(level 12 needs ~4 GB).") {
    run_.args().opt("seeds", kStudy.seeds_option(), "comma-separated jitter seeds (non-negative integers)");
    run_.parse(argc, argv);
    seeds_ = run_.args().seeds("seeds");
  }

  int run() {
    open_data_file();
    for (const StudyUnit& unit : run_.units()) level(unit);
    run_.finish();
    return 0;
  }

 private:
  // The data file: per level, for every seed the plain grid's row and the jittered one's.
  void open_data_file() {
    std::vector<std::string> seed_names;
    for (uint64_t seed : seeds_) seed_names.push_back(fmt(static_cast<long long>(seed)));
    cache_ = &run_.open(
        {{"program", "core_voronoi"}, {"seeds", join(seed_names, ",")}, {"H", fmt(dom_.H)},
         {"Omega_H", "(-H, 1+H)^2"}, {"jitter_amplitude", fmt(kAmplitude)},
         {"r_c_grid_formula", "sqrt(2)*max(dx/2, g_lo, g_hi), g_lo = first*dx + H, g_hi = 1 + H - last*dx"},
         {"imoto_bound", "sqrt(2)*(1+1/4)*dx/2 (imoto Sec. 5)"},
         {"thesis_range", "1.4*dx <= r_c <= 1.8*dx (thesis Ch. 4)"},
         {"r_c_omega", "max cover over the cells of particles in Omega (boundary cells excluded)"}},
        1);
    rss_reset_ = reset_peak_rss();
    cache_->table().set("peak_rss_note", rss_reset_ ? "VmHWM reset before each row: peak of that row's run"
                                                    : "VmHWM of the process so far (reset unsupported)");
    cache_->table().set("time_note", "time_s: voronoi_cells only (triangulation + cells), not particle set-up");
  }

  // One level: the plain grid measured once, then the jittered grid of every seed, each seed
  // with the plain grid's row beside its own.
  void level(const StudyUnit& unit) {
    if (cache_->has(unit.key, 2 * seeds_.size()) || !run_.claim()) return;
    const int k = unit.level;
    const double dx = std::ldexp(1.0, -k);
    const double g_lo = grid_first(dx, dom_) * dx - dom_.lo();
    const double g_hi = dom_.hi() - grid_last(dx, dom_) * dx;
    const double pred = std::sqrt(2.0) * std::max({dx / 2, g_lo, g_hi});
    Row grid;
    {
      const Particles p = jittered_grid(dx, 0, 0.0, dom_);
      grid = measure(p, dom_, dx, rss_reset_);
    }
    const std::string grid_line =
        line_printf("level %d dx=%.6g N=%zu grid: r_c/dx=%.6f (pred %.6f) %.2fs %.0f MiB", k,
                    dx, grid.n, grid.r_c / dx, pred / dx, grid.time_s, grid.rss);
    std::string seed_lines;
    for (uint64_t seed : seeds_) {
      add(k, dx, pred, seed, "grid", grid);
      Row r;
      {
        const Particles p = jittered_grid(dx, seed, kAmplitude, dom_);
        r = measure(p, dom_, dx, rss_reset_);
      }
      add(k, dx, pred, seed, "jittered", r);
      seed_lines += line_printf("\n[core_voronoi] level %d seed %llu jittered: r_c/dx=%.6f "
                                "(in Omega %.6f) area_rel_err=%.2g %.2fs %.0f MiB",
                                k, static_cast<unsigned long long>(seed), r.r_c / dx,
                                r.r_c_omega / dx,
                                std::abs(r.area_sum - dom_.area_H()) / dom_.area_H(), r.time_s,
                                r.rss);
    }
    run_.unit_done(0, grid_line + seed_lines);
  }

  // One row, by name: the columns are voronoi_study()'s, listed in catalog.cpp, not here.
  void add(int k, double dx, double pred, uint64_t seed, const char* dist, const Row& r) {
    const double imoto = std::sqrt(2.0) * 1.25 * dx / 2;
    TsvRow row = run_.row();
    row["level"] = fmt(k), row["dx"] = fmt(dx), row["seed"] = fmt(static_cast<long long>(seed));
    row["distribution"] = dist, row["N"] = fmt(r.n), row["N_in_omega"] = fmt(r.n_in);
    row["area_sum"] = fmt(r.area_sum);
    row["area_rel_err"] = fmt(std::abs(r.area_sum - dom_.area_H()) / dom_.area_H());
    row["r_c"] = fmt(r.r_c), row["r_c_over_dx"] = fmt(r.r_c / dx);
    row["r_c_omega_over_dx"] = fmt(r.r_c_omega / dx), row["r_c_grid_pred"] = fmt(pred);
    row["imoto_bound"] = fmt(imoto), row["imoto_holds"] = r.r_c <= imoto ? "1" : "0";
    row["thesis_range_holds"] = (r.r_c >= 1.4 * dx && r.r_c <= 1.8 * dx) ? "1" : "0";
    row["worst_x"] = fmt(r.wx), row["worst_y"] = fmt(r.wy);
    row["min_area_over_dx2"] = fmt(r.amin), row["max_area_over_dx2"] = fmt(r.amax);
    row["time_s"] = fmt(r.time_s), row["peak_rss_mb"] = fmt(r.rss);
    run_.add(row);
  }

  static constexpr double kAmplitude = 0.25;
  StudyRunner run_;
  std::vector<uint64_t> seeds_;
  const Domain dom_;
  UnitCache* cache_ = nullptr;
  bool rss_reset_ = false;
};

int body(int argc, char** argv) { return CoreVoronoi(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("core_voronoi", body, argc, argv); }
