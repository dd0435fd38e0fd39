// Time-step stability of the θ-method for the discrete heat problem (thesis (3.2)).
//
// With f = 0 and g̃ = 0 (the difference of two solutions obeys exactly this) one step is
//   U^{k+1} = G U^k,   G = (I − θκΔt M)^{-1} (I + (1−θ)κΔt M),   M = M_ΩΩ.
// M = −D^{-1} S with S = −D M symmetric (laplacian_matrix.hpp), so M is self-adjoint in the
// D-inner product ⟨x, y⟩_D = Σ V_j x_j y_j (the §3.3 ℓ² norm) and has real eigenvalues −λ,
// λ ≥ 0.  G is a rational function of M, hence also D-self-adjoint, and
//   ‖G‖_D = max_λ |g(κΔtλ)|,   g(μ) = (1 − (1−θ)μ) / (1 + θμ).
// g < 1 for every μ > 0; g ≥ −1 ⟺ (1 − 2θ)μ ≤ 2.  So for θ < ½ the scheme is stable in the
// ℓ² norm exactly when
//   Δt ≤ Δt* = 2 / ((1 − 2θ) κ λ_max),
// and for Δt > Δt* the top mode grows by |g(κΔtλ_max)| > 1 per step.  For θ ≥ ½ there is
// no limit.  λ_max is computed by Lanczos on the symmetric form B = D^{1/2}(−M)D^{-1/2}.
//
// The thesis' bound (3.3) instead guarantees the discrete maximum principle (Lemma 3.3,
// condition (3.7): every coefficient of the explicit part non-negative), which needs
//   Δt ≤ 1 / ((1−θ) κ max_j |M_jj|),   |M_jj| = 2d Σ_{i≠j} V_i w_h(r_ij)/r_ij².
// (3.3) replaces max_j |M_jj| by 2d c_w/h², c_w = ∫_{R^d} w(|x|)/|x|² dx, times 1/δ.
#pragma once
#include <cstdint>

#include <Eigen/Core>

#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

// --- Largest eigenvalue of −M_ΩΩ -----------------------------------------------------------
struct LanczosResult {
  double lambda_max = 0;  // largest Ritz value (≤ λ_max up to rounding)
  double residual = 0;    // ‖B v − θ v‖ of its Ritz pair: an eigenvalue lies within it
  int iterations = 0;     // Lanczos steps = products with M
  bool converged = false;
};

// Plain Lanczos (no reorthogonalization: the extreme Ritz value converges first and is
// not disturbed by the ghost copies the loss of orthogonality produces) from a seeded
// random start.  Stops when residual ≤ tol · lambda_max, or on an invariant subspace.
// The residual bounds the distance to an eigenvalue; the Ritz value itself is accurate to
// about residual²/gap (at 2^-6 tol = 1e-4 and 1e-6 give the same λ_max to 5 digits).
// Throws NumericalError if max_iter is reached without convergence or a value is not finite.
LanczosResult largest_eigenvalue(const DiscreteLaplacian& L, double tol = 1e-4,
                                 int max_iter = 1000, uint64_t seed = 1);

// --- Time-step limits ----------------------------------------------------------------------
// g(μ) above: the factor of the mode with eigenvalue −λ, μ = κΔtλ.
double theta_amplification(double mu, double theta);
// Δt* = 2/((1−2θ)κλ_max); +inf for θ ≥ ½.
double stability_limit(double lambda_max, double kappa, double theta);
// The thesis' bound (3.3): min{ δ/(2dκ(1−θ)) c_w^{-1} h², 1/(1−θ) } for θ ∈ [0, 1).
double thesis_bound_33(const WeightFunction& w, double h, double kappa, double theta,
                       double delta = 1.0, int d = 2);
// Condition (3.7) of Lemma 3.3 on the actual particles: 1/((1−θ)κ max_j |M_jj|).
double thesis_condition_37(const DiscreteLaplacian& L, double kappa, double theta);

// --- A run of the homogeneous problem --------------------------------------------------------
struct StabilityRun {
  long steps = 0;            // steps taken
  double growth_max = 0;     // max_{k ≥ 1} ‖U^k‖_D / ‖U^0‖_D
  double growth_final = 0;   // ‖U^n‖_D / ‖U^0‖_D at the last step
  double last_factor = 0;    // ‖U^n‖_D / ‖U^{n−1}‖_D (→ |g(κΔtλ_max)| when unstable)
  bool grew = false;         // stopped because growth exceeded stop_growth (or non-finite)
  double cg_mean_iterations = 0;
  double seconds = 0;
};

// The θ-method with f = 0, zero values outside Ω, and seeded random U^0 in Ω (every mode
// present, so the top one cannot be missed).  Runs max_steps steps, or stops early when
// ‖U^k‖ > stop_growth·‖U^0‖.  Implicit steps: CG on D(I − θκΔt M), tolerance cg_tol.
StabilityRun run_homogeneous(const DiscreteLaplacian& L, double kappa, double theta, double dt,
                             long max_steps, double stop_growth, uint64_t seed,
                             double cg_tol = 1e-10);

}  // namespace gpm
