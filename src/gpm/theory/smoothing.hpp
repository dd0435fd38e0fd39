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

}  // namespace gpm
