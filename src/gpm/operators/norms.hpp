// Norms and convergence rates as the documents define them.
//
// Relative errors: ‖v − v_h‖_{ℓ∞(Ω)} / ‖v‖, the max over particles in Ω (imoto §5,
// thesis §4.1).  Rates: the documents quote the two-finest-level slope
// log(e₁/e₂)/log(h₁/h₂); we also give a least-squares slope over all levels.
#pragma once
#include <cstdint>
#include <vector>

namespace gpm {

// max_i |a_i| over the particles flagged in `mask` (all if mask is empty).
double max_abs(const std::vector<double>& a, const std::vector<uint8_t>& mask = {});
// max_i |a_i − b_i| over the flagged particles.
double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b,
                    const std::vector<uint8_t>& mask = {});

// log(e1/e2) / log(h1/h2): the documents' "numerical convergence rate".
double two_level_rate(double h1, double e1, double h2, double e2);
// Least-squares slope of log e against log h over the points with h, e > 0, and the half-width
// of its 95 % confidence interval (Student's t with points − 2 degrees of freedom: the scatter
// of the points about the line, so a series whose rate drifts with the level gets a wide
// interval).  Slope NaN under two points; half-width NaN under three.
struct RateFit {
  double slope, half95;
  int points;
};
RateFit least_squares_fit(const std::vector<double>& h, const std::vector<double>& e);
// Its slope alone.
double least_squares_rate(const std::vector<double>& h, const std::vector<double>& e);

}  // namespace gpm
