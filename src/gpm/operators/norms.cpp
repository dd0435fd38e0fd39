#include "gpm/operators/norms.hpp"

#include <cmath>
#include <limits>

#include <gsl/gsl_cdf.h>

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

RateFit least_squares_fit(const std::vector<double>& h, const std::vector<double>& e) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> xs, ys;
  for (std::size_t k = 0; k < h.size() && k < e.size(); ++k)
    if (h[k] > 0 && e[k] > 0 && std::isfinite(h[k]) && std::isfinite(e[k]))
      xs.push_back(std::log(h[k])), ys.push_back(std::log(e[k]));
  RateFit fit{nan, nan, static_cast<int>(xs.size())};
  if (fit.points < 2) return fit;
  // Centred sums: the slope and its residual scatter without cancellation.
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) mx += xs[k], my += ys[k];
  mx /= fit.points, my /= fit.points;
  double sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) sxx += (xs[k] - mx) * (xs[k] - mx), sxy += (xs[k] - mx) * (ys[k] - my);
  if (!(sxx > 0)) return fit;
  fit.slope = sxy / sxx;
  if (fit.points < 3) return fit;  // two points fit exactly: no scatter to measure
  double ssr = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double r = ys[k] - my - fit.slope * (xs[k] - mx);
    ssr += r * r;
  }
  const int dof = fit.points - 2;
  fit.half95 = gsl_cdf_tdist_Pinv(0.975, dof) * std::sqrt(ssr / dof / sxx);
  return fit;
}

double least_squares_rate(const std::vector<double>& h, const std::vector<double>& e) {
  return least_squares_fit(h, e).slope;
}

}  // namespace gpm
