// The fused kernel once built (FusedKernel::Impl in kernel.cpp derives from this struct and
// adds nothing): its state (h, the cell list, the volumes in sorted order, one plan per
// weight), the per-thread workspace, and the loops over one chord range of candidates.
// This file holds the block path that serves any weights and fields (masked_range_t,
// run_block); the fully fused one-weight loop is in kernel_fused1.hpp, the compact mode in
// kernel_compact.hpp, and the choice of an instantiation in kernel_dispatch.hpp.
//
// Why a struct in the anonymous namespace rather than FusedKernel::Impl itself: the plans
// (WPlan, kernel_blocks.hpp) live in the private headers' anonymous namespace, and GCC
// warns (-Wsubobject-linkage) when a class of external linkage defined in a header holds
// such a type; a class defined in kernel.cpp itself may, so Impl is derived there.
// Private to the kernel: included by kernel.cpp only.
#pragma once
#include <cstdint>
#include <type_traits>
#include <vector>

#include "gpm/geometry/cells.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/kernel/kernel_blocks.hpp"  // the per-weight loops and plans (and kernel_poly.hpp)

namespace gpm {
namespace {

struct KernelPass {
  static constexpr int kMaxFields = FusedKernel::kMaxFields;

  double h = 0, h2 = 0, invh = 0;
  KernelOptions opt;
  CellList cl;
  std::vector<double> Vs;  // volumes, sorted order, padded
  std::vector<WPlan> plans;
  bool need_iq = false;
  bool need_pow[4] = {false, false, false, false};

  // Per-thread working storage.
  struct Thread {
    static constexpr int kStage = 512;  // compact mode: accepted pairs staged before a block
    int nf;
    std::vector<vd> dx, dy, q, ip[4], vv[kMaxFields], vdv[kMaxFields];
    BlockView view;
    int nvec = 0;
    std::vector<vd> acc;
    // compact mode staging (unaligned appends)
    std::vector<double> st;
    double *sdx, *sdy, *sr2, *sV, *sv[kMaxFields];
    int scnt = 0;
    Thread(std::size_t nacc, int nf_) : nf(nf_), acc(nacc) {
      dx.resize(kBlockVec);
      dy.resize(kBlockVec);
      q.resize(kBlockVec);
      for (int m = 1; m < 4; ++m) ip[m].resize(kBlockVec);
      for (int f = 0; f < nf; ++f) vv[f].resize(kBlockVec), vdv[f].resize(kBlockVec);
      view.dx = dx.data();
      view.dy = dy.data();
      view.q = q.data();
      view.ip[0] = nullptr;
      for (int m = 1; m < 4; ++m) view.ip[m] = ip[m].data();
      for (int f = 0; f < kMaxFields; ++f) {
        view.vv[f] = f < nf ? vv[f].data() : nullptr;
        view.vdv[f] = f < nf ? vdv[f].data() : nullptr;
      }
      const std::size_t stride = kStage + 2 * kW;
      st.assign((4 + nf) * stride, 0.0);
      sdx = st.data();
      sdy = sdx + stride;
      sr2 = sdy + stride;
      sV = sr2 + stride;
      for (int f = 0; f < nf; ++f) sv[f] = sV + (f + 1) * stride;
    }
  };

  // Every weight over the block; accumulators added into th.acc.
  void run_block(Thread& th) const {
    if (th.nvec == 0) return;
    const int nf = th.nf;
    vd* a = th.acc.data();
    for (const auto& w : plans) {
      if (w.pg1) {
        int f0 = 0;
        if (w.pg2)
          for (; f0 + 2 <= nf; f0 += 2) w.pg2(w.pi, th.view, th.nvec, f0, a);
        for (; f0 < nf; ++f0) w.pg1(w.pi, th.view, th.nvec, f0, a);
        a += 4 * nf;
        continue;
      }
      if (w.ops & kInterp) {
        int f0 = 0;
        if (w.pi2)
          for (; f0 + 2 <= nf; f0 += 2) w.pi2(w.pi, th.view, th.nvec, f0, a);
        for (; f0 < nf; ++f0) w.pi1(w.pi, th.view, th.nvec, f0, a);
      }
      if (w.ops & (kGrad | kLap)) {
        int f0 = 0;
        if (w.g2)
          for (; f0 + 2 <= nf; f0 += 2) w.g2(w.g, th.view, th.nvec, f0, a);
        for (; f0 < nf; ++f0) w.g1(w.g, th.view, th.nvec, f0, a);
      }
      a += 4 * nf;
    }
    th.nvec = 0;
  }

  // Masked mode, specialized: NF fields (0: any number), POW = Σ 2^m over the powers
  // (1/q)^m some weight needs, RSQRT: 1/√r² by rsqrt14 + Newton.  Block pointers and
  // field pointers are locals, so nothing is reloaded after the stores.
  template <int NF, int POW, bool RSQRT>
  void masked_range_t(Thread& th, int32_t b, int32_t e, double px, double py,
                      const double* const* fs, const vd* vt) const {
    const int nf = NF > 0 ? NF : th.nf;
    const double* __restrict xs = cl.xs();
    const double* __restrict ys = cl.ys();
    const double* __restrict Vp = Vs.data();
    const double* fl[kMaxFields];
    vd vtl[kMaxFields];
    vd* bvv[kMaxFields];
    vd* bvdv[kMaxFields];
    for (int f = 0; f < nf; ++f) {
      fl[f] = fs[f];
      vtl[f] = vt[f];
      bvv[f] = th.vv[f].data();
      bvdv[f] = th.vdv[f].data();
    }
    vd* __restrict bdx = th.dx.data();
    vd* __restrict bdy = th.dy.data();
    vd* __restrict bq = th.q.data();
    vd* __restrict bi1 = th.ip[1].data();
    vd* __restrict bi2 = th.ip[2].data();
    vd* __restrict bi3 = th.ip[3].data();
    const vd PX = vbc(px), PY = vbc(py), H2 = vbc(h2), H = vbc(h), Z = vbc(0.0),
             INVH = vbc(invh);
    int n = th.nvec;
    // Lanes outside the disc (or past the range: only in the peeled last vector) get
    // V = 0; their q stays finite (real particles or the far padding).
    auto step = [&](int32_t k, vm in0, auto tail) __attribute__((always_inline)) {
      const vd dx = vload(xs + k) - PX, dy = vload(ys + k) - PY;
      const vd r2 = dx * dx + dy * dy;
      vm in = r2 < H2;
      if constexpr (decltype(tail)::value) in &= in0;
      const vm nz = in & (r2 > Z);
      const vd V = in ? vload(Vp + k) : Z;
      vd r, i1, i2;
#if defined(__AVX512F__)
      if constexpr (RSQRT) {
        const vd r2s = nz ? r2 : H2;
        const vd y = rsqrt_newton(r2s);
        r = nz ? r2s * y : Z;
        i1 = H * y;  // h/r = 1/q; 1 where r = 0
        i2 = i1 * i1;
      } else
#endif
      {
        r = vsqrt(r2);
        // (h/r)² = h²/r² divides r² itself: the divide does not wait for the sqrt;
        // h/r = (r/h)·(h²/r²).  Both are 1 where r = 0 (those lanes carry V(v − v_j) = 0).
        if constexpr (POW != 0) {
          i2 = H2 / (nz ? r2 : H2);
          i1 = nz ? r * INVH * i2 : vbc(1.0);
        }
      }
      bdx[n] = dx;
      bdy[n] = dy;
      bq[n] = r * INVH;
      if constexpr ((POW & 2) != 0) bi1[n] = i1;
      if constexpr ((POW & 4) != 0) bi2[n] = i2;
      if constexpr ((POW & 8) != 0) bi3[n] = i1 * i2;
      for (int f = 0; f < nf; ++f) {
        const vd v = vload(fl[f] + k);
        bvv[f][n] = V * v;
        bvdv[f][n] = nz ? V * (v - vtl[f]) : Z;  // Λ excludes r = 0
      }
      if (++n == kBlockVec) {
        th.nvec = n;
        run_block(th);
        n = 0;
      }
    };
    int32_t k = b;
    for (; k + kW <= e; k += kW) step(k, vm{}, std::false_type{});
    if (k < e) step(k, iota() < static_cast<int64_t>(e - k), std::true_type{});
    th.nvec = n;
  }

  // The fully fused one-weight loop (kernel_fused1.hpp).
  template <int NP, int NC, bool PI, int GM>
  void fused1_range(Thread& th, int32_t b, int32_t e, double px, double py,
                    const double* const* fs, const vd* vt) const;

  // Compact mode (kernel_compact.hpp).
  void compact_range(Thread& th, int32_t b, int32_t e, double px, double py,
                     const double* const* fs, const vd* vt) const;
  void drain(Thread& th, const vd* vt, bool all) const;
  __attribute__((always_inline)) inline void shared(Thread& th, vd dx, vd dy, vd r2, vm in,
                                                    vd V, const vd* v, const vd* vt) const;

  // One chord range [b, e) of candidates for the target at (px, py): masked_range_t,
  // fused1_range or compact_range, picked once per pass (kernel_dispatch.hpp).
  using RangeFn = void (KernelPass::*)(Thread&, int32_t, int32_t, double, double,
                                       const double* const*, const vd*) const;
};

}  // namespace
}  // namespace gpm
