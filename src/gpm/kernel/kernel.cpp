#include "gpm/kernel/kernel.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <type_traits>
#include <utility>

#if defined(__AVX512F__) || defined(__AVX__) || defined(__SSE2__)
#include <immintrin.h>
#endif

#include "gpm/error.hpp"
#include "gpm/kernel/kernel_blocks.hpp"  // the per-weight loops (and kernel_poly.hpp)
#include "gpm/kernel/simd.hpp"

namespace gpm {


// ---------------------------------------------------------------------------------

struct FusedKernel::Impl {
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

  // The shared quantities of one vector of pairs into the block.  Lanes outside `in`
  // get V = 0 (they contribute exactly 0) and a finite q.
  __attribute__((always_inline)) inline void shared(Thread& th, vd dx, vd dy, vd r2, vm in,
                                                    vd V, const vd* v, const vd* vt) const {
    const vd H = vbc(h), Z = vbc(0.0);
    const vm nz = in & (r2 > Z);
    const vd r2c = in ? r2 : vbc(h2);
    V = in ? V : Z;
    vd r, iq = vbc(1.0);
#if defined(__AVX512F__)
    if (opt.fast_rsqrt) {
      const vd r2s = nz ? r2c : vbc(h2);
      vd y = (vd)_mm512_maskz_rsqrt14_pd(static_cast<__mmask8>(0xFF), (__m512d)r2s);
      const vd half = vbc(0.5), three_half = vbc(1.5);
      y = y * (three_half - half * r2s * y * y);
      y = y * (three_half - half * r2s * y * y);
      r = nz ? r2s * y : Z;
      iq = H * y;  // h/r = 1/q; 1 where r = 0
    } else
#endif
    {
      r = vsqrt(r2c);
      if (need_iq) iq = H / (nz ? r : H);
    }
    const int i = th.nvec;
    th.dx[i] = dx;
    th.dy[i] = dy;
    th.q[i] = r * invh;
    if (need_pow[1]) th.ip[1][i] = iq;
    if (need_pow[2]) th.ip[2][i] = iq * iq;
    if (need_pow[3]) th.ip[3][i] = iq * iq * iq;
    for (int f = 0; f < th.nf; ++f) {
      th.vv[f][i] = V * v[f];
      th.vdv[f][i] = nz ? V * (v[f] - vt[f]) : Z;  // Λ excludes r = 0
    }
    if (++th.nvec == kBlockVec) run_block(th);
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
        vd y = (vd)_mm512_maskz_rsqrt14_pd(static_cast<__mmask8>(0xFF), (__m512d)r2s);
        const vd half = vbc(0.5), three_half = vbc(1.5);
        y = y * (three_half - half * r2s * y * y);
        y = y * (three_half - half * r2s * y * y);
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

  using RangeFn = void (Impl::*)(Thread&, int32_t, int32_t, double, double,
                                 const double* const*, const vd*) const;
  template <int NF, int POW>
  RangeFn pick_range_rs() const {
#if defined(__AVX512F__)
    if (opt.fast_rsqrt) return &Impl::masked_range_t<NF, POW, true>;
#endif
    return &Impl::masked_range_t<NF, POW, false>;
  }
  template <int NF>
  RangeFn pick_range_pow() const {
    const int pow = (need_pow[1] ? 2 : 0) | (need_pow[2] ? 4 : 0) | (need_pow[3] ? 8 : 0);
    switch (pow) {
      case 0: return pick_range_rs<NF, 0>();
      case 2: return pick_range_rs<NF, 2>();
      case 4: return pick_range_rs<NF, 4>();
      case 6: return pick_range_rs<NF, 6>();
      case 8: return pick_range_rs<NF, 8>();
      case 10: return pick_range_rs<NF, 10>();
      case 12: return pick_range_rs<NF, 12>();
      default: return pick_range_rs<NF, 14>();
    }
  }
  RangeFn pick_range(int nf) const {
    return nf == 1 ? pick_range_pow<1>() : nf == 2 ? pick_range_pow<2>() : pick_range_pow<0>();
  }

  // The fully fused loop for the commonest pass — one weight, one field: the shared
  // quantities, the polynomials and the accumulators stay in registers; no block is
  // written.  NP pieces, NC (padded) coefficients; PI: Π wanted; GM: how ∇/Δ get
  // G = w(q)/q²:  0 not wanted,  1..4 own Horner on the pre-divided coefficients times
  // (1/q)^(GM−1),  5 G = W·h²/r² from the Π value W (the same weight: saves a Horner;
  // used when w/q² needs a divide anyway).  Both ∇ and Δ are accumulated (the unrequested
  // one is dropped).  Accumulators are carried across rows through th.acc[0..3].
  template <int NP, int NC, bool PI, int GM>
  void fused1_range(Thread& th, int32_t b, int32_t e, double px, double py,
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

  template <int NP, int NC, bool PI>
  RangeFn pick_f1_gm(int gm) const {
    if constexpr (PI) {
      switch (gm) {
        case 0: return &Impl::fused1_range<NP, NC, true, 0>;
        case 1: return &Impl::fused1_range<NP, NC, true, 1>;
        default: return &Impl::fused1_range<NP, NC, true, 5>;
      }
    } else {
      switch (gm) {
        case 1: return &Impl::fused1_range<NP, NC, false, 1>;
        case 2: return &Impl::fused1_range<NP, NC, false, 2>;
        case 3: return &Impl::fused1_range<NP, NC, false, 3>;
        default: return &Impl::fused1_range<NP, NC, false, 4>;
      }
    }
  }
  template <int NP>
  RangeFn pick_f1_nc(int nc, bool pi, int gm) const {
    switch (nc) {
      case 1:
      case 2: return pi ? pick_f1_gm<NP, 2, true>(gm) : pick_f1_gm<NP, 2, false>(gm);
      case 3: return pi ? pick_f1_gm<NP, 3, true>(gm) : pick_f1_gm<NP, 3, false>(gm);
      case 4: return pi ? pick_f1_gm<NP, 4, true>(gm) : pick_f1_gm<NP, 4, false>(gm);
      case 5: return pi ? pick_f1_gm<NP, 5, true>(gm) : pick_f1_gm<NP, 5, false>(gm);
      case 6: return pi ? pick_f1_gm<NP, 6, true>(gm) : pick_f1_gm<NP, 6, false>(gm);
      default: return pi ? pick_f1_gm<NP, 8, true>(gm) : pick_f1_gm<NP, 8, false>(gm);
    }
  }
  // The fused single-weight loop where it applies (one weight, one field), else nullptr.
  RangeFn pick_fused1(int nf) const {
    if (plans.size() != 1 || nf != 1 || !opt.fuse_single || opt.fast_rsqrt) return nullptr;
    const WPlan& w = plans[0];
    const bool pi = w.ops & kInterp, g = w.ops & (kGrad | kLap);
    // G mode: own Horner with (1/q)^m (m = 0 needs no divide), or W·h²/r² when Π is
    // evaluated anyway and w/q² needs a divide.
    int gm = 0, nc = 0;
    if (pi) nc = w.pi.nc;
    if (g) {
      if (pi && w.g.m > 0) {
        gm = 5;
      } else {
        gm = 1 + w.g.m;
        nc = std::max(nc, w.g.nc);
      }
    }
    const int np = pi ? w.pi.np : w.g.np;
    if (np > 3 || nc > 8) return nullptr;
    if (pi && g) {  // the two polynomials must share the breakpoints
      if (w.pi.np != w.g.np) return nullptr;
      for (int p = 0; p < np; ++p)
        if (w.pi.begin[p] != w.g.begin[p]) return nullptr;
    }
    if (pi && gm != 0 && gm != 1 && gm != 5) return nullptr;
    switch (np) {
      case 1: return pick_f1_nc<1>(nc, pi, gm);
      case 2: return pick_f1_nc<2>(nc, pi, gm);
      default: return pick_f1_nc<3>(nc, pi, gm);
    }
  }

  // Compact mode: the accepted pairs of [b, e) appended to the staging arrays; full
  // vectors of staged pairs go into the block.
  void compact_range(Thread& th, int32_t b, int32_t e, double px, double py,
                     const double* const* fs, const vd* vt) const {
    const int nf = th.nf;
#if defined(__AVX512F__)
    const double* __restrict xs = cl.xs();
    const double* __restrict ys = cl.ys();
    const double* __restrict Vp = Vs.data();
    double* __restrict sdx = th.sdx;
    double* __restrict sdy = th.sdy;
    double* __restrict sr2 = th.sr2;
    double* __restrict sV = th.sV;
    int c = th.scnt;
    const __m512d PX = _mm512_set1_pd(px), PY = _mm512_set1_pd(py), H2 = _mm512_set1_pd(h2);
    for (int32_t k = b; k < e; k += 8) {
      const __m512d dx = _mm512_sub_pd(_mm512_loadu_pd(xs + k), PX);
      const __m512d dy = _mm512_sub_pd(_mm512_loadu_pd(ys + k), PY);
      const __m512d r2 = _mm512_fmadd_pd(dx, dx, _mm512_mul_pd(dy, dy));
      __mmask8 m = _mm512_cmp_pd_mask(r2, H2, _CMP_LT_OQ);
      if (e - k < 8) m &= static_cast<__mmask8>((1u << (e - k)) - 1u);
      _mm512_storeu_pd(sdx + c, _mm512_maskz_compress_pd(m, dx));
      _mm512_storeu_pd(sdy + c, _mm512_maskz_compress_pd(m, dy));
      _mm512_storeu_pd(sr2 + c, _mm512_maskz_compress_pd(m, r2));
      _mm512_storeu_pd(sV + c, _mm512_maskz_compress_pd(m, _mm512_loadu_pd(Vp + k)));
      for (int f = 0; f < nf; ++f)
        _mm512_storeu_pd(th.sv[f] + c, _mm512_maskz_compress_pd(m, _mm512_loadu_pd(fs[f] + k)));
      c += __builtin_popcount(m);
      if (c >= Thread::kStage) {
        th.scnt = c;
        drain(th, vt, false);
        c = th.scnt;
      }
    }
    th.scnt = c;
#else
    const double* xs = cl.xs();
    const double* ys = cl.ys();
    for (int32_t k = b; k < e; ++k) {
      const double dx = xs[k] - px, dy = ys[k] - py;
      const double r2 = dist2(dx, dy);
      if (r2 < h2) {
        const int c = th.scnt;
        th.sdx[c] = dx;
        th.sdy[c] = dy;
        th.sr2[c] = r2;
        th.sV[c] = Vs[k];
        for (int f = 0; f < nf; ++f) th.sv[f][c] = fs[f][k];
        if (++th.scnt >= Thread::kStage) drain(th, vt, false);
      }
    }
#endif
  }

  // Staged pairs → block, full vectors only unless `all` (the last one masked).
  void drain(Thread& th, const vd* vt, bool all) const {
    const int nf = th.nf;
    const int full = th.scnt - th.scnt % kW;
    vd v[kMaxFields];
    for (int i = 0; i < full; i += kW) {
      for (int f = 0; f < nf; ++f) v[f] = vload(th.sv[f] + i);
      shared(th, vload(th.sdx + i), vload(th.sdy + i), vload(th.sr2 + i), vbc(0.0) == vbc(0.0),
             vload(th.sV + i), v, vt);
    }
    int rest = th.scnt - full;
    if (all && rest > 0) {
      for (int f = 0; f < nf; ++f) v[f] = vload(th.sv[f] + full);
      const vm in = iota() < static_cast<int64_t>(rest);
      shared(th, vload(th.sdx + full), vload(th.sdy + full), vload(th.sr2 + full), in,
             vload(th.sV + full), v, vt);
      rest = 0;
    }
    for (int i = 0; i < rest; ++i) {
      th.sdx[i] = th.sdx[full + i];
      th.sdy[i] = th.sdy[full + i];
      th.sr2[i] = th.sr2[full + i];
      th.sV[i] = th.sV[full + i];
      for (int f = 0; f < nf; ++f) th.sv[f][i] = th.sv[f][full + i];
    }
    th.scnt = rest;
  }
};

// ---------------------------------------------------------------------------------

FusedKernel::FusedKernel(const std::vector<double>& x, const std::vector<double>& y,
                         const std::vector<double>& V, double h,
                         std::vector<KernelWeight> weights, KernelOptions opt)
    : impl_(new Impl) {
  try {
    require_positive(h, "influence radius h");
    if (V.size() != x.size()) throw InputError("fused kernel: V and x differ in length");
    if (opt.cells_per_h < 1) throw InputError("fused kernel: cells_per_h must be >= 1");
    if (opt.chunk < 1) opt.chunk = 1;
    impl_->h = h;
    impl_->h2 = h * h;
    impl_->invh = 1.0 / h;
    impl_->opt = opt;
    impl_->cl = CellList(x, y, h / opt.cells_per_h);
    impl_->Vs = impl_->cl.gather(V, 0.0);
    for (const auto& kw : weights) {
      WPlan p;
      p.ops = kw.ops & kAllOps;
      if (p.ops & kInterp) {
        p.pi = build_eval(kw.weight, 0, "interpolant");
        if (p.pi.m > 0)
          throw InputError("weight '" + kw.weight.name +
                           "' is unbounded at r = 0: no interpolant with it");
      }
      if (p.ops & (kGrad | kLap)) {
        p.g = build_eval(kw.weight, 2, "w/r^2");
        if (p.g.m > 3)
          throw InputError("weight '" + kw.weight.name + "': w/r^2 more singular than r^-3");
        p.g1 = pick(false, p.g, p.ops, 1);
        p.g2 = pick(false, p.g, p.ops, 2);
      }
      if (p.ops & kInterp) {
        p.pi1 = pick(true, p.pi, p.ops, 1);
        p.pi2 = pick(true, p.pi, p.ops, 2);
      }
      // Π and ∇/Δ of the same weight with a divide anyway: G = W·(h/r)².  (The
      // breakpoints of w and w/q² are the same pieces.)
      if ((p.ops & kInterp) && (p.ops & (kGrad | kLap)) && p.g.m > 0 && p.pi.np == p.g.np) {
        p.pg1 = pick_pg(p.pi, p.ops, 1);
        p.pg2 = pick_pg(p.pi, p.ops, 2);
      }
      // The powers of h/r the shared stage must provide.
      if (p.pg1) impl_->need_pow[2] = true;
      else if ((p.ops & (kGrad | kLap)) && p.g.m > 0) impl_->need_pow[p.g.m] = true;
      impl_->need_iq = impl_->need_iq || p.pg1 || ((p.ops & (kGrad | kLap)) && p.g.m > 0);
      impl_->plans.push_back(p);
    }
  } catch (...) {
    delete impl_;
    throw;
  }
}

FusedKernel::FusedKernel(const Particles& p, const std::vector<double>& V, double h,
                         std::vector<KernelWeight> weights, KernelOptions opt)
    : FusedKernel(p.x, p.y, V, h, std::move(weights), opt) {}

FusedKernel::~FusedKernel() { delete impl_; }
FusedKernel::FusedKernel(FusedKernel&& o) noexcept : impl_(o.impl_) { o.impl_ = nullptr; }
FusedKernel& FusedKernel::operator=(FusedKernel&& o) noexcept {
  std::swap(impl_, o.impl_);
  return *this;
}

double FusedKernel::h() const { return impl_->h; }
const CellList& FusedKernel::cells() const { return impl_->cl; }
std::size_t FusedKernel::n_weights() const { return impl_->plans.size(); }
const KernelOptions& FusedKernel::options() const { return impl_->opt; }
bool FusedKernel::needs_divide() const { return impl_->need_iq; }

KernelResult FusedKernel::apply(const std::vector<int32_t>& targets,
                                const std::vector<std::vector<double>>& fields) const {
  std::vector<const std::vector<double>*> ptr;
  for (const auto& f : fields) ptr.push_back(&f);
  return apply(targets, ptr);
}

namespace {
// Target positions ordered by their slot in the cell list (cell order: locality).
// Counting sort: O(N + targets), stable for repeated targets.
std::vector<int32_t> order_by_slot(const CellList& cl, const std::vector<int32_t>& targets) {
  const std::size_t n = cl.size();
  for (auto t : targets)
    if (t < 0 || static_cast<std::size_t>(t) >= n) {
      std::ostringstream s;
      s << "fused kernel: target index " << t << " is not a particle (N = " << n << ")";
      throw InputError(s.str());
    }
  std::vector<int32_t> first(n + 1, 0);
  for (auto t : targets) ++first[cl.slot()[t] + 1];
  for (std::size_t k = 1; k <= n; ++k) first[k] += first[k - 1];
  std::vector<int32_t> order(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i)
    order[first[cl.slot()[targets[i]]]++] = static_cast<int32_t>(i);
  return order;
}

int thread_count(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }
}  // namespace

KernelResult FusedKernel::apply(const std::vector<int32_t>& targets,
                                const std::vector<const std::vector<double>*>& fields) const {
  KernelResult res;
  apply(targets, fields, res);
  return res;
}

void FusedKernel::apply(const std::vector<int32_t>& targets,
                        const std::vector<const std::vector<double>*>& fields,
                        KernelResult& res) const {
  const Impl& I = *impl_;
  const int nf = static_cast<int>(fields.size());
  if (nf > kMaxFields) throw InputError("fused kernel: more than 8 fields in one pass");
  const std::size_t n = I.cl.size(), stride = n + CellList::kPad;
  for (const auto* f : fields)
    if (f == nullptr || f->size() != n)
      throw InputError("fused kernel: a field's size differs from the number of particles");

  // Reuse the result's storage when called again with the same targets (time loops).
  const int nw = static_cast<int>(I.plans.size());
  if (res.targets_ != targets || res.order_.size() != targets.size()) {
    res.order_ = order_by_slot(I.cl, targets);
    res.targets_ = targets;
  }
  res.nw_ = nw;
  res.nf_ = nf;
  res.column_.assign(static_cast<std::size_t>(nw) * nf * 4, -1);
  int ncol = 0;
  for (int w = 0; w < nw; ++w)
    for (int f = 0; f < nf; ++f)
      for (int c = 0; c < 4; ++c) {
        const unsigned op = c == 0 ? kInterp : c == 3 ? kLap : kGrad;
        if (I.plans[w].ops & op) res.column_[(w * nf + f) * 4 + c] = ncol++;
      }
  const std::size_t nt = targets.size();
  res.data_.resize(static_cast<std::size_t>(ncol) * nt);  // every entry is written below
  if (nt == 0 || nf == 0 || nw == 0) return;
  // The fields in sorted order (padded with 0), gathered inside the parallel region.
  if (res.work_.size() != nf * stride) res.work_.assign(nf * stride, 0.0);
  const double* fs[kMaxFields] = {};
  for (int f = 0; f < nf; ++f) fs[f] = res.work_.data() + f * stride;

  const int32_t* order = res.order_.data();
  const double h4 = I.h2 * I.h2;
  const double scale[4] = {1.0 / I.h2, kD / h4, kD / h4, 2.0 * kD / h4};
  const std::size_t nacc = static_cast<std::size_t>(nw) * nf * 4;
  double* out = res.data_.data();
  double* work = res.work_.data();
  const int32_t* colmap = res.column_.data();
  const int32_t* index = I.cl.index().data();
  const Impl::RangeFn fused1 = I.opt.compact ? nullptr : I.pick_fused1(nf);
  const Impl::RangeFn range = fused1 ? fused1 : I.pick_range(nf);

#pragma omp parallel num_threads(thread_count(I.opt.threads))
  {
    for (int f = 0; f < nf; ++f) {
      const double* src = fields[f]->data();
      double* dst = work + f * stride;
#pragma omp for schedule(static)
      for (std::size_t k = 0; k < n; ++k) dst[k] = src[index[k]];
    }
    Impl::Thread th(nacc, nf);
    vd vt[kMaxFields];
#pragma omp for schedule(dynamic, I.opt.chunk)
    for (std::size_t it = 0; it < nt; ++it) {
      const int32_t pos = order[it];
      const int32_t slot = I.cl.slot()[targets[pos]];
      const double px = I.cl.xs()[slot], py = I.cl.ys()[slot];
      for (int f = 0; f < nf; ++f) vt[f] = vbc(fs[f][slot]);
      std::fill(th.acc.begin(), th.acc.end(), vbc(0.0));
      th.nvec = 0;
      th.scnt = 0;
      if (I.opt.compact) {
        I.cl.for_each_range(px, py, I.h, [&](int32_t b, int32_t e) {
          I.compact_range(th, b, e, px, py, fs, vt);
        });
        I.drain(th, vt, true);
      } else {
        I.cl.for_each_range(px, py, I.h, [&](int32_t b, int32_t e) {
          (I.*range)(th, b, e, px, py, fs, vt);
        });
      }
      I.run_block(th);
      // Fixed-order lane reduction: bitwise the same for any thread count.
      for (std::size_t a = 0; a < nacc; ++a) {
        const int32_t col = colmap[a];
        if (col < 0) continue;
        double s = 0;
        for (int l = 0; l < kW; ++l) s += th.acc[a][l];
        out[static_cast<std::size_t>(col) * nt + pos] = s * scale[a % 4];
      }
    }
  }
}

PairCount FusedKernel::count_pairs(const std::vector<int32_t>& targets) const {
  const Impl& I = *impl_;
  const std::vector<int32_t> order = order_by_slot(I.cl, targets);
  int64_t cand = 0, acc = 0;
  const double* xs = I.cl.xs();
  const double* ys = I.cl.ys();
  const std::size_t nt = targets.size();
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : cand, acc) \
    num_threads(thread_count(I.opt.threads))
  for (std::size_t it = 0; it < nt; ++it) {
    const int32_t slot = I.cl.slot()[targets[order[it]]];
    const double px = xs[slot], py = ys[slot];
    I.cl.for_each_range(px, py, I.h, [&](int32_t b, int32_t e) {
      cand += e - b;
      for (int32_t k = b; k < e; ++k) acc += dist2(xs[k] - px, ys[k] - py) < I.h2;
    });
  }
  return {cand, acc};
}

// ---------------------------------------------------------------------------------

bool KernelResult::has(int w, KernelOp op) const {
  if (w < 0 || w >= nw_ || nf_ == 0) return false;
  const int c = op == kInterp ? 0 : op == kGrad ? 1 : op == kLap ? 3 : -1;
  return c >= 0 && column_[(w * nf_) * 4 + c] >= 0;
}

std::span<const double> KernelResult::col(int w, int f, int comp) const {
  if (w < 0 || w >= nw_ || f < 0 || f >= nf_) {
    std::ostringstream s;
    s << "kernel result: no weight " << w << " / field " << f;
    throw InputError(s.str());
  }
  const int32_t c = column_[(w * nf_ + f) * 4 + comp];
  if (c < 0) {
    static const char* names[4] = {"interpolant", "gradient", "gradient", "Laplacian"};
    std::ostringstream s;
    s << "kernel result: the " << names[comp] << " was not requested for weight " << w;
    throw InputError(s.str());
  }
  return {data_.data() + static_cast<std::size_t>(c) * targets_.size(), targets_.size()};
}

std::vector<int32_t> omega_targets(const Particles& p) {
  std::vector<int32_t> t;
  t.reserve(p.count_in_omega());
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.in_omega[i]) t.push_back(static_cast<int32_t>(i));
  return t;
}

}  // namespace gpm
