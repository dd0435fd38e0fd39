// The heat solvers' step count and predicted Laplacian products: small pure functions that the
// solvers (the θ-method's K, the `automatic` propagator's choice) and the pricer share.  Kept
// apart from heat.hpp and heat_krylov.hpp so that a program that only prices heat units (every
// program, through the registry) is not built from the solvers themselves: its code
// fingerprint then does not move with them (cmake/fingerprint.cmake).
#pragma once

namespace gpm {

// K = ⌈T/Δt₀⌉ with a relative slack of 1e-12 (so Δt₀ = T/10 gives K = 10, not 11).
long heat_steps(double T, double dt_nominal);

// Predicted Laplacian products of one series stepped: K products, and for θ > 0 the CG's
// iterations plus one true residual per step (iterations ≈ 30·√(Δt₀/h²), cost_model.hpp).
double heat_stepped_products(double dx, double h, double dt0, double T, double theta);
// Predicted dimension of the Krylov subspace for a level and h (calibrated on the measured
// dimensions: bench/README, the plan), and so its products (one per dimension).
double heat_krylov_products(double dx, double h);

}  // namespace gpm
