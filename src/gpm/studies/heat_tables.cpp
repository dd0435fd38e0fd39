#include "gpm/studies/heat_tables.hpp"

#include "gpm/error.hpp"

namespace gpm {

const std::vector<HeatTable>& heat_tables() {
  // Quick levels: each table in a few minutes here; paper levels: the thesis' own.  Table
  // 4.5's small steps make 2^-7 cost minutes, so its quick series starts at 2^-4 to have three
  // points (a convergence plot is never drawn through two); the paper profile keeps that
  // coarse level too (seconds), so that the quick units stay a part of the paper's.
  static const std::vector<HeatTable> t = {
      {"4.5", "0.0025 h^2", 0.0025, 2, {0, 0.5, 1}, {4, 5, 6}, {4, 5, 6, 7, 8}, "7,8", 7},
      {"4.6", "0.5 h^2", 0.5, 2, {0, 0.5, 1}, {5, 6, 7}, {5, 6, 7, 8, 9}, "8,9", 8},
      // 4.7's finest h15 level is cheap (about 10 min here) and already stored: no trim.
      {"4.7", "0.5 h", 0.5, 1, {0.5, 1}, {5, 6, 7}, {5, 6, 7, 8, 9}, "8,9", 99},
  };
  return t;
}

const HeatTable& heat_table(const std::string& table) {
  if (table.empty()) throw InputError("--table is required: 4.5, 4.6 or 4.7");
  for (auto& t : heat_tables())
    if (t.table == table) return t;
  throw InputError("unknown --table '" + table + "'; valid: 4.5, 4.6, 4.7");
}

std::vector<int> heat_levels(const HeatTable& t, bool paper, const std::string& h_rule) {
  if (!paper) return t.quick;
  std::vector<int> lv;
  for (int k : t.paper)
    if (h_rule != "h15" || k <= t.paper_h15_max_level) lv.push_back(k);
  return lv;
}

std::string HeatReading::name() const {
  return h_rule + (volumes == "cell" ? "_cell" : "") + (dt_rule == "exact" ? "_exact" : "");
}

std::string HeatReading::file_suffix() const {
  return std::string(h_rule == "h15" ? "_h15" : "") + (dt_rule == "exact" ? "_dtexact" : "") +
         (volumes == "cell" ? "_cellvol" : "");
}

std::vector<HeatReading> heat_reading_matrix(const std::vector<std::string>& h_rules,
                                             const std::vector<std::string>& volumes,
                                             const std::vector<std::string>& dt_rules) {
  auto check = [](const std::vector<std::string>& given, const char* option,
                  std::initializer_list<const char*> valid) {
    if (given.empty()) throw InputError(std::string("--") + option + ": no choice given");
    for (auto& g : given) {
      bool ok = false;
      for (const char* v : valid) ok = ok || g == v;
      std::string names;
      for (const char* v : valid) names += (names.empty() ? "" : ", ") + std::string(v);
      if (!ok) throw InputError(std::string("--") + option + ": '" + g + "' is not one of " + names);
    }
  };
  check(h_rules, "h-rule", {"h10", "h15"});
  check(volumes, "volumes", {"lattice", "cell"});
  check(dt_rules, "dt-rule", {"fit", "exact"});
  std::vector<HeatReading> m;
  for (auto& h : h_rules)
    for (auto& v : volumes)
      for (auto& d : dt_rules) {
        HeatReading r{h, v, d};
        for (auto& o : m)
          if (o.name() == r.name()) throw InputError("reading " + r.name() + " given twice");
        m.push_back(r);
      }
  return m;
}

const std::vector<std::string>& heat_columns() {
  static const std::vector<std::string> c = {
      "weight", "theta", "level", "dx", "h", "N", "N_omega", "storage", "K", "dt", "rel_error",
      "rel_error_max", "growth_max", "blew_up", "blowup_step", "growth", "amplification",
      "steps_done", "cg_mean_iterations", "max_rel_residual", "s_per_step", "seconds"};
  return c;
}

}  // namespace gpm
