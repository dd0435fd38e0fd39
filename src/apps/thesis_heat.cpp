// thesis_heat: the discrete heat problem of the thesis, §4.3 (Figures 4.9–4.11,
// Tables 4.5–4.7), one setting of the time step per table (--table, or several in one run):
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
//
// Tables that share a level, h rule, volumes, weight and seed share the Laplacian and the
// Krylov subspace (issue 58, item 2): `--table 4.5,4.6,4.7 --out DIR/thesis_table{table}.tsv`
// builds each once; each table keeps the subspace size its own series settle at
// (HeatSetting::size_group), so its rows are those of its own run, bit for bit.
#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <memory>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/progress.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/heat_krylov.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/tau_preconditioner.hpp"
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
void write_rates_input(UnitCache& cache, const std::string& path) {
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
HeatPropagator stored_propagator(UnitCache& cache, const std::vector<std::string>& key) {
  const TsvTable& d = cache.table();
  for (std::size_t i = 0; i < d.rows.size(); ++i)
    if (d.text(i, "weight") == key[0] && d.text(i, "theta") == key[1] && d.text(i, "level") == key[2])
      return parse_heat_propagator(d.text(i, "propagator"));
  return HeatPropagator::stepped;
}

// A path with "{table}" replaced by the table's name in file names (4.6: 4_6) and "{reading}"
// by the reading's store suffix.
std::string reading_path(const std::string& pattern, const HeatTable& t, const PdeReading& r) {
  std::string s = pattern, name = t.table;
  std::replace(name.begin(), name.end(), '.', '_');
  for (const auto& [mark, by] : {std::pair<std::string, std::string>{"{table}", name}, {"{reading}", r.file_suffix()}})
    if (auto at = s.find(mark); at != std::string::npos) s.replace(at, mark.size(), by);
  return s;
}

// The data file's header for one reading.
// A preconditioned run names its solver, so its rows (other iteration counts, the same errors
// to the tolerance) never mix with plain CG's in one file.
std::vector<std::pair<std::string, std::string>> heat_params(const HeatTable& ts, const StudyRunner& run,
                                                             const HeatSetting& hs, bool guarded,
                                                             const PdeReading& r, bool tau) {
  const bool fit = r.dt_rule == DtRule::fit;
  std::vector<std::pair<std::string, std::string>> p = {{"program", "thesis_heat"}, {"table", ts.table}, {"profile", profile_name(run.profile())},
          {"seed", fmt(static_cast<long long>(run.seed()))}, {"kappa", fmt(kHeatKappa)}, {"T", fmt(kHeatT)},
          {"dt_nominal", ts.dt_rule}, {"steps", fit ? "K = ceil(T/dt_nominal), dt = T/K"
                              : "dt = dt_nominal, K = ceil(T/dt_nominal) (last step at K dt >= T)"},
          {"tol", fmt(hs.tol)}, {"blowup", guarded ? fmt(hs.blowup_factor) : "off"},
          {"h_rule", h_rule_name(r.h_rule)},
          {"h", pde_h_formula(r.h_rule)}, {"volumes", pde_volumes_description(r.volumes)},
          {"error", "(4.2): max_k ||u-U||_l2(Omega_H) / max_k ||u||_l2(Omega_H)"}};
  if (tau) p.emplace_back("solver", "implicit steps: CG preconditioned by the lattice's tau (DST-I) matrix");
  return p;
}

// The program, in the order of the thesis' §4.3 and the deal.II step-6 style: the options,
// the readings and series they select, one data file per reading, then per group of series
// sharing one Laplacian (a level, an h rule and a weight): the particles, the Laplacian, the
// θ-method (stepped or propagated) for every series of the group, one row each.
class HeatTables {
 public:
  HeatTables()
      : run_("thesis_heat",
             "Discrete heat problem with the theta-method (thesis §4.3): relative errors (4.2)\n"
             "per weight, theta and level for a time-step setting (Tables 4.5-4.7), under\n"
             "one reading of the set-up or several (comma lists: every combination, each to\n"
             "its own data file, the series of one Laplacian advanced together, the tables'\n"
             "too: one Laplacian and one Krylov subspace for all of them).",
             "quick or paper (levels per table: heat_tables.hpp, gpm study --list)") {}

  int run(int argc, char** argv) {
    declare_options();
    run_.parse(argc, argv);
    read_choices();
    select_units();
    open_files();
    for (std::size_t g = 0, next = 0; g < units_.size(); g = next) {
      next = group_end(g);
      advance_group(g, next);
    }
    return finish();
  }

 private:
  // A series still to do of one group: its table, reading and θ.
  struct Todo {
    std::size_t table, reading;
    double theta;
  };

  StudyRunner run_;
  std::vector<const HeatTable*> tables_;
  std::vector<std::size_t> unit_table_;  // the table of each unit
  std::vector<HRule> h_rules_;
  std::vector<PdeVolumes> volume_choices_;
  std::vector<PdeReading> readings_;
  HeatSetting hs_;
  bool guarded_ = false, rechecking_ = false, tau_ = false, given_propagator_ = false;
  LaplacianStorage storage_ = LaplacianStorage::automatic;
  HeatPropagator how_ = HeatPropagator::automatic;
  double max_bytes_ = 0;
  std::vector<StudyUnit> units_;
  std::string out_, rates_input_;
  std::vector<UnitCache*> caches_;
  const Domain dom_;
  Particles p_;  // of the level being run, with the volumes of each choice
  std::map<PdeVolumes, std::vector<double>> V_;
  int p_level_ = -1;
  std::vector<std::pair<int, HRule>> checked_;  // (level, h rule) whose connectivity is checked

  void declare_options() {
    Args& a = run_.args();
    a.opt("table", "", "4.5 (dt = 0.0025h^2), 4.6 (dt = 0.5h^2) or 4.7 (dt = 0.5h) (required); or several\n"
                       "  (4.5,4.6,4.7: one Laplacian and one subspace for their series; --out then\n"
                       "  puts {table} where the table's name goes: DIR/thesis_table{table}.tsv)")
        .output("rates-input", "", "data file of the series that never blew up (for rate_table);\n"
                                   "  with several readings or tables, a pattern with {reading} or {table}\n"
                                   "  as --out")
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
        .opt("solver", "cg", "implicit steps: cg (plain conjugate gradients, the reference of every stored\n"
                             "  row) or tau (preconditioned by the lattice's fast sine transform);\n"
                             "  --verify --solver tau compares plain CG's rows at 1e-6")
        .opt("propagator", "auto", "stepped: the theta-method step by step (the reference); krylov: the\n"
                                   "  recurrence propagated exactly in a Krylov subspace (heat_krylov.hpp);\n"
                                   "  auto: per series, the one with fewer predicted Laplacian products.\n"
                                   "  --recheck recomputes each row by the propagator that made it; so does\n"
                                   "  --verify, unless given one: every row by it, compared at 1e-4")
        .opt("max-gb", "8", "memory budget of an assembled Laplacian (GB)");
  }

  // The table, the readings (every combination of the listed choices; InputError naming a bad
  // one) and the θ-method's settings.
  void read_choices() {
    Args& a = run_.args();
    for (auto& t : a.list("table")) {
      const HeatTable* table = &heat_table(t);
      if (chosen(tables_, table)) throw InputError("--table: " + t + " is given twice");
      tables_.push_back(table);
    }
    std::vector<DtRule> dt_rules;
    for (auto& s : a.list("h-rule")) h_rules_.push_back(parse_h_rule(s));
    for (auto& s : a.list("volumes")) volume_choices_.push_back(parse_pde_volumes(s));
    for (auto& s : a.list("dt-rule")) dt_rules.push_back(parse_dt_rule(s));
    readings_ = pde_reading_matrix(h_rules_, volume_choices_, dt_rules);
    hs_.kappa = kHeatKappa;
    hs_.T = kHeatT;
    hs_.tol = a.tolerance("tol");
    // The documents' error (4.2) is defined however large U grows: by default no guard, and a
    // run stops early only where a value is no longer finite (reported as a blow-up).
    guarded_ = a.str("blowup") != "off";
    hs_.blowup_factor = guarded_ ? a.positive("blowup") : std::numeric_limits<double>::infinity();
    // ||U^k|| ≤ blowup·||U^0|| holds at k = 0 only for a factor above 1.
    if (!(hs_.blowup_factor > 1)) throw InputError("--blowup must exceed 1, got " + a.str("blowup"));
    storage_ = parse_laplacian_storage(a.str("storage"));
    how_ = parse_heat_propagator(a.str("propagator"));
    rechecking_ = run_.mode() == CacheMode::verify || run_.mode() == CacheMode::recheck;
    const std::string solver = a.str("solver");
    if (solver != "cg" && solver != "tau") throw InputError("--solver '" + solver + "' is not cg or tau");
    tau_ = solver == "tau";
    // --verify may recompute by another, cheaper path than the rows' own (the store compares
    // at that path's tolerance, store.hpp); --recheck writes rows, so only by their own.
    const bool recheck = run_.mode() == CacheMode::recheck;
    if (recheck && tau_)
      throw InputError("--solver tau with --recheck: the stored rows were made with plain CG (their "
                       "iteration counts would differ); --verify --solver tau compares their numbers");
    if (recheck && a.has("propagator"))
      throw InputError("--propagator with --recheck: each stored row is recomputed by the propagator that "
                       "made it (its column 'propagator'); --verify --propagator compares by another");
    // A --verify given a propagator recomputes every row by it; the store compares a row made
    // by another one at the propagator path's tolerance.
    given_propagator_ = rechecking_ && a.has("propagator");
    max_bytes_ = a.positive("max-gb") * 1e9;
    out_ = run_.out(), rates_input_ = a.str("rates-input");
    if (readings_.size() > 1 && out_.find("{reading}") == std::string::npos)
      throw InputError("--out '" + out_ + "' names one file for " + std::to_string(readings_.size()) +
                       " readings; put {reading} where the reading's suffix goes (e.g. "
                       "results/paper/thesis_table4_6{reading}.tsv)");
    if (tables_.size() > 1 && out_.find("{table}") == std::string::npos)
      throw InputError("--out '" + out_ + "' names one file for " + std::to_string(tables_.size()) +
                       " tables; put {table} where the table's name goes (e.g. "
                       "results/paper/thesis_table{table}.tsv)");
    for (const auto& [many, mark] : {std::pair<bool, std::string>{readings_.size() > 1, "{reading}"}, {tables_.size() > 1, "{table}"}})
      if (many && !rates_input_.empty() && rates_input_.find(mark) == std::string::npos)
        throw InputError("--rates-input '" + rates_input_ + "' needs " + mark + " too, as --out");
  }

  // Each table's units (registry.cpp): one series (weight, θ) per level and h rule, in the
  // order (level, h rule, weight, θ); --levels, else the profile's levels.  Kept: those of the
  // chosen h rules, weights and θ (a subset run only adds units: a unit is keyed by them).
  // Several tables' units are merged in that order (table after weight), so that the series
  // of one Laplacian, whatever their table, form one group.
  void select_units() {
    Args& a = run_.args();
    std::vector<double> thetas;
    if (!a.str("thetas").empty()) {
      thetas = a.nums("thetas");
      for (double th : thetas)
        if (std::none_of(tables_.begin(), tables_.end(), [&](const HeatTable* t) { return chosen(t->thetas, th); }))
          throw InputError("--thetas: " + fmt(th) + " is not a theta of " +
                           (tables_.size() > 1 ? "any of Tables " : "Table ") + a.str("table"));
    }
    std::vector<std::string> weights = pde_weights();
    if (!a.str("weights").empty()) {
      weights = a.list("weights");
      for (auto& w : weights)
        if (std::find(pde_weights().begin(), pde_weights().end(), w) == pde_weights().end())
          throw InputError("--weights: '" + w + "' is not a weight of the heat tables");
    }
    std::vector<int> levels;
    std::vector<std::pair<StudyUnit, std::size_t>> units;
    for (std::size_t t = 0; t < tables_.size(); ++t) {
      const HeatTable& ts = *tables_[t];
      const UnitScope scope{run_.profile() == Profile::paper, run_.levels(ts.quick, ts.paper), run_.levels_given()};
      for (const StudyUnit& u : study_registry().study(heat_study_name(ts)).units(scope))
        if (chosen(h_rules_, parse_h_rule(u.part)) && chosen(weights, u.key[0]) &&
            (thetas.empty() || chosen(thetas, parse_number(u.key[1], "theta")))) {
          units.push_back({u, t});
          if (!chosen(levels, u.level)) levels.push_back(u.level);
        }
    }
    auto order = [](const std::pair<StudyUnit, std::size_t>& x) {
      const StudyUnit& u = x.first;
      return std::make_tuple(u.level, u.part, std::find(pde_weights().begin(), pde_weights().end(), u.key[0]) - pde_weights().begin());
    };
    std::stable_sort(units.begin(), units.end(), [&](const auto& x, const auto& y) { return order(x) < order(y); });
    for (auto& [u, t] : units) units_.push_back(u), unit_table_.push_back(t);
    require_pde_levels_fit_memory(levels, h_rules_, storage_, max_bytes_);
  }

  // The data files: one per table and reading, one row per (weight, θ, level).
  void open_files() {
    std::vector<StudyRunner::DataFile> files;
    for (const HeatTable* t : tables_)
      for (auto& r : readings_) files.push_back({reading_path(out_, *t, r), heat_params(*t, run_, hs_, guarded_, r, tau_)});
    caches_ = run_.open_files(files, heat_columns(), 3);
  }
  // The data file of a table and reading.
  UnitCache& cache(std::size_t table, std::size_t reading) { return *caches_[table * readings_.size() + reading]; }

  // The end of the group that starts at unit g: the series of one (level, h rule, weight),
  // which share one Laplacian.
  std::size_t group_end(std::size_t g) const {
    std::size_t next = g;
    while (next < units_.size() && units_[next].level == units_[g].level && units_[next].part == units_[g].part &&
           units_[next].key[0] == units_[g].key[0])
      ++next;
    return next;
  }

  // The level's particles and the volumes of each choice (once per level).
  void prepare_level(int k) {
    if (p_level_ == k) return;
    const double dx = std::ldexp(1.0, -k);
    p_ = jittered_grid(dx, run_.seed());
    for (PdeVolumes vc : volume_choices_) V_[vc] = pde_volumes(vc, p_, dx, dom_);
    p_level_ = k;
  }

  // A table's nominal step Δt₀ = c h^p.
  double dt0(std::size_t table, double h) const { return tables_[table]->c * std::pow(h, tables_[table]->p); }

  // One group: its series still to do (every table's, every reading of its h rule, each θ),
  // claimed as one piece of work; then one Laplacian per volumes choice that cannot share, the
  // series run together on it, one row each.
  void advance_group(std::size_t g, std::size_t next) {
    const StudyUnit& first = units_[g];
    const int k = first.level;
    const HRule h_rule = parse_h_rule(first.part);
    const std::string wname = first.key[0];
    const double dx = std::ldexp(1.0, -k), h = first.h;
    std::vector<Todo> todo;
    double work = 0;
    for (std::size_t t = 0; t < tables_.size(); ++t)
      for (std::size_t r = 0; r < readings_.size(); ++r) {
        if (readings_[r].h_rule != h_rule) continue;
        for (std::size_t u = g; u < next; ++u) {
          if (unit_table_[u] != t) continue;
          const double th = parse_number(units_[u].key[1], "theta");
          if (!cache(t, r).has({wname, fmt(th), fmt(k)}))
            todo.push_back({t, r, th}), work += heat_unit_work(dx, h, dt0(t, h), hs_.T, th);
        }
      }
    // On a cluster the group goes to one rank together.
    if (todo.empty() || !run_.claim_group(static_cast<int>(todo.size()), work)) return;
    prepare_level(k);
    if (!chosen(checked_, std::make_pair(k, h_rule))) require_h_connectivity(p_, h), checked_.push_back({k, h_rule});
    // One Laplacian per (level, h rule, weight), built with the first series' volumes; a series
    // of other volumes runs on it through volumes_for (the stored entries do not depend on
    // them) where it is assembled as the half, else on a Laplacian of its own.  Every series'
    // numbers are those it gives alone.  (The readings' order keeps each volumes choice's
    // series together, so the units finish in the order claimed.)
    const WeightFunction& w = weight(wname);
    std::vector<bool> done(todo.size(), false);
    while (std::find(done.begin(), done.end(), false) != done.end()) {
      const PdeVolumes own = readings_[todo[std::find(done.begin(), done.end(), false) - done.begin()].reading].volumes;
      const DiscreteLaplacian L(p_, V_[own], w, h, storage_, max_bytes_);
      const bool shares = L.assembled() && storage_ != LaplacianStorage::full;
      std::map<PdeVolumes, DiscreteLaplacian::Volumes> other;
      std::vector<std::size_t> here;
      std::vector<HeatSetting> settings;
      std::vector<HeatPropagator> hows;
      for (std::size_t u = 0; u < todo.size(); ++u) {
        const PdeReading& r = readings_[todo[u].reading];
        if (done[u] || (r.volumes != own && !shares)) continue;
        HeatSetting s = hs_;
        s.theta = todo[u].theta;
        s.dt_nominal = dt0(todo[u].table, h);
        s.fit_T = r.dt_rule == DtRule::fit;
        s.size_group = static_cast<int>(todo[u].table);  // each table sizes its subspace alone
        if (r.volumes != own) {
          if (!other.count(r.volumes)) other.emplace(r.volumes, L.volumes_for(p_, w, V_[r.volumes]));
          s.volumes = &other.at(r.volumes);
        }
        here.push_back(u), settings.push_back(s), done[u] = true;
        hows.push_back(rechecking_ && !given_propagator_
                           ? stored_propagator(cache(todo[u].table, todo[u].reading), {wname, fmt(todo[u].theta), fmt(k)})
                           : how_);
      }
      // A fine level's subspace grows for up to an hour: one line per size tried says how far
      // (none in a unit's first seconds, so the coarse levels' logs stay short).
      std::string names;
      for (const HeatTable* t : tables_) names += (names.empty() ? "" : ",") + t->table;
      const std::string unit = (tables_.size() > 1 ? "Tables " : "Table ") + names + ", " + h_rule_name(h_rule) + ", " +
                               wname + ", level " + fmt(k);
      const Stopwatch clock;
      KrylovSettings ks;
      ks.on_size = [&](const KrylovTry& t) {
        if (clock.seconds() < 5) return;
        std::fprintf(stderr, "[thesis_heat] %s: Krylov subspace m=%d, trajectories moved %.2g of the error (stop at %.0e), %.2g of its size%s, %.0f s\n",
                     unit.c_str(), t.m, t.change, ks.tol, t.of_data, t.rounding ? " (stalled: rounding, taken)" : "",
                     clock.seconds());
      };
      // --solver tau: each implicit series its own P = D(I/V + θκΔt T1)D (its θ, Δt and volumes).
      std::vector<std::unique_ptr<TauPreconditioner>> pcs;
      if (tau_)
        for (std::size_t i = 0; i < settings.size(); ++i) {
          HeatSetting& s = settings[i];
          if (!(s.theta > 0)) continue;
          const std::vector<double>& V = V_[readings_[todo[here[i]].reading].volumes];
          double vbar = 0;
          for (int32_t j : L.omega()) vbar += V[j];
          vbar /= static_cast<double>(L.n_unknowns());
          const double dt = s.fit_T ? s.T / static_cast<double>(heat_steps(s.T, s.dt_nominal)) : s.dt_nominal;
          pcs.push_back(std::make_unique<TauPreconditioner>(p_, L, w, dx, 1.0 / vbar, s.theta * s.kappa * dt, &V));
          s.pc = pcs.back().get();
        }
      const std::vector<HeatResult> rs = naming_unit(unit, [&] { return run_heat(p_, L, settings, hows, dx, ks); });
      for (std::size_t i = 0; i < here.size(); ++i) write_row(todo[here[i]], rs[i], L, wname, k, dx, h);
    }
  }

  // One series' row, by column name (heat_columns()); a blown-up series has no error.
  void write_row(const Todo& t, const HeatResult& res, const DiscreteLaplacian& L, const std::string& wname, int k,
                 double dx, double h) {
    const PdeReading& r = readings_[t.reading];
    const HeatTable& ts = *tables_[t.table];
    const std::string na = "NA";
    TsvRow row = run_.row();
    row["weight"] = wname, row["theta"] = fmt(t.theta), row["level"] = fmt(k);
    row["dx"] = fmt(dx), row["h"] = fmt(h), row["N"] = fmt(p_.size());
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
    run_.add(t.table * readings_.size() + t.reading, row);
    const std::string head = line_printf("%s%s%s: %-28s theta=%-3g dx=2^-%d h=%.4f K=%ld ", ts.table.c_str(),
                                         readings_.size() > 1 ? " " : "",
                                         readings_.size() > 1 ? r.name().c_str() : "", wname.c_str(), t.theta, k,
                                         h, res.K);
    run_.unit_done(0, head + (res.blew_up
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
    if (cache(t.table, t.reading).writes() && !rates_input_.empty())
      write_rates_input(cache(t.table, t.reading), reading_path(rates_input_, ts, r));
  }

  // The run's end: every row gathered and written; the rates input of each table and reading.
  int finish() {
    if (!run_.finish()) return 0;  // verify/recheck: nothing more is written
    if (!rates_input_.empty())
      for (std::size_t t = 0; t < tables_.size(); ++t)
        for (std::size_t r = 0; r < readings_.size(); ++r)
          write_rates_input(cache(t, r), reading_path(rates_input_, *tables_[t], readings_[r]));
    return 0;
  }

  template <class List, class V>
  static bool chosen(const List& list, const V& v) {
    return std::find(list.begin(), list.end(), v) != list.end();
  }
};

int body(int argc, char** argv) {
  HeatTables program;
  return program.run(argc, argv);
}

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_heat", body, argc, argv); }
