// The fused kernel's per-weight loops over blocks of pairs, and the plan of one weight
// (which loop serves it); the pick of one instantiation per weight is in
// kernel_dispatch.hpp.  Private to the kernel: included by kernel.cpp only (through
// kernel_pass.hpp; its anonymous namespace is that translation unit's).
#pragma once
#include <type_traits>
#include <utility>

#include "gpm/kernel/kernel_poly.hpp"

namespace gpm {
namespace {

// ---------------------------------------------------------------------------------
// The per-weight loops.  A block holds the shared per-pair quantities of up to kBlockVec
// vectors of pairs (structure of arrays, aligned): dx, dy, q, (1/q)^m, and per field
// V_i·v_i and V_i·(v_i − v_j) (0 outside the disc and, for the latter, at r = 0).  Each
// weight streams over the block once with its accumulators in registers; the loops are
// instantiated for the pieces, the (padded) number of coefficients, the operators and
// groups of one or two fields, and picked once per weight when the kernel is built
// (pick, pick_pg in kernel_dispatch.hpp).

constexpr int kBlockVec = 64;  // vectors per block (512 pairs with AVX-512; ~24 KB)

struct BlockView {
  const vd *dx, *dy, *q;
  const vd* ip[4];  // ip[m] = (1/q)^m, m = 1..3 (those some weight needs)
  const vd* vv[FusedKernel::kMaxFields];
  const vd* vdv[FusedKernel::kMaxFields];
};

using BlockFn = void (*)(const PolyEval&, const BlockView&, int nvec, int f0, vd* acc);

template <int NP, int NC>
__attribute__((always_inline)) inline vd eval_t(const PolyEval& e, vd q) {
  vd s = horner<NC>(e.c[0], q);
  for (int p = 1; p < NP; ++p) {
    const vd t = horner<NC>(e.c[p], q);
    s = (q >= vbc(e.begin[p])) ? t : s;
  }
  return s;
}

// acc[4·f + 0] += Σ V v w(q) for fields f0 … f0+NF−1.  Two accumulator sets (even and odd
// vectors) halve the dependency chain through the sums; the order is fixed.
template <int NP, int NC, int NF>
void pi_block(const PolyEval& e, const BlockView& B, int nvec, int f0, vd* acc) {
  vd a[2][NF];
  const vd* vv[NF];
  for (int f = 0; f < NF; ++f) a[0][f] = a[1][f] = vbc(0.0), vv[f] = B.vv[f0 + f];
  auto step = [&](int i, int s) __attribute__((always_inline)) {
    const vd W = eval_t<NP, NC>(e, B.q[i]);
    for (int f = 0; f < NF; ++f) a[s][f] += vv[f][i] * W;
  };
  int i = 0;
  for (; i + 2 <= nvec; i += 2) step(i, 0), step(i + 1, 1);
  if (i < nvec) step(i, 0);
  for (int f = 0; f < NF; ++f) acc[4 * (f0 + f)] += a[0][f] + a[1][f];
}

// acc[4·f + 1..2] += Σ V (v − v_j) dx,dy G(q);  acc[4·f + 3] += Σ V (v − v_j) G(q).
template <int NP, int NC, bool M, bool GRAD, bool LAP, int NF>
void g_block(const PolyEval& e, const BlockView& B, int nvec, int f0, vd* acc) {
  vd ax[2][NF], ay[2][NF], al[2][NF];
  const vd* vdv[NF];
  for (int f = 0; f < NF; ++f) {
    for (int s = 0; s < 2; ++s) ax[s][f] = ay[s][f] = al[s][f] = vbc(0.0);
    vdv[f] = B.vdv[f0 + f];
  }
  const vd* ipm = B.ip[e.m];
  auto step = [&](int i, int s) __attribute__((always_inline)) {
    vd G = eval_t<NP, NC>(e, B.q[i]);
    if constexpr (M) G *= ipm[i];
    for (int f = 0; f < NF; ++f) {
      const vd t = G * vdv[f][i];
      if constexpr (GRAD) {
        ax[s][f] += t * B.dx[i];
        ay[s][f] += t * B.dy[i];
      }
      if constexpr (LAP) al[s][f] += t;
    }
  };
  int i = 0;
  for (; i + 2 <= nvec; i += 2) step(i, 0), step(i + 1, 1);
  if (i < nvec) step(i, 0);
  for (int f = 0; f < NF; ++f) {
    if constexpr (GRAD) {
      acc[4 * (f0 + f) + 1] += ax[0][f] + ax[1][f];
      acc[4 * (f0 + f) + 2] += ay[0][f] + ay[1][f];
    }
    if constexpr (LAP) acc[4 * (f0 + f) + 3] += al[0][f] + al[1][f];
  }
}

// Π and ∇/Δ of one weight whose w/q² needs (1/q)^m, m ≥ 1: G = W·(h/r)² from the Π
// value W (one Horner instead of two).
template <int NP, int NC, bool GRAD, bool LAP, int NF>
void pg_block(const PolyEval& e, const BlockView& B, int nvec, int f0, vd* acc) {
  vd ap[2][NF], ax[2][NF], ay[2][NF], al[2][NF];
  const vd *vv[NF], *vdv[NF];
  for (int f = 0; f < NF; ++f) {
    for (int s = 0; s < 2; ++s) ap[s][f] = ax[s][f] = ay[s][f] = al[s][f] = vbc(0.0);
    vv[f] = B.vv[f0 + f];
    vdv[f] = B.vdv[f0 + f];
  }
  const vd* ip2 = B.ip[2];
  auto step = [&](int i, int s) __attribute__((always_inline)) {
    const vd W = eval_t<NP, NC>(e, B.q[i]);
    const vd G = W * ip2[i];
    for (int f = 0; f < NF; ++f) {
      ap[s][f] += vv[f][i] * W;
      const vd t = G * vdv[f][i];
      if constexpr (GRAD) {
        ax[s][f] += t * B.dx[i];
        ay[s][f] += t * B.dy[i];
      }
      if constexpr (LAP) al[s][f] += t;
    }
  };
  int i = 0;
  for (; i + 2 <= nvec; i += 2) step(i, 0), step(i + 1, 1);
  if (i < nvec) step(i, 0);
  for (int f = 0; f < NF; ++f) {
    acc[4 * (f0 + f)] += ap[0][f] + ap[1][f];
    if constexpr (GRAD) {
      acc[4 * (f0 + f) + 1] += ax[0][f] + ax[1][f];
      acc[4 * (f0 + f) + 2] += ay[0][f] + ay[1][f];
    }
    if constexpr (LAP) acc[4 * (f0 + f) + 3] += al[0][f] + al[1][f];
  }
}

// Fallbacks for more pieces or coefficients than instantiated: runtime loops, one field.
void pi_generic(const PolyEval& e, const BlockView& B, int nvec, int f0, vd* acc) {
  vd a = vbc(0.0);
  for (int i = 0; i < nvec; ++i) a += B.vv[f0][i] * eval(e, B.q[i]);
  acc[4 * f0] += a;
}
template <bool GRAD, bool LAP>
void g_generic(const PolyEval& e, const BlockView& B, int nvec, int f0, vd* acc) {
  vd ax = vbc(0.0), ay = vbc(0.0), al = vbc(0.0);
  for (int i = 0; i < nvec; ++i) {
    vd G = eval(e, B.q[i]);
    if (e.m > 0) G *= B.ip[e.m][i];
    const vd t = G * B.vdv[f0][i];
    ax += t * B.dx[i];
    ay += t * B.dy[i];
    al += t;
  }
  if (GRAD) acc[4 * f0 + 1] += ax, acc[4 * f0 + 2] += ay;
  if (LAP) acc[4 * f0 + 3] += al;
}

// The plan of one weight, made when the kernel is built: its polynomials and the block
// loops picked for them.
struct WPlan {
  unsigned ops = 0;
  PolyEval pi, g;                      // w(q) and w(q)/q² (g.m: power of 1/q)
  BlockFn pi1 = nullptr, pi2 = nullptr;  // one field, two fields (nullptr: use pi1)
  BlockFn g1 = nullptr, g2 = nullptr;
  BlockFn pg1 = nullptr, pg2 = nullptr;  // Π and G together (G = W·(h/r)²), if set
};

}  // namespace
}  // namespace gpm
