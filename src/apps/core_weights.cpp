// core_weights: the property table of every reference weight function in the registry
// (normalization, order, positivity, regularity hypotheses — all computed from the
// pieces), and the errata table of the printed formulas that do not normalize.
//
//   core_weights --out data/core_weights.tsv --errata data/core_weights_errata.tsv
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/weights/weights.hpp"

namespace {

const char* yes_no(bool b) { return b ? "yes" : "no"; }

void set_header(gpm::TsvTable& t, const gpm::Args& args) {
  t.set("program", "core_weights");
  t.set("profile", args.str("profile"));
  for (auto& [k, v] : args.values())
    if (k != "profile") t.set("arg_" + k, v);
  gpm::add_provenance(t);
}

gpm::TsvTable property_table(const gpm::Args& args) {
  gpm::TsvTable t;
  set_header(t, args);
  t.set("norm", "2π∫r w dr (d=2) or 4π∫r² w dr (d=3), GSL qags, tol 1e-13");
  t.columns = {"name",     "label",      "source", "role",    "dimension",    "constant",
               "norm",     "order_k",    "positive", "p0",    "continuous",   "c1",
               "hyp_1_2",  "hyp_1_3",    "imoto_hyp2_k", "inv_r2_integral", "admissible"};
  for (auto& w : gpm::weight_registry()) {
    const auto p = gpm::compute_properties(w);
    gpm::TsvRow row = t.named_row();
    row["name"] = w.name, row["label"] = w.label, row["source"] = w.source, row["role"] = w.role;
    row["dimension"] = gpm::fmt(w.dimension), row["constant"] = gpm::fmt(w.constant);
    row["norm"] = gpm::fmt(p.norm(w.dimension)), row["order_k"] = gpm::fmt(p.order_k);
    row["positive"] = yes_no(p.positive), row["p0"] = gpm::fmt(p.p0);
    row["continuous"] = yes_no(p.continuous), row["c1"] = yes_no(p.c1);
    row["hyp_1_2"] = yes_no(p.hyp_1_2), row["hyp_1_3"] = yes_no(p.hyp_1_3);
    row["imoto_hyp2_k"] = gpm::fmt(p.imoto_hyp2_k), row["inv_r2_integral"] = gpm::fmt(p.inv_r2_integral);
    row["admissible"] = yes_no(p.admissible);
    t.add_row(row);
  }
  return t;
}

gpm::TsvTable errata_table(const gpm::Args& args) {
  gpm::TsvTable t;
  set_header(t, args);
  t.columns = {"name", "source", "printed", "corrected", "printed_norm", "corrected_norm",
               "evidence"};
  for (auto& e : gpm::weight_errata()) {
    gpm::TsvRow row = t.named_row();
    row["name"] = e.name, row["source"] = e.source, row["printed"] = e.printed;
    row["corrected"] = e.corrected, row["printed_norm"] = gpm::fmt(e.printed_norm_2d);
    row["corrected_norm"] = gpm::fmt(e.corrected_norm_2d), row["evidence"] = e.evidence;
    t.add_row(row);
  }
  return t;
}

// A fixed-width view of the property table, then counts a reader can check against it.
void print_summary(const gpm::TsvTable& props, const gpm::TsvTable& errata) {
  const std::vector<std::string> shown = {"name", "dimension", "norm", "order_k", "positive",
                                          "p0", "continuous", "c1", "hyp_1_2", "hyp_1_3",
                                          "imoto_hyp2_k", "inv_r2_integral", "admissible"};
  std::printf("%-29s %3s %-20s %5s %4s %3s %4s %3s %4s %4s %4s %-10s %4s\n", "name", "d",
              "norm", "order", "pos", "p0", "cont", "c1", "h1.2", "h1.3", "hyp2", "∫w/r",
              "adm");
  std::map<std::string, int> yes;
  for (auto& row : props.rows) {
    std::vector<std::string> v;
    for (auto& c : shown) v.push_back(row[static_cast<std::size_t>(props.column(c))]);
    std::printf("%-29s %3s %-20s %5s %4s %3s %4s %3s %4s %4s %4s %-10.10s %4s\n", v[0].c_str(),
                v[1].c_str(), v[2].c_str(), v[3].c_str(), v[4].c_str(), v[5].c_str(),
                v[6].c_str(), v[7].c_str(), v[8].c_str(), v[9].c_str(), v[10].c_str(),
                v[11].c_str(), v[12].c_str());
    for (std::size_t k = 0; k < shown.size(); ++k)
      if (v[k] == "yes") ++yes[shown[k]];
  }
  std::printf("\n%zu weights: %d admissible, %d positive on (0,1), %d continuous, %d C1, "
              "%d with Hyp 1.2, %d with Hyp 1.3\n",
              props.rows.size(), yes["admissible"], yes["positive"], yes["continuous"],
              yes["c1"], yes["hyp_1_2"], yes["hyp_1_3"]);
  std::printf("%zu errata (printed form does not normalize or is discontinuous):\n",
              errata.rows.size());
  for (auto& e : gpm::weight_errata())
    std::printf("  %-16s printed norm %.12f -> corrected %.12f\n", e.name.c_str(),
                e.printed_norm_2d, e.corrected_norm_2d);
}

// The program: the options read once; run() computes both tables, writes them and prints
// the summary.
class CoreWeights {
 public:
  CoreWeights(int argc, char** argv)
      : args_("core_weights",
              "Computes the properties of every reference weight function (normalization,\n"
              "order of Hypothesis 1.1, positivity, p0, regularity hypotheses) and lists\n"
              "the printed formulas that are wrong, with the computed evidence.") {
    args_.output("out", "", "property table TSV, one row per registry weight (required)")
        .output("errata", "", "errata TSV, one row per wrong printed formula (optional)")
        .opt("profile", "quick", "run profile recorded in the header: quick or paper "
                                 "(the table is the same for both)");
    args_.parse(argc, argv);
    args_.required("out");
    gpm::parse_profile(args_.str("profile"));  // rejects unknown profiles
  }

  int run() {
    const auto props = property_table(args_);
    const auto errata = errata_table(args_);
    props.save(args_.str("out"));
    if (!args_.str("errata").empty()) errata.save(args_.str("errata"));
    print_summary(props, errata);
    std::printf("wrote %s%s%s\n", args_.str("out").c_str(),
                args_.str("errata").empty() ? "" : " and ", args_.str("errata").c_str());
    return 0;
  }

 private:
  gpm::Args args_;
};

int body(int argc, char** argv) { return CoreWeights(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("core_weights", body, argc, argv); }
