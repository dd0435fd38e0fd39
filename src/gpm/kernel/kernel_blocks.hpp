// The fused kernel's per-weight loops over blocks of pairs and the dispatchers that pick
// one instantiation per weight.  Private to the kernel: included by kernel.cpp only (its
// anonymous namespace is that translation unit's).
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
// groups of one or two fields, and picked once per weight when the kernel is built.

constexpr int kBlockVec = 64;  // vectors per block (512 pairs with AVX-512; ~24 KB)

struct BlockView {
  const vd *dx, *dy, *q;
  const vd* ip[4];  // ip[m] = (1/q)^m, m = 1..3 (those some weight needs)
  const vd* vv[FusedKernel::kMaxFields];
  const vd* vdv[FusedKernel::kMaxFields];
};

using BlockFn = void (*)(const PolyEval&, const BlockView&, int nvec, int f0, vd* acc);

// Coefficient counts instantiated (a polynomial is padded with zero coefficients).
constexpr int padded_nc(int nc) { return nc <= 2 ? 2 : nc <= 3 ? 3 : nc <= 4 ? 4 : nc <= 6 ? 6 : 8; }

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

template <int NP, int NC, bool GRAD, bool LAP>
BlockFn pick_pg_nf(int nf) {
  return nf == 1 ? &pg_block<NP, NC, GRAD, LAP, 1> : &pg_block<NP, NC, GRAD, LAP, 2>;
}
template <int NP, int NC>
BlockFn pick_pg_ops(unsigned ops, int nf) {
  const bool grad = ops & kGrad, lap = ops & kLap;
  if (grad && lap) return pick_pg_nf<NP, NC, true, true>(nf);
  if (grad) return pick_pg_nf<NP, NC, true, false>(nf);
  return pick_pg_nf<NP, NC, false, true>(nf);
}
template <int NP>
BlockFn pick_pg_nc(int nc, unsigned ops, int nf) {
  switch (padded_nc(nc)) {
    case 2: return pick_pg_ops<NP, 2>(ops, nf);
    case 3: return pick_pg_ops<NP, 3>(ops, nf);
    case 4: return pick_pg_ops<NP, 4>(ops, nf);
    case 6: return pick_pg_ops<NP, 6>(ops, nf);
    default: return pick_pg_ops<NP, 8>(ops, nf);
  }
}
// nullptr where not instantiated (then Π and G go separately).
BlockFn pick_pg(const PolyEval& pi, unsigned ops, int nf) {
  if (pi.nc > 8) return nullptr;
  switch (pi.np) {
    case 1: return pick_pg_nc<1>(pi.nc, ops, nf);
    case 2: return pick_pg_nc<2>(pi.nc, ops, nf);
    case 3: return pick_pg_nc<3>(pi.nc, ops, nf);
    default: return nullptr;
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

template <int NP, int NC>
BlockFn pick_pi_nf(int nf) {
  return nf == 1 ? &pi_block<NP, NC, 1> : &pi_block<NP, NC, 2>;
}
template <int NP, int NC, bool M, bool GRAD, bool LAP>
BlockFn pick_g_nf(int nf) {
  return nf == 1 ? &g_block<NP, NC, M, GRAD, LAP, 1> : &g_block<NP, NC, M, GRAD, LAP, 2>;
}
template <int NP, int NC, bool M>
BlockFn pick_g_ops(unsigned ops, int nf) {
  const bool grad = ops & kGrad, lap = ops & kLap;
  if (grad && lap) return pick_g_nf<NP, NC, M, true, true>(nf);
  if (grad) return pick_g_nf<NP, NC, M, true, false>(nf);
  return pick_g_nf<NP, NC, M, false, true>(nf);
}
template <int NP, int NC>
BlockFn pick_g_m(int m, unsigned ops, int nf) {
  return m > 0 ? pick_g_ops<NP, NC, true>(ops, nf) : pick_g_ops<NP, NC, false>(ops, nf);
}
template <int NP>
BlockFn pick_nc(bool pi, int nc, int m, unsigned ops, int nf) {
  switch (padded_nc(nc)) {
    case 2: return pi ? pick_pi_nf<NP, 2>(nf) : pick_g_m<NP, 2>(m, ops, nf);
    case 3: return pi ? pick_pi_nf<NP, 3>(nf) : pick_g_m<NP, 3>(m, ops, nf);
    case 4: return pi ? pick_pi_nf<NP, 4>(nf) : pick_g_m<NP, 4>(m, ops, nf);
    case 6: return pi ? pick_pi_nf<NP, 6>(nf) : pick_g_m<NP, 6>(m, ops, nf);
    default: return pi ? pick_pi_nf<NP, 8>(nf) : pick_g_m<NP, 8>(m, ops, nf);
  }
}
// nf: group size (1 or 2).  Returns nullptr where only the one-field fallback exists.
BlockFn pick(bool pi, const PolyEval& e, unsigned ops, int nf) {
  if (e.np <= 3 && e.nc <= 8) {
    switch (e.np) {
      case 1: return pick_nc<1>(pi, e.nc, e.m, ops, nf);
      case 2: return pick_nc<2>(pi, e.nc, e.m, ops, nf);
      default: return pick_nc<3>(pi, e.nc, e.m, ops, nf);
    }
  }
  if (nf != 1) return nullptr;
  if (pi) return &pi_generic;
  const bool grad = ops & kGrad, lap = ops & kLap;
  return grad && lap ? &g_generic<true, true> : grad ? &g_generic<true, false>
                                                     : &g_generic<false, true>;
}

struct WPlan {
  unsigned ops = 0;
  PolyEval pi, g;                      // w(q) and w(q)/q² (g.m: power of 1/q)
  BlockFn pi1 = nullptr, pi2 = nullptr;  // one field, two fields (nullptr: use pi1)
  BlockFn g1 = nullptr, g2 = nullptr;
  BlockFn pg1 = nullptr, pg2 = nullptr;  // Π and G together (G = W·(h/r)²), if set
};


}  // namespace
}  // namespace gpm
