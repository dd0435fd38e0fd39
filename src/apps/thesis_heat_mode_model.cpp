// thesis_heat_mode_model: what the heat tables' errors (thesis §4.3, Tables 4.5–4.7) are made
// of, predicted without solving anything, and set beside a data file's measured errors.
//
// The model itself (the one Fourier mode, the θ-step's amplification at the discrete decay
// rate μ(1 + δ)(1 − ε)) is src/gpm/studies/judge/heat_mode_model.hpp, shared with the checked
// reasons of gpm checked-reasons; this program writes its rows and rates to files.
//
//   thesis_heat_mode_model --table 4.6 --data results/paper/thesis_table4_6.tsv
//     [--cell results/paper/thesis_table4_6_cellvol.tsv] --out rows.tsv --rates rates.tsv
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/heat_mode_model.hpp"
#include "gpm/studies/define/heat_tables.hpp"

using namespace gpm;

namespace {

// The program: the data files read and modelled once; run() writes every row beside its
// prediction, then (if asked) the rates, then a line per row.
class ModeModel {
 public:
  ModeModel(int argc, char** argv)
      : a_("thesis_heat_mode_model",
           "The heat tables' errors (thesis 4.3) predicted from one Fourier mode: time step,\n"
           "smoothing error eps(kh) and volume mismatch, beside a data file's measured errors;\n"
           "per (weight, theta) the rates at the table's rate levels.  Solves nothing.") {
    a_.opt("table", "", "4.5, 4.6 or 4.7: the rate levels (heat_tables.hpp) (required)")
        .opt("data", "", "thesis_heat data file (required)")
        .opt("cell", "", "optional thesis_heat data file of the same table run with V_i = dx^2")
        .output("out", "", "TSV: one row per data row with its prediction (required)")
        .output("rates", "", "TSV: per (weight, theta), rates reproduced, predicted, without the\n"
                             "  mismatch and with V_i = dx^2 (optional)");
    a_.parse(argc, argv);
    table_ = &heat_table(a_.str("table"));
    const std::string data = a_.required("data");
    out_ = a_.required("out");
    rows_ = mode_model(TsvTable::load(data));
    if (!a_.str("cell").empty()) cell_rows_ = mode_model(TsvTable::load(a_.str("cell")));
  }

  int run() {
    predictions();
    if (!a_.str("rates").empty()) rates();
    check_output_paths({{"--out", out_}, {"--rates", a_.str("rates")}});
    o_.save(out_);
    if (rt_) rt_->save(a_.str("rates"));
    report();
    return 0;
  }

 private:
  // Every row beside its prediction.
  void predictions() {
    o_.set("program", "thesis_heat_mode_model");
    for (auto& [k, v] : a_.values()) o_.set(k, v);
    o_.set("mode", "u = exp(-mu t) sin(pi x) sin(pi y), mu = 2 kappa pi^2, |k| = pi sqrt 2");
    o_.set("predicted", "max_k |g(z)^k - exp(-mu k dt)|, g(z) = (1-(1-theta)z)/(1+theta z), "
                        "z = mu (1+delta)(1-eps(|k|h)) dt");
    add_provenance(o_);
    o_.columns = {"weight", "theta", "level", "h", "K", "dt", "volume_mismatch", "eps_smoothing",
                  "rel_error", "predicted", "predicted_no_mismatch", "measured_over_predicted"};
    for (auto& r : rows_) {
      TsvRow row = o_.named_row();
      row["weight"] = r.weight, row["theta"] = r.theta, row["level"] = fmt(r.level), row["h"] = fmt(r.h);
      row["K"] = fmt(r.K), row["dt"] = fmt(r.dt), row["volume_mismatch"] = fmt(r.mismatch);
      row["eps_smoothing"] = fmt(r.eps), row["rel_error"] = fmt(r.measured), row["predicted"] = fmt(r.predicted);
      row["predicted_no_mismatch"] = fmt(r.no_mismatch), row["measured_over_predicted"] = fmt(r.measured / r.predicted);
      o_.add_row(row);
    }
  }

  // Rates at the table's rate levels, per (weight, θ).
  void rates() {
    rt_.emplace();
    rt_->set("program", "thesis_heat_mode_model --rates");
    for (auto& [k, v] : a_.values()) rt_->set(k, v);
    rt_->set("levels", table_->rate_levels);
    rt_->set("rate", "log(e_coarse/e_fine)/log(h_coarse/h_fine), as the thesis takes its rates");
    add_provenance(*rt_);
    rt_->columns = {"key", "rate_reproduced", "rate_predicted", "rate_no_mismatch", "rate_cell",
                    "ratio_coarse", "ratio_fine", "mismatch_coarse", "mismatch_fine"};
    for (const ModeRate& r : mode_rates(*table_, rows_, cell_rows_)) {
      TsvRow row = rt_->named_row();
      row["key"] = r.key, row["rate_reproduced"] = fmt(r.reproduced), row["rate_predicted"] = fmt(r.predicted);
      row["rate_no_mismatch"] = fmt(r.no_mismatch), row["rate_cell"] = r.cell ? fmt(*r.cell) : "NA";
      row["ratio_coarse"] = fmt(r.ratio_coarse), row["ratio_fine"] = fmt(r.ratio_fine);
      row["mismatch_coarse"] = fmt(r.mismatch_coarse), row["mismatch_fine"] = fmt(r.mismatch_fine);
      rt_->add_row(row);
    }
  }

  void report() const {
    for (auto& r : rows_)
      std::printf("%-28s theta=%-3s 2^-%d  measured %.4e  predicted %.4e  ratio %.3f\n",
                  r.weight.c_str(), r.theta.c_str(), r.level, r.measured, r.predicted,
                  r.measured / r.predicted);
  }

  Args a_;
  const HeatTable* table_ = nullptr;
  std::string out_;
  std::vector<ModeRow> rows_, cell_rows_;
  TsvTable o_;
  std::optional<TsvTable> rt_;
};

int body(int argc, char** argv) { return ModeModel(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_heat_mode_model", body, argc, argv); }
