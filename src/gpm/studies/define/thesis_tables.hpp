// The thesis' truncation-error tables (Chapter 4.1, Tables 4.1–4.3) as the package defines
// them: the two test functions, each table's weights, operators, h formula and levels, and the
// columns of their data files.  The programs (src/apps/tables/thesis_truncation.hpp), the registry and
// the plan read them here.
//
// The two readings of h (printed, scaled) are defined in influence_radius.hpp.
#pragma once
#include <string>
#include <vector>

#include "gpm/geometry/influence_radius.hpp"
#include "gpm/operators/fused_errors.hpp"

namespace gpm {



// The thesis' two test functions: Case 1 (quartic) and Case 2 (sin 2π(x+y)).
struct ThesisCase {
  std::string label;     // "case1", "case2" (the tables' columns)
  std::string function;  // test-function registry name
};
const std::vector<ThesisCase>& thesis_cases();

// One table of the thesis, as its program declares it.
struct ThesisTableSpec {
  std::string program;                  // e.g. "thesis_table4_1"
  // The name of the table's weight mix in the calibration and the benchmarks: "thesis4_1".
  std::string mix() const { return "thesis" + program.substr(std::string("thesis_table").size()); }
  std::string summary;                  // --help text
  std::string table;                    // "Table 4.1 (Section 4.1.1)"
  int c = 3, p = 3;                     // h = (3.1^c · 2^-10 · Δx)^(1/p) as printed
  std::vector<ErrorRequest> requests;   // weights × operators, all in one pass
  std::vector<HReading> readings;       // which h readings to run
  std::vector<int> quick_printed, quick_scaled;  // levels of the quick profile per reading
  std::vector<int> paper_levels;        // the thesis' levels (both readings)
  std::string rate_levels;              // levels the thesis takes its rates from, e.g. "10,11"
  // Uniform volumes V_i = |Ω_H|/N are a variant beyond the thesis (it uses Voronoi volumes):
  // in the paper profile they run up to this level only, where their (different) behaviour
  // is already plain, instead of doubling the cost of the thesis' finest levels.
  int paper_uniform_max_level = 10;
};

// The columns of the tables' data files; the first three (h reading, volumes, level) are
// the unit's key.
const std::vector<std::string>& thesis_table_columns();

// The three tables, defined once: their programs, `make plan` and the tests read them here.
const std::vector<ThesisTableSpec>& thesis_table_specs();
const ThesisTableSpec& thesis_table_spec(const std::string& program);  // InputError if unknown

}  // namespace gpm
