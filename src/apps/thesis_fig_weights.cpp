// thesis_fig_weights: samples w(r) of the thesis' Chapter-4 weight functions for the graphs of
// Figures 4.2 (cubic B-spline, quintic B-spline, quadratic spike) and 4.4 (quadratic and cubic
// spike), and of the gradient/Laplacian weights of Section 4.1.2.  The values come from the
// weight registry (the B-splines as corrected there; see the report's errata).
#include <cmath>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/io/progress.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

const std::vector<std::string> kWeights = {
    "quadratic_spike",    "cubic_bspline",              "quintic_bspline",
    "cubic_spike",        "quartic_polynomial",         "piecewise_cubic_polynomial",
    "piecewise_quintic_polynomial"};

// The program: the options read once; run() samples every weight and writes the table.
class FigWeights {
 public:
  FigWeights(int argc, char** argv)
      : a_("thesis_fig_weights", "w(r) samples of the thesis' Chapter-4 weights (Figures 4.2, 4.4).") {
    a_.output("out", "", "output TSV (required)").opt("samples", "401", "samples on [0, 1.2]");
    a_.parse(argc, argv);
    a_.required("out");
    n_ = a_.integer("samples", 2, 1000000);
  }

  int run() {
    const Stopwatch wall;
    TsvTable t;
    t.set("program", "thesis_fig_weights");
    t.set("samples", fmt(n_));
    t.set("range", "r in [0, 1.2]");
    t.columns = {"r"};
    for (auto& w : kWeights) {
      t.columns.push_back(w);
      t.set("source_" + w, weight(w).source);
    }
    for (long long i = 0; i < n_; ++i) {
      const double r = 1.2 * static_cast<double>(i) / static_cast<double>(n_ - 1);
      std::vector<std::string> row{fmt(r)};
      for (auto& w : kWeights) row.push_back(fmt(weight(w).value(r)));
      t.add_row(row);
    }
    add_provenance(t);
    t.set("wall_time_s", wall.seconds());
    t.save(a_.str("out"));
    return 0;
  }

 private:
  Args a_;
  long long n_ = 0;
};

int body(int argc, char** argv) { return FigWeights(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_fig_weights", body, argc, argv); }
