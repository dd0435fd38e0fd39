#include "gpm/studies/define/cost_model.hpp"

#include <algorithm>
#include <cmath>

#include "gpm/error.hpp"

namespace gpm {

double grid_particle_count(double dx, const Domain& dom) {
  const double n1 = static_cast<double>(grid_last(dx, dom) - grid_first(dx, dom) + 1);
  return n1 * n1;
}

double omega_target_estimate(double dx) {
  require_positive(dx, "dx");
  return 1.0 / (dx * dx);
}

namespace {
// Φ(a) = ∫_0^a φ(t) dt for φ(t) = min(1, 1 + H − t) on t ≥ 0 (φ > 0 for every a ≤ 1 + H).
double Phi(double a, double H) {
  if (a <= H) return a;
  return H + (1 + H) * (a - H) - 0.5 * (a * a - H * H);
}
}  // namespace

double mean_disc_area(double h, const Domain& dom) {
  require_positive(h, "h");
  const double H = dom.H;
  if (h > 1 + H) throw InputError("mean_disc_area: h = " + std::to_string(h) + " exceeds 1 + H");
  if (h <= H) return M_PI * h * h;  // no target's disc leaves Ω_H
  // A = 4 ∫_0^h φ(z₁) Φ(√(h² − z₁²)) dz₁ with z₁ = h sin θ (removes the √ end point
  // singularity); composite midpoint rule on θ ∈ (0, π/2), split at the kink z₁ = H.
  const double th_k = std::asin(std::min(1.0, H / h));
  auto integrate = [&](double a, double b) {
    const int n = 4000;
    double s = 0;
    for (int i = 0; i < n; ++i) {
      const double th = a + (b - a) * (i + 0.5) / n;
      const double z1 = h * std::sin(th), c = h * std::cos(th);
      const double phi = std::min(1.0, 1 + H - z1);
      s += phi * Phi(c, H) * c;  // dz₁ = h cos θ dθ
    }
    return s * (b - a) / n;
  };
  return 4 * (integrate(0, th_k) + integrate(th_k, M_PI / 2));
}

double predicted_pairs(double dx, double h, const Domain& dom) {
  return omega_target_estimate(dx) * mean_disc_area(h, dom) / (dx * dx);
}

PassCost PassCost::fit(double targets, double pairs_a, double secs_a, double pairs_b,
                       double secs_b) {
  if (!(targets > 0) || !(pairs_b > pairs_a) || !(secs_a > 0) || !(secs_b > 0))
    throw InputError("PassCost::fit: needs targets > 0, pairs_b > pairs_a and positive times");
  PassCost c;
  c.per_pair_s = (secs_b - secs_a) / (pairs_b - pairs_a);
  c.per_target_s = (secs_a - c.per_pair_s * pairs_a) / targets;
  if (c.per_target_s < 0 || c.per_pair_s <= 0) {
    c.per_target_s = 0;
    c.per_pair_s = secs_b / pairs_b;
  }
  return c;
}

double poisson_unit_work(double dx, double h) { return predicted_pairs(dx, h) / h; }

double heat_unit_work(double dx, double h, double dt0, double T, double theta) {
  const double its = theta > 0 ? 30 * std::sqrt(dt0 / (h * h)) : 0;
  return std::ceil(T / dt0) * (1 + its) * predicted_pairs(dx, h);
}

}  // namespace gpm
