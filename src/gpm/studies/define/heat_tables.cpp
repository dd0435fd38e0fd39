#include "gpm/studies/define/heat_tables.hpp"

#include <algorithm>

#include "gpm/error.hpp"

namespace gpm {

const std::vector<HeatTable>& heat_tables() {
  // Quick levels: each table in a few minutes here; paper levels: the thesis' own.  Table
  // 4.5's small steps make 2^-7 cost minutes, so its quick series starts at 2^-4 to have three
  // points (a convergence plot is never drawn through two); the paper profile keeps that
  // coarse level too (seconds), so that the quick units stay a part of the paper's.
  static const std::vector<HeatTable> t = {
      {"4.5", "0.0025 h^2", 0.0025, 2, {0, 0.5, 1}, {4, 5, 6}, {4, 5, 6, 7, 8}, "7,8"},
      {"4.6", "0.5 h^2", 0.5, 2, {0, 0.5, 1}, {5, 6, 7}, {5, 6, 7, 8, 9}, "8,9"},
      {"4.7", "0.5 h", 0.5, 1, {0.5, 1}, {5, 6, 7}, {5, 6, 7, 8, 9}, "8,9"},
  };
  return t;
}

const HeatTable& heat_table(const std::string& table) {
  if (table.empty()) throw InputError("--table is required: 4.5, 4.6 or 4.7");
  for (auto& t : heat_tables())
    if (t.table == table) return t;
  throw InputError("unknown --table '" + table + "'; valid: 4.5, 4.6, 4.7");
}

std::string heat_study_name(const HeatTable& t) {
  std::string name = "thesis_table" + t.table;
  std::replace(name.begin(), name.end(), '.', '_');
  return name;
}

std::string dt_rule_name(DtRule r) { return r == DtRule::fit ? "fit" : "exact"; }

DtRule parse_dt_rule(const std::string& s, const std::string& option) {
  for (DtRule r : {DtRule::fit, DtRule::exact})
    if (dt_rule_name(r) == s) return r;
  throw InputError(option + ": '" + s + "' is not fit or exact");
}

std::string PdeReading::name() const {
  return h_rule_name(h_rule) + (volumes == PdeVolumes::cell ? "_cell" : "") + (dt_rule == DtRule::exact ? "_exact" : "");
}

std::string PdeReading::file_suffix() const {
  return std::string(h_rule == HRule::h15 ? "_h15" : "") + (dt_rule == DtRule::exact ? "_dtexact" : "") +
         (volumes == PdeVolumes::cell ? "_cellvol" : "");
}

PdeReading PdeReading::named(const std::string& name) {
  for (const PdeReading& r : pde_readings())
    if (r.name() == name) return r;
  throw InputError("unknown set-up reading '" + name + "'");
}

std::vector<PdeReading> pde_reading_matrix(const std::vector<HRule>& h_rules, const std::vector<PdeVolumes>& volumes,
                                       const std::vector<DtRule>& dt_rules) {
  if (h_rules.empty()) throw InputError("--h-rule: no choice given");
  if (volumes.empty()) throw InputError("--volumes: no choice given");
  if (dt_rules.empty()) throw InputError("--dt-rule: no choice given");
  std::vector<PdeReading> m;
  for (HRule h : h_rules)
    for (PdeVolumes v : volumes)
      for (DtRule d : dt_rules) {
        const PdeReading r{h, v, d};
        for (auto& o : m)
          if (o.name() == r.name()) throw InputError("reading " + r.name() + " given twice");
        m.push_back(r);
      }
  return m;
}

const std::vector<PdeReading>& pde_readings() {
  static const std::vector<PdeReading> all =
      pde_reading_matrix({HRule::h10, HRule::h15}, {PdeVolumes::lattice, PdeVolumes::cell}, {DtRule::fit, DtRule::exact});
  return all;
}

const std::vector<std::string>& heat_columns() {
  static const std::vector<std::string> c = {
      "weight", "theta", "level", "dx", "h", "N", "N_omega", "storage", "propagator", "subspace", "K", "dt", "rel_error",
      "rel_error_max", "growth_max", "blew_up", "blowup_step", "growth", "amplification",
      "steps_done", "cg_mean_iterations", "max_rel_residual", "s_per_step", "seconds"};
  return c;
}

}  // namespace gpm
