// plan_vs_actual: the plan beside what the studies measured.  Reads a plan file (plan
// --out) and, for each modelled study, its data file <datadir>/<study>.tsv; joins the units
// whose time the study records (study_plan.cpp: recorded_seconds) and writes one row per
// (study, level) with the predicted and the measured seconds and their ratio, one row per
// study (level = all; also the predicted and recorded peak memory) and a total row.
// Units that ran but are not in the plan are counted (`unplanned`): a drift between the
// plan's mirror of a study's levels and the program itself shows there.  A study whose data
// file is missing (not run yet) gets a row with units_run = 0.
//
//   plan_vs_actual --plan data/quick/plan.tsv --datadir data/quick --out data/quick/plan_vs_actual.tsv
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <string>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/plan/study_plan.hpp"

using namespace gpm;

namespace {

// Sums over the units that ran: seconds and pair interactions, predicted and recorded (the
// work only over units where both sides know it: not Voronoi).
struct Cmp {
  int planned = 0, run = 0;
  double predicted_s = 0, actual_s = 0, predicted_all_s = 0, peak_pred = 0;
  double work_pred = 0, work_act = 0;
  void add(double pred, double act, double wp, double wa) {
    ++run;
    predicted_s += pred;
    actual_s += act;
    if (std::isfinite(wp) && std::isfinite(wa) && wp > 0) work_pred += wp, work_act += wa;
  }
  void add(const Cmp& o) {
    planned += o.planned, run += o.run;
    predicted_s += o.predicted_s, actual_s += o.actual_s, predicted_all_s += o.predicted_all_s;
    peak_pred = std::max(peak_pred, o.peak_pred);
    work_pred += o.work_pred, work_act += o.work_act;
  }
};

// The program: the plan read once and its columns found; run() compares every modelled study,
// then writes the total row and the file.
class PlanVsActual {
 public:
  PlanVsActual(int argc, char** argv)
      : a_("plan_vs_actual", "Predicted (plan) against measured (data files) seconds per study and level.") {
    a_.opt("plan", "", "plan file (plan --out) (required)")
        .opt("datadir", "", "directory of the studies' data files (required)")
        .output("out", "", "output TSV (required)");
    a_.parse(argc, argv);
    if (a_.str("plan").empty() || a_.str("datadir").empty() || a_.str("out").empty())
      throw InputError("--plan, --datadir and --out are required (see --help)");
    plan_ = TsvTable::load(a_.str("plan"));
    auto pc = [&](const char* n) {
      const int c = plan_.column(n);
      if (c < 0) throw InputError(a_.str("plan") + ": no column '" + std::string(n) + "'");
      return c;
    };
    c_study_ = pc("study"), c_var_ = pc("variant"), c_level_ = pc("level"), c_time_ = pc("time_s");
    c_mem_ = pc("peak_mib"), c_rec_ = pc("recorded"), c_pairs_ = pc("pairs"), c_prod_ = pc("products");
    c_method_ = pc("method");
    c_trim_ = plan_.column("trimmed");  // units a profile skips (absent in older plans)
  }

  int run() {
    describe();
    for (auto& study : planned_studies()) compare(study);
    total_row();
    out_.save(a_.str("out"));
    std::printf("wrote %s\n", a_.str("out").c_str());
    return 0;
  }

 private:
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  static std::string na(double v) { return std::isfinite(v) ? fmt(v) : std::string("NA"); }
  // A plan row of this study that the profile runs (not trimmed).
  bool planned_row(std::size_t i, const std::string& study) const {
    const auto& r = plan_.rows[i];
    return r[c_study_] == study && (c_trim_ < 0 || r[c_trim_] == "no");
  }

  void describe() {
    out_.set("program", "plan_vs_actual");
    out_.set("plan", a_.str("plan"));
    out_.set("profile", plan_.get("profile").value_or("?"));
    out_.set("plan_written_utc", plan_.get("written_utc").value_or("?"));
    out_.set("datadir", a_.str("datadir"));
    out_.set("ratio", "actual_s / predicted_s over the units that ran (both sides the same units)");
    out_.set("predicted_total_s", "all planned units, run or not (incl. set-up not in the rows)");
    out_.set("work_ratio", "recorded / predicted pair interactions (machine-independent; heat: "
                           "steps and CG iterations only, see study_plan.hpp; Voronoi: none)");
    add_provenance(out_);
    out_.columns = {"study", "level", "units_planned", "units_run", "unplanned", "predicted_s",
                    "actual_s", "ratio", "work_ratio", "predicted_total_s", "peak_pred_mib",
                    "peak_actual_mib"};
  }

  // One study: its planned units beside the units its data file recorded, a row per level and
  // one for the study (with the peak memory), and its line on stdout.
  void compare(const std::string& study) {
    const std::string path = a_.str("datadir") + "/" + study + ".tsv";
    // The plan's pair interactions per unit (and its non-zeros, which heat rows lack).
    std::map<std::pair<std::string, int>, double> planned_pairs, planned_work;
    for (std::size_t i = 0; i < plan_.rows.size(); ++i) {
      if (!planned_row(i, study)) continue;
      const auto& r = plan_.rows[i];
      const std::pair<std::string, int> key{r[c_var_], static_cast<int>(plan_.integer(i, c_level_))};
      const double pairs = plan_.number(i, c_pairs_);
      planned_pairs[key] = pairs;
      planned_work[key] = r[c_method_] == "voronoi" ? kNaN : pairs * std::max(1.0, plan_.number(i, c_prod_));
    }
    std::map<std::pair<std::string, int>, RecordedUnit> rec;
    double peak_actual = kNaN;
    if (std::filesystem::exists(path)) {
      const TsvTable d = TsvTable::load(path);
      rec = recorded_units(study, d, planned_pairs);
      peak_actual = recorded_peak_mib(study, d);
    }
    std::map<int, Cmp> lv;
    Cmp st;
    std::map<std::pair<std::string, int>, bool> planned_keys;
    for (std::size_t i = 0; i < plan_.rows.size(); ++i) {
      if (!planned_row(i, study)) continue;
      const auto& r = plan_.rows[i];
      const int k = static_cast<int>(plan_.integer(i, c_level_));
      const double pred = plan_.number(i, c_time_);
      Cmp& c = lv[k];
      c.predicted_all_s += pred;
      st.predicted_all_s += pred;
      c.peak_pred = std::max(c.peak_pred, plan_.number(i, c_mem_));
      st.peak_pred = std::max(st.peak_pred, c.peak_pred);
      if (r[c_rec_] != "yes") continue;
      ++c.planned, ++st.planned;
      planned_keys[{r[c_var_], k}] = true;
      auto it = rec.find({r[c_var_], k});
      if (it == rec.end() || !std::isfinite(it->second.seconds)) continue;
      const double wp = planned_work[{r[c_var_], k}], wa = it->second.pair_interactions;
      c.add(pred, it->second.seconds, wp, wa);
      st.add(pred, it->second.seconds, wp, wa);
    }
    int unplanned = 0;
    std::map<int, int> unplanned_at;
    for (auto& [key, s] : rec)
      if (!planned_keys.count(key)) ++unplanned, ++unplanned_at[key.second];
    for (auto& [k, c] : lv) emit(study, fmt(k), c, unplanned_at[k], kNaN);
    emit(study, "all", st, unplanned, peak_actual);
    if (unplanned > 0)
      std::fprintf(stderr, "[plan_vs_actual] %s: %d recorded units are not in the plan\n", study.c_str(), unplanned);
    total_.add(st);
    std::printf("%-22s run %3d/%3d units  predicted %9.2f s  measured %9.2f s  ratio %6.3f  "
                "work ratio %6.3f\n",
                study.c_str(), st.run, st.planned, st.predicted_s, st.actual_s,
                st.run && st.predicted_s > 0 ? st.actual_s / st.predicted_s : kNaN,
                st.work_pred > 0 ? st.work_act / st.work_pred : kNaN);
  }

  void emit(const std::string& study, const std::string& level, const Cmp& c, int unpl, double peak_act) {
    TsvRow row = out_.named_row();
    row["study"] = study, row["level"] = level;
    row["units_planned"] = fmt(c.planned), row["units_run"] = fmt(c.run), row["unplanned"] = fmt(unpl);
    row["predicted_s"] = c.run ? fmt(c.predicted_s) : "NA";
    row["actual_s"] = c.run ? fmt(c.actual_s) : "NA";
    row["ratio"] = c.run && c.predicted_s > 0 ? fmt(c.actual_s / c.predicted_s) : "NA";
    row["work_ratio"] = c.work_pred > 0 ? fmt(c.work_act / c.work_pred) : "NA";
    row["predicted_total_s"] = fmt(c.predicted_all_s);
    row["peak_pred_mib"] = fmt(c.peak_pred), row["peak_actual_mib"] = na(peak_act);
    out_.add_row(row);
  }

  void total_row() {
    TsvRow row = out_.named_row();
    row["study"] = "total", row["level"] = "all";
    row["units_planned"] = fmt(total_.planned), row["units_run"] = fmt(total_.run), row["unplanned"] = "0";
    row["predicted_s"] = fmt(total_.predicted_s), row["actual_s"] = fmt(total_.actual_s);
    row["ratio"] = total_.predicted_s > 0 ? fmt(total_.actual_s / total_.predicted_s) : "NA";
    row["work_ratio"] = total_.work_pred > 0 ? fmt(total_.work_act / total_.work_pred) : "NA";
    row["predicted_total_s"] = fmt(total_.predicted_all_s);
    row["peak_pred_mib"] = fmt(total_.peak_pred), row["peak_actual_mib"] = "NA";
    out_.add_row(row);
  }

  Args a_;
  TsvTable plan_, out_;
  int c_study_ = -1, c_var_ = -1, c_level_ = -1, c_time_ = -1, c_mem_ = -1, c_rec_ = -1, c_pairs_ = -1,
      c_prod_ = -1, c_method_ = -1, c_trim_ = -1;
  Cmp total_;
};

int body(int argc, char** argv) { return PlanVsActual(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("plan_vs_actual", body, argc, argv); }
