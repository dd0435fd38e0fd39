// Vectors of doubles for the neighbour-sum loops: GCC vector extensions as wide as the
// target's widest double vector (8 lanes with AVX-512), with the few helpers every loop
// needs.  Shared by the fused kernel (kernel.cpp and its private headers) and the
// measured-limit benchmark (bench/bench_limit.cpp), which must time exactly the kernel's
// instruction mix.
// The arithmetic is written once; the compiler emits one instruction per operation, so
// nothing depends on the auto-vectorizer.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__AVX512F__) || defined(__AVX__) || defined(__SSE2__)
#include <immintrin.h>
#endif

namespace gpm::simd {

#if defined(__AVX512F__)
constexpr int kW = 8;
#elif defined(__AVX__)
constexpr int kW = 4;
#else
constexpr int kW = 2;
#endif
typedef double vd __attribute__((vector_size(kW * sizeof(double))));
typedef int64_t vm __attribute__((vector_size(kW * sizeof(int64_t))));  // lane masks

inline vd vload(const double* p) {
  vd v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline vd vbc(double a) { return vd{} + a; }

inline vd vsqrt(vd x) {
#if defined(__AVX512F__)
  // maskz with a full mask: the same instruction, without GCC 12's spurious
  // -Wmaybe-uninitialized from _mm512_undefined_pd in _mm512_sqrt_pd.
  return (vd)_mm512_maskz_sqrt_pd(static_cast<__mmask8>(0xFF), (__m512d)x);
#elif defined(__AVX__)
  return (vd)_mm256_sqrt_pd((__m256d)x);
#elif defined(__SSE2__)
  return (vd)_mm_sqrt_pd((__m128d)x);
#else
  vd r;
  for (int l = 0; l < kW; ++l) r[l] = std::sqrt(x[l]);
  return r;
#endif
}

#if defined(__AVX512F__)
// 1/√x by rsqrt14 (14 bits) and two Newton steps (≤ 2 ulp): KernelOptions::fast_rsqrt, the
// same recipe in the masked and the compact loops.  Every lane is computed (a full mask).
inline vd rsqrt_newton(vd x) {
  vd y = (vd)_mm512_maskz_rsqrt14_pd(static_cast<__mmask8>(0xFF), (__m512d)x);
  const vd half = vbc(0.5), three_half = vbc(1.5);
  y = y * (three_half - half * x * y * y);
  y = y * (three_half - half * x * y * y);
  return y;
}
#endif

template <int NC>
inline vd horner(const double* c, vd q) {
  vd s = vbc(c[NC - 1]);
  for (int j = NC - 2; j >= 0; --j) s = s * q + c[j];
  return s;
}

inline double hsum(vd v) {
  double s = 0;
  for (int l = 0; l < kW; ++l) s += v[l];
  return s;
}

}  // namespace gpm::simd
