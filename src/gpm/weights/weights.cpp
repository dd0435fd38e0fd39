// Reference weight functions: the evaluation of a weight's pieces and the properties
// computed from them (weights.hpp).  The registry of named weights is in
// weight_registry.cpp, the printed forms that are wrong in weight_errata.cpp.
//
// Every property in WeightProperties is computed from the pieces (GSL quadrature, GSL
// polynomial roots, knot comparisons: piece_algebra.hpp); nothing is copied from the
// documents.
#include "gpm/weights/weights.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "gpm/weights/piece_algebra.hpp"

namespace gpm {
namespace {

using namespace pieces;  // the polynomial algebra (piece_algebra.hpp)

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// imoto Hypothesis 2 with k (eq. (8)): sup|w/r^(k+1)| < ∞ and sup|(w/r^k)'| < ∞ on (0,1).
bool imoto_hypothesis2(const WeightFunction& w, int k) {
  return bounded_on_unit_interval(w.divided_by_power(k + 1)) &&
         bounded_on_unit_interval(derivative_pieces(w.divided_by_power(k)));
}

// Largest even-moment order of Hypothesis 1.1 (thesis Prop. 1.4): k = (first even l whose
// moment ∫ r^(d−1+l) w dr is nonzero) − 1; 99 if l = 2..10 all vanish.
int order_of(const std::vector<PolyPiece>& ps, int d) {
  for (int l = 2; l <= 10; l += 2) {
    const int m = d - 1 + l;
    if (std::abs(integrate(ps, m)) >= 1e-12 * integrate_abs(ps, m)) return l - 1;
  }
  return 99;
}

}  // namespace

// ---------------------------------------------------------------------------------
// PolyPiece and WeightFunction.

double PolyPiece::value(double r) const {
  if (r == 0) return value_at_zero(p_min, c);
  double s = 0;
  for (std::size_t k = c.size(); k-- > 0;) s = s * r + c[k];
  return s * std::pow(r, p_min);
}

double PolyPiece::derivative(double r) const {
  if (r == 0) return derivative_piece(*this).value(0);
  double s = 0;
  for (std::size_t k = c.size(); k-- > 0;) s = s * r + c[k] * (p_min + static_cast<int>(k));
  return s * std::pow(r, p_min - 1);
}

// Support is [0,1): outside it (r ≥ 1, and r < 0, which is no distance) w = w' = 0.
double WeightFunction::value(double r) const {
  if (!(r >= 0 && r < 1)) return 0.0;
  for (auto& p : shape)
    if (r < p.r_end) return constant * p.value(r);
  return 0.0;
}

double WeightFunction::derivative(double r) const {
  if (!(r >= 0 && r < 1)) return 0.0;
  for (auto& p : shape)
    if (r < p.r_end) return constant * p.derivative(r);
  return 0.0;
}

std::vector<PolyPiece> WeightFunction::scaled_pieces() const {
  std::vector<PolyPiece> out = shape;
  for (auto& p : out)
    for (double& x : p.c) x *= constant;
  return out;
}

std::vector<PolyPiece> WeightFunction::divided_by_power(int k) const {
  std::vector<PolyPiece> out = scaled_pieces();
  for (auto& p : out) p.p_min -= k;
  return out;
}

// ---------------------------------------------------------------------------------
// Properties.

WeightProperties compute_properties(const WeightFunction& w) {
  const auto ps = w.scaled_pieces();
  WeightProperties p;
  p.norm_2d = 2 * kPi * integrate(ps, 1);
  p.norm_3d = 4 * kPi * integrate(ps, 2);
  p.order_k = order_of(ps, w.dimension);
  p.positive = positive_on_open_unit_interval(ps);
  p.p0 = lowest_power(ps.front());
  p.continuous = extends_continuously(ps);
  p.c1 = extends_c1(ps);
  p.hyp_1_2 = extends_c1(w.divided_by_power(1));
  p.hyp_1_3 = extends_c1(w.divided_by_power(2));
  for (int k = 0; k <= 3; ++k)
    if (imoto_hypothesis2(w, k)) p.imoto_hyp2_k = k;
  // w/r is integrable at 0 iff p0 ≥ 1; decide divergence from p0, not from the quadrature.
  p.inv_r2_integral = p.p0 <= 0 ? std::copysign(kInf, trimmed(ps.front()).c.front())
                                : 2 * kPi * integrate(ps, -1);
  bool nonnegative_powers = true;
  for (auto& piece : ps) nonnegative_powers = nonnegative_powers && lowest_power(piece) >= 0;
  p.admissible = p.continuous && std::abs(p.norm(w.dimension) - 1) < 1e-12 && nonnegative_powers;
  return p;
}

}  // namespace gpm
