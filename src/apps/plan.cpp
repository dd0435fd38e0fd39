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
#include "gpm/studies/define/registry.hpp"
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

// A study's entry in a per-study map, or an empty one: the plan's tables list every planned
// study, including one whose units were all trimmed.
template <class Map>
const typename Map::mapped_type& entry(const Map& m, const std::string& study) {
  static const typename Map::mapped_type none{};
  const auto it = m.find(study);
  return it == m.end() ? none : it->second;
}

// The program: a plan is made in four steps (calibrate, units, totals, outputs) and each
// output is written by its own step, in the order a reader of the plan files meets them.
class Plan {
 public:
  Plan(int argc, char** argv) : a_("plan",
         "Predicted pair interactions, time and peak memory of every modelled study and level\n"
         "of a profile, printed before anything runs (see src/gpm/studies/plan/study_plan.hpp).") {
    declare_options();
    a_.parse(argc, argv);
    a_.required("out");
    profile_ = parse_profile(a_.str("profile"));
    scope_.study = a_.str("study");
    if (!scope_.study.empty()) study_registry().study(scope_.study);  // an unknown one, before any work
    if (!a_.str("levels").empty()) scope_.levels = levels_option(a_, profile_, {}, {}, 3, 13);
    if (!scope_.levels.empty() && scope_.study.empty())
      throw InputError("--levels " + a_.str("levels") + ": name the study it prices (--study)");
  }

  int run() {
    calibrate_or_reuse();
    units_ = plan_units(profile_, cal_, study_registry(), scope_);
    write_units();
    write_summary();
    write_heat_matrix();
    write_calibration_table();
    if (!a_.has("quiet")) print();
    return 0;
  }

 private:
  Args a_;
  Profile profile_{};
  PlanScope scope_;
  Stopwatch wall_;
  Calibration cal_;
  std::vector<PlanUnit> units_;
  // Run units per (study, level), per study and in all; trimmed units apart.
  std::map<std::string, std::map<int, Agg>> per_level_, per_level_trimmed_;
  std::map<std::string, Agg> per_study_;
  // before_trims: every unit at today's speed; before: also the full-matrix product.
  Agg all_, trimmed_, before_trims_, before_;
  // What P processes would take (the summary's "P processes" rows).
  const std::vector<int> ranks_ = {2, 16, 64};
  std::vector<double> makespan_;
  // The heat reading matrix in all, and what the profile runs of those tables today.
  HeatMatrixCost heat_total_{"all", 0, 0, 0, 0, 0};
  double catalog_total_ = 0;

  void declare_options() {
    a_.opt("profile", "quick", "quick or paper")
        .output("out", "", "TSV: one row per unit of work (required)")
        .output("summary", "", "TSV: per (study, level), per study and total (optional)")
        .opt("calibration", "", "reuse the calibration in the header of this earlier plan file")
        .output("calibration-table", "", "TSV: the calibration as a readable table (optional)")
        .output("heat-matrix", "", "TSV: the heat tables' whole reading matrix priced alone, per\n"
                                   "  reading and batched (heat_matrix_costs; optional)")
        .opt("bench", "data/bench/kernel.tsv", "make bench's kernel file, shown beside the "
                                               "calibration when present")
        .flag("quiet", "do not print the table")
        .opt("study", "", "price this study only (gpm study --list names them)")
        .opt("levels", "", "with --study: these comma-separated levels instead of the profile's, every\n"
                           "  part of the study at them (e.g. levels past the documents before running them)");
  }

  // A few seconds of the studies' own code paths on small levels, or an earlier plan's header.
  void calibrate_or_reuse() {
    if (!a_.str("calibration").empty()) {
      if (!std::filesystem::exists(a_.str("calibration")))
        throw InputError("--calibration: no file " + a_.str("calibration"));
      cal_ = Calibration::read(TsvTable::load(a_.str("calibration")));
    } else {
      cal_ = calibrate();
    }
  }

  // One row per unit of work, the calibration in the header; the totals on the way.
  void write_units() {
    TsvTable t;
    t.set("program", "plan");
    t.set("profile", profile_name(profile_));
    t.set("pairs_note", "neighbour pairs of one pass (fused) / non-zeros of the Laplacian "
                        "(assembled, matrix_free): (1/dx^2) * A(h)/dx^2, A = mean |B(x,h) & Omega_H|");
    t.set("time_note", "predicted wall time of the unit as the study records it (recorded = yes)");
    t.set("memory_note", "predicted peak resident size of the study program during the unit");
    cal_.write(t);
    add_provenance(t);
    t.columns = {"study", "variant", "level", "dx", "h", "N", "pairs", "products", "method",
                 "time_s", "peak_mib", "recorded", "trimmed", "basis"};
    t.set("trimmed_note", "a unit the profile skips (a trim of the study catalog: its reason); "
                          "not in the totals, summed in the summary's 'trimmed' row");
    for (auto& u : units_) {
      TsvRow row = t.named_row();
      row["study"] = u.study, row["variant"] = u.variant, row["level"] = fmt(u.level);
      row["dx"] = fmt(u.dx), row["h"] = fmt(u.h), row["N"] = fmt(u.N), row["pairs"] = fmt(u.pairs);
      row["products"] = fmt(u.products), row["method"] = u.method, row["time_s"] = fmt(u.time_s);
      row["peak_mib"] = fmt(u.mem_mib), row["recorded"] = u.recorded ? "yes" : "no";
      row["trimmed"] = u.trimmed.empty() ? "no" : u.trimmed, row["basis"] = u.basis;
      t.add_row(row);
      before_trims_.add(u);
      before_.add(u, true);
      if (!u.trimmed.empty()) {
        per_level_trimmed_[u.study][u.level].add(u);
        trimmed_.add(u);
        continue;
      }
      per_level_[u.study][u.level].add(u);
      per_study_[u.study].add(u);
      all_.add(u);
    }
    t.set("total_time_s", all_.time_s);
    t.set("trimmed_time_s", trimmed_.time_s);
    t.set("peak_mib", all_.peak_mib);
    t.set("wall_time_s", wall_.seconds());
    t.save(a_.str("out"));
  }

  // One row per (study, level), per study, the totals, and what P processes would take.
  void write_summary() {
    TsvTable s;
    s.set("program", "plan --summary");
    s.set("profile", profile_name(profile_));
    s.set("units_file", a_.str("out"));
    s.set("calibration_source", cal_.source);
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
      for (auto& [k, g] : entry(per_level_, study)) row(study, fmt(k), g, false);
      for (auto& [k, g] : entry(per_level_trimmed_, study)) row(study, fmt(k), g, true);
      row(study, "all", entry(per_study_, study), false);
    }
    row("total", "all", all_, false);
    if (trimmed_.units > 0) {
      row("trimmed (not run)", "all", trimmed_, true);
      row("total before trims", "all", before_trims_, false);
    }
    row("total before", "all", before_, false);
    // What P processes could do with the same units, as the MPI runner divides them
    // (runner.hpp): a fused truncation pass is shared, each rank taking 1/P of its targets;
    // Voronoi volumes are computed by every rank that needs them (counted on every process);
    // a Poisson or heat unit runs whole on one rank (here longest first to the least loaded,
    // the best such dealing; the runner deals in loop order by a rough cost, which can fall
    // short of it).  Each at this machine's calibrated speed: a prediction, not a measurement.
    std::vector<double> whole_units;
    double shared_s = 0, every_rank_s = 0;
    for (auto& u : units_) {
      if (!u.trimmed.empty()) continue;
      if (u.method == "fused") shared_s += u.time_s;
      else if (u.method == "voronoi") every_rank_s += u.time_s;
      else whole_units.push_back(u.time_s);
    }
    std::sort(whole_units.rbegin(), whole_units.rend());
    for (int P : ranks_) {
      std::vector<double> load(P, every_rank_s + shared_s / P);
      for (double tu : whole_units) *std::min_element(load.begin(), load.end()) += tu;
      makespan_.push_back(*std::max_element(load.begin(), load.end()));
    }
    s.set("processes_note", "'P processes' (MPI runner): fused passes shared over the P ranks "
                            "(1/P of the targets each), Voronoi volumes on every rank, Poisson "
                            "and heat units whole, longest first to the least loaded (the "
                            "runner deals them in loop order by a rough cost); bounded below by "
                            "the longest whole unit (" +
                                human_time(whole_units.empty() ? 0 : whole_units[0]) + ")");
    for (std::size_t i = 0; i < ranks_.size(); ++i) {
      Agg g = all_;
      g.time_s = makespan_[i];
      row(fmt(ranks_[i]) + " processes", "all", g, false);
    }
    if (!a_.str("summary").empty()) s.save(a_.str("summary"));
  }

  // The heat reading matrix: every reading of Tables 4.5-4.7, priced three ways, beside what
  // the profile_ runs of those tables today (its one reading per h rule, trims applied).
  void write_heat_matrix() {
    const std::vector<HeatMatrixCost> hm = heat_matrix_costs(profile_, cal_);
    TsvTable hmt;
    hmt.set("program", "plan --heat-matrix");
    hmt.set("profile", profile_name(profile_));
    hmt.set("calibration_source", cal_.source);
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
      for (auto& m : hm) {
      double catalog = 0;
      std::string study = "thesis_table" + m.table;
      std::replace(study.begin(), study.end(), '.', '_');
      for (auto& u : units_)
        if (u.trimmed.empty() && (u.study == study || u.study == study + "_h15")) catalog += u.time_s;
      heat_row(m, catalog);
      heat_total_.series += m.series, heat_total_.alone_s += m.alone_s, heat_total_.per_reading_s += m.per_reading_s;
      heat_total_.batched_s += m.batched_s, heat_total_.propagated_s += m.propagated_s, catalog_total_ += catalog;
    }
    heat_row(heat_total_, catalog_total_);
    hmt.set("profile_total_today_s", all_.time_s);
    hmt.set("profile_total_with_batched_matrix_s", all_.time_s - catalog_total_ + heat_total_.batched_s);
    hmt.set("profile_total_with_propagated_matrix_s", all_.time_s - catalog_total_ + heat_total_.propagated_s);
    if (!a_.str("heat-matrix").empty()) hmt.save(a_.str("heat-matrix"));
  }

  // The calibration as a table (quantity, value, unit).
  void write_calibration_table() {
    if (!a_.str("calibration-table").empty()) {
      TsvTable c;
      c.set("program", "plan --calibration-table");
      c.set("profile", profile_name(profile_));
      c.set("calibration_source", cal_.source);
      add_provenance(c);
      c.columns = {"quantity", "value", "unit"};
      // Every row is a (quantity, value, unit) triple: one named row here, so the calls below
      // stay one line each and a change of c.columns cannot swap value and unit.
      auto add = [&](const std::string& quantity, const std::string& value, const std::string& unit) {
        TsvRow row = c.named_row();
        row["quantity"] = quantity, row["value"] = value, row["unit"] = unit;
        c.add_row(row);
      };
      for (auto& [mix, pc] : cal_.fused) {
        add("fused pass " + mix + ": pair rate", fmt(1 / pc.per_pair_s), "pairs/s");
        add("fused pass " + mix + ": per target", fmt(pc.per_target_s * 1e6), "us");
      }
      add("Voronoi volumes", fmt(cal_.voronoi_s_per_particle * 1e6), "us/particle");
      add("Laplacian set-up", fmt(cal_.setup_s_per_nnz * 1e9), "ns/non-zero");
      add("assembled product (symmetric half)", fmt(cal_.spmv_s_per_nnz * 1e9), "ns/non-zero");
      add("assembled product (full matrix)", fmt(cal_.spmv_full_s_per_nnz * 1e9), "ns/non-zero");
      add("matrix-free product: pair rate", fmt(1 / cal_.matrix_free.per_pair_s), "pairs/s");
      add("matrix-free product: per target", fmt(cal_.matrix_free.per_target_s * 1e6), "us");
      for (auto& [w, r] : cal_.block_ratio)
        add("block product of " + fmt(w) + " columns (time per vector)", fmt(r), "x single product");
      add("calibration wall time", fmt(cal_.seconds), "s");
      add("calibration CPU time", fmt(cal_.cpu_seconds), "s");
      add("load average before / after", fmt(cal_.load_before) + " / " + fmt(cal_.load_after), "");
      if (std::filesystem::exists(a_.str("bench"))) {
        const TsvTable b = TsvTable::load(a_.str("bench"));
        const int cv = b.column("variant"), ct = b.column("threads"), cr = b.column("pairs_per_s");
        if (cv >= 0 && ct >= 0 && cr >= 0)
          for (auto& r : b.rows)
            if (r[cv] == "fused9" && r[ct] == "2")
              add("make bench fused9, 2 threads (" + b.get("written_utc").value_or("?") + ")", r[cr],
                  "pairs/s");
      }
      c.save(a_.str("calibration-table"));
    }
  }

  // The table on the terminal.
  void print() const {
      std::printf("plan, profile %s (%s: %.1f s wall, %.1f s CPU, load %.1f; %zu units)\n",
                  profile_name(profile_).c_str(), cal_.source.c_str(), cal_.seconds, cal_.cpu_seconds,
                  cal_.load_before, units_.size());
      std::printf("%-22s %5s %5s %11s %11s %12s %10s  %s\n", "study", "level", "units", "N",
                  "pair inter.", "time", "peak MiB", "method");
      for (auto& study : planned_studies()) {
        for (auto& [k, g] : entry(per_level_, study))
          std::printf("%-22s %5d %5d %11.4g %11.4g %12s %10.0f  %s\n", study.c_str(), k, g.units,
                      g.N, g.pair_work, human_time(g.time_s).c_str(), g.peak_mib,
                      g.method_list().c_str());
        const Agg& g = entry(per_study_, study);
        std::printf("%-22s %5s %5d %11s %11.4g %12s %10.0f\n", study.c_str(), "all", g.units, "",
                    g.pair_work, human_time(g.time_s).c_str(), g.peak_mib);
      }
      std::printf("%-22s %5s %5d %11s %11.4g %12s %10.0f\n", "TOTAL", "", all_.units, "",
                  all_.pair_work, human_time(all_.time_s).c_str(), all_.peak_mib);
      if (trimmed_.units > 0) {
        for (auto& study : planned_studies())
          for (auto& [k, g] : entry(per_level_trimmed_, study))
            std::printf("  trimmed: %-13s %5d %5d %11.4g %11.4g %12s\n", study.c_str(), k, g.units,
                        g.N, g.pair_work, human_time(g.time_s).c_str());
        std::printf("%-22s %5s %5d %11s %11.4g %12s   (TOTAL %.2fx less)\n", "BEFORE TRIMS", "",
                    before_trims_.units, "", before_trims_.pair_work,
                    human_time(before_trims_.time_s).c_str(),
                    before_trims_.time_s / std::max(1e-9, all_.time_s));
      }
      std::printf("%-22s %5s %5d %11s %11.4g %12s   (TOTAL %.2fx less: trims %.2fx, half storage %.2fx)\n",
                  "BEFORE (+ full matrix)", "", before_.units, "", before_.pair_work,
                  human_time(before_.time_s).c_str(), before_.time_s / std::max(1e-9, all_.time_s),
                  before_trims_.time_s / std::max(1e-9, all_.time_s),
                  before_.time_s / std::max(1e-9, before_trims_.time_s));
      for (std::size_t i = 0; i < ranks_.size(); ++i)
        std::printf("%-22s %5s %5s %11s %11s %12s   (predicted: fused passes shared, the rest dealt whole)\n",
                    (fmt(ranks_[i]) + " PROCESSES").c_str(), "", "", "", "",
                    human_time(makespan_[i]).c_str());
      std::printf("HEAT READING MATRIX (%d series): alone %s, per reading %s, batched %s; the profile "
                  "runs %s of these tables today; whole profile %s -> %s with the matrix batched\n",
                  heat_total_.series, human_time(heat_total_.alone_s).c_str(), human_time(heat_total_.per_reading_s).c_str(),
                  human_time(heat_total_.batched_s).c_str(), human_time(catalog_total_).c_str(),
                  human_time(all_.time_s).c_str(), human_time(all_.time_s - catalog_total_ + heat_total_.batched_s).c_str());
      std::printf("wrote %s%s%s\n", a_.str("out").c_str(), a_.str("summary").empty() ? "" : " and ",
                  a_.str("summary").c_str());
  }
};

int body(int argc, char** argv) { return Plan(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("plan", body, argc, argv); }
