#include "gpm/operators/testfunctions.hpp"

#include <cmath>
#include <numbers>

#include "gpm/error.hpp"

namespace gpm {
namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;

double sin_v(double x, double y) { return std::sin(kTwoPi * (x + y)); }
double sin_d(double x, double y) { return kTwoPi * std::cos(kTwoPi * (x + y)); }
double sin_lap(double x, double y) { return -2 * kTwoPi * kTwoPi * std::sin(kTwoPi * (x + y)); }

double q_v(double x, double y) { return std::pow(x - 0.5, 4) + std::pow(y - 0.5, 4); }
double q_x(double x, double) { return 4 * std::pow(x - 0.5, 3); }
double q_y(double, double y) { return 4 * std::pow(y - 0.5, 3); }
double q_lap(double x, double y) { return 12 * (x - 0.5) * (x - 0.5) + 12 * (y - 0.5) * (y - 0.5); }

double l_v(double x, double y) { return 1 + 2 * x - 3 * y; }
double l_x(double, double) { return 2; }
double l_y(double, double) { return -3; }
double l_lap(double, double) { return 0; }

const std::vector<TestFunction>& table() {
  static const std::vector<TestFunction> t = {
      {"sin2pi", sin_v, sin_d, sin_d, sin_lap},
      {"quartic", q_v, q_x, q_y, q_lap},
      {"linear", l_v, l_x, l_y, l_lap},
  };
  return t;
}
}  // namespace

const TestFunction& test_function(const std::string& name) {
  for (auto& f : table())
    if (f.name == name) return f;
  std::string valid;
  for (auto& f : table()) valid += (valid.empty() ? "" : ", ") + f.name;
  throw InputError("unknown test function '" + name + "'; valid: " + valid);
}

std::vector<std::string> test_function_names() {
  std::vector<std::string> n;
  for (auto& f : table()) n.push_back(f.name);
  return n;
}

}  // namespace gpm
