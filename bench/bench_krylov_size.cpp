// bench_krylov_size: a heat table's rows with the Krylov subspace held at a chosen size
// (issue 58, item 4).  The propagator grows its subspace until the trajectories stop moving,
// and from 2^-9 on the piecewise quintic stops by the rounding rule (heat_krylov.hpp) rather
// than by its tolerance: Table 4.5's identified series at 2^-10 took m = 386.  How far would
// a larger subspace move those rows?  This program builds the series' Laplacian as
// thesis_heat does (jittered grid, the reading's h, volumes and Δt) and propagates them in a
// subspace of each size asked for, one run each, comparing every row with the stored file:
//
//   bench_krylov_size --table 4.5 --level 10 --sizes 526
//     --compare results/paper/thesis_table4_5_h15_dtexact_cellvol.tsv --out data/bench/krylov_size.tsv
//
// A size m is taken as the propagator takes a size: grown from the schedule's size before it
// (m' + max(16, m'/6), made even) and compared once with it, the tolerance set so that the
// first comparison settles; `change` is that comparison (the trajectories' movement between
// m' and m, in units of the series' error, and `of_data` in units of its data).  At the size
// the stored row holds, the rows must equal the stored ones to the scale at which the store's
// own path reproduces them (2^-9: 1.8e-13 here, 5e-12 by verify-store-full): the check that
// this program's set-up is thesis_heat's.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/heat_krylov.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/weights/weights.hpp"
#include "limit_table.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

// The size the propagator tries after m (heat_krylov.cpp's schedule).
int next_size(int m) {
  m += std::max(16, m / 6);
  return m + m % 2;
}

// The size before m in that schedule: the propagator reaches m only from it.
int size_before(int m) {
  for (int f = 2; f < m; ++f)
    if (next_size(f) == m) return f;
  throw gpm::InputError("--sizes: " + std::to_string(m) + " is no size of the propagator's schedule (m + max(16, m/6), even)");
}

// The stored row of (weight, θ, level), or -1.
long stored_row(const gpm::TsvTable& s, const std::string& w, double theta, int level) {
  for (std::size_t i = 0; i < s.rows.size(); ++i)
    if (s.text(i, "weight") == w && s.number(i, s.require_column("theta")) == theta &&
        s.number(i, s.require_column("level")) == level)
      return static_cast<long>(i);
  return -1;
}

int body(int argc, char** argv) {
  gpm::Args args("bench_krylov_size",
                 "A heat table's rows with the Krylov subspace held at chosen sizes, against the stored rows.");
  args.opt("table", "4.5", "4.5, 4.6 or 4.7")
      .opt("level", "10", "level k (dx = 2^-k)")
      .opt("h-rule", "h15", "h10 or h15")
      .opt("dt-rule", "exact", "fit or exact (thesis_heat --dt-rule)")
      .opt("volumes", "cell", "lattice or cell")
      .opt("weight", "piecewise_quintic_polynomial", "the weight")
      .opt("thetas", "", "theta values (default: the table's)")
      .opt("sizes", "526", "subspace sizes, comma list, each a size of the propagator's schedule")
      .opt("seed", "1", "jitter seed")
      .opt("compare", "", "the store file holding the series' rows (empty: no comparison)")
      .output("out", "data/bench/krylov_size.tsv", "TSV output");
  args.parse(argc, argv);
  const auto t_start = Clock::now();
  const gpm::HeatTable& table = gpm::heat_table(args.str("table"));
  const double kd = args.num("level");
  if (!(kd >= 3 && kd <= 12 && kd == std::floor(kd))) throw gpm::InputError("--level: an integer 3..12, got " + args.str("level"));
  const int k = static_cast<int>(kd);
  const gpm::HRule rule = gpm::parse_h_rule(args.str("h-rule"));
  const gpm::DtRule dt_rule = gpm::parse_dt_rule(args.str("dt-rule"));
  const gpm::PdeVolumes vol = gpm::parse_pde_volumes(args.str("volumes"));
  const std::string wn = args.str("weight");
  const gpm::WeightFunction& w = gpm::weight(wn);
  std::vector<double> thetas = args.str("thetas").empty() ? table.thetas : args.nums("thetas");
  for (double th : thetas)
    if (std::find(table.thetas.begin(), table.thetas.end(), th) == table.thetas.end())
      throw gpm::InputError("--thetas: " + gpm::fmt(th) + " is not a theta of Table " + table.table);
  std::vector<int> sizes;
  for (double m : args.nums("sizes")) {
    if (!(m >= 18 && m == std::floor(m))) throw gpm::InputError("--sizes: whole numbers from 18, got " + gpm::fmt(m));
    size_before(static_cast<int>(m));
    sizes.push_back(static_cast<int>(m));
  }
  gpm::TsvTable stored;
  const bool compare = !args.str("compare").empty();
  if (compare) stored = gpm::TsvTable::load(args.str("compare"), false);

  gpm::TsvTable t;
  t.set("program", "bench_krylov_size");
  for (auto& [key, val] : args.values()) t.set("arg_" + key, val);
  t.set("subspace", "taken at m after one comparison with the schedule's previous size m_before (tolerance 1e300)");
  t.set("change", "trajectories' movement from m_before to m, max over the series, in units of each series' largest error");
  t.set("of_data", "the same in units of each series' largest value");
  t.set("diff_rel_error", "(rel_error - stored) / stored, the stored row's subspace in stored_subspace");
  t.set("cpu_family_model", bench::cpu_family_model());
  t.set("loadavg_1min_start", bench::loadavg());
  gpm::add_provenance(t);
  t.columns = {"table", "level", "h_rule", "weight", "theta", "subspace", "m_before", "change", "of_data",
               "rel_error", "rel_error_max", "seconds", "stored_subspace", "stored_rel_error",
               "diff_rel_error", "diff_rel_error_max"};

  // The series' particles, volumes, h and Laplacian, as thesis_heat builds them.
  const double dx = std::ldexp(1.0, -k), h = gpm::pde_h(rule, dx);
  const gpm::Particles p = gpm::jittered_grid(dx, args.seed());
  const std::vector<double> V = gpm::pde_volumes(vol, p, dx);
  const gpm::DiscreteLaplacian L(p, V, w, h);
  std::printf("[bench_krylov_size] Table %s 2^-%d %s %s: N_omega %ld, Laplacian %.1f s\n", table.table.c_str(), k,
              gpm::h_rule_name(rule).c_str(), wn.c_str(), static_cast<long>(L.n_unknowns()), since(t_start));
  std::vector<gpm::HeatSetting> settings;
  for (double th : thetas) {
    gpm::HeatSetting s;
    s.kappa = gpm::kHeatKappa, s.T = gpm::kHeatT, s.theta = th;
    s.dt_nominal = table.c * std::pow(h, table.p);
    s.fit_T = dt_rule == gpm::DtRule::fit;
    s.blowup_factor = std::numeric_limits<double>::infinity();
    settings.push_back(s);
  }

  // Each size: one propagation whose first comparison settles it.
  for (int m : sizes) {
    gpm::KrylovSettings ks;
    ks.first = size_before(m), ks.max_dim = m, ks.tol = 1e300;
    gpm::KrylovTry last;
    ks.on_size = [&](const gpm::KrylovTry& tr) { last = tr; };
    const auto t0 = Clock::now();
    const std::vector<gpm::HeatResult> rs = gpm::propagate_heat(p, L, settings, ks);
    const double secs = since(t0);
    for (std::size_t i = 0; i < rs.size(); ++i) {
      const gpm::HeatResult& r = rs[i];
      std::string sm = "", se = "", d1 = "", d2 = "";
      const long row = compare ? stored_row(stored, wn, thetas[i], k) : -1;
      if (row >= 0) {
        const double e = stored.number(row, stored.require_column("rel_error"));
        const double em = stored.number(row, stored.require_column("rel_error_max"));
        sm = stored.text(row, "subspace"), se = gpm::fmt(e);
        d1 = gpm::fmt((r.rel_error - e) / e), d2 = gpm::fmt((r.rel_error_max - em) / em);
      }
      t.add_row({table.table, gpm::fmt(k), gpm::h_rule_name(rule), wn, gpm::fmt(thetas[i]), gpm::fmt(r.subspace),
                 gpm::fmt(ks.first), gpm::fmt(last.change), gpm::fmt(last.of_data), gpm::fmt(r.rel_error),
                 gpm::fmt(r.rel_error_max), gpm::fmt(secs), sm, se, d1, d2});
      std::printf("[bench_krylov_size] m=%d (from %d, moved %.3g of the error) theta=%g err=%.10e stored m=%s err=%s diff %s  %.0f s\n",
                  r.subspace, ks.first, last.change, thetas[i], r.rel_error, sm.c_str(), se.c_str(), d1.c_str(), secs);
    }
    std::fflush(stdout);
    t.set("wall_time_s", since(t_start));
    t.set("peak_rss_mib", gpm::peak_rss_mib());
    t.save(args.str("out"));  // after each size: a partial run keeps what it measured
  }
  t.set("loadavg_1min_end", bench::loadavg());
  t.save(args.str("out"));
  std::printf("  wrote %s\n", args.str("out").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("bench_krylov_size", body, argc, argv); }
