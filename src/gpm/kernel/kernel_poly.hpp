// The fused kernel's weights as plain polynomial coefficients and their evaluation, scalar
// and over vectors of pairs.  Private to the kernel: included by kernel.cpp and
// plain_baseline.cpp only (its anonymous namespace gives each its own copy).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstring>

#include "gpm/error.hpp"
#include "gpm/kernel/simd.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {
namespace {

constexpr int kD = 2;  // space dimension

// Vectors of pairs: gpm/kernel/simd.hpp (kW lanes, vd, vm, vload, vbc, vsqrt, horner).
using namespace simd;

inline vm iota() {
  vm v;
  for (int l = 0; l < kW; ++l) v[l] = l;
  return v;
}

// ---------------------------------------------------------------------------------
// A weight (or w/q²) as plain coefficients: on piece p (q ≥ begin[p], pieces ascending)
//   f(q) = (1/q)^m · Σ_j c[p][j] q^j.

constexpr int kMaxPieces = 8, kMaxCoef = 12;

struct PolyEval {
  int np = 1, nc = 1, m = 0;
  double begin[kMaxPieces] = {};
  double c[kMaxPieces][kMaxCoef] = {};
};

// w(q)/q^s from the weight's pieces, constant folded in.
PolyEval build_eval(const WeightFunction& w, int s, const std::string& what) {
  struct P {
    double a;
    int e;  // power of the first coefficient
    std::vector<double> c;
  };
  std::vector<P> ps;
  double cursor = 0;
  auto zero_piece = [&](double a) { ps.push_back({a, 0, {}}); };
  for (const auto& piece : w.shape) {
    if (piece.r_begin >= 1) break;  // support is [0, 1)
    if (piece.r_begin < cursor || !(piece.r_end > piece.r_begin))
      throw InputError("weight '" + w.name + "': pieces must be ascending and non-empty");
    if (piece.r_begin > cursor) zero_piece(cursor);
    std::size_t j0 = 0, j1 = piece.c.size();
    while (j0 < j1 && piece.c[j0] == 0) ++j0;
    while (j1 > j0 && piece.c[j1 - 1] == 0) --j1;
    P p{piece.r_begin, piece.p_min + static_cast<int>(j0) - s, {}};
    for (std::size_t j = j0; j < j1; ++j) p.c.push_back(w.constant * piece.c[j]);
    if (p.c.empty()) p.e = 0;
    ps.push_back(std::move(p));
    cursor = piece.r_end;
  }
  if (ps.empty()) zero_piece(0);
  if (cursor < 1) zero_piece(cursor);
  if (ps.size() > static_cast<std::size_t>(kMaxPieces))
    throw InputError("weight '" + w.name + "': more than 8 pieces for the kernel");
  PolyEval ev;
  ev.np = static_cast<int>(ps.size());
  for (const auto& p : ps)
    if (!p.c.empty()) ev.m = std::max(ev.m, -p.e);
  int nc = 1;
  for (int i = 0; i < ev.np; ++i) {
    const auto& p = ps[i];
    ev.begin[i] = p.a;
    for (std::size_t j = 0; j < p.c.size(); ++j) {
      const int idx = p.e + ev.m + static_cast<int>(j);
      if (idx >= kMaxCoef)
        throw InputError("weight '" + w.name + "': degree too high for the kernel (" + what +
                         ")");
      ev.c[i][idx] = p.c[j];
      nc = std::max(nc, idx + 1);
    }
  }
  ev.nc = nc;
  return ev;
}


inline vd horner_n(const double* c, int nc, vd q) {
  switch (nc) {
    case 1: return vbc(c[0]);
    case 2: return horner<2>(c, q);
    case 3: return horner<3>(c, q);
    case 4: return horner<4>(c, q);
    case 5: return horner<5>(c, q);
    case 6: return horner<6>(c, q);
    case 7: return horner<7>(c, q);
    case 8: return horner<8>(c, q);
    case 9: return horner<9>(c, q);
    case 10: return horner<10>(c, q);
    case 11: return horner<11>(c, q);
    default: return horner<12>(c, q);
  }
}

// Branch-free: every piece is evaluated and the last one with q ≥ begin is kept.  The
// factor (1/q)^m is the caller's.
__attribute__((always_inline)) inline vd eval(const PolyEval& e, vd q) {
  vd s = horner_n(e.c[0], e.nc, q);
  for (int p = 1; p < e.np; ++p) {
    const vd t = horner_n(e.c[p], e.nc, q);
    s = (q >= vbc(e.begin[p])) ? t : s;
  }
  return s;
}

// Scalar evaluation (the plain baseline): branchy piece search, one divide.
inline double eval_scalar(const PolyEval& e, double q, double h_over_r) {
  int p = 0;
  while (p + 1 < e.np && q >= e.begin[p + 1]) ++p;
  double s = 0;
  for (int j = e.nc - 1; j >= 0; --j) s = s * q + e.c[p][j];
  for (int k = 0; k < e.m; ++k) s *= h_over_r;
  return s;
}


}  // namespace
}  // namespace gpm
