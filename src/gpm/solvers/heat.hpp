// The discrete heat problem of the thesis, (3.2), with the θ-method in time:
//
//   (U_i^{k+1} − U_i^k)/Δt − κ Δ_h U_i^{k+θ} = f_i^{k+θ}   for x_i ∈ Ω, k = 0 … K−1,
//   U_i^k = g̃_i^k outside Ω,   U_i^0 = ã_i,
//
// for the thesis' example (§4.3): f = 0, ũ(x, y, t) = exp(−2κπ²t) sin(πx) sin(πy) on all of
// Ω_H, so g̃ = ũ outside Ω and ã = ũ(·, 0).  Because g̃ is a fixed profile s(x) times
// e(t) = exp(−2κπ²t), the boundary contribution M_ΩB g̃^k = e(t^k)·c with c = (M ŝ)_Ω
// computed once.  One step is then
//   (I − θκΔt M_ΩΩ) U^{k+1} = U^k + (1−θ)κΔt (M_ΩΩ U^k + e^k c) + θκΔt e^{k+1} c,
// explicit for θ = 0, otherwise conjugate gradients on the symmetric form
// (D − θκΔt D M_ΩΩ), warm-started from U^k.  The Laplacian (assembled or matrix-free) is
// built once and reused by every step.
//
// Time steps: the thesis defines Δt = T/K (§3.1) but prescribes Δt = 0.0025h², 0.5h², 0.5h
// (§4.3), which rarely divide T.  Two readings:
//   fit   (default) K = ⌈T/Δt₀⌉ (with a 1e-12 relative slack) and Δt = T/K ≤ Δt₀;
//   exact Δt = Δt₀ as prescribed, K = ⌈T/Δt₀⌉ steps, so the last t^K = KΔt₀ ≥ T.
// They differ most for Δt₀ = 0.5h at T = 0.1, where K is 2 or 3: under `fit` Δt jumps by 1.5
// from 2^-8 to 2^-9 while h falls by 1.19, under `exact` Δt falls with h.
//
// Error (4.2): ‖ũ − U‖_{ℓ∞([0,T]; ℓ²(Ω_H))} / ‖ũ‖_{ℓ∞([0,T]; ℓ²(Ω_H))} with the discrete norm
// of §3.3, ‖v‖_{ℓ²(S)} = (Σ_{x_i ∈ S} V_i v_i²)^{1/2}, over ALL particles (S = Ω_H), the
// maxima over t^k, k = 0 … K.  Outside Ω the error is zero (boundary values are exact).
//
// Blow-up: if ‖U^k‖_{ℓ²(Ω_H)} exceeds blowup_factor·‖U^0‖ or any value is not finite, the run
// stops and reports the step, the growth ‖U^k‖/‖U^0‖ and the last one-step amplification.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "gpm/geometry/domain.hpp"
#include "gpm/solvers/heat_cost.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"

namespace gpm {

struct HeatSetting {
  double kappa = 0.5, T = 0.1;
  double theta = 1;          // θ ∈ [0, 1]
  double dt_nominal = 0;     // Δt₀; K = ⌈T/Δt₀⌉ and Δt = T/K (fit_T) or Δt₀ (!fit_T)
  bool fit_T = true;         // the reading of the time step (above)
  double tol = 1e-10;        // CG relative residual per implicit step
  int max_iter = 20000;
  double blowup_factor = 1e6;
  // Implicit steps: start the CG from the extrapolation 2U^k − U^{k−1} (from the second
  // step on) instead of U^k.  Off by default: the stored results were made from U^k, and a
  // different start gives the same solution only to the CG tolerance.
  bool extrapolate = false;
  // Other volumes on the Laplacian's particles (DiscreteLaplacian::volumes_for: V_i = Δx²
  // beside (A.10)'s on one assembled Laplacian, one reading more per series, not one
  // Laplacian more); nullptr: the Laplacian's own.  The series' numbers equal those of a
  // Laplacian built with these volumes, bit for bit.
  const DiscreteLaplacian::Volumes* volumes = nullptr;
  // Called after every step k = 1 … steps_done with U^k on the unknowns; empty: nothing is
  // formed (the Krylov propagator forms U^k only for this).  The tests compare the two
  // propagators' trajectories through it.
  std::function<void(long, const Eigen::VectorXd&)> observe;
  // The implicit steps' CG preconditioned by pc, a P ≈ D − θκΔt D M_ΩΩ (tau_preconditioner.hpp
  // with shift 1/V̄ and scale θκΔt); nullptr: plain CG, the reference of every stored row.
  const Preconditioner* pc = nullptr;
  // The Krylov propagator (heat_krylov.hpp) sizes the subspace of the series that share an
  // operator together.  Series of different size groups share its products but each group
  // takes the size at which its own series settle, the size it would take alone: one run over
  // Tables 4.5-4.7 (one group each) gives every table the rows it gives alone.  The stepper
  // ignores it.
  int size_group = 0;
};

struct HeatResult {
  long K = 0;                // steps of the full run
  double dt = 0;             // T/K (fit_T) or Δt₀
  long steps_done = 0;       // K unless blown up
  bool blew_up = false;
  long blowup_step = -1;     // k with ‖U^k‖ > factor·‖U^0‖ or non-finite
  double growth = 0;         // ‖U^k‖/‖U^0‖ at that step (inf if non-finite)
  double amplification = 0;  // ‖U^k‖/‖U^{k−1}‖ at that step
  double growth_max = 0;     // max_k ‖U^k‖/‖U^0‖ over the steps done: > 1 means unstable
                             // (the exact ℓ² norm decays by exp(−2κπ²t))
  double rel_error = 0;      // (4.2); NaN if blown up
  double rel_error_max = 0;  // the same with ℓ∞(Ω) in space (Theorem 3.1's norm), relative
  double seconds = 0, seconds_per_step = 0;
  double mean_cg_iterations = 0;
  double max_rel_residual = 0;  // largest final CG residual over the implicit steps
  double products = 0;          // Laplacian products spent on the series (its share of a
                                // shared Krylov subspace's)
  int subspace = 0;             // Krylov propagator: the subspace dimension m; 0 when stepped
};

// The fixed vectors of §4.3's example on one Laplacian and volumes, which every propagator
// of the θ-method starts from: V at the unknowns (d), the profile s = ũ(·, 0) there (sk),
// the boundary forcing c = (M ŝ)_Ω, and the norms' constant parts.
struct HeatExample {
  Eigen::VectorXd d, sk, c;
  double out_l2sq = 0;   // Σ_{x_i ∉ Ω} V_i s_i²: the boundary part of ‖ũ(·, t)‖² / e(t)²
  double ref_l2 = 0;     // ‖ũ(·, 0)‖_{ℓ²(Ω_H)}, the denominator of (4.2)
  double max_exact = 0;  // max_Ω |s|, the denominator of the ℓ∞ error
  double lambda = 0;     // e(t) = exp(−λt), λ = 2κπ²
};
HeatExample heat_example(const Particles& p, const DiscreteLaplacian& L,
                         const DiscreteLaplacian::Volumes* volumes, double kappa);

// K = ⌈T/Δt₀⌉: heat_steps (heat_cost.hpp).

// The exact solution of the example.
double heat_exact(double x, double y, double t, double kappa);

HeatResult solve_heat(const Particles& p, const DiscreteLaplacian& L, const HeatSetting& s);

// Several series on one Laplacian (the θ of a table, other time steps), advanced together:
// every product M·x of a step is one block product for all the series that need it
// (DiscreteLaplacian::apply_block), the implicit series' conjugate gradients run in lockstep
// (each with its own α, β and stopping test; a converged series waits), and a series that
// blows up or has fewer steps drops out.  Each result equals solve_heat of its setting alone
// bit for bit (solve_heat is this with one series), except the times: the joint run's wall
// time is split over the series in proportion to their columns in the block products.
std::vector<HeatResult> solve_heat_block(const Particles& p, const DiscreteLaplacian& L,
                                         const std::vector<HeatSetting>& settings);

}  // namespace gpm
