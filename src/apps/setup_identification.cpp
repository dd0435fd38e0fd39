// setup_identification — the rule of paper/04-setup-rule.md applied to the result store: which
// reading of the thesis' Chapter 4 set-up (h rule, volumes, time-step rule) the documents' own
// fingerprint (Table 4.6's θ = 0 rates) identifies.  The rule and its fingerprint:
// src/gpm/studies/judge/setup_identification.hpp.
//
//   setup_identification --store results/paper --published tables/published/thesis_table4_6_long.tsv
//     --out data/paper/setup_identification.tsv
#include <cstdio>
#include <string>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/setup_identification.hpp"

using namespace gpm;

namespace {

int body(int argc, char** argv) {
  Args a("setup_identification",
         "Which reading of the thesis' Chapter 4 set-up the published theta = 0 rates of\n"
         "Table 4.6 identify (paper/04-setup-rule.md), from the result store (TSV).");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published/thesis_table4_6_long.tsv", "Table 4.6's published rates")
      .output("out", "", "output TSV (required)");
  a.parse(argc, argv);
  const std::string out = a.required("out");
  SetupIdentification id =
      identify_setup(StoreSnapshot(a.str("store")), setup_fingerprint_study(study_registry()), TsvTable::load(a.str("published")));
  add_provenance(id.table);
  id.table.save(out);
  if (!id.identified)
    std::printf("setup_identification: undecided, %zu readings still without a rate (%s); wrote %s\n",
                id.incomplete.size(), join(id.incomplete, ", ").c_str(), out.c_str());
  else
    std::printf("setup_identification: %s identified (%s); wrote %s\n", id.identified->name().c_str(),
                id.decisions.c_str(), out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("setup_identification", body, argc, argv); }
