// The smoothing part of the discrete Laplacian of thesis (1.4): what the operator does to a
// smooth function before any particle enters.  Its continuous form
//   L v(x) = 2d ∫ (v(y) − v(x)) w_h(|y − x|)/|y − x|² dy,   w_h(r) = w(r/h)/h^d,
// multiplies a Fourier mode e^{ik·x} by −|k|²(1 − ε(|k|h)) with, in d = 2,
//   ε(kh) = 1 − (8π/(kh)²) ∫₀¹ (1 − J₀(kh·s)) w(s)/s ds.
// ε ~ c(kh)² for small kh (the O(h²) of the truncation-error theorems) and flattens as kh
// approaches 1.  For v = sin 2π(x+y), |k| = 2π√2.  Comparing ε with a measured error shows how
// much of it is the operator's smoothing and how much the particles (or anything else).
#pragma once
#include "gpm/weights/weights.hpp"

namespace gpm {

// ε(kh) for a normalized weight in d = 2 (GSL quadrature and Bessel J₀, to about 1e-12).
double laplacian_smoothing_error(const WeightFunction& w, double kh);

// The same for the gradient of operators.hpp, ∇_h v(p) = d Σ V_i (v_i − v(p))(x_i − p)/r_i² w_h:
// its continuous form maps e^{ik·x} to ik(1 − ε_∇(kh)) e^{ik·x} with, in d = 2,
//   ε_∇(kh) = 1 − (4π/(kh)) ∫₀¹ J₁(kh·s) w(s) ds,
// again ~ c(kh)² for small kh (the normalization 2π∫ s w = 1 makes ε_∇(0) = 0).
double gradient_smoothing_error(const WeightFunction& w, double kh);

// The even radial moments m_q = 2π ∫₀¹ s^(q+1) w(s) ds of a weight (m_0 = 1 when normalized).
double radial_moment(const WeightFunction& w, int q);

// The smoothing part of the interpolant Π_h v = ∫ v(y) w_h(|y − x|) dy for thesis §4.1.1's
// Case 1, v = X⁴ + Y⁴ (X = x − ½, Y = y − ½).  Expanding v(x − y) about x, the odd moments
// vanish and
//   Π_h v − v = 3 m_2 h² (X² + Y²) + (3/4) m_4 h⁴,
// exactly (v is a quartic).  Relative to max_Ω |v| = 1/8, its maximum over Ω = (0,1)² sits at
// a corner (X² + Y² = ½) or at the centre.  A weight of order k = 3 (m_2 = 0: the cubic spike)
// leaves the constant (3/4) m_4 h⁴: the O(h⁴) of Theorem 1.11.
double interpolant_smoothing_error_case1(const WeightFunction& w, double h);

}  // namespace gpm
