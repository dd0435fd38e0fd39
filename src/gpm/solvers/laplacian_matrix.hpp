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
// Storage.  Assembled: the symmetric half of the Ω × Ω block, written without the volumes,
//   K_kl = 2d·G(r/h)/h⁴ (l > k, one entry per pair), so that
//   (M_ΩΩ x)_k = M_kk x_k + Σ_{l≠k} K_kl V_l x_l   for any volumes,
// plus the small Ω × B block (particles outside Ω) in full, for the boundary values; 12 bytes
// per stored entry (value + column index).  A product streams about half the bytes of the
// full Ω × all matrix (the heat steps run at the speed of memory: bench/bench_laplacian).
// The product's sums are split into fixed blocks of rows, each with its own partial sums,
// added in block order: the result is the same for any number of threads.  It differs from
// the full matrix's row sums at rounding level only (another order of the same terms).
// Within a row the sum goes to eight partial sums in a fixed order (entry j to j mod 8, each
// term an explicit fma), not to the vectorizer's choice, so that a block of vectors applied
// in one pass (apply_block, the heat θ-method's series together) gives each column exactly.
// At Δx = 2^-9 with h ≈ 0.097 each row has ~7,700 entries and even the half would need
// ~14 GB, so above a memory budget (default 8 GB) the map is applied matrix-free by the
// fused kernel (kernel.hpp), recomputing the weights on every product — on the device when
// this process uses one (device_pass.hpp), the conjugate gradients staying on the host.
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
#include "gpm/solvers/laplacian_storage.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

class FusedKernel;
class DevicePass;

// LaplacianStorage, estimated_laplacian_nnz, kAssembledBytesPerNonzero: laplacian_storage.hpp.

class DiscreteLaplacian {
 public:
  // Throws InputError for h ≤ 0, sizes that differ, a non-positive volume or no particle in Ω.
  // `automatic` assembles when kAssembledBytesPerNonzero·nnz estimated ≤ max_bytes, else
  // goes matrix-free.
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
  bool assembled() const { return assembled_; }  // the half or the full matrix
  double nnz_estimate() const { return nnz_estimate_; }
  int64_t nnz() const;             // of the Ω × all matrix: exact when assembled, else the estimate
  int64_t stored_entries() const;  // entries kept by the assembled storage (0 if matrix-free)
  double bytes() const;            // memory of the assembled storage (0 if matrix-free)
  double assembly_seconds() const { return assembly_s_; }
  // The full matrix Ω × all, built from the assembled storage on the first call (for the
  // diagnostics that read its entries; InputError when matrix-free).
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& matrix() const;

  // y = (M v)_Ω for v over all particles (size N).
  void apply_full(const Eigen::VectorXd& v_full, Eigen::VectorXd& y) const;
  // y = M_ΩΩ x for x over the unknowns (the values outside Ω taken as 0).
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // Y = M_ΩΩ X for a block of s = X.cols() vectors over the unknowns, interleaved (row k
  // holds the s values of unknown k), in one pass over the stored entries: each entry's
  // column index and value are read once for all s vectors and the s values it touches are
  // adjacent, so the product, bound by its gathers and scatters, costs much less per
  // vector.  Column c of Y equals apply() of column c of X bit for bit (the same sums in the
  // same order and the same fixed row blocks) for the assembled and the full storage;
  // matrix-free, the columns go through apply() one by one.
  using RowBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  void apply_block(const RowBlock& X, RowBlock& Y) const;
  // The parts of M_ΩΩ that depend on the volumes, for other volumes V' on the same
  // particles, weight and h (the stored K_kl do not): V' at the unknowns and the diagonal
  // of the Laplacian built with V', summed in the order of its assembly, so that a column
  // multiplied with them equals that Laplacian's apply() bit for bit; the Ω × B block's
  // values with V' (in the stored order) and V' itself, for apply_full and the norms of a
  // solver that runs several volumes on one Laplacian (the heat readings).  Assembled half only.
  struct Volumes {
    Eigen::VectorXd at_unknowns, diagonal;
    std::vector<double> boundary;  // the Ω × B entries with V', aligned with the stored ones
    std::vector<double> all;       // V' at every particle
  };
  Volumes volumes_for(const Particles& p, const WeightFunction& w,
                      const std::vector<double>& V) const;
  // apply_block with column c multiplied by the Laplacian of volumes *per_column[c] (nullptr:
  // this one's own); InputError unless assembled as the half.
  void apply_block(const RowBlock& X, RowBlock& Y,
                   const std::vector<const Volumes*>& per_column) const;
  // apply_full for the Laplacian of other volumes (volumes_for), bit for bit as that
  // Laplacian's apply_full; nullptr: this one's own.
  void apply_full(const Eigen::VectorXd& v_full, Eigen::VectorXd& y, const Volumes* other) const;
  // The diagonal of M_ΩΩ: −2d Σ_{i≠j} V_i w_h/r² (negative for a positive weight).
  const Eigen::VectorXd& diagonal() const { return diag_; }

  // Particle values ↔ unknowns.
  Eigen::VectorXd restrict_to_omega(const std::vector<double>& full) const;
  // Full vector with the unknowns x inside Ω and `outside` at the other particles.
  Eigen::VectorXd extend(const Eigen::VectorXd& x, const std::vector<double>& outside) const;

 private:
  void assemble(const Particles& p, const WeightFunction& w);
  void assemble_full(const Particles& p, const WeightFunction& w);
  // The diagonal for volumes V, summed over the neighbours in the order of a cell list of
  // cells `cell` wide (h/2: the assembly's order; h/4: the matrix-free one's); with
  // `boundary`, also the Ω × B entries for V in the stored order (assembled half only).
  Eigen::VectorXd diagonal_with(const Particles& p, const WeightFunction& w,
                                const std::vector<double>& V, double cell,
                                std::vector<double>* boundary = nullptr) const;
  void plan_blocks();
  void apply_assembled(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  template <int W>
  void apply_assembled_block(const RowBlock& X, RowBlock& Y,
                             const std::vector<const Volumes*>& per_column) const;
  template <int W>
  void apply_full_block(const RowBlock& X, RowBlock& Y) const;
  // The rows' sums from the blocks' partial sums t (s interleaved columns), both products.
  // Column c's diagonal is diag[c].
  void sum_blocks(const double* x, const double* t, int s, int tw, const double* const* diag,
                  double* y) const;
  // Threads only pay off for large products: a parallel region costs microseconds (and
  // much more on a loaded machine), a row of a small matrix nanoseconds.
  bool threaded() const {
    return full_storage_ ? full_->nonZeros() > 2000000 : up_col_.size() > 1000000;
  }

  std::size_t n_ = 0;
  double h_ = 0;
  std::vector<double> V_;
  std::vector<int32_t> omega_, unknown_;
  bool assembled_ = false, full_storage_ = false;
  double nnz_estimate_ = 0, assembly_s_ = 0;
  int64_t nnz_ = 0;  // Ω × all, counted during assembly
  // The symmetric half: row k's entries (l > k, ascending) at up_ptr_[k] … up_ptr_[k+1].
  std::vector<int64_t> up_ptr_;
  std::vector<int32_t> up_col_;
  std::vector<double> up_val_;
  // The Ω × B block: particle index and M_ki = 2d·V_i·G/h⁴.
  std::vector<int64_t> b_ptr_;
  std::vector<int32_t> b_col_;
  std::vector<double> b_val_;
  Eigen::VectorXd vol_;   // V at the unknowns
  Eigen::VectorXd diag_;
  // Fixed blocks of rows for the product: block b holds rows [row_[b], row_[b+1]) and its
  // partial sums cover unknowns [row_[b], reach_[b]] at part_ + offset_[b].
  std::vector<int64_t> block_row_, block_reach_, block_offset_;
  std::vector<int32_t> first_block_;  // per unknown: the first block whose reach covers it
  mutable std::vector<double> part_, part_block_;  // part_block_: s interleaved columns
  mutable Eigen::VectorXd z_;
  mutable std::unique_ptr<Eigen::SparseMatrix<double, Eigen::RowMajor, int>> full_;
  std::unique_ptr<FusedKernel> kernel_;
  std::unique_ptr<DevicePass> device_;  // matrix-free on a device (device_pass.hpp), if used
  mutable Eigen::VectorXd work_;  // full-length scratch for the matrix-free apply()
  mutable RowBlock z_block_, work_block_;  // V X, and X over all particles (full storage)
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
// A preconditioner for the conjugate gradients: z = P⁻¹ r for a symmetric positive definite
// P ≈ S (tau_preconditioner.hpp).  Without one (nullptr) the iteration is plain CG, the
// reference every stored row was made with, operation for operation as before.
class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  virtual void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const = 0;
};

struct CgResult {
  int iterations = 0;
  double rel_residual = 0;            // ‖b − Sx‖₂/‖b‖₂ at exit, recomputed
  double recursive_rel_residual = 0;  // the recursively updated one at exit
};
std::string cg_number(double v);  // %g, for the messages (1e-10, not 0.000000)
// With a preconditioner pc, the same stopping rule on the unpreconditioned residual ‖r‖₂, so
// both iterations answer the same question.
template <class Apply>
CgResult conjugate_gradient(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                            double tol, int max_iter, const std::string& what,
                            const Preconditioner* pc = nullptr);
template <class Apply>
CgResult cg_iterate(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    const Eigen::VectorXd& Sx0, double tol, int max_iter, const std::string& what,
                    const Preconditioner* pc = nullptr);
void cg_check_true_residual(CgResult& res, const Eigen::VectorXd& b, const Eigen::VectorXd& Sx,
                            double tol, const std::string& what);

// cg_iterate's loop as a state, for a caller that runs several solves in lockstep and
// computes their products S p together (the heat θ-method's series, solve_heat_block):
//   CgState cg(b, Sx0, …);  while (!cg.done()) { q = S·cg.direction(); cg.update(x, q); }
// is cg_iterate, operation for operation.
class CgState {
 public:
  CgState(const Eigen::VectorXd& b, const Eigen::VectorXd& Sx0, double tol, int max_iter,
          std::string what, const Preconditioner* pc = nullptr);
  // True once ‖r‖₂ ≤ tol·‖b‖₂; throws NumericalError when not and max_iter is reached.
  bool done() const;
  const Eigen::VectorXd& direction() const { return p_; }
  // One iteration with q = S·direction(): x and the residual move along p.
  void update(Eigen::VectorXd& x, const Eigen::VectorXd& q);
  CgResult result() const;  // rel_residual still to be set (cg_check_true_residual)

 private:
  Eigen::VectorXd r_, p_, z_;  // z_ = P⁻¹ r (preconditioned only)
  const Preconditioner* pc_ = nullptr;
  double bnorm_ = 0, rr_ = 0, rz_ = 0, stop_ = 0, tol_ = 0;
  int iterations_ = 0, max_iter_ = 0;
  std::string what_;
};

// ---------------------------------------------------------------------------------
template <class Apply>
CgResult cg_iterate(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    const Eigen::VectorXd& Sx0, double tol, int max_iter, const std::string& what,
                    const Preconditioner* pc) {
  CgState cg(b, Sx0, tol, max_iter, what, pc);
  Eigen::VectorXd q(b.size());
  while (!cg.done()) {
    apply(cg.direction(), q);
    cg.update(x, q);
  }
  return cg.result();
}

template <class Apply>
CgResult conjugate_gradient(Apply&& apply, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                            double tol, int max_iter, const std::string& what,
                            const Preconditioner* pc) {
  const double bnorm = b.norm();
  if (!std::isfinite(bnorm)) throw NumericalError(what + ": non-finite right-hand side");
  if (bnorm == 0) {
    x.setZero();
    return CgResult{};
  }
  if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd q(b.size());
  apply(x, q);
  CgResult res = cg_iterate(apply, b, x, q, tol, max_iter, what, pc);
  apply(x, q);  // the true residual, once
  cg_check_true_residual(res, b, q, tol, what);
  return res;
}

}  // namespace gpm
