// The fused neighbour-sum kernel: the loop every study spends its time in.
//
// For each target particle j (a particle, so v(x_j) = v_j), ONE pass over the particles
// within h evaluates, for several weights × several fields, any of
//   Π_h v(x_j) = h^-2     Σ_{r<h}   V_i v_i w(q)
//   ∇_h v(x_j) = d h^-4   Σ_{0<r<h} V_i (v_i − v_j)(x_i − x_j) G(q)
//   Δ_h v(x_j) = 2d h^-4  Σ_{0<r<h} V_i (v_i − v_j) G(q)
// with q = r/h and G(q) = w(q)/q² — imoto (2)–(4) = thesis (1.2)–(1.4) written with
// w_h(r) = w(q)/h² and 1/r² = 1/(h² q²).  d = 2.
//
// How (measured gains: bench/bench_kernel.cpp and the report's performance appendix, paper/60-performance.md):
//  * particles sorted by cells of size h/cells_per_h (CellList, default h/4), structure of
//    arrays, the volumes and the fields gathered into the sorted order; targets processed
//    in cell order (locality), OpenMP dynamic schedule over chunks of targets;
//  * per row of cells only the contiguous slot range overlapping the disc (the chord):
//    ~1.34 candidates per neighbour at h/4 (2.6 for h-cells, 2.9 for 3×3 h-cells);
//  * one branch-free loop per range over vectors of 8 candidates (GCC vector extensions
//    = explicit AVX-512; nothing depends on the auto-vectorizer); lanes outside the disc
//    get V = 0 by a select (mask), the range's last vector is peeled for the end mask;
//  * r = √r², q = r/h shared by all weights and fields; the weights' pieces are turned
//    once into plain coefficients of w(q) and of the pre-divided w(q)/q² = (1/q)^m·P(q),
//    so a weight with w = O(r²) (p0 ≥ 2) needs no divide at all, and (h/r)² = h²/r² divides
//    r² itself (the divide runs beside the square root instead of after it);
//  * piecewise polynomials evaluated branch-free: Horner on every piece (instantiated for
//    the number of pieces and coefficients), selected by q against the breakpoints;
//  * one weight, one field (the commonest pass): everything in ONE fused loop with the
//    accumulators in registers across rows; with Π requested too, ∇/Δ use
//    G = W·h²/r² from the Π value (one Horner instead of two);
//  * several weights or fields: per 64 vectors the shared per-pair quantities (dx, dy, q,
//    powers of h/r, V·v, V·(v − v_j)) go to a small aligned block (L1), then each weight
//    streams over it once with its accumulators in registers (two sets, even/odd);
//  * accumulators reduced once per target in a fixed order: results are bitwise
//    identical for any number of threads.
// Options that were measured and did not pay off on the project's machine (kept for the
// benchmark): compact mode (AVX-512 compress of the accepted pairs before the square root)
// and 1/√r² by rsqrt14 + Newton steps.
// Double precision throughout.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "gpm/geometry/cells.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

enum KernelOp : unsigned { kInterp = 1u, kGrad = 2u, kLap = 4u, kAllOps = 7u };

struct KernelWeight {
  WeightFunction weight;
  unsigned ops = kAllOps;  // which of Π, ∇, Δ to evaluate with this weight
};

struct KernelOptions {
  int cells_per_h = 4;   // cell size h / cells_per_h
  bool compact = false;  // compact the accepted pairs before the sqrt (slower; see above)
  bool fast_rsqrt = false;  // AVX-512 only: 1/√r² by rsqrt14 + 2 Newton steps (≤ 2 ulp)
  bool fuse_single = true;  // one weight + one field: the fully fused loop (no block)
  int chunk = 16;        // OpenMP dynamic schedule chunk, in targets
  int threads = 0;       // OpenMP threads; 0 = the OpenMP default
};

// Results of one FusedKernel::apply: one column per requested (weight, field, component),
// each indexed like the target list that was passed.
class KernelResult {
 public:
  std::size_t size() const { return targets_.size(); }
  const std::vector<int32_t>& targets() const { return targets_; }
  int n_weights() const { return nw_; }
  int n_fields() const { return nf_; }
  bool has(int w, KernelOp op) const;
  // Π_h v_f, ∂x and ∂y of ∇_h v_f, Δ_h v_f for weight w at every target.
  // InputError if that operator was not requested for weight w.
  std::span<const double> interpolant(int w, int f) const { return col(w, f, 0); }
  std::span<const double> grad_x(int w, int f) const { return col(w, f, 1); }
  std::span<const double> grad_y(int w, int f) const { return col(w, f, 2); }
  std::span<const double> laplacian(int w, int f) const { return col(w, f, 3); }

 private:
  friend class FusedKernel;
  std::span<const double> col(int w, int f, int comp) const;
  std::vector<int32_t> targets_;
  int nw_ = 0, nf_ = 0;
  std::vector<int32_t> column_;  // ((w·nf + f)·4 + comp) → column, or −1
  std::vector<double> data_;     // column c occupies [c·n, (c+1)·n)
  std::vector<int32_t> order_;   // workspace: target positions in cell order
  std::vector<double> work_;     // workspace: the fields in sorted order
};

struct PairCount {
  int64_t candidates = 0;  // slots visited by the chord ranges
  int64_t accepted = 0;    // pairs (target, i) with |x_i − x_j| < h, the target itself included
};

class FusedKernel {
 public:
  static constexpr int kMaxFields = 8;

  // Particles (x, y) with volumes V (original order).  The weights are copied; their
  // pieces are turned into plain coefficients once here.  InputError for h ≤ 0, sizes
  // that differ, a weight unbounded at 0 asked for Π, or more pieces/coefficients than
  // the kernel holds (8 pieces, 12 coefficients).
  FusedKernel(const std::vector<double>& x, const std::vector<double>& y,
              const std::vector<double>& V, double h, std::vector<KernelWeight> weights,
              KernelOptions opt = {});
  FusedKernel(const Particles& p, const std::vector<double>& V, double h,
              std::vector<KernelWeight> weights, KernelOptions opt = {});
  ~FusedKernel();
  FusedKernel(FusedKernel&&) noexcept;
  FusedKernel& operator=(FusedKernel&&) noexcept;

  double h() const;
  const CellList& cells() const;
  std::size_t n_weights() const;
  const KernelOptions& options() const;
  // Whether the pass needs the divide 1/q (some weight's w/q² has a negative power).
  bool needs_divide() const;

  // Evaluates the requested operators of every weight for every field (each sampled at
  // the particles, original order; at most kMaxFields) at the targets (particle indices).
  KernelResult apply(const std::vector<int32_t>& targets,
                     const std::vector<const std::vector<double>*>& fields) const;
  KernelResult apply(const std::vector<int32_t>& targets,
                     const std::vector<std::vector<double>>& fields) const;
  // The same into `out`, reusing its storage (and its target ordering when the targets
  // are the same as last time): no allocation in a time loop.
  void apply(const std::vector<int32_t>& targets,
             const std::vector<const std::vector<double>*>& fields, KernelResult& out) const;
  // Candidate and accepted pairs of these targets (untimed bookkeeping for rates).
  PairCount count_pairs(const std::vector<int32_t>& targets) const;

 private:
  struct Impl;
  Impl* impl_;
};

// Indices of the particles in Ω (the targets of every truncation-error study).
std::vector<int32_t> omega_targets(const Particles& p);

}  // namespace gpm
