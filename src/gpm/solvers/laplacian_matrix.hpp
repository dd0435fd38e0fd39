// The discrete Laplacian Δ_h as a linear map, for the Poisson and heat solvers.
//
// Thesis (1.4) with d = 2 and w_h(r) = w(r/h)/h²:
//   Δ_h v(x_j) = 2d Σ_{0<r<h} V_i (v_i − v_j) w_h(r)/r²,   r = |x_i − x_j|.
// Rows are the particles in Ω (the unknowns, numbered in increasing particle index),
// columns are all particles: (M v)_j = Δ_h v(x_j).  With the boundary values moved to the
// right-hand side, the solvers need the Ω×Ω block M_ΩΩ (v = 0 outside Ω).
//
// Symmetry.  Off the diagonal M_ji = 2d V_i w_h/r²; multiplied by V_j it becomes
// 2d V_i V_j w_h/r², symmetric in (i, j).  So S = −D M_ΩΩ with D = diag(V_j) is symmetric,
// and for a positive weight (Hypothesis 1.4) it is diagonally dominant with a positive
// diagonal: positive definite once every particle of Ω is h-connected to the outside
// (thesis Theorem 2.2).  The solvers run conjugate gradients on S (for V_i = |Ω_H|/N, D is
// a constant and S is M_ΩΩ up to the factor −V).
//
// Storage.  Assembled: an Eigen row-major sparse matrix Ω × all, 12 bytes per non-zero
// (value + column index).  At Δx = 2^-9 with h ≈ 0.097 each row has ~7,700 entries and the
// matrix would need ~24 GB, so above a memory budget (default 8 GB) the map is applied
// matrix-free by the fused kernel (kernel.hpp), recomputing the weights on every product.
#pragma once
#include <algorithm>
#include <Eigen/Core>
#include <cmath>
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

class FusedKernel;

enum class LaplacianStorage { automatic, assembled, matrix_free };
LaplacianStorage parse_laplacian_storage(const std::string& s);  // InputError if unknown
std::string laplacian_storage_name(LaplacianStorage s);

// Non-zeros of the Ω × all matrix before assembly: N_Ω·(1 + πh²·N/|Ω_H|), the expected
// count of particles within h (the disc may be cut by the edge of Ω_H: an over-estimate).
double estimated_laplacian_nnz(std::size_t n, std::size_t n_omega, double h,
                               const Domain& dom = Domain{});

class DiscreteLaplacian {
 public:
  // Throws InputError for h ≤ 0, sizes that differ, a non-positive volume or no particle in Ω.
  // `automatic` assembles when 12·nnz estimated ≤ max_bytes, else goes matrix-free.
  DiscreteLaplacian(const Particles& p, const std::vector<double>& V, const WeightFunction& w,
                    double h, LaplacianStorage storage = LaplacianStorage::automatic,
                    double max_bytes = 8e9);
  ~DiscreteLaplacian();
  DiscreteLaplacian(DiscreteLaplacian&&) noexcept;

  std::size_t n_particles() const { return n_; }
  std::size_t n_unknowns() const { return omega_.size(); }
  const std::vector<int32_t>& omega() const { return omega_; }        // unknown → particle
  const std::vector<int32_t>& unknown_of() const { return unknown_; }  // particle → unknown, −1
  const std::vector<double>& volumes() const { return V_; }
  double h() const { return h_; }
  bool assembled() const { return assembled_; }
  double nnz_estimate() const { return nnz_estimate_; }
  int64_t nnz() const;             // exact when assembled, else the estimate
  double bytes() const;            // memory of the assembled matrix (0 if matrix-free)
  double assembly_seconds() const { return assembly_s_; }
  // The assembled matrix Ω × all (InputError when matrix-free).
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& matrix() const;

  // y = (M v)_Ω for v over all particles (size N).
  void apply_full(const Eigen::VectorXd& v_full, Eigen::VectorXd& y) const;
  // y = M_ΩΩ x for x over the unknowns (the values outside Ω taken as 0).
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // The diagonal of M_ΩΩ: −2d Σ_{i≠j} V_i w_h/r² (negative for a positive weight).
  const Eigen::VectorXd& diagonal() const { return diag_; }

  // Particle values ↔ unknowns.
  Eigen::VectorXd restrict_to_omega(const std::vector<double>& full) const;
  // Full vector with the unknowns x inside Ω and `outside` at the other particles.
  Eigen::VectorXd extend(const Eigen::VectorXd& x, const std::vector<double>& outside) const;

 private:
  void assemble(const Particles& p, const WeightFunction& w);
  void compute_diagonal(const Particles& p, const WeightFunction& w);

  std::size_t n_ = 0;
  double h_ = 0;
  std::vector<double> V_;
  std::vector<int32_t> omega_, unknown_;
  bool assembled_ = false;
  double nnz_estimate_ = 0, assembly_s_ = 0;
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> M_;
  Eigen::VectorXd diag_;
  std::unique_ptr<FusedKernel> kernel_;
  mutable Eigen::VectorXd work_;  // full-length scratch for apply()
};

// Conjugate gradients for S x = b with a symmetric positive definite S given as a map
// apply(x, y): y = S x.  Starts from the x passed in (warm start).  Stops when
// ‖r‖₂ ≤ tol·‖b‖₂ for the recursively updated residual r, then recomputes b − S x once
// (one more product per solve): on a singular or indefinite S the recursive residual can
// fall below tol while the true one does not (seen with h just below the h-connectivity
// threshold: "converged", true residual 0.44), so a true residual above
// max(10³·tol, 10⁻¹⁰)·‖b‖₂ is a failure.  Throws NumericalError naming `what` if pᵀSp ≤ 0
// (S not positive definite), on a non-finite value, if max_iter is reached, or on that
// residual mismatch.
//
// The two halves are callable on their own, for a caller that already holds S x₀ and
// computes S x at exit anyway (the heat θ-method: one product M·U^k per step gives the
// explicit part of the right-hand side, the initial residual and the previous solve's true
// residual): cg_iterate starts from Sx0 = S x₀, cg_check_true_residual takes Sx = S x at
// exit.  Same arithmetic as conjugate_gradient, so the same iterates bit for bit.
struct CgResult {
  int iterations = 0;
  double rel_residual = 0;            // ‖b − Sx‖₂/‖b‖₂ at exit, recomputed
  double recursive_rel_residual = 0;  // the recursively updated one at exit
};
std::string cg_number(double v);  // %g, for the messages (1e-10, not 0.000000)
template <class Apply>
CgResult conjugate_gradient(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                            double tol, int max_iter, const std::string& what);
template <class Apply>
CgResult cg_iterate(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    const Eigen::VectorXd& Sx0, double tol, int max_iter, const std::string& what);
void cg_check_true_residual(CgResult& res, const Eigen::VectorXd& b, const Eigen::VectorXd& Sx,
                            double tol, const std::string& what);

// ---------------------------------------------------------------------------------
template <class Apply>
CgResult cg_iterate(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    const Eigen::VectorXd& Sx0, double tol, int max_iter, const std::string& what) {
  CgResult res;
  const double bnorm = b.norm();
  if (!std::isfinite(bnorm)) throw NumericalError(what + ": non-finite right-hand side");
  Eigen::VectorXd r(b.size()), p(b.size()), q(b.size());
  r = b - Sx0;
  p = r;
  double rr = r.squaredNorm();
  const double stop = tol * tol * bnorm * bnorm;
  while (rr > stop) {
    if (res.iterations >= max_iter)
      throw NumericalError(what + ": conjugate gradients did not reach the relative residual " +
                           cg_number(tol) + " in " + std::to_string(max_iter) +
                           " iterations (now " + cg_number(std::sqrt(rr) / bnorm) + ")");
    apply(p, q);
    const double pq = p.dot(q);
    if (!std::isfinite(pq))
      throw NumericalError(what + ": non-finite value p^T S p = " + cg_number(pq) +
                           " at iteration " + std::to_string(res.iterations));
    if (!(pq > 0))
      throw NumericalError(what + ": the matrix is not positive definite (p^T S p = " +
                           cg_number(pq) + " at iteration " +
                           std::to_string(res.iterations) + ")");
    const double alpha = rr / pq;
    x += alpha * p;
    r -= alpha * q;
    const double rr_new = r.squaredNorm();
    if (!std::isfinite(rr_new))
      throw NumericalError(what + ": non-finite residual at iteration " +
                           std::to_string(res.iterations));
    p = r + (rr_new / rr) * p;
    rr = rr_new;
    ++res.iterations;
  }
  res.recursive_rel_residual = std::sqrt(rr) / bnorm;
  return res;
}

template <class Apply>
CgResult conjugate_gradient(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                            double tol, int max_iter, const std::string& what) {
  const double bnorm = b.norm();
  if (!std::isfinite(bnorm)) throw NumericalError(what + ": non-finite right-hand side");
  if (bnorm == 0) {
    x.setZero();
    return CgResult{};
  }
  if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd q(b.size());
  apply(x, q);
  CgResult res = cg_iterate(apply, b, x, q, tol, max_iter, what);
  apply(x, q);  // the true residual, once
  cg_check_true_residual(res, b, q, tol, what);
  return res;
}

}  // namespace gpm
