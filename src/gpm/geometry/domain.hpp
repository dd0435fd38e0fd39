// The domain of all three documents and the particle distributions on it.
//
//   Ω   = (0,1)²,   Ω_H = (−H, 1+H)²  with H = 0.1  (imoto §5, thesis Ch. 4 take the
//   square, not the rounded H-neighbourhood of Ω).
//
// Jittered grid (imoto §5, thesis Ch. 4): particle (i,j) sits at ((i+η¹ᵢⱼ)Δx, (j+η²ᵢⱼ)Δx)
// with η ∈ (−1/4, 1/4).  η depends only on (seed, i, j, component) through a counter-based
// hash, so the distribution is the same for any thread count or sub-domain.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace gpm {

struct Domain {
  double H = 0.1;
  double lo() const { return -H; }
  double hi() const { return 1.0 + H; }
  double side() const { return 1.0 + 2.0 * H; }
  double area_H() const { return side() * side(); }  // |Ω_H|
  static bool in_omega(double x, double y) { return x > 0 && x < 1 && y > 0 && y < 1; }
  bool in_omega_H(double x, double y) const {
    return x > lo() && x < hi() && y > lo() && y < hi();
  }
};

// Structure of arrays: the kernel streams x and y separately.
struct Particles {
  std::vector<double> x, y;
  std::vector<int32_t> gi, gj;      // grid node each particle came from
  std::vector<uint8_t> in_omega;    // 1 where x_i ∈ Ω (the error is measured there)
  std::size_t size() const { return x.size(); }
  std::size_t count_in_omega() const;
  void push(double px, double py, int32_t i, int32_t j);
};

// The jitter η ∈ (−1/4, 1/4)·amplitude/0.25 of node (i, j), component c ∈ {0,1}.
// SplitMix64 finalizer over a packed counter: a pure function of its arguments.
double jitter(uint64_t seed, int64_t i, int64_t j, int c, double amplitude = 0.25);

// All grid nodes (iΔx, jΔx) inside Ω_H, each moved by η·Δx.  Nodes are selected before
// jittering, so N equals the node count (1,521 at Δx = 2^-5).  A jittered particle that
// would leave the open square Ω_H (possible only in the outermost node rows, when the
// node is closer than Δx/4 to the edge) is mirrored back across that edge; the mirror
// image is nearer its node than the jittered point was, so |η| < 1/4 still holds.
// amplitude = 0 gives the plain grid.  Throws InputError for dx ≤ 0, non-finite dx,
// or dx too coarse to place a particle inside Ω.
Particles jittered_grid(double dx, uint64_t seed, double amplitude = 0.25,
                        const Domain& dom = Domain{});

// Number of grid nodes per axis inside (lo, hi): used by tests and the cost model.
int64_t grid_first(double dx, const Domain& dom);
int64_t grid_last(double dx, const Domain& dom);

}  // namespace gpm
