// The thesis' truncation-error studies (Chapter 4.1, Tables 4.1–4.3), shared by the three
// table programs: the level loop that measures every weight × operator × test function of a
// table (define/thesis_tables.hpp) in one fused kernel pass per (h reading, volume choice,
// level).
#pragma once
#include "gpm/studies/define/thesis_tables.hpp"

namespace gpm {

// Runs the table: for each level (ascending) and each (reading, volumes) not yet in the data
// file, one fused pass; writes one row per weight × operator × case and saves after every
// pass.  The paper profile's cost of each pass is the plan's (study_plan.hpp).
int run_thesis_table(const ThesisTableSpec& spec, int argc, char** argv);

}  // namespace gpm
