// The fully fused loop of the commonest pass (one weight, one field, Π/∇/Δ in any mix):
// everything in registers, no block written (bench_kernel's fused1 against fused1_block,
// the same pass through the block; bench_limit times this loop's step with every candidate
// in L1).  FusedKernel takes it where pick_fused1 (kernel_dispatch.hpp) allows, and the
// block path of kernel_pass.hpp otherwise.
// Private to the kernel: included by kernel.cpp only.
#pragma once
#include <cstdint>
#include <type_traits>

#include "gpm/kernel/kernel_pass.hpp"

namespace gpm {
namespace {

// The fully fused loop for the commonest pass — one weight, one field: the shared
// quantities, the polynomials and the accumulators stay in registers; no block is
// written.  NP pieces, NC (padded) coefficients; PI: Π wanted; GM: how ∇/Δ get
// G = w(q)/q²:  0 not wanted,  1..4 own Horner on the pre-divided coefficients times
// (1/q)^(GM−1),  5 G = W·h²/r² from the Π value W (the same weight: saves a Horner;
// used when w/q² needs a divide anyway).  Both ∇ and Δ are accumulated (the unrequested
// one is dropped).  Accumulators are carried across rows through th.acc[0..3].
template <int NP, int NC, bool PI, int GM>
inline void KernelPass::fused1_range(Thread& th, int32_t b, int32_t e, double px, double py,
                                     const double* const* fs, const vd* vt) const {
  constexpr bool G = GM != 0;
  constexpr int M = (GM >= 1 && GM <= 4) ? GM - 1 : 0;
  const WPlan& w = plans[0];
  const double* __restrict xs = cl.xs();
  const double* __restrict ys = cl.ys();
  const double* __restrict Vp = Vs.data();
  const double* __restrict fv = fs[0];
  const double* brk = PI ? w.pi.begin : w.g.begin;  // Π and w/q² share the breakpoints
  const vd PX = vbc(px), PY = vbc(py), H2 = vbc(h2), H = vbc(h), Z = vbc(0.0),
           INVH = vbc(invh), VT = vt[0];
  vd api = th.acc[0], agx = th.acc[1], agy = th.acc[2], alap = th.acc[3];
  // One vector of candidates from slot k; `in0` masks lanes past the end of the range
  // (only the last vector of a range needs it: the loop is peeled).  Lanes outside the
  // disc read real particles (or the far padding) and get V = 0, so they contribute 0;
  // their q stays finite.
  auto step = [&](int32_t k, vm in0, auto tail) __attribute__((always_inline)) {
    const vd dx = vload(xs + k) - PX, dy = vload(ys + k) - PY;
    const vd r2 = dx * dx + dy * dy;
    vm in = r2 < H2;
    if constexpr (decltype(tail)::value) in &= in0;
    const vm nz = in & (r2 > Z);  // 0 < r < h: Λ
    const vd V = in ? vload(Vp + k) : Z;
    const vd v = vload(fv + k);
    const vd q = vsqrt(r2) * INVH;
    vd W, Gq;
    if constexpr (PI || GM == 5) {
      W = horner<NC>(w.pi.c[0], q);
      for (int p = 1; p < NP; ++p) W = (q >= vbc(brk[p])) ? horner<NC>(w.pi.c[p], q) : W;
    }
    if constexpr (PI) api += (V * v) * W;
    if constexpr (G) {
      if constexpr (GM == 5) {
        Gq = nz ? W * (H2 / r2) : Z;  // r = 0 is outside Λ
      } else {
        Gq = horner<NC>(w.g.c[0], q);
        for (int p = 1; p < NP; ++p) Gq = (q >= vbc(brk[p])) ? horner<NC>(w.g.c[p], q) : Gq;
        // (1/q)^m; m = 2 divides r² directly, so the divide does not wait for the sqrt.
        if constexpr (M == 1) Gq *= H / (nz ? vsqrt(r2) : H);
        if constexpr (M == 2) Gq *= H2 / (nz ? r2 : H2);
        if constexpr (M == 3) {
          const vd iq = H / (nz ? vsqrt(r2) : H);
          Gq *= iq * iq * iq;
        }
        Gq = nz ? Gq : Z;  // r = 0 is outside Λ
      }
      const vd t = Gq * (V * (v - VT));
      agx += t * dx;
      agy += t * dy;
      alap += t;
    }
  };
  int32_t k = b;
  for (; k + kW <= e; k += kW) step(k, vm{}, std::false_type{});
  if (k < e) step(k, iota() < static_cast<int64_t>(e - k), std::true_type{});
  th.acc[0] = api;
  th.acc[1] = agx;
  th.acc[2] = agy;
  th.acc[3] = alap;
}

}  // namespace
}  // namespace gpm
