// plan: what a profile will cost, before any study runs.  For every modelled study and
// level it prints the particles, the predicted pair interactions, time and peak memory
// (study_plan.hpp: the units, the calibration, the memory model), and writes
//   --out      one row per unit of work (a fused pass, a Voronoi decomposition, a Poisson
//              solve, a heat run), the calibration in the header;
//   --summary  one row per (study, level), a row per study (level = all) and the total.
// The times come from a calibration of a few seconds on the spot (the studies' own code
// paths on small levels), or from an earlier plan file's header (--calibration), so that
// the quick and paper plans of one `make` share one calibration.
//
//   plan --profile paper --out data/paper/plan.tsv --summary data/paper/plan_summary.tsv
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/io/progress.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/plan/study_plan.hpp"

using namespace gpm;

namespace {

std::string human_time(double s) {
  char b[32];
  if (s < 120) std::snprintf(b, sizeof b, "%.1f s", s);
  else if (s < 7200) std::snprintf(b, sizeof b, "%.1f min", s / 60);
  else std::snprintf(b, sizeof b, "%.1f h", s / 3600);
  return b;
}

// Per (study, level) and per study: sums of time and pair interactions, largest memory.
struct Agg {
  int units = 0;
  double N = 0, pair_work = 0, time_s = 0, peak_mib = 0;
  std::set<std::string> methods;
  // before: the unit's time with the full-matrix product (PlanUnit::time_before_s).
  void add(const PlanUnit& u, bool before = false) {
    ++units;
    N = std::max(N, u.N);
    pair_work += u.method == "voronoi" ? 0 : u.pairs * std::max(1.0, u.products);
    time_s += before ? u.time_before_s : u.time_s;
    peak_mib = std::max(peak_mib, u.mem_mib);
    methods.insert(u.method);
  }
  std::string method_list() const {
    std::string s;
    for (auto& m : methods) s += (s.empty() ? "" : "+") + m;
    return s;
  }
};

int body(int argc, char** argv) {
  Args a("plan",
         "Predicted pair interactions, time and peak memory of every modelled study and level\n"
         "of a profile, printed before anything runs (see src/gpm/studies/plan/study_plan.hpp).");
  a.opt("profile", "quick", "quick or paper")
      .output("out", "", "TSV: one row per unit of work (required)")
      .output("summary", "", "TSV: per (study, level), per study and total (optional)")
      .opt("calibration", "", "reuse the calibration in the header of this earlier plan file")
      .output("calibration-table", "", "TSV: the calibration as a readable table (optional)")
      .output("heat-matrix", "", "TSV: the heat tables' whole reading matrix priced alone, per\n"
                                 "  reading and batched (heat_matrix_costs; optional)")
      .opt("bench", "data/bench/kernel.tsv", "make bench's kernel file, shown beside the "
                                             "calibration when present")
      .flag("quiet", "do not print the table");
  a.parse(argc, argv);
  a.required("out");
  const Profile profile = parse_profile(a.str("profile"));
  const Stopwatch wall;

  Calibration cal;
  if (!a.str("calibration").empty()) {
    if (!std::filesystem::exists(a.str("calibration")))
      throw InputError("--calibration: no file " + a.str("calibration"));
    cal = Calibration::read(TsvTable::load(a.str("calibration")));
  } else {
    cal = calibrate();
  }
  const std::vector<PlanUnit> units = plan_units(profile, cal);

  // --- The units file. ------------------------------------------------------------------
  TsvTable t;
  t.set("program", "plan");
  t.set("profile", profile_name(profile));
  t.set("pairs_note", "neighbour pairs of one pass (fused) / non-zeros of the Laplacian "
                      "(assembled, matrix_free): (1/dx^2) * A(h)/dx^2, A = mean |B(x,h) & Omega_H|");
  t.set("time_note", "predicted wall time of the unit as the study records it (recorded = yes)");
  t.set("memory_note", "predicted peak resident size of the study program during the unit");
  cal.write(t);
  add_provenance(t);
  t.columns = {"study", "variant", "level", "dx", "h", "N", "pairs", "products", "method",
               "time_s", "peak_mib", "recorded", "trimmed", "basis"};
  t.set("trimmed_note", "a unit the profile skips (a trim of the study catalog: its reason); "
                        "not in the totals, summed in the summary's 'trimmed' row");
  // Run units per (study, level), per study and in all; trimmed units apart.
  std::map<std::string, std::map<int, Agg>> per_level, per_level_trimmed;
  std::map<std::string, Agg> per_study;
  // before_trims: every unit at today's speed; before: also the full-matrix product.
  Agg all, trimmed, before_trims, before;
  for (auto& u : units) {
    TsvRow row = t.named_row();
    row["study"] = u.study, row["variant"] = u.variant, row["level"] = fmt(u.level);
    row["dx"] = fmt(u.dx), row["h"] = fmt(u.h), row["N"] = fmt(u.N), row["pairs"] = fmt(u.pairs);
    row["products"] = fmt(u.products), row["method"] = u.method, row["time_s"] = fmt(u.time_s);
    row["peak_mib"] = fmt(u.mem_mib), row["recorded"] = u.recorded ? "yes" : "no";
    row["trimmed"] = u.trimmed.empty() ? "no" : u.trimmed, row["basis"] = u.basis;
    t.add_row(row);
    before_trims.add(u);
    before.add(u, true);
    if (!u.trimmed.empty()) {
      per_level_trimmed[u.study][u.level].add(u);
      trimmed.add(u);
      continue;
    }
    per_level[u.study][u.level].add(u);
    per_study[u.study].add(u);
    all.add(u);
  }
  t.set("total_time_s", all.time_s);
  t.set("trimmed_time_s", trimmed.time_s);
  t.set("peak_mib", all.peak_mib);
  t.set("wall_time_s", wall.seconds());
  t.save(a.str("out"));

  // --- The summary. -------------------------------------------------------------------------
  TsvTable s;
  s.set("program", "plan --summary");
  s.set("profile", profile_name(profile));
  s.set("units_file", a.str("out"));
  s.set("calibration_source", cal.source);
  s.set("pair_interactions_note", "sum over units of pairs x max(1, products) (Voronoi: 0)");
  add_provenance(s);
  s.set("trimmed_note", "trimmed = yes: units the profile skips (study catalog trims), not in "
                        "the study and total rows; 'before trims' = total + trimmed; 'before' = "
                        "before trims with the full-matrix Laplacian product (the storage before "
                        "the symmetric half)");
  s.columns = {"study", "level", "units", "N", "pair_interactions", "time_s", "peak_mib", "method",
               "trimmed"};
  auto row = [&](const std::string& study, const std::string& level, const Agg& g, bool trim) {
    TsvRow r = s.named_row();
    r["study"] = study, r["level"] = level, r["units"] = fmt(g.units), r["N"] = fmt(g.N);
    r["pair_interactions"] = fmt(g.pair_work), r["time_s"] = fmt(g.time_s);
    r["peak_mib"] = fmt(g.peak_mib), r["method"] = g.method_list(), r["trimmed"] = trim ? "yes" : "no";
    s.add_row(r);
  };
  for (auto& study : planned_studies()) {
    for (auto& [k, g] : per_level[study]) row(study, fmt(k), g, false);
    for (auto& [k, g] : per_level_trimmed[study]) row(study, fmt(k), g, true);
    row(study, "all", per_study[study], false);
  }
  row("total", "all", all, false);
  if (trimmed.units > 0) {
    row("trimmed (not run)", "all", trimmed, true);
    row("total before trims", "all", before_trims, false);
  }
  row("total before", "all", before, false);
  // What P processes could do with the same units, as the MPI runner divides them
  // (runner.hpp): a fused truncation pass is shared, each rank taking 1/P of its targets;
  // Voronoi volumes are computed by every rank that needs them (counted on every process);
  // a Poisson or heat unit runs whole on one rank (here longest first to the least loaded,
  // the best such dealing; the runner deals in loop order by a rough cost, which can fall
  // short of it).  Each at this machine's calibrated speed: a prediction, not a measurement.
  std::vector<double> whole_units;
  double shared_s = 0, every_rank_s = 0;
  for (auto& u : units) {
    if (!u.trimmed.empty()) continue;
    if (u.method == "fused") shared_s += u.time_s;
    else if (u.method == "voronoi") every_rank_s += u.time_s;
    else whole_units.push_back(u.time_s);
  }
  std::sort(whole_units.rbegin(), whole_units.rend());
  const std::vector<int> ranks = {2, 16, 64};
  std::vector<double> makespan;
  for (int P : ranks) {
    std::vector<double> load(P, every_rank_s + shared_s / P);
    for (double tu : whole_units) *std::min_element(load.begin(), load.end()) += tu;
    makespan.push_back(*std::max_element(load.begin(), load.end()));
  }
  s.set("processes_note", "'P processes' (MPI runner): fused passes shared over the P ranks "
                          "(1/P of the targets each), Voronoi volumes on every rank, Poisson "
                          "and heat units whole, longest first to the least loaded (the "
                          "runner deals them in loop order by a rough cost); bounded below by "
                          "the longest whole unit (" +
                              human_time(whole_units.empty() ? 0 : whole_units[0]) + ")");
  for (std::size_t i = 0; i < ranks.size(); ++i) {
    Agg g = all;
    g.time_s = makespan[i];
    row(fmt(ranks[i]) + " processes", "all", g, false);
  }
  if (!a.str("summary").empty()) s.save(a.str("summary"));

  // --- The heat reading matrix: every reading of Tables 4.5-4.7, priced three ways, beside
  // what the profile runs of those tables today (its one reading per h rule, trims applied).
  const std::vector<HeatMatrixCost> hm = heat_matrix_costs(profile, cal);
  TsvTable hmt;
  hmt.set("program", "plan --heat-matrix");
  hmt.set("profile", profile_name(profile));
  hmt.set("calibration_source", cal.source);
  hmt.set("readings", "h10, h15 x volumes lattice (A.10), cell (dx^2) x dt = T/K, dt = dt0: 8 per table");
  hmt.set("columns_note", "alone: every series streams the Laplacian by itself; per_reading: one run per "
                          "reading, its theta together; batched: every series of a (level, h rule, "
                          "weight) in one block stream; propagated: batched, each series by the default "
                          "propagator (auto: the Krylov subspace where its stepped products exceed the "
                          "subspace's dimension, heat_krylov.hpp); catalog: the units of these tables the "
                          "profile runs today (h10 and h15 with (A.10) volumes and dt = T/K, by the default "
                          "propagator)");
  add_provenance(hmt);
  hmt.columns = {"table", "series", "alone_s", "per_reading_s", "batched_s", "propagated_s", "catalog_s",
                 "batched_over_per_reading", "propagated_over_batched"};
  auto heat_row = [&](const HeatMatrixCost& m, double catalog) {
    TsvRow row = hmt.named_row();
    row["table"] = m.table, row["series"] = fmt(m.series), row["alone_s"] = fmt(m.alone_s);
    row["per_reading_s"] = fmt(m.per_reading_s), row["batched_s"] = fmt(m.batched_s);
    row["propagated_s"] = fmt(m.propagated_s);
    row["catalog_s"] = fmt(catalog), row["batched_over_per_reading"] = fmt(m.batched_s / m.per_reading_s);
    row["propagated_over_batched"] = fmt(m.propagated_s / m.batched_s);
    hmt.add_row(row);
  };
  HeatMatrixCost total{"all", 0, 0, 0, 0, 0};
  double catalog_total = 0;
  for (auto& m : hm) {
    double catalog = 0;
    std::string study = "thesis_table" + m.table;
    std::replace(study.begin(), study.end(), '.', '_');
    for (auto& u : units)
      if (u.trimmed.empty() && (u.study == study || u.study == study + "_h15")) catalog += u.time_s;
    heat_row(m, catalog);
    total.series += m.series, total.alone_s += m.alone_s, total.per_reading_s += m.per_reading_s;
    total.batched_s += m.batched_s, total.propagated_s += m.propagated_s, catalog_total += catalog;
  }
  heat_row(total, catalog_total);
  hmt.set("profile_total_today_s", all.time_s);
  hmt.set("profile_total_with_batched_matrix_s", all.time_s - catalog_total + total.batched_s);
  hmt.set("profile_total_with_propagated_matrix_s", all.time_s - catalog_total + total.propagated_s);
  if (!a.str("heat-matrix").empty()) hmt.save(a.str("heat-matrix"));

  // --- The calibration as a table (quantity, value, unit). --------------------------------
  if (!a.str("calibration-table").empty()) {
    TsvTable c;
    c.set("program", "plan --calibration-table");
    c.set("profile", profile_name(profile));
    c.set("calibration_source", cal.source);
    add_provenance(c);
    c.columns = {"quantity", "value", "unit"};
    // Every row is a (quantity, value, unit) triple: one named row here, so the calls below
    // stay one line each and a change of c.columns cannot swap value and unit.
    auto add = [&](const std::string& quantity, const std::string& value, const std::string& unit) {
      TsvRow row = c.named_row();
      row["quantity"] = quantity, row["value"] = value, row["unit"] = unit;
      c.add_row(row);
    };
    for (auto& [mix, pc] : cal.fused) {
      add("fused pass " + mix + ": pair rate", fmt(1 / pc.per_pair_s), "pairs/s");
      add("fused pass " + mix + ": per target", fmt(pc.per_target_s * 1e6), "us");
    }
    add("Voronoi volumes", fmt(cal.voronoi_s_per_particle * 1e6), "us/particle");
    add("Laplacian set-up", fmt(cal.setup_s_per_nnz * 1e9), "ns/non-zero");
    add("assembled product (symmetric half)", fmt(cal.spmv_s_per_nnz * 1e9), "ns/non-zero");
    add("assembled product (full matrix)", fmt(cal.spmv_full_s_per_nnz * 1e9), "ns/non-zero");
    add("matrix-free product: pair rate", fmt(1 / cal.matrix_free.per_pair_s), "pairs/s");
    add("matrix-free product: per target", fmt(cal.matrix_free.per_target_s * 1e6), "us");
    for (auto& [w, r] : cal.block_ratio)
      add("block product of " + fmt(w) + " columns (time per vector)", fmt(r), "x single product");
    add("calibration wall time", fmt(cal.seconds), "s");
    add("calibration CPU time", fmt(cal.cpu_seconds), "s");
    add("load average before / after", fmt(cal.load_before) + " / " + fmt(cal.load_after), "");
    if (std::filesystem::exists(a.str("bench"))) {
      const TsvTable b = TsvTable::load(a.str("bench"));
      const int cv = b.column("variant"), ct = b.column("threads"), cr = b.column("pairs_per_s");
      if (cv >= 0 && ct >= 0 && cr >= 0)
        for (auto& r : b.rows)
          if (r[cv] == "fused9" && r[ct] == "2")
            add("make bench fused9, 2 threads (" + b.get("written_utc").value_or("?") + ")", r[cr],
                "pairs/s");
    }
    c.save(a.str("calibration-table"));
  }

  // --- The printed table. -----------------------------------------------------------------
  if (!a.has("quiet")) {
    std::printf("plan, profile %s (%s: %.1f s wall, %.1f s CPU, load %.1f; %zu units)\n",
                profile_name(profile).c_str(), cal.source.c_str(), cal.seconds, cal.cpu_seconds,
                cal.load_before, units.size());
    std::printf("%-22s %5s %5s %11s %11s %12s %10s  %s\n", "study", "level", "units", "N",
                "pair inter.", "time", "peak MiB", "method");
    for (auto& study : planned_studies()) {
      for (auto& [k, g] : per_level[study])
        std::printf("%-22s %5d %5d %11.4g %11.4g %12s %10.0f  %s\n", study.c_str(), k, g.units,
                    g.N, g.pair_work, human_time(g.time_s).c_str(), g.peak_mib,
                    g.method_list().c_str());
      const Agg& g = per_study[study];
      std::printf("%-22s %5s %5d %11s %11.4g %12s %10.0f\n", study.c_str(), "all", g.units, "",
                  g.pair_work, human_time(g.time_s).c_str(), g.peak_mib);
    }
    std::printf("%-22s %5s %5d %11s %11.4g %12s %10.0f\n", "TOTAL", "", all.units, "",
                all.pair_work, human_time(all.time_s).c_str(), all.peak_mib);
    if (trimmed.units > 0) {
      for (auto& study : planned_studies())
        for (auto& [k, g] : per_level_trimmed[study])
          std::printf("  trimmed: %-13s %5d %5d %11.4g %11.4g %12s\n", study.c_str(), k, g.units,
                      g.N, g.pair_work, human_time(g.time_s).c_str());
      std::printf("%-22s %5s %5d %11s %11.4g %12s   (TOTAL %.2fx less)\n", "BEFORE TRIMS", "",
                  before_trims.units, "", before_trims.pair_work,
                  human_time(before_trims.time_s).c_str(),
                  before_trims.time_s / std::max(1e-9, all.time_s));
    }
    std::printf("%-22s %5s %5d %11s %11.4g %12s   (TOTAL %.2fx less: trims %.2fx, half storage %.2fx)\n",
                "BEFORE (+ full matrix)", "", before.units, "", before.pair_work,
                human_time(before.time_s).c_str(), before.time_s / std::max(1e-9, all.time_s),
                before_trims.time_s / std::max(1e-9, all.time_s),
                before.time_s / std::max(1e-9, before_trims.time_s));
    for (std::size_t i = 0; i < ranks.size(); ++i)
      std::printf("%-22s %5s %5s %11s %11s %12s   (predicted: fused passes shared, the rest dealt whole)\n",
                  (fmt(ranks[i]) + " PROCESSES").c_str(), "", "", "", "",
                  human_time(makespan[i]).c_str());
    std::printf("HEAT READING MATRIX (%d series): alone %s, per reading %s, batched %s; the profile "
                "runs %s of these tables today; whole profile %s -> %s with the matrix batched\n",
                total.series, human_time(total.alone_s).c_str(), human_time(total.per_reading_s).c_str(),
                human_time(total.batched_s).c_str(), human_time(catalog_total).c_str(),
                human_time(all.time_s).c_str(), human_time(all.time_s - catalog_total + total.batched_s).c_str());
    std::printf("wrote %s%s%s\n", a.str("out").c_str(), a.str("summary").empty() ? "" : " and ",
                a.str("summary").c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("plan", body, argc, argv); }
