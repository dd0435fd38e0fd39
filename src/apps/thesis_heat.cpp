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
#include <map>
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
#include "gpm/solvers/heat_krylov.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/cost_model.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/run/runner.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// --- Parameters: the tables, weights, κ and T are the catalog's (gpm/studies/define/heat_tables.hpp). ---

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

// The propagator that made a stored unit's row (stepped where the file has none), for
// --verify/--recheck: a row is recomputed the way it was made.
HeatPropagator stored_propagator(LevelCache& cache, const std::vector<std::string>& key) {
  const TsvTable& d = cache.table();
  for (std::size_t i = 0; i < d.rows.size(); ++i)
    if (d.text(i, "weight") == key[0] && d.text(i, "theta") == key[1] && d.text(i, "level") == key[2])
      return parse_heat_propagator(d.text(i, "propagator"));
  return HeatPropagator::stepped;
}

// A path with "{reading}" replaced by the reading's store suffix.
std::string reading_path(const std::string& pattern, const PdeSetup& r) {
  std::string s = pattern;
  const std::string mark = "{reading}";
  if (auto at = s.find(mark); at != std::string::npos) s.replace(at, mark.size(), r.file_suffix());
  return s;
}

// The data file's header for one reading.
std::vector<std::pair<std::string, std::string>> heat_params(const HeatTable& ts, const StudyRunner& run,
                                                             const HeatSetting& hs, bool guarded,
                                                             const PdeSetup& r) {
  const bool fit = r.dt_rule == DtRule::fit;
  return {{"program", "thesis_heat"}, {"table", ts.table}, {"profile", profile_name(run.profile())},
          {"seed", fmt(static_cast<long long>(run.seed()))}, {"kappa", fmt(kHeatKappa)}, {"T", fmt(kHeatT)},
          {"dt_nominal", ts.dt_rule}, {"steps", fit ? "K = ceil(T/dt_nominal), dt = T/K"
                              : "dt = dt_nominal, K = ceil(T/dt_nominal) (last step at K dt >= T)"},
          {"tol", fmt(hs.tol)}, {"blowup", guarded ? fmt(hs.blowup_factor) : "off"},
          {"h_rule", h_rule_name(r.h_rule)},
          {"h", pde_h_formula(r.h_rule)}, {"volumes", pde_volumes_description(r.volumes)},
          {"error", "(4.2): max_k ||u-U||_l2(Omega_H) / max_k ||u||_l2(Omega_H)"}};
}

int body(int argc, char** argv) {
  StudyRunner run("thesis_heat",
                  "Discrete heat problem with the theta-method (thesis §4.3): relative errors (4.2)\n"
                  "per weight, theta and level for one time-step setting (Tables 4.5-4.7), under\n"
                  "one reading of the set-up or several (comma lists: every combination, each to\n"
                  "its own data file, the series of one Laplacian advanced together).",
                  "quick or paper (levels per table: heat_tables.hpp, gpm study --list)");
  Args& a = run.args();
  a.opt("table", "", "4.5 (dt = 0.0025h^2), 4.6 (dt = 0.5h^2) or 4.7 (dt = 0.5h) (required)")
      .output("rates-input", "", "data file of the series that never blew up (for rate_table);\n"
                                 "  with several readings, a pattern with {reading} as --out")
      .opt("dt-rule", "fit", "fit: dt = T/K, K = ceil(T/dt0) (the thesis' dt = T/K); exact: dt = dt0,\n"
                             "  K = ceil(T/dt0) steps (last step at K dt0 >= T); or both: fit,exact")
      .opt("h-rule", "h10", "h10: h = (2.6^4 2^-10 dx)^(1/4) as printed; h15: (2.6^4 2^-15 dx)^(1/4);\n"
                            "  or both: h10,h15")
      .opt("volumes", "lattice", "lattice: V_i = |Omega_H|/N (thesis (A.10)); cell: V_i = dx^2; or both\n"
                                 "  (a diagnostic: (A.10) differs from dx^2 by 0.8%, 0.13%, -0.2% at 2^-7..2^-9)")
      .opt("tol", "1e-10", "CG relative residual per implicit step")
      .opt("blowup", "off", "off (default): run to T, stopping only at a non-finite value, so an\n"
                            "  unstable theta = 0 run still has the error (4.2) and a rate; or a factor:\n"
                            "  stop when ||U^k|| > blowup * ||U^0|| (l2(Omega_H))")
      .opt("thetas", "", "run only these theta of the table (comma list; default: all of them)")
      .opt("weights", "", "run only these weights (comma list; default: all three)")
      .opt("storage", "auto", "Laplacian storage: auto, assembled, matrix_free")
      .opt("propagator", "auto", "stepped: the theta-method step by step (the reference); krylov: the\n"
                                 "  recurrence propagated exactly in a Krylov subspace (heat_krylov.hpp);\n"
                                 "  auto: per series, the one with fewer predicted Laplacian products.\n"
                                 "  --verify/--recheck recompute each row by the propagator that made it")
      .opt("max-gb", "8", "memory budget of an assembled Laplacian (GB)");
  run.parse(argc, argv);
  const HeatTable& ts = heat_table(a.str("table"));
  // The readings: every combination of the listed choices (InputError naming a bad one).
  std::vector<HRule> h_rules;
  std::vector<PdeVolumes> volume_choices;
  std::vector<DtRule> dt_rules;
  for (auto& s : a.list("h-rule")) h_rules.push_back(parse_h_rule(s));
  for (auto& s : a.list("volumes")) volume_choices.push_back(parse_pde_volumes(s));
  for (auto& s : a.list("dt-rule")) dt_rules.push_back(parse_dt_rule(s));
  const std::vector<PdeSetup> readings = pde_setup_matrix(h_rules, volume_choices, dt_rules);
  HeatSetting hs;
  hs.kappa = kHeatKappa;
  hs.T = kHeatT;
  hs.tol = a.tolerance("tol");
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
  // A subset of the weights, as of the θ: a run only adds units.
  std::vector<std::string> weights = pde_weights();
  if (!a.str("weights").empty()) {
    weights = a.list("weights");
    for (auto& w : weights)
      if (std::find(pde_weights().begin(), pde_weights().end(), w) == pde_weights().end())
        throw InputError("--weights: '" + w + "' is not a weight of the heat tables");
  }
  const auto storage = parse_laplacian_storage(a.str("storage"));
  const HeatPropagator how = parse_heat_propagator(a.str("propagator"));
  const bool rechecking = run.mode() == CacheMode::verify || run.mode() == CacheMode::recheck;
  if (rechecking && a.has("propagator"))
    throw InputError("--propagator with --verify/--recheck: each stored row is recomputed by the "
                     "propagator that made it (its column 'propagator')");
  const double max_bytes = a.positive("max-gb") * 1e9;
  // The table's units (registry.cpp): one series (weight, θ) per level and h rule, in the
  // order (level, h rule, weight, θ); --levels, else the profile's levels.  Kept: those of
  // the chosen h rules, weights and θ.
  const UnitScope scope{run.profile() == Profile::paper, run.levels(ts.quick, ts.paper), run.levels_given()};
  auto chosen = [](const auto& list, const auto& v) { return std::find(list.begin(), list.end(), v) != list.end(); };
  std::vector<StudyUnit> units;
  std::vector<int> levels;
  for (const StudyUnit& u : study_registry().study(heat_study_name(ts)).units(scope))
    if (chosen(h_rules, parse_h_rule(u.part)) && chosen(weights, u.key[0]) &&
        chosen(thetas, parse_number(u.key[1], "theta"))) {
      units.push_back(u);
      if (!chosen(levels, u.level)) levels.push_back(u.level);
    }
  require_pde_levels_fit_memory(levels, h_rules, storage, max_bytes);
  const std::string out = run.out(), rates_input = a.str("rates-input");
  if (readings.size() > 1 && out.find("{reading}") == std::string::npos)
    throw InputError("--out '" + out + "' names one file for " + std::to_string(readings.size()) +
                     " readings; put {reading} where the reading's suffix goes (e.g. "
                     "results/paper/thesis_table4_6{reading}.tsv)");
  if (readings.size() > 1 && !rates_input.empty() && rates_input.find("{reading}") == std::string::npos)
    throw InputError("--rates-input '" + rates_input + "' needs {reading} too, for " +
                     std::to_string(readings.size()) + " readings");

  // --- The data files: one per reading, one row per (weight, θ, level). ----------------------
  std::vector<StudyRunner::DataFile> files;
  for (auto& r : readings) files.push_back({reading_path(out, r), heat_params(ts, run, hs, guarded, r)});
  const std::vector<LevelCache*> caches = run.open_files(files, heat_columns(), 3);
  const Domain dom;
  Particles p;  // of the level being run, with the volumes of each choice
  std::map<PdeVolumes, std::vector<double>> V;
  int p_level = -1;
  std::vector<std::pair<int, HRule>> checked;  // (level, h rule) whose connectivity is checked
  for (std::size_t g = 0, next = 0; g < units.size(); g = next) {
    // A group: the series of one (level, h rule, weight), which share one Laplacian.
    const StudyUnit& first = units[g];
    const int k = first.level;
    const HRule h_rule = parse_h_rule(first.part);
    const std::string wname = first.key[0];
    std::vector<double> group_thetas;
    for (next = g; next < units.size() && units[next].level == k && units[next].part == first.part &&
                   units[next].key[0] == wname;
         ++next)
      group_thetas.push_back(parse_number(units[next].key[1], "theta"));
    // The level: particles and the volumes of each choice.
    const double dx = std::ldexp(1.0, -k);
    if (p_level != k) {
      p = jittered_grid(dx, run.seed());
      for (PdeVolumes vc : volume_choices) V[vc] = pde_volumes(vc, p, dx, dom);
      p_level = k;
    }
    // h and the nominal step Δt₀ of the table.
    const double h = first.h;
    const double dt0 = ts.c * std::pow(h, ts.p);
    // The series still to do of this weight: (reading, θ), every reading of this h rule.
    // They share one Laplacian (on a cluster they go to one rank together).
    struct Todo {
      std::size_t reading;
      double theta;
    };
    std::vector<Todo> todo;
    double work = 0;
    for (std::size_t r = 0; r < readings.size(); ++r) {
      if (readings[r].h_rule != h_rule) continue;
      for (double th : group_thetas)
        if (!caches[r]->has({wname, fmt(th), fmt(k)}))
          todo.push_back({r, th}), work += heat_unit_work(dx, h, dt0, hs.T, th);
    }
    if (todo.empty() || !run.claim_group(static_cast<int>(todo.size()), work)) continue;
    if (!chosen(checked, std::make_pair(k, h_rule)))
      require_h_connectivity(p, h), checked.push_back({k, h_rule});
    // One Laplacian per (level, h rule, weight), built with the first series' volumes;
    // a series of other volumes runs on it through volumes_for (the stored entries do not
    // depend on them) where it is assembled as the half, else on a Laplacian of its own.
    // Every series' numbers are those it gives alone.  (The readings' order keeps each
    // volumes choice's series together, so the units finish in the order claimed.)
    const WeightFunction& w = weight(wname);
    std::vector<bool> done(todo.size(), false);
    while (std::find(done.begin(), done.end(), false) != done.end()) {
      const PdeVolumes own =
          readings[todo[std::find(done.begin(), done.end(), false) - done.begin()].reading].volumes;
      const DiscreteLaplacian L(p, V[own], w, h, storage, max_bytes);
      const bool shares = L.assembled() && storage != LaplacianStorage::full;
      std::map<PdeVolumes, DiscreteLaplacian::Volumes> other;
      std::vector<std::size_t> here;
      std::vector<HeatSetting> settings;
      std::vector<HeatPropagator> hows;
      for (std::size_t u = 0; u < todo.size(); ++u) {
        const PdeSetup& r = readings[todo[u].reading];
        if (done[u] || (r.volumes != own && !shares)) continue;
        HeatSetting s = hs;
        s.theta = todo[u].theta;
        s.dt_nominal = dt0;
        s.fit_T = r.dt_rule == DtRule::fit;
        if (r.volumes != own) {
          if (!other.count(r.volumes)) other.emplace(r.volumes, L.volumes_for(p, w, V[r.volumes]));
          s.volumes = &other.at(r.volumes);
        }
        here.push_back(u), settings.push_back(s), done[u] = true;
        hows.push_back(rechecking ? stored_propagator(*caches[todo[u].reading], {wname, fmt(todo[u].theta), fmt(k)})
                                  : how);
      }
      const std::vector<HeatResult> rs =
          naming_unit("Table " + ts.table + ", " + h_rule_name(h_rule) + ", " + wname + ", level " + fmt(k),
                      [&] { return run_heat(p, L, settings, hows, dx); });
      for (std::size_t i = 0; i < here.size(); ++i) {
        const Todo& t = todo[here[i]];
        const HeatResult& res = rs[i];
        const PdeSetup& r = readings[t.reading];
        // The row, by column name (heat_columns()); a blown-up series has no error.
        const std::string na = "NA";
        TsvRow row = run.row();
        row["weight"] = wname, row["theta"] = fmt(t.theta), row["level"] = fmt(k);
        row["dx"] = fmt(dx), row["h"] = fmt(h), row["N"] = fmt(p.size());
        row["N_omega"] = fmt(L.n_unknowns()), row["storage"] = L.assembled() ? "assembled" : "matrix_free";
        row["propagator"] = res.subspace > 0 ? "krylov" : "stepped", row["subspace"] = fmt(res.subspace);
        row["K"] = fmt(static_cast<long long>(res.K)), row["dt"] = fmt(res.dt);
        row["rel_error"] = res.blew_up ? na : fmt(res.rel_error);
        row["rel_error_max"] = res.blew_up ? na : fmt(res.rel_error_max);
        row["growth_max"] = fmt(res.growth_max), row["blew_up"] = res.blew_up ? "yes" : "no";
        row["blowup_step"] = res.blew_up ? fmt(static_cast<long long>(res.blowup_step)) : na;
        row["growth"] = res.blew_up ? fmt(res.growth) : na;
        row["amplification"] = res.blew_up ? fmt(res.amplification) : na;
        row["steps_done"] = fmt(static_cast<long long>(res.steps_done));
        row["cg_mean_iterations"] = fmt(res.mean_cg_iterations);
        row["max_rel_residual"] = fmt(res.max_rel_residual);
        row["s_per_step"] = fmt(res.seconds_per_step), row["seconds"] = fmt(res.seconds);
        run.add(t.reading, row);
        const std::string head = line_printf(
            "%s%s%s: %-28s theta=%-3g dx=2^-%d h=%.4f K=%ld ", ts.table.c_str(),
            readings.size() > 1 ? " " : "", readings.size() > 1 ? r.name().c_str() : "",
            wname.c_str(), t.theta, k, h, res.K);
        run.unit_done(0, head + (res.blew_up
            ? line_printf("BLOW-UP at step %ld: ||U||/||U0|| = %.3g (x%.3g in the last step)  %.2f s",
                          res.blowup_step, res.growth, res.amplification, res.seconds)
            : (res.subspace > 0
            ? line_printf("err=%.4e Krylov m=%d  %.0f products  %.2f s", res.rel_error, res.subspace,
                          res.products, res.seconds)
            : line_printf("err=%.4e CG %.1f it/step  %.3g s/step  %.2f s", res.rel_error,
                          res.mean_cg_iterations, res.seconds_per_step, res.seconds)) +
              // Not stopped is not "stable": a series that grew is said to have grown.
              (res.growth_max > 2 ? line_printf("  (||U||/||U0|| grew to %.3g: run to T, no guard)", res.growth_max)
                                  : std::string())));
        if (caches[t.reading]->writes() && !rates_input.empty())
          write_rates_input(*caches[t.reading], reading_path(rates_input, r));
      }
    }
  }
  if (!run.finish()) return 0;
  if (!rates_input.empty())
    for (std::size_t r = 0; r < readings.size(); ++r)
      write_rates_input(*caches[r], reading_path(rates_input, readings[r]));
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_heat", body, argc, argv); }
