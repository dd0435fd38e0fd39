// bench_pcg: plain conjugate gradients against the τ-preconditioned ones (issue 58, item 1)
// on Table 4.4's Poisson problem, unit by unit, in one run on one machine: iterations,
// seconds (set-up of the preconditioner apart), seconds per iteration and the relative error
// each reaches, with the largest difference between the two solutions.
//
// The problem is thesis_table4_4's (jittered grid, f = −Δu, u = sin 2π(x + y), both readings
// of h and the volumes); each level's Laplacian is built once and both solvers run on it, so
// the time ratio is the solvers' alone.  --solvers tau alone prices a level where plain CG
// would take hours (its iterations are then the store's, not re-measured).
//   bench_pcg --levels 5,6,7,8 --volumes cell,lattice --out data/bench/pcg.tsv
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/poisson_probes.hpp"
#include "gpm/solvers/tau_preconditioner.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/weights/weights.hpp"
#include "limit_table.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

int body(int argc, char** argv) {
  gpm::Args args("bench_pcg",
                 "Plain CG against tau-preconditioned CG on Table 4.4's Poisson problem: "
                 "iterations, seconds and errors per unit, both on one Laplacian.");
  args.opt("levels", "5,6,7", "levels k (dx = 2^-k)")
      .opt("h-rules", "h10,h15", "readings of h (h10, h15)")
      .opt("weights", "quartic_polynomial,piecewise_cubic_polynomial,piecewise_quintic_polynomial",
           "weights")
      .opt("volumes", "cell", "volumes: lattice (|Omega_H|/N), cell (dx^2), comma list")
      .opt("solvers", "cg,tau", "cg, tau or both (cg first)")
      .opt("tol", "1e-10", "relative residual of both solvers (Table 4.4's)")
      .opt("storage", "auto", "Laplacian storage: auto, assembled, matrix_free")
      .opt("seed", "1", "jitter seed")
      .output("out", "data/bench/pcg.tsv", "TSV output");
  args.parse(argc, argv);
  const auto t_start = Clock::now();
  std::vector<int> levels;
  for (double k : args.nums("levels")) {
    if (k < 3 || k > 12 || k != std::floor(k)) throw gpm::InputError("--levels: integers 3..12");
    levels.push_back(static_cast<int>(k));
  }
  std::vector<gpm::HRule> rules;
  for (auto& s : args.list("h-rules")) rules.push_back(gpm::parse_h_rule(s));
  std::vector<gpm::PdeVolumes> vols;
  for (auto& s : args.list("volumes")) vols.push_back(gpm::parse_pde_volumes(s));
  const std::vector<std::string> solvers = args.list("solvers");
  for (auto& s : solvers)
    if (s != "cg" && s != "tau") throw gpm::InputError("--solvers: '" + s + "' is not cg or tau");
  const std::vector<std::string> weights = args.list("weights");
  for (auto& w : weights) gpm::weight(w);  // InputError for an unknown one, before any work
  const double tol = args.tolerance("tol");
  const auto storage = gpm::parse_laplacian_storage(args.str("storage"));
  const uint64_t seed = args.seed();

  gpm::TsvTable t;
  t.set("program", "bench_pcg");
  for (auto& [k, val] : args.values()) t.set("arg_" + k, val);
  t.set("problem", "thesis Table 4.4: -Delta_h U = f in Omega, U = u outside, u = sin 2pi(x+y)");
  t.set("tau", "P = D T1 D, T1 the lattice stencil's tau matrix (DST-I), D = diag(V)");
  t.set("setup_s", "building the preconditioner (eigenvalues, FFTW plan); not in solve_s");
  t.set("diff_vs_cg", "max_i |U_tau - U_cg| / max_Omega |u| (tau rows; empty without a cg row)");
  t.set("cpu_family_model", bench::cpu_family_model());
  t.set("loadavg_1min_start", bench::loadavg());
  gpm::add_provenance(t);
  t.columns = {"volumes", "h_rule", "weight", "level", "dx", "h", "N_omega", "storage", "solver",
               "iterations", "rel_residual", "setup_s", "solve_s", "s_per_iteration", "rel_error",
               "diff_vs_cg"};
  const gpm::TestFunction& u = gpm::test_function("sin2pi");
  for (gpm::PdeVolumes vol : vols)
    for (int k : levels) {
      const double dx = std::ldexp(1.0, -k);
      const gpm::Particles p = gpm::jittered_grid(dx, seed);
      const std::vector<double> V = gpm::pde_volumes(vol, p, dx);
      const gpm::PoissonData d = gpm::poisson_data(p, u);
      for (gpm::HRule rule : rules)
        for (const std::string& wn : weights) {
          const double h = gpm::pde_h(rule, dx);
          const gpm::DiscreteLaplacian L(p, V, gpm::weight(wn), h, storage);
          std::vector<double> U_cg;
          for (const std::string& s : solvers) {
            const auto t0 = Clock::now();
            std::unique_ptr<gpm::TauPreconditioner> pc;
            if (s == "tau") pc = std::make_unique<gpm::TauPreconditioner>(p, L, gpm::weight(wn), dx);
            const double setup = since(t0);
            const gpm::PoissonResult r = gpm::solve_poisson(p, L, d.f, d.g, tol, 20000, true, pc.get());
            double err = 0, diff = 0;
            for (std::size_t i = 0; i < p.size(); ++i)
              if (p.in_omega[i]) err = std::max(err, std::fabs(d.g[i] - r.U[i]));
            if (s == "cg") U_cg = r.U;
            else if (!U_cg.empty())
              for (std::size_t i = 0; i < p.size(); ++i) diff = std::max(diff, std::fabs(U_cg[i] - r.U[i]));
            const std::string rname = rule == gpm::HRule::h10 ? "h10" : "h15";
            t.add_row({gpm::pde_volumes_name(vol), rname, wn, gpm::fmt(k), gpm::fmt(dx), gpm::fmt(h),
                       gpm::fmt(L.n_unknowns()), L.assembled() ? "assembled" : "matrix_free", s,
                       gpm::fmt(r.cg.iterations), gpm::fmt(r.cg.rel_residual), gpm::fmt(setup),
                       gpm::fmt(r.solve_seconds), gpm::fmt(r.solve_seconds / std::max(1, r.cg.iterations)),
                       gpm::fmt(err / d.umax), U_cg.empty() || s == "cg" ? "" : gpm::fmt(diff / d.umax)});
            std::printf("[bench_pcg] %-7s %s %-28s 2^-%d %-4s %4d it  setup %.2f s  solve %.2f s  "
                        "err %.10e\n", gpm::pde_volumes_name(vol).c_str(), rname.c_str(), wn.c_str(),
                        k, s.c_str(), r.cg.iterations, setup, r.solve_seconds, err / d.umax);
            std::fflush(stdout);
          }
          t.set("peak_rss_mib", gpm::peak_rss_mib());
          t.set("wall_time_s", since(t_start));
          t.save(args.str("out"));  // after each unit: a partial run keeps what it measured
        }
    }
  t.set("loadavg_1min_end", bench::loadavg());
  t.save(args.str("out"));
  std::printf("  wrote %s\n", args.str("out").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("bench_pcg", body, argc, argv); }
