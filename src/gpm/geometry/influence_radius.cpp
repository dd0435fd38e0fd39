#include "gpm/geometry/influence_radius.hpp"

#include <cmath>

#include "gpm/error.hpp"

namespace gpm {

double imoto_h(double m, double dx) {
  require_positive(m, "regular order m");
  require_positive(dx, "dx");
  return 2.6 * std::pow(2.0, 5.0 / m - 5.0) * std::pow(dx, 1.0 / m);
}

std::string h_reading_name(HReading r) { return r == HReading::printed ? "printed" : "scaled"; }

HReading parse_h_reading(const std::string& s) {
  if (s == "printed") return HReading::printed;
  if (s == "scaled") return HReading::scaled;
  throw InputError("unknown h reading '" + s + "'; valid: printed, scaled");
}

double thesis_h(HReading r, int c, int p, double dx) {
  require_positive(dx, "dx");
  if (p <= 0 || c <= 0) throw InputError("thesis_h: powers c and p must be positive");
  if (r == HReading::printed)
    return std::pow(std::pow(3.1, c) * std::ldexp(1.0, -10) * dx, 1.0 / p);
  return 3.1 * std::pow(2.0, 5.0 / p - 5.0) * std::pow(dx, 1.0 / p);
}

std::string h_rule_name(HRule r) { return r == HRule::h10 ? "h10" : "h15"; }

HRule parse_h_rule(const std::string& s, const std::string& option) {
  for (HRule r : pde_h_rules())
    if (h_rule_name(r) == s) return r;
  throw InputError(option + ": '" + s + "' is not h10 or h15");
}

namespace {
int pde_exponent(HRule rule) { return rule == HRule::h10 ? -10 : -15; }
}  // namespace

double pde_h(HRule rule, double dx) {
  require_positive(dx, "dx");
  return std::pow(std::pow(2.6, 4) * std::ldexp(1.0, pde_exponent(rule)) * dx, 0.25);
}

std::string pde_h_formula(HRule rule) {
  return "(2.6^4 2^" + std::to_string(pde_exponent(rule)) + " dx)^(1/4)";
}

const std::vector<HRule>& pde_h_rules() {
  static const std::vector<HRule> r = {HRule::h10, HRule::h15};
  return r;
}

}  // namespace gpm
