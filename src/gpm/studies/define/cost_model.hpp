// The cost model: how much work a study level will be, known before it runs.
//
// Every study spends its time in neighbour sums over the pairs (target j in Ω, particle i
// with |x_i − x_j| < h).  Their number is predictable from Δx and h alone: the jittered grid
// has density 1/Δx² in Ω_H, so a target at x sees about |B(x, h) ∩ Ω_H| / Δx² particles
// (the target itself included: it is one of the grid's points).  Averaged over the targets,
// which fill Ω uniformly,
//
//   pairs ≈ N_Ω · A(h) / Δx²,   A(h) = (1/|Ω|) ∫_Ω |B(x, h) ∩ Ω_H| dx
//         = ∫_{|z|<h} φ(z₁) φ(z₂) dz,   φ(t) = |{s ∈ (0,1) : s + t ∈ (−H, 1+H)}| = min(1, 1+H−|t|),
//
// exact in expectation for a uniform density.  A(h) = πh² while h ≤ H; above H the disc
// of a target near ∂Ω is cut by the edge of Ω_H (the thesis' printed h exceeds H = 0.1 on the
// coarse levels), which the plain estimate N_Ω·πh²/Δx² over-counts (by 6.6 % against the
// counted pairs for Table 4.2's printed h = 0.25 at Δx = 2^-5).
// N_Ω ≈ 1/Δx²: the grid nodes strictly inside Ω, plus the edge nodes whose jitter (|η| < ¼,
// symmetric) moves them inward with probability ½.  tests/unit/test_cost_model.cpp compares
// the prediction with counted pairs.
//
// Time: a fused pass costs t = a·N_Ω + b·pairs (per-target work — exact values, error
// maxima, bookkeeping — plus per-pair work); a and b are fitted on the spot from two timed
// passes of the study's own weight mix (study_plan.cpp).
#pragma once
#include "gpm/geometry/domain.hpp"

namespace gpm {

// Particles of jittered_grid(dx): (last − first + 1)², exact.
double grid_particle_count(double dx, const Domain& dom = Domain{});

// Expected particles in Ω (the targets of every study): 1/Δx².
double omega_target_estimate(double dx);

// A(h) above: the mean area of B(x, h) ∩ Ω_H over x ∈ Ω (quadrature, relative error < 1e-9).
double mean_disc_area(double h, const Domain& dom = Domain{});

// Predicted pairs of one pass over the targets in Ω: (1/Δx²) · A(h)/Δx².
double predicted_pairs(double dx, double h, const Domain& dom = Domain{});

// Relative work of the PDE units, for dealing them over the ranks of a cluster (the plan has
// the calibrated model; these need only be in proportion).  A product costs the non-zeros,
// predicted_pairs.  A Poisson solve: iterations ∝ 1/h.  A heat run: K = ⌈T/Δt₀⌉ steps of one
// product plus (θ > 0) CG iterations ≈ 30·√(Δt₀/h²) (measured 3 at Δt₀ = 0.0025h², 14–22 at
// 0.5h²).
double poisson_unit_work(double dx, double h);
double heat_unit_work(double dx, double h, double dt0, double T, double theta);

// t = per_target·targets + per_pair·pairs, seconds.
struct PassCost {
  double per_target_s = 0, per_pair_s = 0;
  double seconds(double targets, double pairs) const {
    return per_target_s * targets + per_pair_s * pairs;
  }
  // Fitted through two timed passes (targets the same, pairs different); a negative
  // intercept (timer noise) is set to 0 and the slope refitted through the larger pass.
  static PassCost fit(double targets, double pairs_a, double secs_a, double pairs_b,
                      double secs_b);
};

}  // namespace gpm
