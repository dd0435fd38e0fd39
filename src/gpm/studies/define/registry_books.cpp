#include "gpm/studies/define/registry_books.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/census.hpp"

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

}  // namespace

void imoto_books(RegisteredStudy& s) {
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
  s.price = [](UnitPricer& p, const StudyUnit& u) { p.add_fused("imoto_fig5_table1", u.variant, u.level, u.h, "imoto9"); };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows) rows.put("m=" + rows.text(r, "m"), rows.level(r), rows.v(r, "time_s"), rows.v(r, "pairs"));
  };
}

void truncation_books(RegisteredStudy& s, const ThesisTableSpec& t) {
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
}

void poisson_books(RegisteredStudy& s) {
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
  // Past plain CG's reach (2^-11, issue 59): the same realizations solved by τ-PCG, in files
  // of their own (the solver's header line keeps their rows apart from plain CG's); the error
  // constants read them as further levels of the cellvol series (judge/error_constants.hpp).
  // Their check recomputes the cheap 2^-5 h15 units, solved the same way; each census names
  // the 2^-11 units stored so far (h15 first; h10 at 2^-11 is about 70 min a unit here).
  const std::vector<std::string> tau_coarse = {"--levels", "5", "--only", "h15"};
  for (const auto& [seed, census] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"1", {"--levels", "5,11", "--only", "h15"}},
           {"2", {"--levels", "5,11", "--only", "h15"}},
           {"3", {"--levels", "5,11", "--only", "h15"}}}) {
    const std::string tail = seed == "1" ? "" : "_seed" + seed;
    s.store_files.push_back({.name = "thesis_table4_4_cellvol_tau" + tail,
                             .slice = "cell_tau" + tail,
                             .args = {"--volumes", "cell", "--solver", "tau", "--seed", seed},
                             .census = census,
                             .coarse = tau_coarse});
  }
  s.published = PublishedRates{
      .table = "thesis_table4_4", .file = "thesis_table4_4_long.tsv", .key = {"h_rule", "weight"},
      .printed_slice = "h10",
      .identified_slice = [](const PdeReading& r) {
        return h_rule_name(r.h_rule) + (r.volumes == PdeVolumes::cell ? "_cell" : "");
      },
      .split_by = "h_rule"};
  s.figures = {{.name = "thesis_fig4_8", .per_reading = true}};
  s.price = [](UnitPricer& p, const StudyUnit& su) { price_poisson_solve(p, "thesis_table4_4", su, 2); };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows)
      rows.put(rows.text(r, "h_rule") + "/" + rows.text(r, "weight"), rows.level(r), rows.v(r, "seconds"),
               rows.v(r, "nnz") * (rows.v(r, "cg_iterations") + 2));
  };
}

void heat_books(RegisteredStudy& s, const HeatTable& hp) {
  const std::string name = s.name;
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
}

void poisson_diagnostic_books(RegisteredStudy& s) {
  s.files = {{.name = "thesis_poisson_diagnostic"}};
  s.store_files = {{.name = "thesis_poisson_diagnostic", .slice = "all",
                    .census = {"--levels", "7,8,9", "--variants", "seed1,plain,seed1_cell,plain_cell"},
                    .coarse = {"--levels", "7", "--weights", "quartic_polynomial", "--variants",
                               "seed1,plain,seed1_cell"}}};
  // Priced as Table 4.4's solve of the same h rule and weight, plus one product for the
  // consistency.
  s.price = [](UnitPricer& p, const StudyUnit& su) { price_poisson_solve(p, "thesis_poisson_diagnostic", su, 3); };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    const Rows rows{d, out};
    for (auto& r : d.rows)
      rows.put(rows.text(r, "h_rule") + "/" + rows.text(r, "weight") + "/" + rows.text(r, "variant"), rows.level(r),
               rows.v(r, "seconds"), kNaN);
  };
}

void voronoi_books(RegisteredStudy& s) {
  s.files = {{.name = "core_voronoi"}};
  // The store holds the paper levels (2^-12: 2.4e7 particles, about 4 GB); its check
  // recomputes 2^-5.
  s.store_files = {{.name = "core_voronoi", .slice = "all", .coarse = {"--levels", "5"}}};
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
}

}  // namespace gpm
