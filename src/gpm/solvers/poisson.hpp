// The discrete Poisson problem of the thesis, (2.2):
//
//   −Δ_h U_i = f_i   for the particles x_i ∈ Ω,
//    U_i     = g̃_i  for the other particles (on Γ ∪ Γ_H),
//
// solved by moving the boundary columns to the right-hand side,
//   −M_ΩΩ U_Ω = f + M_ΩB g̃,
// and running conjugate gradients on the symmetric form S U_Ω = D(f + M_ΩB g̃) with
// S = −D M_ΩΩ, D = diag(V_j) (see laplacian_matrix.hpp).
//
// Solvability (thesis Theorem 2.2): for a positive weight the problem has a unique solution
// iff every particle of Ω is joined to a particle outside Ω by a chain of particles with
// consecutive distances < h (h-connectivity, Definition 1.8).  solve_poisson checks it first
// by a breadth-first search from the particles outside Ω and refuses an unconnected
// distribution, naming one unconnected particle.
// The search itself is gpm::h_connectivity (connectivity.hpp, the thesis-truncation issue).
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "gpm/geometry/domain.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"

namespace gpm {

// Throws InputError "distribution is not h-connected for h = …: particle i at (x, y) …"
// if gpm::h_connectivity (connectivity.hpp) finds an unconnected particle.
void require_h_connectivity(const Particles& p, double h);

struct PoissonResult {
  std::vector<double> U;     // all particles: the solution in Ω, g̃ outside
  CgResult cg;
  double solve_seconds = 0;  // conjugate gradients only
};

// f: the source at every particle (only the values in Ω are used); g: g̃ at every particle
// (only the values outside Ω are used).  tol: relative residual of CG on the symmetric
// form.  Checks h-connectivity first (set check_connectivity = false only in tests that
// study the unchecked failure).  pc: a preconditioner of S (tau_preconditioner.hpp with
// shift 0, scale 1); nullptr: plain CG, the reference.
PoissonResult solve_poisson(const Particles& p, const DiscreteLaplacian& L,
                            const std::vector<double>& f, const std::vector<double>& g,
                            double tol = 1e-10, int max_iter = 20000,
                            bool check_connectivity = true, const Preconditioner* pc = nullptr);

// Where the error of a solved problem sits: the relative ℓ∞(Ω) error max|u − U| / max|u|
// over the particles in Ω, the particle attaining it and its distance from ∂Ω, and the same
// relative error over the particles at least `margin` from ∂Ω (e.g. margin = h: targets whose
// whole stencil lies in Ω, away from the boundary layer).
struct ErrorLocation {
  double rel_error = 0;
  std::size_t argmax = 0;
  double x = 0, y = 0, distance_to_boundary = 0;
  double rel_error_inner = 0;  // over particles with distance ≥ margin (0 if there are none)
};
ErrorLocation locate_error(const Particles& p, const std::vector<double>& exact,
                           const std::vector<double>& U, double margin);

}  // namespace gpm
