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

int body(int argc, char** argv) {
  Args a("plan_vs_actual",
         "Predicted (plan) against measured (data files) seconds per study and level.");
  a.opt("plan", "", "plan file (plan --out) (required)")
      .opt("datadir", "", "directory of the studies' data files (required)")
      .output("out", "", "output TSV (required)");
  a.parse(argc, argv);
  if (a.str("plan").empty() || a.str("datadir").empty() || a.str("out").empty())
    throw InputError("--plan, --datadir and --out are required (see --help)");
  const TsvTable plan = TsvTable::load(a.str("plan"));
  auto pc = [&](const char* n) {
    const int c = plan.column(n);
    if (c < 0) throw InputError(a.str("plan") + ": no column '" + std::string(n) + "'");
    return c;
  };
  const int c_study = pc("study"), c_var = pc("variant"), c_level = pc("level"),
            c_time = pc("time_s"), c_mem = pc("peak_mib"), c_rec = pc("recorded"),
            c_pairs = pc("pairs"), c_prod = pc("products"), c_method = pc("method");
  const int c_trim = plan.column("trimmed");  // units a profile skips (absent in older plans)

  TsvTable out;
  out.set("program", "plan_vs_actual");
  out.set("plan", a.str("plan"));
  out.set("profile", plan.get("profile").value_or("?"));
  out.set("plan_written_utc", plan.get("written_utc").value_or("?"));
  out.set("datadir", a.str("datadir"));
  out.set("ratio", "actual_s / predicted_s over the units that ran (both sides the same units)");
  out.set("predicted_total_s", "all planned units, run or not (incl. set-up not in the rows)");
  out.set("work_ratio", "recorded / predicted pair interactions (machine-independent; heat: "
                        "steps and CG iterations only, see study_plan.hpp; Voronoi: none)");
  add_provenance(out);
  out.columns = {"study", "level", "units_planned", "units_run", "unplanned", "predicted_s",
                 "actual_s", "ratio", "work_ratio", "predicted_total_s", "peak_pred_mib",
                 "peak_actual_mib"};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto f = [](double v) { return std::isfinite(v) ? fmt(v) : std::string("NA"); };

  Cmp total;
  for (auto& study : planned_studies()) {
    const std::string path = a.str("datadir") + "/" + study + ".tsv";
    // The plan's pair interactions per unit (and its non-zeros, which heat rows lack).
    std::map<std::pair<std::string, int>, double> planned_pairs, planned_work;
    for (std::size_t i = 0; i < plan.rows.size(); ++i) {
      const auto& r = plan.rows[i];
      if (r[c_study] != study || (c_trim >= 0 && r[c_trim] != "no")) continue;
      const std::pair<std::string, int> key{r[c_var], static_cast<int>(plan.integer(i, c_level))};
      const double pairs = plan.number(i, c_pairs);
      planned_pairs[key] = pairs;
      planned_work[key] =
          r[c_method] == "voronoi" ? nan : pairs * std::max(1.0, plan.number(i, c_prod));
    }
    std::map<std::pair<std::string, int>, RecordedUnit> rec;
    double peak_actual = nan;
    if (std::filesystem::exists(path)) {
      const TsvTable d = TsvTable::load(path);
      rec = recorded_units(study, d, planned_pairs);
      peak_actual = recorded_peak_mib(study, d);
    }
    std::map<int, Cmp> lv;
    Cmp st;
    std::map<std::pair<std::string, int>, bool> planned_keys;
    for (std::size_t i = 0; i < plan.rows.size(); ++i) {
      const auto& r = plan.rows[i];
      if (r[c_study] != study || (c_trim >= 0 && r[c_trim] != "no")) continue;
      const int k = static_cast<int>(plan.integer(i, c_level));
      const double pred = plan.number(i, c_time);
      Cmp& c = lv[k];
      c.predicted_all_s += pred;
      st.predicted_all_s += pred;
      c.peak_pred = std::max(c.peak_pred, plan.number(i, c_mem));
      st.peak_pred = std::max(st.peak_pred, c.peak_pred);
      if (r[c_rec] != "yes") continue;
      ++c.planned, ++st.planned;
      planned_keys[{r[c_var], k}] = true;
      auto it = rec.find({r[c_var], k});
      if (it == rec.end() || !std::isfinite(it->second.seconds)) continue;
      const double wp = planned_work[{r[c_var], k}], wa = it->second.pair_interactions;
      c.add(pred, it->second.seconds, wp, wa);
      st.add(pred, it->second.seconds, wp, wa);
    }
    int unplanned = 0;
    std::map<int, int> unplanned_at;
    for (auto& [key, s] : rec)
      if (!planned_keys.count(key)) ++unplanned, ++unplanned_at[key.second];
    auto emit = [&](const std::string& level, const Cmp& c, int unpl, double peak_act) {
      TsvRow row = out.named_row();
      row["study"] = study, row["level"] = level;
      row["units_planned"] = fmt(c.planned), row["units_run"] = fmt(c.run), row["unplanned"] = fmt(unpl);
      row["predicted_s"] = c.run ? fmt(c.predicted_s) : "NA";
      row["actual_s"] = c.run ? fmt(c.actual_s) : "NA";
      row["ratio"] = c.run && c.predicted_s > 0 ? fmt(c.actual_s / c.predicted_s) : "NA";
      row["work_ratio"] = c.work_pred > 0 ? fmt(c.work_act / c.work_pred) : "NA";
      row["predicted_total_s"] = fmt(c.predicted_all_s);
      row["peak_pred_mib"] = fmt(c.peak_pred), row["peak_actual_mib"] = f(peak_act);
      out.add_row(row);
    };
    for (auto& [k, c] : lv) emit(fmt(k), c, unplanned_at[k], nan);
    emit("all", st, unplanned, peak_actual);
    if (unplanned > 0)
      std::fprintf(stderr, "[plan_vs_actual] %s: %d recorded units are not in the plan\n",
                   study.c_str(), unplanned);
    total.add(st);
    std::printf("%-22s run %3d/%3d units  predicted %9.2f s  measured %9.2f s  ratio %6.3f  "
                "work ratio %6.3f\n",
                study.c_str(), st.run, st.planned, st.predicted_s, st.actual_s,
                st.run && st.predicted_s > 0 ? st.actual_s / st.predicted_s : nan,
                st.work_pred > 0 ? st.work_act / st.work_pred : nan);
  }
  TsvRow row = out.named_row();
  row["study"] = "total", row["level"] = "all";
  row["units_planned"] = fmt(total.planned), row["units_run"] = fmt(total.run), row["unplanned"] = "0";
  row["predicted_s"] = fmt(total.predicted_s), row["actual_s"] = fmt(total.actual_s);
  row["ratio"] = total.predicted_s > 0 ? fmt(total.actual_s / total.predicted_s) : "NA";
  row["work_ratio"] = total.work_pred > 0 ? fmt(total.work_act / total.work_pred) : "NA";
  row["predicted_total_s"] = fmt(total.predicted_all_s);
  row["peak_pred_mib"] = fmt(total.peak_pred), row["peak_actual_mib"] = "NA";
  out.add_row(row);
  out.save(a.str("out"));
  std::printf("wrote %s\n", a.str("out").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("plan_vs_actual", body, argc, argv); }
