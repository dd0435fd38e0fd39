// The thesis' heat tables (§4.3, Tables 4.5–4.7) as one catalog: thesis_heat runs them,
// `make plan` prices them and the tests read them from here.
//
// Each table fixes the time step Δt₀ = c·h^p, the θ values and its levels per profile; the
// rest is common: κ = 0.5, T = 0.1, the three polynomial weights (pde_weights(), catalog.hpp), h by the rule of
// influence_radius.hpp (h10 as printed, h15 the alternative reading).
//
// The paper profile runs every reading at the table's paper levels; which readings, seeds
// and levels past the thesis' the store holds is the census' (heat_store_readings,
// heat_band_seeds, heat_beyond in define/census.hpp).  `--levels` runs any level.
#pragma once
#include <string>
#include <vector>

#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"

namespace gpm {

struct HeatTable {
  std::string table;             // "4.5", "4.6", "4.7"
  std::string dt_rule;           // Δt₀ as printed, for the data file's header
  double c = 0;                  // Δt₀ = c·h^p
  int p = 2;
  std::vector<double> thetas;
  std::vector<int> quick, paper;  // levels k, Δx = 2^-k
  std::string rate_levels;        // the levels of the thesis' rates
};

const std::vector<HeatTable>& heat_tables();
const HeatTable& heat_table(const std::string& table);  // InputError naming the valid ones
// The registry's name of a table's study (the data file of its printed reading): thesis_table4_6.
std::string heat_study_name(const HeatTable& t);

constexpr double kHeatKappa = 0.5, kHeatT = 0.1;

// The time-step rule: fit, Δt = T/K with K = ⌈T/Δt₀⌉ (the thesis' Δt = T/K, as printed), or
// exact, Δt = Δt₀.  Its name is what options and the set-up readings say.
enum class DtRule { fit, exact };
std::string dt_rule_name(DtRule r);
// InputError "OPTION: 'x' is not fit or exact".
DtRule parse_dt_rule(const std::string& s, const std::string& option = "--dt-rule");

// One reading of Chapter 4's PDE set-up (paper/04-setup-rule.md): the h rule (h10 as printed,
// h15), the volumes (lattice: (A.10)'s |Ω_H|/N as printed, cell: Δx²) and the time step (fit
// as printed, exact).  The one map from a reading to its name in the rate tables and to its
// store file (the registry's store files carry these names).
struct PdeReading {
  HRule h_rule = HRule::h10;
  PdeVolumes volumes = PdeVolumes::lattice;
  DtRule dt_rule = DtRule::fit;
  // h10, h15_cell, h10_exact, h15_cell_exact, …
  std::string name() const;
  // The store file's suffix after "thesis_table4_6": "" for the printed reading, else
  // _h15, _dtexact, _cellvol in that order.
  std::string file_suffix() const;
  // The reading of that name; InputError if none.
  static PdeReading named(const std::string& name);
};
// Every combination of the given choices, h rule outermost, then volumes, then time step;
// InputError for an empty choice or a reading given twice.
std::vector<PdeReading> pde_reading_matrix(const std::vector<HRule>& h_rules, const std::vector<PdeVolumes>& volumes,
                                       const std::vector<DtRule>& dt_rules);
// The eight readings (h10, h10_exact, h10_cell, …).
const std::vector<PdeReading>& pde_readings();

// The columns of a heat data file; the first three (weight, θ, level) are the unit's key.
const std::vector<std::string>& heat_columns();

}  // namespace gpm
