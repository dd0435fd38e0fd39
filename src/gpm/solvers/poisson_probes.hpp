// Small measurements on a solved discrete Poisson problem, shared by the failure study
// (src/apps/thesis_poisson_failure.cpp) and its tests: the extremes of U over Ω and the
// particle of Γ ∪ Γ_H that the particles of Ω see most negatively.
//
// The maximum principle (thesis Lemma 2.4) says that with f ≤ 0 the solution stays below the
// largest boundary value.  Its sharpest single test puts g̃ = −1 at one particle b outside Ω
// (0 elsewhere, f = 0): then U = −(−M_ΩΩ)⁻¹ M_Ωb must be ≤ 0.  A weight that is negative on
// part of (0,1) makes some entries of the column M_Ωb negative; the particle whose column
// sum Σ_j M_jb is smallest is where the sign change shows most.  For a positive weight every
// column is ≥ 0 and the choice merely picks the most weakly coupled particle.
#pragma once
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <vector>

#include "gpm/geometry/connectivity.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"

namespace gpm {

// The data of a Poisson problem −Δ_h U = f, U = g̃ outside Ω, for the exact solution u at
// every particle: g[i] = u(x_i), f[i] = −Δu(x_i); umax = max over Ω of |u|.
struct PoissonData {
  std::vector<double> f, g;
  double umax = 0;
};
inline PoissonData poisson_data(const Particles& p, const TestFunction& u) {
  PoissonData d;
  d.f.resize(p.size());
  d.g.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    d.g[i] = u.v(p.x[i], p.y[i]);
    d.f[i] = -u.lap(p.x[i], p.y[i]);
    if (p.in_omega[i]) d.umax = std::max(d.umax, std::fabs(d.g[i]));
  }
  return d;
}

inline double omega_max(const Particles& p, const std::vector<double>& U) {
  double m = -1e300;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.in_omega[i]) m = std::max(m, U[i]);
  return m;
}

inline double omega_max_abs(const Particles& p, const std::vector<double>& U) {
  double m = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.in_omega[i]) m = std::max(m, std::fabs(U[i]));
  return m;
}

// The particle outside Ω, coupled to at least one particle of Ω, with the smallest column
// sum of the assembled Ω × all matrix (InputError from matrix() if matrix-free).
inline std::size_t most_negative_boundary_particle(const DiscreteLaplacian& L) {
  const auto& M = L.matrix();
  const auto& unk = L.unknown_of();
  std::vector<double> sum(L.n_particles(), 0.0);
  std::vector<char> seen(L.n_particles(), 0);
  for (int r = 0; r < M.rows(); ++r)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(M, r); it; ++it)
      if (unk[it.col()] < 0) sum[it.col()] += it.value(), seen[it.col()] = 1;
  std::size_t best = 0;
  double lowest = 1e300;
  for (std::size_t b = 0; b < sum.size(); ++b)
    if (seen[b] && sum[b] < lowest) lowest = sum[b], best = b;
  return best;
}

// The h-connectivity threshold h* of a distribution: the smallest h for which
// h_connectivity holds, by 50 bisection steps between 0.1 dx and 3 dx (to ~3e-15·dx; the
// search is exact for each h).  The failure study and its tests share it, so that "0.98 h*"
// is the same radius in both (the unchecked solve below h* reacts to the last bit of h).
inline double h_connectivity_threshold(const Particles& p, double dx) {
  double lo = 0.1 * dx, hi = 3 * dx;
  while (!h_connectivity(p, hi).connected) hi *= 2;
  for (int it = 0; it < 50; ++it) {
    const double mid = 0.5 * (lo + hi);
    (h_connectivity(p, mid).connected ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace gpm
