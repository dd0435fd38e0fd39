// The fused kernel's compact mode (KernelOptions::compact): the accepted pairs of a chord
// range compressed (AVX-512 compress) into staging arrays before the square root, then
// fed to the block in full vectors.  Measured and found not to pay off on the project's
// machine (kernel.hpp, "How"); kept for the benchmark (bench_kernel's fused1_compact) and
// checked by the tests against the kernel's other paths.
// Private to the kernel: included by kernel.cpp only.
#pragma once
#include <cstdint>

#if defined(__AVX512F__) || defined(__AVX__) || defined(__SSE2__)
#include <immintrin.h>
#endif

#include "gpm/kernel/kernel_pass.hpp"

namespace gpm {
namespace {

// The shared quantities of one vector of pairs into the block.  Lanes outside `in`
// get V = 0 (they contribute exactly 0) and a finite q.  (Compact mode's: the masked loop
// of kernel_pass.hpp writes its block itself.)
__attribute__((always_inline)) inline void KernelPass::shared(Thread& th, vd dx, vd dy, vd r2,
                                                              vm in, vd V, const vd* v,
                                                              const vd* vt) const {
  const vd H = vbc(h), Z = vbc(0.0);
  const vm nz = in & (r2 > Z);
  const vd r2c = in ? r2 : vbc(h2);
  V = in ? V : Z;
  vd r, iq = vbc(1.0);
#if defined(__AVX512F__)
  if (opt.fast_rsqrt) {
    const vd r2s = nz ? r2c : vbc(h2);
    const vd y = rsqrt_newton(r2s);
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

// Compact mode: the accepted pairs of [b, e) appended to the staging arrays; full
// vectors of staged pairs go into the block.
inline void KernelPass::compact_range(Thread& th, int32_t b, int32_t e, double px, double py,
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
inline void KernelPass::drain(Thread& th, const vd* vt, bool all) const {
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

}  // namespace
}  // namespace gpm
