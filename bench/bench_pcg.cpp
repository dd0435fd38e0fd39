// bench_pcg: plain conjugate gradients against the τ-preconditioned ones (issue 58, item 1)
// on Table 4.4's Poisson problem, unit by unit, in one run on one machine: iterations,
// seconds (set-up of the preconditioner apart), seconds per iteration and the relative error
// each reaches, with the largest difference between the two solutions.  --problem heat: the
// implicit θ steps of a heat table instead (--table 4.6 or 4.7, its Δt₀ and the θ > 0 of
// --thetas, the fit reading of the time step), stepped: mean CG iterations per step and the
// error (4.2) of each solver, P = D(I/V̄ + θκΔt T₁)D.
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
#include <limits>
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
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/poisson_probes.hpp"
#include "gpm/solvers/tau_preconditioner.hpp"
#include "gpm/studies/define/heat_tables.hpp"
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
  args.opt("problem", "poisson", "poisson (Table 4.4) or heat (the implicit steps of --table)")
      .opt("table", "4.6", "heat: 4.6 (dt0 = 0.5 h^2) or 4.7 (dt0 = 0.5 h)")
      .opt("thetas", "0.5,1", "heat: theta values > 0")
      .opt("levels", "5,6,7", "levels k (dx = 2^-k)")
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
  const std::string problem = args.str("problem");
  if (problem != "poisson" && problem != "heat")
    throw gpm::InputError("--problem: '" + problem + "' is not poisson or heat");
  const bool heat = problem == "heat";
  const gpm::HeatTable& table = gpm::heat_table(args.str("table"));
  std::vector<double> thetas = args.nums("thetas");
  for (double th : thetas)
    if (!(th > 0 && th <= 1)) throw gpm::InputError("--thetas: values in (0, 1], got " + gpm::fmt(th));
  if (!heat) thetas = {0};

  gpm::TsvTable t;
  t.set("program", "bench_pcg");
  for (auto& [k, val] : args.values()) t.set("arg_" + k, val);
  t.set("problem", heat ? "thesis Table " + table.table + ": implicit theta steps, dt0 = " + table.dt_rule +
                             ", dt = T/K (fit); rel_error (4.2), iterations per step (mean)"
                       : "thesis Table 4.4: -Delta_h U = f in Omega, U = u outside, u = sin 2pi(x+y)");
  t.set("tau", "P = D T1 D, T1 the lattice stencil's tau matrix (DST-I), D = diag(V)");
  t.set("setup_s", "building the preconditioner (eigenvalues, FFTW plan); not in solve_s");
  t.set("diff_vs_cg", heat ? "|rel_error_tau - rel_error_cg| / rel_error_cg (tau rows; empty without a cg row)"
                            : "max_i |U_tau - U_cg| / max_Omega |u| (tau rows; empty without a cg row)");
  t.set("iterations", heat ? "mean CG iterations per implicit step" : "CG iterations of the solve");
  t.set("cpu_family_model", bench::cpu_family_model());
  t.set("loadavg_1min_start", bench::loadavg());
  gpm::add_provenance(t);
  t.columns = {"volumes", "h_rule", "weight", "level", "theta", "dx", "h", "N_omega", "storage", "solver",
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
          for (double theta : thetas) {
            std::vector<double> U_cg;
            double err_cg = -1;
            for (const std::string& s : solvers) {
              const auto t0 = Clock::now();
              // Poisson: P = D T1 D.  Heat: P = D(I/V + theta kappa dt T1)D, V the unknowns' mean.
              std::unique_ptr<gpm::TauPreconditioner> pc;
              gpm::HeatSetting hs;
              if (heat) {
                hs.kappa = gpm::kHeatKappa, hs.T = gpm::kHeatT, hs.theta = theta, hs.tol = tol;
                hs.dt_nominal = table.c * std::pow(h, table.p);
                hs.blowup_factor = std::numeric_limits<double>::infinity();
              }
              if (s == "tau" && heat) {
                double vbar = 0;
                for (int32_t k : L.omega()) vbar += V[k];
                vbar /= static_cast<double>(L.n_unknowns());
                const double dt = hs.T / static_cast<double>(gpm::heat_steps(hs.T, hs.dt_nominal));
                pc = std::make_unique<gpm::TauPreconditioner>(p, L, gpm::weight(wn), dx, 1.0 / vbar,
                                                              theta * hs.kappa * dt);
              } else if (s == "tau") {
                pc = std::make_unique<gpm::TauPreconditioner>(p, L, gpm::weight(wn), dx);
              }
              const double setup = since(t0);
              double its = 0, res = 0, secs = 0, err = 0, diff = 0;
              if (heat) {
                hs.pc = pc.get();
                const gpm::HeatResult r = gpm::solve_heat(p, L, hs);
                its = r.mean_cg_iterations, res = r.max_rel_residual, err = r.rel_error;
                secs = r.seconds;
                if (s == "cg") err_cg = err;
                else if (err_cg >= 0) diff = std::fabs(err - err_cg) / err_cg;
              } else {
                const gpm::PoissonResult r = gpm::solve_poisson(p, L, d.f, d.g, tol, 20000, true, pc.get());
                its = r.cg.iterations, res = r.cg.rel_residual, secs = r.solve_seconds;
                for (std::size_t i = 0; i < p.size(); ++i)
                  if (p.in_omega[i]) err = std::max(err, std::fabs(d.g[i] - r.U[i]));
                err /= d.umax;
                if (s == "cg") U_cg = r.U;
                else if (!U_cg.empty())
                  for (std::size_t i = 0; i < p.size(); ++i) diff = std::max(diff, std::fabs(U_cg[i] - r.U[i]));
                diff /= d.umax;
              }
              const bool compared = s == "tau" && (heat ? err_cg >= 0 : !U_cg.empty());
              const std::string rname = rule == gpm::HRule::h10 ? "h10" : "h15";
              t.add_row({gpm::pde_volumes_name(vol), rname, wn, gpm::fmt(k), heat ? gpm::fmt(theta) : "",
                         gpm::fmt(dx), gpm::fmt(h), gpm::fmt(L.n_unknowns()),
                         L.assembled() ? "assembled" : "matrix_free", s, gpm::fmt(its), gpm::fmt(res),
                         gpm::fmt(setup), gpm::fmt(secs), gpm::fmt(its > 0 ? secs / its : 0.0),
                         gpm::fmt(err), compared ? gpm::fmt(diff) : ""});
              std::printf("[bench_pcg] %-7s %s %-28s 2^-%d %s%-4s %6.1f it  setup %.2f s  solve %.2f s  "
                          "err %.10e\n", gpm::pde_volumes_name(vol).c_str(), rname.c_str(), wn.c_str(), k,
                          heat ? ("theta " + gpm::fmt(theta) + " ").c_str() : "", s.c_str(), its, setup,
                          secs, err);
              std::fflush(stdout);
            }
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
