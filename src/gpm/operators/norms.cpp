#include "gpm/operators/norms.hpp"

#include <cmath>
#include <limits>

#include "gpm/error.hpp"

namespace gpm {

double max_abs(const std::vector<double>& a, const std::vector<uint8_t>& mask) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (mask.empty() || mask[i]) {
      if (!std::isfinite(a[i]))
        throw NumericalError("non-finite value at particle " + std::to_string(i));
      m = std::max(m, std::fabs(a[i]));
    }
  return m;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b,
                    const std::vector<uint8_t>& mask) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (mask.empty() || mask[i]) {
      const double d = a[i] - b[i];
      if (!std::isfinite(d))
        throw NumericalError("non-finite value at particle " + std::to_string(i));
      m = std::max(m, std::fabs(d));
    }
  return m;
}

double two_level_rate(double h1, double e1, double h2, double e2) {
  if (!(e1 > 0 && e2 > 0 && h1 > 0 && h2 > 0) || h1 == h2)
    return std::numeric_limits<double>::quiet_NaN();
  return std::log(e1 / e2) / std::log(h1 / h2);
}

double least_squares_rate(const std::vector<double>& h, const std::vector<double>& e) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t k = 0; k < h.size() && k < e.size(); ++k) {
    if (!(h[k] > 0 && e[k] > 0)) continue;
    const double x = std::log(h[k]), y = std::log(e[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
  }
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  const double den = n * sxx - sx * sx;
  return den != 0 ? (n * sxy - sx * sy) / den : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace gpm
