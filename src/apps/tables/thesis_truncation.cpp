#include "apps/tables/thesis_truncation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/cost_model.hpp"  // predicted_pairs: the progress line's work
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/run/runner.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Particles of a level and, computed only when a pass needs them, their Voronoi volumes.
struct LevelData {
  int level = 0;
  Particles p;
  std::optional<std::vector<double>> voronoi;
  double voronoi_s = 0;
  const std::vector<double>& voronoi_volumes(const Domain& dom) {
    if (!voronoi) {
      const auto t0 = std::chrono::steady_clock::now();
      voronoi = voronoi_cells(p, dom, false).area;
      voronoi_s = seconds_since(t0);
    }
    return *voronoi;
  }
};

// The relative error as the header states it; the gradient clause only where a gradient
// is measured (Table 4.3).
std::string rel_error_definition(const std::vector<ErrorRequest>& requests) {
  std::string d = "max over particles in Omega of |exact - approx| / max over particles in "
                  "Omega of |exact|";
  for (auto& r : requests)
    if (r.op == Operator::grad) return d + " (gradient: |.| the Euclidean length of the vector)";
  return d;
}

// The program of one table: the options read once; run() chooses the units, opens the cached
// data file, states the work to do and makes one fused pass per unit it lacks.
class ThesisTable {
 public:
  ThesisTable(const ThesisTableSpec& spec, int argc, char** argv)
      : spec_(spec), run_(study_registry().study(spec.program), spec.summary) {
    Args& args = run_.args();
    args.opt("readings", "", "comma-separated h readings: printed, scaled (default: the table's)")
        .opt("volumes", "voronoi,uniform", "comma-separated volume choices: voronoi, uniform")
        .opt("max-level", "", "drop levels above this one (e.g. to bound a paper run)");
    run_.parse(argc, argv);
    for (HReading r : spec_.readings) readings_.push_back(h_reading_name(r));
    if (!args.str("readings").empty()) {
      readings_.clear();
      for (auto& s : args.list("readings")) readings_.push_back(h_reading_name(parse_h_reading(s)));
    }
    for (auto& s : args.list("volumes")) volumes_.push_back(volumes_name(parse_volumes(s)));
    if (readings_.empty() || volumes_.empty())
      throw InputError("--readings and --volumes must name at least one choice each");
    if (!args.str("max-level").empty()) max_level_ = static_cast<int>(args.integer("max-level", 2, 13));
    for (auto& c : thesis_cases()) functions_.push_back(c.function);
    rows_per_unit_ = spec_.requests.size() * thesis_cases().size();
  }

  int run() {
    choose_units();
    open_data_file();
    expect_work();
    for (const StudyUnit& u : units_) pass(u);
    run_.finish();
    return 0;
  }

 private:
  // The entry's units of this run (each reading at its profile levels, or all at --levels),
  // less the readings, volumes and levels the options leave out.
  void choose_units() {
    auto chosen = [](const std::vector<std::string>& list, const std::string& v) {
      return std::find(list.begin(), list.end(), v) != list.end();
    };
    for (const StudyUnit& u : run_.units())
      if (chosen(readings_, u.key[0]) && chosen(volumes_, u.key[1]) && u.level <= max_level_) units_.push_back(u);
  }

  // The data file: its parameters decide whether an earlier run's rows are reused.
  void open_data_file() {
    std::vector<std::pair<std::string, std::string>> params = {
        {"program", spec_.program},
        {"table", spec_.table},
        {"seed", fmt(static_cast<long long>(run_.seed()))},
        {"H", fmt(dom_.H)},
        {"jitter_amplitude", "0.25"},
        {"h_printed", "(3.1^" + fmt(spec_.c) + " * 2^-10 * dx)^(1/" + fmt(spec_.p) + ")"},
        {"h_scaled", "3.1 * 2^(5/" + fmt(spec_.p) + " - 5) * dx^(1/" + fmt(spec_.p) + ")"},
        {"cases", "case1 = (x-1/2)^4 + (y-1/2)^4, case2 = sin(2 pi (x+y))"},
        {"rel_error", rel_error_definition(spec_.requests)},
        {"rate_levels_thesis", spec_.rate_levels},
    };
    std::string wnames;
    for (auto& r : spec_.requests) wnames += (wnames.empty() ? "" : ",") + r.weight + ":" + operator_name(r.op);
    params.push_back({"requests", wnames});
    cache_ = &run_.open(params, thesis_table_columns(), 3);
    cache_->table().set("profile", profile_name(run_.profile()));
    cache_->table().set("paper_uniform_max_level", fmt(spec_.paper_uniform_max_level));
    cache_->table().set("time_s", "wall time of the fused pass (all weights, operators, cases)");
    cache_->table().set("voronoi_s", "wall time of the Voronoi volumes of the level (0: uniform)");
  }

  // What is left to do, for the progress line's ETA.
  void expect_work() {
    double total = 0;
    for (const StudyUnit& u : units_)
      if (!cache_->has(u.key, rows_per_unit_)) total += predicted_pairs(std::ldexp(1.0, -u.level), u.h);
    run_.expect(total, "pairs");
  }

  // One unit (reading, volumes, level): the level's particles (and Voronoi volumes) built on
  // its first pass that runs, then one fused pass over every weight, operator and case.
  void pass(const StudyUnit& u) {
    if (cache_->has(u.key, rows_per_unit_) || !run_.claim_shared()) return;
    const int k = u.level;
    const double dx = std::ldexp(1.0, -k), h = u.h;
    const HReading r = parse_h_reading(u.key[0]);
    const Volumes v = parse_volumes(u.key[1]);
    if (!level_ || level_->level != k) {
      level_ = std::make_unique<LevelData>();
      level_->level = k;
      level_->p = jittered_grid(dx, run_.seed(), 0.25, dom_);
    }
    const Particles& p = level_->p;
    std::vector<double> uniform;
    double vor_s = 0;
    const std::vector<double>* V = nullptr;
    if (v == Volumes::voronoi) {
      V = &level_->voronoi_volumes(dom_);
      vor_s = level_->voronoi_s;
    } else {
      uniform = uniform_volumes(p, dom_);
      V = &uniform;
    }
    const auto t0 = std::chrono::steady_clock::now();
    // One pass (on a cluster: this rank's share of the targets, then all shares merged;
    // with --parts: part by part, each saved, so a long pass resumes).
    const ErrorMaxima maxima = run_.shared_pass(
        h_reading_name(r) + "_" + volumes_name(v) + "_level" + fmt(k),
        [&](TargetShare s) { return fused_error_maxima(p, *V, h, spec_.requests, functions_, true, s); });
    const FusedErrors e = relative_errors(maxima, spec_.requests, functions_);
    const double pass_s = seconds_since(t0);
    const double rss = peak_rss_mib();
    for (auto& er : e.errors) {
      std::string label;
      for (auto& c : thesis_cases())
        if (c.function == er.function) label = c.label;
      TsvRow row = run_.row();  // thesis_table_columns(), by name
      row["h_reading"] = h_reading_name(r), row["volumes"] = volumes_name(v), row["level"] = fmt(k);
      row["weight"] = er.weight, row["operator"] = operator_name(er.op), row["function"] = label;
      row["dx"] = fmt(dx), row["h"] = fmt(h), row["h_over_H"] = fmt(h / dom_.H);
      row["N"] = fmt(p.size()), row["N_omega"] = fmt(p.count_in_omega()), row["pairs"] = fmt(e.pairs);
      row["rel_error"] = fmt(er.rel_error), row["time_s"] = fmt(pass_s), row["voronoi_s"] = fmt(vor_s);
      row["peak_rss_mib"] = fmt(rss);
      run_.add(row);
    }
    run_.unit_done(predicted_pairs(dx, h),
                   line_printf("level %d %s/%s h=%.5g%s N=%zu pairs=%.3g pass %.2fs "
                               "voronoi %.2fs peak %.0f MiB",
                               k, h_reading_name(r).c_str(), volumes_name(v).c_str(), h,
                               h > dom_.H ? " (h > H)" : "", p.size(), e.pairs, pass_s, vor_s, rss));
  }

  const ThesisTableSpec& spec_;
  StudyRunner run_;
  std::vector<std::string> readings_, volumes_, functions_;
  int max_level_ = 99;
  std::size_t rows_per_unit_ = 0;
  const Domain dom_;
  UnitCache* cache_ = nullptr;
  std::vector<StudyUnit> units_;
  std::unique_ptr<LevelData> level_;  // built on the first pass of a level that runs
};

}  // namespace

int run_thesis_table(const ThesisTableSpec& spec, int argc, char** argv) {
  return ThesisTable(spec, argc, argv).run();
}

}  // namespace gpm
