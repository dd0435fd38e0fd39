// The thesis' heat tables (§4.3, Tables 4.5–4.7) as one catalog: thesis_heat runs them,
// `make plan` prices them and the tests read them from here.
//
// Each table fixes the time step Δt₀ = c·h^p, the θ values and its levels per profile; the
// rest is common: κ = 0.5, T = 0.1, the three polynomial weights (pde_weights(), catalog.hpp), h by the rule of
// influence_radius.hpp (h10 as printed, h15 the alternative reading).
//
// Trim of the paper profile: the h15 reading stops one level before the finest in Tables
// 4.5 and 4.6.  Table 4.4 (the Poisson problem of the same chapter, same h rules and
// volumes) settles the reading at the documents' own levels: the h10 rates are explained by
// a diagnostic checked against the stored data (the volume mismatch of (A.10)), the h15
// rates are not (report: paper scale, checked reasons).  So the finest heat levels, which
// cost most, run under h10 only; h15 keeps its coarser levels for the comparison, and
// `--levels` still runs any level.
#pragma once
#include <string>
#include <vector>

namespace gpm {

struct HeatTable {
  std::string table;             // "4.5", "4.6", "4.7"
  std::string dt_rule;           // Δt₀ as printed, for the data file's header
  double c = 0;                  // Δt₀ = c·h^p
  int p = 2;
  std::vector<double> thetas;
  std::vector<int> quick, paper;  // levels k, Δx = 2^-k
  std::string rate_levels;        // the levels of the thesis' rates
  int paper_h15_max_level = 99;   // the trim above
};

const std::vector<HeatTable>& heat_tables();
const HeatTable& heat_table(const std::string& table);  // InputError naming the valid ones

// The levels of a table for a profile and h rule (the paper profile's h15 trim applied).
std::vector<int> heat_levels(const HeatTable& t, bool paper, const std::string& h_rule);

constexpr double kHeatKappa = 0.5, kHeatT = 0.1;

// One reading of the heat tables' set-up (paper/04-setup-rule.md): the h rule (h10 as
// printed, h15), the volumes (lattice: (A.10)'s |Ω_H|/N as printed, cell: Δx²) and the time
// step (fit: Δt = T/K as printed, exact: Δt = Δt₀).  The one map from a reading to its name
// in the rate tables and to its store file (the registry's store files carry these names).
struct HeatReading {
  std::string h_rule = "h10", volumes = "lattice", dt_rule = "fit";
  // h10, h15_cell, h10_exact, h15_cell_exact, …
  std::string name() const;
  // The store file's suffix after "thesis_table4_6": "" for the printed reading, else
  // _h15, _dtexact, _cellvol in that order.
  std::string file_suffix() const;
};
// Every combination of the given choices, h rule outermost, then volumes, then time step;
// InputError naming an unknown choice.
std::vector<HeatReading> heat_reading_matrix(const std::vector<std::string>& h_rules,
                                             const std::vector<std::string>& volumes,
                                             const std::vector<std::string>& dt_rules);

// The columns of a heat data file; the first three (weight, θ, level) are the unit's key.
const std::vector<std::string>& heat_columns();

}  // namespace gpm
