#include "gpm/studies/define/registry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "gpm/error.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/io/args.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/census.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/thesis_tables.hpp"

namespace gpm {

namespace {

double dx_of(int k) { return std::ldexp(1.0, -k); }
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// --- Reading a data file back: a unit's time is repeated on each of its rows (the first
// is kept), its level and numbers by column name (a non-number: NaN). -----------------------
struct Rows {
  const TsvTable& d;
  RecordedUnits& out;
  int level(const std::vector<std::string>& r) const {
    return static_cast<int>(parse_number(r[d.require_column("level")], "level"));
  }
  double v(const std::vector<std::string>& r, const char* name) const {
    try {
      return parse_number(r[d.require_column(name)], "value");
    } catch (const InputError&) {
      return kNaN;
    }
  }
  const std::string& text(const std::vector<std::string>& r, const char* name) const {
    return r[d.require_column(name)];
  }
  void put(const std::string& var, int k, double s, double work) const {
    out.emplace(std::make_pair(var, k), RecordedUnit{s, work});
  }
};

// --- The studies ----------------------------------------------------------------------------

// An entry's identity: its catalog name (also its program's), item, make group, levels,
// columns and the coarse levels the paper profile re-checks.
RegisteredStudy identity(const std::string& name, const std::string& item, const std::string& group,
                         ProfileLevels levels, std::vector<std::string> columns, std::vector<int> recheck) {
  RegisteredStudy s;
  s.name = s.program = name;
  s.item = item, s.group = group, s.levels = std::move(levels), s.columns = std::move(columns);
  s.recheck_levels = std::move(recheck);
  return s;
}

// imoto §5: one fused pass per (level, m), nine weights.
RegisteredStudy imoto() {
  RegisteredStudy s = identity("imoto_fig5_table1", "imoto Figure 5, Table 1", "imoto", imoto_study().levels,
                               imoto_study().columns, {5, 6, 7});
  s.files = {{.name = "imoto_fig5_table1",
              .side_outputs = {{"--printed-out", "imoto_pi3_printed"}},
              .rates = {{.name = "imoto_table1", .input = "imoto_fig5_table1", .scored = true}}}};
  // Seed 1 is the reproduction; seeds 2-5 and the plain grid (no jitter) show how much of a
  // rate is one realization's particle noise (seeds 4, 5 at the coarse and the rate levels
  // only); cellvol is the delta-free error (V_i = dx^2).
  const std::vector<std::string> coarse = {"--levels", "5,6,7"};
  const std::vector<std::string> rate_levels = {"--levels", "5,6,7,11,12"};
  s.store_files = {{.name = "imoto_fig5_table1", .slice = "all", .coarse = coarse},
                   {.name = "imoto_fig5_table1_seed2", .slice = "seed2", .args = {"--seed", "2"}, .coarse = coarse},
                   {.name = "imoto_fig5_table1_seed3", .slice = "seed3", .args = {"--seed", "3"}, .coarse = coarse},
                   {.name = "imoto_fig5_table1_seed4", .slice = "seed4", .args = {"--seed", "4"},
                    .census = rate_levels, .coarse = coarse},
                   {.name = "imoto_fig5_table1_seed5", .slice = "seed5", .args = {"--seed", "5"},
                    .census = rate_levels, .coarse = coarse},
                   {.name = "imoto_fig5_table1_plain", .slice = "plain", .args = {"--jitter", "0"}, .coarse = coarse},
                   {.name = "imoto_fig5_table1_cellvol", .slice = "cellvol", .args = {"--volumes", "cell"},
                    .coarse = coarse}};
  s.published = PublishedRates{.table = "imoto_table1", .file = "imoto_table1.tsv",
                               .key = {"operator", "weight", "m"}, .printed_slice = "all"};
  s.figures = {{.name = "imoto_fig5"}};
  // A unit: one fused pass of the nine weights per (level, m), the particles shared by a
  // level's units.
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels)
      for (double m : imoto_study().orders) out.push_back({k, imoto_h(m, dx_of(k)), {fmt(k), fmt(m)}, "m=" + fmt(m)});
    return out;
  };
  s.price = [](UnitPricer& p, const StudyUnit& u) { p.add_fused("imoto_fig5_table1", u.variant, u.level, u.h, "imoto9"); };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) rows.put("m=" + rows.text(r, "m"), rows.level(r), rows.v(r, "time_s"), rows.v(r, "pairs"));
  };
  return s;
}

// Thesis Tables 4.1–4.3: one fused pass per (h reading, volumes, level); Voronoi once per level.
RegisteredStudy thesis_truncation(const ThesisTableSpec& t) {
  std::vector<int> quick = t.quick_printed;
  for (int k : t.quick_scaled)
    if (std::find(quick.begin(), quick.end(), k) == quick.end()) quick.push_back(k);
  std::sort(quick.begin(), quick.end());
  RegisteredStudy s = identity(t.program, "thesis " + t.table, "truncation", {quick, t.paper_levels},
                               thesis_table_columns(), {5, 6, 7});
  // One rate table per (h reading, volumes) the program runs; the printed h with Voronoi
  // volumes is the thesis' own set-up (the scoreboard's).
  StudyFile file{.name = t.program};
  for (const char* volumes : {"voronoi", "uniform"})
    for (HReading r : t.readings)
      file.rates.push_back({.name = t.program + "_rates_" + h_reading_name(r) + "_" + volumes,
                            .input = t.program,
                            .where = {{"h_reading", h_reading_name(r)}, {"volumes", volumes}},
                            .scored = r == HReading::printed && std::string(volumes) == "voronoi"});
  s.files = {file};
  // Table 4.3 has two operators, so its rates are keyed by the operator too.
  std::vector<std::string> key = {"weight", "function"};
  for (auto& q : t.requests)
    if (q.op != t.requests.front().op) key = {"weight", "operator", "function"};
  // Seed 1 is the reproduction; …_seed2, …_seed3 (Tables 4.1 and 4.3) are other jitter
  // realizations at the coarse and the rate levels, for the seed band.
  const std::vector<std::string> coarse = {"--levels", "5,6,7"};
  s.store_files = {{.name = t.program, .slice = "", .coarse = coarse}};
  if (t.program != "thesis_table4_2")
    for (const char* seed : {"2", "3"})
      s.store_files.push_back({.name = t.program + "_seed" + seed, .slice = std::string("_seed") + seed,
                               .args = {"--seed", seed}, .census = {"--levels", "5,6,7,10,11"}, .coarse = coarse});
  // A stored file holds every (h reading, volumes): one slice each, the file's suffix after.
  s.published = PublishedRates{
      .table = t.program, .file = t.program + "_long.tsv", .key = key, .printed_slice = "printed_voronoi",
      .cut = [](const StoreFile& f, const TsvTable& data) {
        std::vector<StoreSlice> out;
        for (const std::string reading : {"printed", "scaled"})
          for (const std::string volumes : {"voronoi", "uniform"}) {
            TsvTable slice = rows_where(data, {{"h_reading", reading}, {"volumes", volumes}});
            if (!slice.rows.empty()) out.push_back({reading + "_" + volumes + f.slice, std::move(slice)});
          }
        return out;
      }};
  // The document's figures of the table: errors against h (Table 4.3: the gradient, then
  // the Laplacian).
  const std::map<std::string, std::vector<std::string>> figures = {
      {"thesis_table4_1", {"thesis_fig4_3"}}, {"thesis_table4_2", {"thesis_fig4_5"}},
      {"thesis_table4_3", {"thesis_fig4_6", "thesis_fig4_7"}}};
  for (const std::string& f : figures.at(t.program)) s.figures.push_back({.name = f, .scripts = {"figures/thesis_errors.gp"}});
  // A unit: one fused pass per (level, h reading, volumes), keyed as the data file's rows.
  // Without --levels each reading runs at the profile's levels of its own (the quick profile
  // gives the printed and the scaled h different ones), and the paper profile trims the
  // uniform volumes above paper_uniform_max_level (rows beyond the document, no published
  // rate): those units are priced and marked, not run; with --levels every unit runs.
  s.units = [&t](const UnitScope& scope) {
    auto levels_of = [&](HReading r) -> const std::vector<int>& {
      if (scope.levels_given) return scope.levels;
      return scope.paper ? t.paper_levels : r == HReading::printed ? t.quick_printed : t.quick_scaled;
    };
    std::vector<int> all;
    for (HReading r : t.readings) all.insert(all.end(), levels_of(r).begin(), levels_of(r).end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    std::vector<StudyUnit> out;
    for (int k : all)
      for (HReading r : t.readings)
        for (Volumes v : {Volumes::voronoi, Volumes::uniform}) {
          const auto& lv = levels_of(r);
          if (std::find(lv.begin(), lv.end(), k) == lv.end()) continue;
          StudyUnit u{k, thesis_h(r, t.c, t.p, dx_of(k)), {h_reading_name(r), volumes_name(v), fmt(k)},
                      h_reading_name(r) + "/" + volumes_name(v)};
          if (scope.paper && !scope.levels_given && v == Volumes::uniform && k > t.paper_uniform_max_level)
            u.trimmed = "uniform volumes stop at 2^-" + fmt(t.paper_uniform_max_level) + " (beyond the document: no published rate)";
          out.push_back(std::move(u));
        }
    return out;
  };
  // The level's Voronoi volumes are computed once, for its first pass that uses them.
  s.price = [&t](UnitPricer& p, const StudyUnit& u) {
    if (u.key[1] == volumes_name(Volumes::voronoi) && !p.priced(t.program, "voronoi", u.level))
      p.add_voronoi(t.program, "voronoi", u.level);
    p.add_fused(t.program, u.variant, u.level, u.h, t.mix());
  };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) {
      const int k = rows.level(r);
      rows.put(rows.text(r, "h_reading") + "/" + rows.text(r, "volumes"), k, rows.v(r, "time_s"),
               rows.v(r, "pairs"));
      const double vs = rows.v(r, "voronoi_s");  // the level's Voronoi time, on each of its rows
      if (vs > 0) {
        auto& slot = out[{"voronoi", k}];
        slot.seconds = std::max(slot.seconds, vs);
        slot.pair_interactions = kNaN;
      }
    }
  };
  return s;
}

// A Poisson solve of Table 4.4's problem as the plan prices it: the Laplacian's set-up and
// the CG iterations of its (h rule, weight) at 2^-5 carried as 1/h, plus `extra` products
// (the right-hand side and residual check; the diagnostic's consistency).  The unit's key
// starts with the h rule and the weight.
void price_poisson_solve(UnitPricer& p, const std::string& study, const StudyUnit& su, int extra) {
  PlanUnit u = p.base(study, su.variant, su.level, su.h);
  const bool as = p.is_assembled(u);
  const double its = p.cal().poisson_its.at(su.key[0] + "/" + su.key[1]) * pde_h(parse_h_rule(su.key[0]), dx_of(5)) / u.h;
  u.products = its + extra;
  u.method = as ? "assembled" : "matrix_free";
  const double setup = p.laplacian_setup_s(u, as);
  u.time_s = setup + u.products * p.product_s(u, as);
  u.time_before_s = setup + u.products * p.product_before_s(u);
  u.mem_mib = p.pde_mib(u, as);
  u.basis = "setup + (CG its " + fmt(std::round(its)) + " + " + fmt(extra) + ") products";
  p.units().push_back(u);
}

// Table 4.4: per (h rule, weight, level) the Laplacian's set-up and a CG solve, its
// iterations carried from 2^-5 as 1/h.
RegisteredStudy poisson() {
  RegisteredStudy s = identity("thesis_table4_4", "thesis Figure 4.8, Table 4.4", "poisson", poisson_table().levels,
                               poisson_table().columns, {5, 6});
  s.files = {{.name = "thesis_table4_4",
              .rates = {{.name = "thesis_table4_4_rates", .input = "thesis_table4_4", .scored = true}}}};
  // Both readings of h in one file (the verdicts give each its slice); cellvol is the reading
  // V_i = dx^2; seeds 2, 3 at the coarse and the rate levels, and under V_i = dx^2 (the
  // identified volumes) seeds 2-5: a band that decides (five realizations).  Under V_i = dx^2
  // also the levels past the thesis (census.hpp: poisson_beyond), for seed 1 and the seeds
  // it names at the first of them; no published value exists there (gpm rate-levels).
  const StoreBeyond beyond = poisson_beyond();
  const std::vector<std::string> coarse = {"--levels", "5,6"}, rate_levels = {"--levels", "5,6,8,9"};
  s.store_files = {{.name = "thesis_table4_4", .slice = "all", .coarse = coarse, .readings = {"h10", "h15"}},
                   {.name = "thesis_table4_4_cellvol", .slice = "cell", .args = {"--volumes", "cell"},
                    .census = {"--levels", with_levels("5,6,7,8,9", beyond.levels)}, .coarse = coarse,
                    .readings = {"h10_cell", "h15_cell"}},
                   {.name = "thesis_table4_4_seed2", .slice = "seed2", .args = {"--seed", "2"},
                    .census = rate_levels, .coarse = coarse},
                   {.name = "thesis_table4_4_seed3", .slice = "seed3", .args = {"--seed", "3"},
                    .census = rate_levels, .coarse = coarse}};
  for (const char* seed : {"2", "3", "4", "5"})
    s.store_files.push_back({.name = std::string("thesis_table4_4_cellvol_seed") + seed,
                             .slice = std::string("cell_seed") + seed,
                             .args = {"--volumes", "cell", "--seed", seed},
                             .census = {"--levels", with_levels("5,6,8,9", beyond.levels_for(seed))},
                             .coarse = coarse});
  s.published = PublishedRates{
      .table = "thesis_table4_4", .file = "thesis_table4_4_long.tsv", .key = {"h_rule", "weight"},
      .printed_slice = "h10",
      .identified_slice = [](const PdeReading& r) {
        return h_rule_name(r.h_rule) + (r.volumes == PdeVolumes::cell ? "_cell" : "");
      },
      .split_by = "h_rule"};
  s.figures = {{.name = "thesis_fig4_8", .per_reading = true}};
  // A unit: one Laplacian and CG solve per (level, h rule, weight), the particles shared by
  // a level's units.
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels)
      for (HRule rule : pde_h_rules())
        for (auto& w : pde_weights())
          out.push_back({k, pde_h(rule, dx_of(k)), {h_rule_name(rule), w, fmt(k)}, h_rule_name(rule) + "/" + w});
    return out;
  };
  s.price = [](UnitPricer& p, const StudyUnit& su) { price_poisson_solve(p, "thesis_table4_4", su, 2); };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows)
      rows.put(rows.text(r, "h_rule") + "/" + rows.text(r, "weight"), rows.level(r), rows.v(r, "seconds"),
               rows.v(r, "nnz") * (rows.v(r, "cg_iterations") + 2));
  };
  return s;
}

// The data file of a heat table under an h rule (the catalog's two readings).
std::string heat_file(const HeatTable& hp, HRule rule) {
  return heat_study_name(hp) + (rule == HRule::h15 ? "_h15" : "");
}

// Tables 4.5–4.7 under both h rules: K = ⌈T/Δt₀⌉ steps, one product per step (M·U^k, which
// also serves the CG's initial and true residuals) plus (θ > 0) the CG iterations; the
// Laplacian's set-up once per (level, weight), not in the per-row seconds.
RegisteredStudy heat(const HeatTable& hp) {
  const std::string name = heat_file(hp, HRule::h10);
  RegisteredStudy s = identity(name, "thesis Table " + hp.table, "heat", {hp.quick, hp.paper}, heat_columns(), {5});
  s.program = "thesis_heat", s.fixed_args = {"--table", hp.table};
  // Each run also writes the rows of the series that never blew up (…_finite), which is what
  // its rate table reads; the h10 reading is the one the thesis prints.
  for (HRule rule : pde_h_rules()) {
    const std::string f = heat_file(hp, rule);
    s.files.push_back({.name = f,
                       .args = rule == HRule::h15 ? std::vector<std::string>{"--h-rule", "h15"} : std::vector<std::string>{},
                       .side_outputs = {{"--rates-input", f + "_finite"}},
                       .rates = {{.name = f + "_rates", .input = f + "_finite", .scored = rule == HRule::h10}}});
  }
  // One store file per set-up reading stored (h rule x volumes x time step), a slice each.
  for (const HeatStoreReading& r : heat_store_readings(hp.table)) {
    const PdeReading reading = PdeReading::named(r.reading);
    std::vector<std::string> args;
    if (reading.h_rule != HRule::h10) args.insert(args.end(), {"--h-rule", h_rule_name(reading.h_rule)});
    if (reading.dt_rule != DtRule::fit) args.insert(args.end(), {"--dt-rule", dt_rule_name(reading.dt_rule)});
    if (reading.volumes != PdeVolumes::lattice) args.insert(args.end(), {"--volumes", pde_volumes_name(reading.volumes)});
    const StoreBeyond beyond = heat_beyond(hp.table, r.reading);
    const std::string census = with_levels(r.census, beyond.levels);
    s.store_files.push_back(
        {.name = name + reading.file_suffix(), .slice = reading.name(), .args = args,
         .census = census.empty() ? std::vector<std::string>{} : std::vector<std::string>{"--levels", census},
         .coarse = {"--levels", "5"}, .readings = {reading.name()}});
    // Other jitter realizations of this reading at the coarse level and the rate levels: the
    // seed band of each rate (verdicts.cpp: slice "<reading>_seedN" beside "<reading>").
    for (const std::string& seed : heat_band_seeds(hp.table, r.reading)) {
      std::vector<std::string> seeded = args;
      seeded.insert(seeded.end(), {"--seed", seed});
      s.store_files.push_back({.name = name + reading.file_suffix() + "_seed" + seed,
                               .slice = reading.name() + "_seed" + seed, .args = seeded,
                               .census = {"--levels", with_levels("5," + hp.rate_levels, beyond.levels_for(seed))},
                               .coarse = {"--levels", "5"}});
    }
  }
  s.published = PublishedRates{.table = name, .file = name + "_long.tsv", .key = {"weight", "theta"},
                               .printed_slice = "h10",
                               .identified_slice = [](const PdeReading& r) { return r.name(); },
                               .finite_series = true};
  // Table 4.6's explicit (theta = 0) rates fix the number of steps, so h: the set-up rule's
  // fingerprint (paper/04-setup-rule.md).
  if (hp.table == "4.6") s.published->setup_fingerprint = {"theta", "0"};
  // The document's figure of the table (Figures 4.9–4.11), drawn in each reading.
  const std::map<std::string, std::string> figure = {{"4.5", "thesis_fig4_9"}, {"4.6", "thesis_fig4_10"}, {"4.7", "thesis_fig4_11"}};
  s.figures = {{.name = figure.at(hp.table), .scripts = {"figures/thesis_heat.gp"}, .per_reading = true}};
  // A unit: one series (weight, θ) at a level under an h rule (StudyUnit::part: in a make run
  // each rule writes its own data file), keyed as the data file's rows.  The series of one
  // (level, h rule, weight) share a Laplacian, set up once for the first of them.  Both h
  // rules run at every level of the profile: each is a reading the set-up rule weighs.
  s.units = [&hp](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels)
      for (HRule rule : pde_h_rules())
        for (auto& w : pde_weights())
          for (double th : hp.thetas) {
            StudyUnit u{k, pde_h(rule, dx_of(k)), {w, fmt(th), fmt(k)}, w + "/theta=" + fmt(th)};
            u.part = h_rule_name(rule);
            out.push_back(std::move(u));
          }
    return out;
  };
  s.price = [&hp](UnitPricer& p, const StudyUnit& su) {
    const HRule rule = parse_h_rule(su.part);
    const std::string study = heat_file(hp, rule), w = su.key[0];
    const int k = su.level;
    PlanUnit a = p.base(study, "setup/" + w, k, su.h);
    const bool as = p.is_assembled(a);
    a.method = as ? "assembled" : "matrix_free";
    a.time_s = p.laplacian_setup_s(a, as);
    a.time_before_s = a.time_s;
    a.mem_mib = p.pde_mib(a, as);
    a.recorded = false;
    a.basis = "Laplacian set-up (not in the rows' seconds)";
    if (!p.priced(study, a.variant, k)) p.units().push_back(a);
    const double th = parse_number(su.key[1], "theta"), K = p.heat_steps(hp.table, su.h);
    PlanUnit u = p.base(study, su.variant, k, su.h);
    const double its = p.heat_cg_its(hp.table, rule, w, th, su.h);
    const double stepped = K * (1 + its);
    u.method = a.method;
    u.mem_mib = a.mem_mib;
    u.time_before_s = stepped * p.product_before_s(u);
    if (p.heat_krylov_chosen(u, hp.table, th)) {
      // The default propagator (auto) runs it in the Krylov subspace its table's θ share
      // (one subspace per level, h rule, weight and volumes): its share of that.
      const double n = static_cast<double>(hp.thetas.size());
      u.products = p.heat_krylov_dim(u) / n;
      u.time_s = p.heat_krylov_s(u, as) / n;
      u.mem_mib = a.mem_mib + p.heat_krylov_mib(u);
      u.basis = "K=" + fmt(K) + " steps, Krylov m=" + fmt(std::round(p.heat_krylov_dim(u))) + " shared by " +
                fmt(hp.thetas.size()) + " series";
    } else {
      u.products = stepped;
      u.time_s = u.products * p.product_s(u, as);
      u.basis = "K=" + fmt(K) + " steps, " + fmt(std::round(its * 10) / 10) + " CG its/step";
    }
    p.units().push_back(u);
  };
  // A heat row does not record its non-zeros: its work is the steps done × products per
  // step (from its mean CG iterations) × the plan's non-zeros.
  s.recorded = [&hp](const std::string&, const TsvTable& d, const PlannedPairs& planned, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) {
      const std::string var = rows.text(r, "weight") + "/theta=" + rows.text(r, "theta");
      const int k = rows.level(r);
      const double th = rows.v(r, "theta");
      const double per_step = (th < 1 ? 1 : 0) + (th > 0 ? rows.v(r, "cg_mean_iterations") + 1 : 0);
      // A Krylov row: its share of the subspace's m products (the table's θ share one).
      const bool krylov = d.column("propagator") >= 0 && rows.text(r, "propagator") == "krylov";
      const double products = krylov
                                  ? rows.v(r, "subspace") / static_cast<double>(hp.thetas.size())
                                  : rows.v(r, "steps_done") * per_step;
      auto it = planned.find({var, k});
      rows.put(var, k, rows.v(r, "seconds"), it == planned.end() ? kNaN : it->second * products);
    }
  };
  return s;
}

// thesis_poisson_diagnostic: per (level, particle set, h rule, weight) one Laplacian, its
// consistency on u and a CG solve (Table 4.4's problem; the reasons chapter reads it).  The
// store holds the rate levels on the particle sets the reasons use; its check recomputes
// 2^-7 for one weight.
RegisteredStudy poisson_diagnostic_study() {
  RegisteredStudy s = identity("thesis_poisson_diagnostic", "thesis Table 4.4: where the error sits", "diagnostic",
                               poisson_diagnostic().levels, poisson_diagnostic().columns, {7});
  s.own_seeds = true;  // its particle sets are its --variants
  s.files = {{.name = "thesis_poisson_diagnostic"}};
  s.store_files = {{.name = "thesis_poisson_diagnostic", .slice = "all",
                    .census = {"--levels", "7,8,9", "--variants", "seed1,plain,seed1_cell,plain_cell"},
                    .coarse = {"--levels", "7", "--weights", "quartic_polynomial", "--variants",
                               "seed1,plain,seed1_cell"}}};
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels)
      for (const ParticleSet& var : poisson_diagnostic().variants)
        for (HRule rule : pde_h_rules())
          for (auto& w : pde_weights())
            out.push_back({k, pde_h(rule, dx_of(k)), {h_rule_name(rule), w, fmt(k), var.name},
                           h_rule_name(rule) + "/" + w + "/" + var.name});
    return out;
  };
  // Priced as Table 4.4's solve of the same h rule and weight, plus one product for the
  // consistency.
  s.price = [](UnitPricer& p, const StudyUnit& su) { price_poisson_solve(p, "thesis_poisson_diagnostic", su, 3); };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows)
      rows.put(rows.text(r, "h_rule") + "/" + rows.text(r, "weight") + "/" + rows.text(r, "variant"), rows.level(r),
               rows.v(r, "seconds"), kNaN);
  };
  return s;
}

// core_voronoi: the plain grid once per level, the jittered grid per seed.
RegisteredStudy voronoi() {
  RegisteredStudy s = identity("core_voronoi", "covering radius (imoto §5, thesis Ch. 4)", "core", voronoi_study().levels,
                               voronoi_study().columns, {5});
  s.own_seeds = true;  // --seeds, a list of its own
  s.files = {{.name = "core_voronoi"}};
  // The store holds the paper levels (2^-12: 2.4e7 particles, about 4 GB); its check
  // recomputes 2^-5.
  s.store_files = {{.name = "core_voronoi", .slice = "all", .coarse = {"--levels", "5"}}};
  // A unit: a level, the plain grid and the jittered grid of every seed (--seeds; the plan
  // prices the default ones, as a make run uses them).
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels) out.push_back({k, 0, {fmt(k)}, "level"});
    return out;
  };
  s.price = [](UnitPricer& p, const StudyUnit& u) {
    p.add_voronoi("core_voronoi", "grid", u.level);
    for (int seed : voronoi_study().seeds) p.add_voronoi("core_voronoi", "jittered/seed=" + fmt(seed), u.level);
  };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) {
      const std::string& dist = rows.text(r, "distribution");
      rows.put(dist == "grid" ? std::string("grid") : dist + "/seed=" + rows.text(r, "seed"), rows.level(r),
               rows.v(r, "time_s"), kNaN);
    }
  };
  return s;
}

}  // namespace

std::vector<std::string> PublishedRates::rate_key() const {
  std::vector<std::string> out;
  for (auto& k : key)
    if (k != split_by) out.push_back(k);
  return out;
}

const std::vector<std::string>& row_provenance_columns() {
  static const std::vector<std::string> c = {"code", "made_on", "checked", "seal"};
  return c;
}

std::vector<std::string> RegisteredStudy::header() const {
  std::vector<std::string> h = columns;
  for (auto& c : row_provenance_columns()) h.push_back(c);
  return h;
}

const StoreFile* RegisteredStudy::find_store_file_of(const std::string& reading) const {
  if (!published || !published->identified_slice) return nullptr;
  const std::string slice = published->identified_slice(PdeReading::named(reading));
  for (const StoreFile& f : store_files)
    if (std::find(f.readings.begin(), f.readings.end(), slice) != f.readings.end()) return &f;
  return nullptr;
}

const StoreFile& RegisteredStudy::store_file_of(const std::string& reading) const {
  if (!published || !published->identified_slice)
    throw InputError("study '" + name + "' keeps no set-up readings in the store");
  if (const StoreFile* f = find_store_file_of(reading)) return *f;
  throw InputError("study '" + name + "' stores no file of the reading '" + reading + "'");
}

std::vector<std::string> RegisteredStudy::command_args(const std::vector<std::string>& file_args) const {
  std::vector<std::string> a = fixed_args;
  a.insert(a.end(), file_args.begin(), file_args.end());
  return a;
}

void StudyRegistry::add(RegisteredStudy s) {
  if (!s.units || !s.price) throw InputError("study '" + s.name + "' lists no units or no price for them");
  for (auto& o : studies_) {
    if (o.name == s.name) throw InputError("study '" + s.name + "' is registered twice");
    for (auto& f : s.files)
      for (auto& g : o.files)
        if (f.name == g.name) throw InputError("data file '" + f.name + "' of study '" + s.name +
                                               "' is already written by '" + o.name + "'");
  }
  studies_.push_back(std::move(s));
}

const RegisteredStudy& StudyRegistry::study(const std::string& name) const {
  std::string valid;
  for (auto& s : studies_) {
    if (s.name == name) return s;
    valid += (valid.empty() ? "" : ", ") + s.name;
  }
  throw InputError("unknown study '" + name + "'; valid: " + valid);
}

const RegisteredStudy& StudyRegistry::study_of_file(const std::string& file) const {
  for (auto& s : studies_)
    for (auto& f : s.files)
      if (f.name == file) return s;
  throw InputError("no registered study writes the data file '" + file + "'");
}

TsvTable store_file_table(const StudyRegistry& registry) {
  TsvTable t;
  t.columns = {"study", "file", "program", "args", "census", "coarse", "slice"};
  for (auto& s : registry)
    for (auto& f : s.store_files) {
      TsvRow row = t.named_row();
      row["study"] = s.name, row["file"] = f.name, row["program"] = s.program;
      row["args"] = join(s.command_args(f.args), " "), row["census"] = join(f.census, " ");
      row["coarse"] = join(f.coarse, " "), row["slice"] = f.slice;
      t.add_row(row);
    }
  return t;
}

const StudyRegistry& study_registry() {
  static const StudyRegistry r = [] {
    StudyRegistry v;
    v.add(imoto());
    for (auto& t : thesis_table_specs()) v.add(thesis_truncation(t));
    v.add(poisson());
    for (auto& hp : heat_tables()) v.add(heat(hp));
    v.add(voronoi());
    v.add(poisson_diagnostic_study());
    return v;
  }();
  return r;
}

const RegisteredStudy& setup_fingerprint_study(const StudyRegistry& registry) {
  const RegisteredStudy* found = nullptr;
  for (auto& s : registry)
    if (s.published && !s.published->setup_fingerprint.first.empty()) {
      if (found) throw InputError("two studies carry the set-up fingerprint: " + found->name + ", " + s.name);
      found = &s;
    }
  if (!found) throw InputError("no registered study carries the set-up fingerprint");
  return *found;
}

const RegisteredStudy& registered_study_of_file(const std::string& file) {
  return study_registry().study_of_file(file);
}

}  // namespace gpm
