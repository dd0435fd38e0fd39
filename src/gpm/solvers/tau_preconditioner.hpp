// A fast-sine-transform preconditioner for the particle Laplacian's symmetric systems
// (issue 58): Poisson's S = −D M_ΩΩ and the implicit heat step's D − θκΔt D M_ΩΩ.
//
// On the unjittered lattice x = (iΔx, jΔx) with one volume V, S couples node k to node
// k + (m, n) by c(m, n) = 2d·V²·w_h(r)/r², r = Δx√(m² + n²) < h (laplacian_matrix.hpp), the
// same for every node: S is a symmetric two-level Toeplitz matrix on the nodes of the
// unknowns.  Its τ-approximation T — the same stencil with the sine transform's boundary
// rule — is diagonal in the 2-D DST-I basis (Chan & Ng, SIAM Review 38, 1996; Serra
// Capizzano's τ preconditioners), with eigenvalues
//   λ(a, b) = Σ_{(m,n) ≠ 0} c(m, n)·(1 − cos mθ_a · cos nθ_b),   θ_a = aπ/(N_x + 1),
// on the smallest lattice rectangle N_x × N_y holding every unknown's node (a, b = 1 … N).
// The stencil is symmetric in m and in n, so this equals the lattice symbol at (θ_a, θ_b).
// Jitter and the volumes perturb S; P keeps only the volumes' diagonal scaling:
//   P = D (shift·I + scale·T₁) D,   D = diag(V_k),
// T₁ the τ-matrix of c/V² (volume-free), so Poisson is shift = 0, scale = 1 and a heat step
// shift = 1/V̄ (V̄ the mean volume of the unknowns), scale = θκΔt.  P⁻¹ r costs two 2-D
// DST-I (FFTW, planned with FFTW_ESTIMATE so that every run computes the same sums) and a
// division: r's entries are placed at their nodes (zero at nodes of no unknown), so
// P⁻¹ = D⁻¹ R (shift + scale·T₁)⁻¹ Rᵀ D⁻¹ is symmetric positive definite for any jitter.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "gpm/geometry/domain.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

class TauPreconditioner final : public Preconditioner {
 public:
  // The unknowns are L's (their nodes p.gi, p.gj), the volumes L's own or `volumes` (heat
  // readings on one Laplacian).  InputError for dx ≤ 0, two unknowns on one node, or
  // shift < 0 / scale ≤ 0; NumericalError if an eigenvalue is not positive (a weight
  // negative somewhere: Hypothesis 1.4 fails).
  TauPreconditioner(const Particles& p, const DiscreteLaplacian& L, const WeightFunction& w,
                    double dx, double shift = 0, double scale = 1,
                    const std::vector<double>* volumes = nullptr);
  ~TauPreconditioner() override;
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override;

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  // λ(a, b) of T₁, a = 1 … nx, b = 1 … ny (row-major in a), before shift and scale.
  const std::vector<double>& eigenvalues() const { return lambda_; }
  // The lattice symbol Σ c(m,n)/V²·(1 − cos mθ cos nφ) at any (θ, φ), summed directly over
  // the stencil (the test checks the separable sum of the constructor against it).
  double symbol(double theta, double phi) const;

 private:
  struct Plan;
  int nx_ = 0, ny_ = 0;
  std::vector<int64_t> cell_;     // per unknown: its node's index in the nx × ny rectangle
  Eigen::VectorXd inv_v_;         // 1/V_k per unknown
  std::vector<double> lambda_;    // T₁'s eigenvalues
  std::vector<double> inv_diag_;  // 1/((shift + scale·λ)·4(nx+1)(ny+1)): the DST scaling folded in
  std::vector<int> sm_, sn_;      // the stencil: offsets and c(m, n)/V²
  std::vector<double> sc_;
  std::unique_ptr<Plan> plan_;
};

}  // namespace gpm
