// thesis_heat: the discrete heat problem of the thesis, §4.3 (Figures 4.9–4.11,
// Tables 4.5–4.7), one setting of the time step per run (--table):
//
//   4.5: Δt₀ = 0.0025h², θ = 0, ½, 1, Δx = 2^-5 … 2^-8 (rates from 2^-7, 2^-8; the run adds
//        the coarse 2^-4, seconds, so that the quick series has three points);
//   4.6: Δt₀ = 0.5h²,    θ = 0, ½, 1, Δx = 2^-5 … 2^-9 (rates from 2^-8, 2^-9);
//   4.7: Δt₀ = 0.5h,     θ = ½, 1,    Δx = 2^-5 … 2^-9.
// κ = 0.5, T = 0.1, ũ = exp(−2κπ²t) sin(πx) sin(πy), weights quartic / piecewise cubic /
// piecewise quintic polynomial, V_i = |Ω_H|/N, h = (2.6⁴·2^-10·Δx)^{1/4} as printed
// (--h-rule h10, the default) or the reading h = (2.6⁴·2^-15·Δx)^{1/4} = imoto_h(4, Δx)
// (--h-rule h15): the printed h exceeds H = 0.1 up to Δx = 2^-8, so stencils near ∂Ω are cut
// by the edge of Ω_H; the Poisson study (thesis_table4_4) runs both readings as well.
// K = ⌈T/Δt₀⌉ and Δt = T/K (heat.hpp).  Error (4.2): ℓ∞ in time of the ℓ²(Ω_H) norm.
//
// Output: --out (every run, cached; a run that blows up has rel_error NA and its step and
// growth factor) and --rates-input (the same rows without any (weight, θ) series that blew
// up at some level, for rate_table: a rate through a blown-up level is not a rate).
//
//   thesis_heat --table 4.6 --profile quick --out data/quick/thesis_table4_6.tsv
//     --rates-input data/quick/thesis_table4_6_finite.tsv
#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/studies/catalog.hpp"
#include "gpm/studies/heat_tables.hpp"
#include "gpm/studies/cost_model.hpp"
#include "gpm/studies/profile.hpp"
#include "gpm/studies/runner.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// --- Parameters: the tables, weights, κ and T are the catalog's (gpm/studies/heat_tables.hpp). ---

// The rows of series (weight, θ) that never blew up: the input of rate_table.
void write_rates_input(LevelCache& cache, const std::string& path) {
  TsvTable t;
  for (const char* key : {"program", "table", "profile", "seed", "h_rule", "h", "dt_nominal", "error"})
    if (auto v = cache.table().get(key)) t.set(key, *v);
  const TsvTable& d = cache.table();
  auto series = [&](std::size_t i) { return d.text(i, "weight") + "|" + d.text(i, "theta"); };
  std::set<std::string> blown;
  for (std::size_t i = 0; i < d.rows.size(); ++i)
    if (d.text(i, "blew_up") == "yes") blown.insert(series(i));
  t.columns = {"weight", "theta", "level", "h", "rel_error"};
  t.set("note", "rows of thesis_heat's data file whose (weight, theta) series never blew up");
  for (std::size_t i = 0; i < d.rows.size(); ++i) {
    if (blown.count(series(i))) continue;
    std::vector<std::string> row;
    for (auto& c : t.columns) row.push_back(d.text(i, c));
    t.add_row(row);
  }
  add_provenance(t);
  t.save(path);
}

int body(int argc, char** argv) {
  StudyRunner run("thesis_heat",
                  "Discrete heat problem with the theta-method (thesis §4.3): relative errors (4.2)\n"
                  "per weight, theta and level for one time-step setting (Tables 4.5-4.7).",
                  "quick or paper (levels per table: heat_tables.hpp, gpm study --list)");
  Args& a = run.args();
  a.opt("table", "", "4.5 (dt = 0.0025h^2), 4.6 (dt = 0.5h^2) or 4.7 (dt = 0.5h) (required)")
      .output("rates-input", "", "data file of the series that never blew up (for rate_table)")
      .opt("dt-rule", "fit", "fit: dt = T/K, K = ceil(T/dt0) (the thesis' dt = T/K); exact: dt = dt0,\n"
                             "  K = ceil(T/dt0) steps (last step at K dt0 >= T)")
      .opt("h-rule", "h10", "h10: h = (2.6^4 2^-10 dx)^(1/4) as printed; h15: (2.6^4 2^-15 dx)^(1/4)")
      .opt("volumes", "lattice", "lattice: V_i = |Omega_H|/N (thesis (A.10)); cell: V_i = dx^2\n"
                                 "  (a diagnostic: (A.10) differs from dx^2 by 0.8%, 0.13%, -0.2% at 2^-7..2^-9)")
      .opt("tol", "1e-10", "CG relative residual per implicit step")
      .opt("blowup", "off", "off (default): run to T, stopping only at a non-finite value, so an\n"
                            "  unstable theta = 0 run still has the error (4.2) and a rate; or a factor:\n"
                            "  stop when ||U^k|| > blowup * ||U^0|| (l2(Omega_H))")
      .opt("thetas", "", "run only these theta of the table (comma list; default: all of them)")
      .opt("storage", "auto", "Laplacian storage: auto, assembled, matrix_free")
      .opt("max-gb", "8", "memory budget of an assembled Laplacian (GB)");
  run.parse(argc, argv);
  const HeatTable& ts = heat_table(a.str("table"));
  const std::string h_rule = a.str("h-rule");
  pde_h(h_rule, 1.0);  // InputError naming the rule unless h10 or h15
  const std::string volumes = a.str("volumes");
  const std::string volumes_text = pde_volumes_description(volumes);  // InputError if unknown
  HeatSetting hs;
  hs.kappa = kHeatKappa;
  hs.T = kHeatT;
  hs.tol = a.tolerance("tol");
  const std::string dt_rule = a.str("dt-rule");
  if (dt_rule != "fit" && dt_rule != "exact")
    throw InputError("--dt-rule: '" + dt_rule + "' is not fit or exact");
  hs.fit_T = dt_rule == "fit";
  // The documents' error (4.2) is defined however large U grows: by default no guard, and a
  // run stops early only where a value is no longer finite (reported as a blow-up).
  const bool guarded = a.str("blowup") != "off";
  hs.blowup_factor = guarded ? a.positive("blowup") : std::numeric_limits<double>::infinity();
  // ||U^k|| ≤ blowup·||U^0|| holds at k = 0 only for a factor above 1.
  if (!(hs.blowup_factor > 1)) throw InputError("--blowup must exceed 1, got " + a.str("blowup"));
  // A subset of the table's θ: a unit is keyed by θ, so a subset run only adds units.
  std::vector<double> thetas = ts.thetas;
  if (!a.str("thetas").empty()) {
    thetas = a.nums("thetas");
    for (double th : thetas)
      if (std::find(ts.thetas.begin(), ts.thetas.end(), th) == ts.thetas.end())
        throw InputError("--thetas: " + fmt(th) + " is not a theta of Table " + ts.table);
  }
  const auto storage = parse_laplacian_storage(a.str("storage"));
  const double max_bytes = a.positive("max-gb") * 1e9;
  const std::vector<int> levels = run.levels(ts.quick, heat_levels(ts, true, h_rule));
  require_pde_levels_fit_memory(levels, {h_rule}, storage, max_bytes);
  const std::string rates_input = a.str("rates-input");

  // --- The data file: one row per (weight, θ, level). ---------------------------------------
  LevelCache& cache = run.open(
      {{"program", "thesis_heat"}, {"table", ts.table}, {"profile", profile_name(run.profile())},
       {"seed", fmt(static_cast<long long>(run.seed()))}, {"kappa", fmt(kHeatKappa)}, {"T", fmt(kHeatT)},
       {"dt_nominal", ts.dt_rule}, {"steps", hs.fit_T ? "K = ceil(T/dt_nominal), dt = T/K"
                           : "dt = dt_nominal, K = ceil(T/dt_nominal) (last step at K dt >= T)"},
       {"tol", fmt(hs.tol)}, {"blowup", guarded ? fmt(hs.blowup_factor) : "off"},
       {"h_rule", h_rule},
       {"h", pde_h_formula(h_rule)}, {"volumes", volumes_text},
       {"error", "(4.2): max_k ||u-U||_l2(Omega_H) / max_k ||u||_l2(Omega_H)"}},
      heat_columns(), 3);
  const Domain dom;
  for (int k : levels) {
    // The level: particles, volumes, h and the nominal step Δt₀ of the table.
    const double dx = std::ldexp(1.0, -k);
    const double h = pde_h(h_rule, dx);
    const double dt0 = ts.c * std::pow(h, ts.p);
    const Particles p = jittered_grid(dx, run.seed());
    const auto V = pde_volumes(volumes, p, dx, dom);
    bool checked = false;
    for (const auto& wname : pde_weights()) {
      // The θ of this weight still to do; on a cluster they go to one rank together (they
      // share this weight's Laplacian).
      std::vector<double> todo;
      double work = 0;
      for (double th : thetas)
        if (!cache.has({wname, fmt(th), fmt(k)}))
          todo.push_back(th), work += heat_unit_work(dx, h, dt0, hs.T, th);
      if (todo.empty() || !run.claim_group(static_cast<int>(todo.size()), work)) continue;
      if (!checked) require_h_connectivity(p, h), checked = true;
      // One Laplacian per (level, weight), reused by every θ and every step; the θ advance
      // together, one block product per step for all of them (each series' numbers as if
      // run alone), K steps of the θ-method from the exact initial value.
      const DiscreteLaplacian L(p, V, weight(wname), h, storage, max_bytes);
      std::vector<HeatSetting> settings;
      for (double th : todo) {
        hs.theta = th;
        hs.dt_nominal = dt0;
        settings.push_back(hs);
      }
      const std::vector<HeatResult> results = solve_heat_block(p, L, settings);
      for (std::size_t u = 0; u < todo.size(); ++u) {
        const double th = todo[u];
        const HeatResult& r = results[u];
        const std::string na = "NA";
        run.add({wname, fmt(th), fmt(k), fmt(dx), fmt(h), fmt(p.size()), fmt(L.n_unknowns()),
                   L.assembled() ? "assembled" : "matrix_free", fmt(static_cast<long long>(r.K)), fmt(r.dt),
                   r.blew_up ? na : fmt(r.rel_error), r.blew_up ? na : fmt(r.rel_error_max),
                   fmt(r.growth_max), r.blew_up ? "yes" : "no", r.blew_up ? fmt(static_cast<long long>(r.blowup_step)) : na,
                   r.blew_up ? fmt(r.growth) : na, r.blew_up ? fmt(r.amplification) : na,
                   fmt(static_cast<long long>(r.steps_done)), fmt(r.mean_cg_iterations), fmt(r.max_rel_residual),
                   fmt(r.seconds_per_step), fmt(r.seconds)});
        const std::string head = line_printf("%s: %-28s theta=%-3g dx=2^-%d h=%.4f K=%ld ",
                                             ts.table.c_str(), wname.c_str(), th, k, h, r.K);
        run.unit_done(0, head + (r.blew_up
            ? line_printf("BLOW-UP at step %ld: ||U||/||U0|| = %.3g (x%.3g in the last step)  %.2f s",
                          r.blowup_step, r.growth, r.amplification, r.seconds)
            : line_printf("err=%.4e CG %.1f it/step  %.3g s/step  %.2f s", r.rel_error,
                          r.mean_cg_iterations, r.seconds_per_step, r.seconds)));
        if (cache.writes() && !rates_input.empty()) write_rates_input(cache, rates_input);
      }
    }
  }
  if (!run.finish()) return 0;
  if (!rates_input.empty()) write_rates_input(cache, rates_input);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_heat", body, argc, argv); }
