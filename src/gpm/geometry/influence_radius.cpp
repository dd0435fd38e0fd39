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

namespace {
int pde_exponent(const std::string& rule) {
  if (rule == "h10") return -10;
  if (rule == "h15") return -15;
  throw InputError("unknown h rule '" + rule + "'; valid: h10, h15");
}
}  // namespace

double pde_h(const std::string& rule, double dx) {
  const int e = pde_exponent(rule);
  require_positive(dx, "dx");
  return std::pow(std::pow(2.6, 4) * std::ldexp(1.0, e) * dx, 0.25);
}

std::string pde_h_formula(const std::string& rule) {
  return "(2.6^4 2^" + std::to_string(pde_exponent(rule)) + " dx)^(1/4)";
}

const std::vector<std::string>& pde_h_rules() {
  static const std::vector<std::string> r = {"h10", "h15"};
  return r;
}

}  // namespace gpm
