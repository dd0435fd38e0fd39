#include "gpm/studies/judge/mode_constants.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/theory/smoothing.hpp"

namespace gpm {

namespace {

constexpr int kTerms = 2000;                           // odd n below this
const double kPoissonWave = 2 * M_PI * std::sqrt(2.0);  // |k| of sin 2π(x+y)
const double kHeatWave = M_PI * std::sqrt(2.0);         // |k| of sin πx sin πy

// The coefficient of sin 2πx sin nπy (and of sin nπx sin 2πy) in u − φ, n odd:
// −Δ(u − φ) = 8π²u with zero boundary values, u's sine coefficients 2·2n/(π(n² − 4)).
double coefficient(int n) { return 32.0 * n / (M_PI * (n * n - 4.0) * (n * n + 4.0)); }

// lim ε(|k|h)/h² for a wave number: ε/(kh)² at kh = 1e-2 (the next term is (kh)² smaller).
double smoothing_limit(const WeightFunction& w, double k) {
  const double kh = 1e-2;
  return laplacian_smoothing_error(w, kh) / (kh * kh) * k * k;
}

}  // namespace

double poisson_boundary_defect(double x, double y) {
  double s = 0;
  for (int n = 1; n < kTerms; n += 2)
    s += coefficient(n) * (std::sin(2 * M_PI * x) * std::sin(n * M_PI * y) + std::sin(n * M_PI * x) * std::sin(2 * M_PI * y));
  return s;
}

double poisson_boundary_factor() {
  static const double R = [] {
    // A grid of spacing 1/100 (u − φ is symmetric in x ↔ y), then a 1/4000 grid about the
    // best point: |u − φ| is smooth, so this finds the maximum to about 1e-6.
    double best = 0, bx = 0.5, by = 0.5;
    for (int i = 1; i < 100; ++i)
      for (int j = i; j < 100; ++j) {
        const double v = std::fabs(poisson_boundary_defect(i / 100.0, j / 100.0));
        if (v > best) best = v, bx = i / 100.0, by = j / 100.0;
      }
    const double cx = bx, cy = by;
    for (int i = -40; i <= 40; ++i)
      for (int j = -40; j <= 40; ++j)
        best = std::max(best, std::fabs(poisson_boundary_defect(cx + i / 4000.0, cy + j / 4000.0)));
    return best;
  }();
  return R;
}

double poisson_mode_error(const WeightFunction& w, double h, double mismatch) {
  const double eps = laplacian_smoothing_error(w, kPoissonWave * h);
  return std::fabs(1.0 / ((1 + mismatch) * (1 - eps)) - 1.0) * poisson_boundary_factor();
}

double poisson_constant_limit(const WeightFunction& w) {
  return smoothing_limit(w, kPoissonWave) * poisson_boundary_factor();
}

double heat_constant_limit(const WeightFunction& w, const HeatTable& table, double theta, double rate) {
  // Δt = c·h^p is tiny here (K up to 1e12 steps), so the steps are not taken one by one:
  // g^k = exp(k log g) at 20001 steps k spread over 0..K (the error is smooth in t = kΔt).
  const double h = 2e-3, mu = kHeatKappa * kHeatWave * kHeatWave;
  const double dt = table.c * std::pow(h, table.p);
  const double K = std::ceil(kHeatT / dt - 1e-9);
  const double eps = laplacian_smoothing_error(w, kHeatWave * h), z = mu * (1 - eps) * dt;
  const double log_g = std::log1p(-(1 - theta) * z) - std::log1p(theta * z);
  double worst = 0;
  for (int i = 0; i <= 20000; ++i) {
    const double k = std::round(K * i / 20000.0);
    worst = std::max(worst, std::fabs(std::exp(k * log_g) - std::exp(-mu * k * dt)));
  }
  return worst / std::pow(h, rate);
}

}  // namespace gpm
