// The θ-method of heat.hpp propagated in a Krylov subspace instead of stepped.
//
// The recurrence has a constant matrix and a constant step: with a = κΔt,
//   (I − θaM) U^{k+1} = (I + (1−θ)aM) U^k + a((1−θ)e^k + θe^{k+1}) c,   U^0 = s,
// where e^k = exp(−λkΔt) and c = (M ŝ)_Ω is one fixed vector (heat.hpp).  M is self-adjoint in
// the volume inner product (D M symmetric, laplacian_matrix.hpp), so with S = diag(√V) the
// map Ã = S M S⁻¹ is symmetric and y = S U obeys the same recurrence with Ã and S c.  Every
// iterate lies in the Krylov space of Ã built from [S s, S c]; the propagator builds an
// orthonormal basis Q of that space (block Lanczos of width 2 with full re-orthogonalization,
// twice: Arnoldi on a symmetric map), diagonalizes T = QᵀÃQ = WΛWᵀ and runs each mode as a
// scalar recurrence,
//   ξ_j^{k+1} = r_j ξ_j^k + g_j((1−θ)e^k + θe^{k+1}) η_j,
//   r_j = (1 + (1−θ)aμ_j)/(1 − θaμ_j),  g_j = a/(1 − θaμ_j),
// with ξ⁰ = WᵀQᵀSs and η = WᵀQᵀSc.  The error (4.2) of step k is a difference of coordinates:
// ‖ũ^k − U^k‖_{ℓ²(Ω)} = ‖e^k ξ⁰ − ξ^k‖ (the exact solution is e^k s on Ω, and outside Ω the
// error is zero), so no N-vector is formed per step.  The ℓ∞ error of each step needs the
// vector S⁻¹QW(e^k ξ⁰ − ξ^k); its maximum over the steps is found exactly by bounding each
// step from an evaluated neighbour (|(Vz)_i − (Vz')_i| ≤ Σ_j max_i|V_ij|·|z_j − z'_j|) and
// evaluating only the steps whose bound reaches the running maximum.
//
// How large a subspace: decided a posteriori.  The basis grows (m, then about m + m/6, …) and
// at each size every series is run in the old and the new subspace; once the coefficient
// trajectories (in the basis Q, every step) differ by less than tol times the series' largest
// error ‖e^k ξ⁰ − ξ^k‖, the larger subspace is taken.  Where that error is a small part of the
// solution, the tolerance can lie below what double precision resolves: 1e-10 of an error of
// 1.6e-4 is 1.6e-14 of the data, and Table 4.5's piecewise quintic at 2^-9 (seed 2) moves by
// 1e-14 to 2e-12 of the data from m = 282 on, size after size: one run met the tolerance by
// chance (m = 526), a re-run had not met it by m = 836, and at 2^-10 no size up to 850 met it.
// So a change that has stopped falling (by less than `stall` from one size to the next) while
// below `rounding` of the series' largest value (its data's norm ‖S U⁰‖ or a larger iterate's)
// is rounding, and the larger subspace is taken as well; the progress callback says which stop
// was met.  An invariant subspace (the space is exhausted, e.g. θ = 0 after m = 2(K+1)) is
// exact.  One subspace serves every series that shares the operator (every θ and time step of
// one Laplacian and one choice of volumes); its size is decided per size group
// (HeatSetting::size_group): each group keeps the modes of the size its own series settled at,
// the first m columns of a basis grown further being the basis grown to m, so a group's
// numbers are those it gives alone, bit for bit (tests/unit/test_heat_krylov.cpp).
//
// Validated against the stepper (tests/unit/test_heat_krylov.cpp: trajectories and errors
// equal to 1e-9 of the error), which stays the reference: --propagator stepped.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "gpm/solvers/heat.hpp"

namespace gpm {

// One larger size tried: how far the series' trajectories moved from the previous size, the
// largest over the series in units of each one's largest error (`change`) and of its largest
// value (`of_data`), and whether the subspace was taken with a series settled by rounding
// (see above) rather than within tol.
struct KrylovTry {
  int m = 0;
  double change = 0, of_data = 0;
  bool rounding = false;
};

struct KrylovSettings {
  double tol = 1e-10;        // the trajectories' change between two sizes, relative to the error
  double rounding = 1e-10;   // relative to a series' largest value: below this a stalled change is rounding
  double stall = 4;          // a change falling by less than this factor per size has stalled
  int first = 32;            // the first size tried
  int max_dim = 3000;        // NumericalError when no size up to this converges
  // Told after each larger size is tried: a fine level's subspace takes an hour, and a run
  // should say so.
  std::function<void(const KrylovTry&)> on_size;
};

// Every series of `settings` (any θ, time step and volumes; blow-up guards as in solve_heat)
// through the Krylov subspace of its operator; results as solve_heat_block gives them, with
// `subspace` the dimension used and `products` the series' share of the subspace's products
// (mean_cg_iterations and max_rel_residual are 0: there is no CG).  Throws NumericalError if
// the subspace does not converge within max_dim or a value is not finite where the stepper's
// would be.
std::vector<HeatResult> propagate_heat(const Particles& p, const DiscreteLaplacian& L,
                                       const std::vector<HeatSetting>& settings,
                                       const KrylovSettings& ks = {});

// Which propagator runs a series: the stepper (heat.hpp), the Krylov subspace, or `automatic`,
// the one with fewer predicted Laplacian products (heat_stepped_products against
// heat_krylov_products).
enum class HeatPropagator { stepped, krylov, automatic };
HeatPropagator parse_heat_propagator(const std::string& s);  // InputError if unknown
std::string heat_propagator_name(HeatPropagator p);          // stepped, krylov, auto

// (heat_stepped_products and heat_krylov_products: heat_cost.hpp.)

// Each series by its propagator (how[i]; one entry: every series): `automatic` sends to the
// Krylov subspace the series whose predicted stepped products exceed the subspace's, the
// others to the stepper.  Results in the order of `settings`.
std::vector<HeatResult> run_heat(const Particles& p, const DiscreteLaplacian& L,
                                 const std::vector<HeatSetting>& settings,
                                 const std::vector<HeatPropagator>& how, double dx,
                                 const KrylovSettings& ks = {});

}  // namespace gpm
