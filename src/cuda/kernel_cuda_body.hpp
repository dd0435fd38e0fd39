// The arithmetic of the CUDA kernels (kernel_cuda.cu), written once for the device and
// the host.
//
// Everything the GPU computes per target lives here as plain functions marked GPM_HD
// (__host__ __device__ under nvcc, nothing under a C++ compiler), so a machine without a
// GPU can still run the very same code on its CPU and compare it with gpm::FusedKernel
// (tests/unit/cuda_body.cpp does).  What the CPU cannot check is only the CUDA plumbing
// around it: uploads, launches, the device's own rounding (FMA contraction by nvcc).
//
// Definitions as in gpm/kernel/kernel.hpp (d = 2, q = r/h, G(q) = w(q)/q²):
//   Π_h v(x_j) = h^-2     Σ_{r<h}   V_i v_i w(q)
//   ∇_h v(x_j) = d h^-4   Σ_{0<r<h} V_i (v_i − v_j)(x_i − x_j) G(q)
//   Δ_h v(x_j) = 2d h^-4  Σ_{0<r<h} V_i (v_i − v_j) G(q)
// Neighbour search: the particles sorted by a uniform grid of cells (gpm::CellList's sorted
// order and cell offsets, uploaded as they are); per row of cells that can meet the disc
// |x − x_j| < h, the contiguous slot range of the cells overlapping the disc's chord —
// the same ranges CellList::for_each_range visits, so the candidate counts agree with the
// CPU kernel's for the same cell size.  One target per thread, sums in double, in slot
// order (deterministic for a given cell size).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/weights/weights.hpp"

#if defined(__CUDACC__)
#define GPM_HD __host__ __device__
#else
#define GPM_HD
#endif

namespace gpm::cuda {

// Operator bits: the same values as gpm::KernelOp (kInterp, kGrad, kLap).
constexpr unsigned kOpInterp = 1u, kOpGrad = 2u, kOpLap = 4u, kOpAll = 7u;
constexpr int kMaxPieces = 8, kMaxCoef = 12;

// A piecewise Laurent polynomial in q on [0, 1): on piece p (q ≥ begin[p], pieces
// ascending, begin[0] = 0)   f(q) = q^e[p] · Σ_{j<nc[p]} c[p][j] q^j.
// Plain data (a kernel argument).  e < 0 only for weights singular at 0; those need a
// divide, and callers never evaluate them at q = 0.
struct PieceTable {
  int np = 0;
  bool negative_power = false;  // some piece has e < 0
  double begin[kMaxPieces] = {};
  int nc[kMaxPieces] = {};
  int e[kMaxPieces] = {};
  double c[kMaxPieces][kMaxCoef] = {};
};

// w(q)/q^shift from the weight's pieces (constant folded in), with gaps in [0, 1) filled by
// zero pieces and zero coefficients at both ends trimmed (so a w = O(q²) weight divided by
// q² has no negative power: no divide).  InputError past kMaxPieces / kMaxCoef.
inline PieceTable piece_table(const WeightFunction& w, int shift) {
  PieceTable t;
  double cursor = 0;
  auto add = [&](double begin, int e, const std::vector<double>& c) {
    if (t.np == kMaxPieces)
      throw InputError("weight '" + w.name + "': more than 8 pieces for the CUDA kernel");
    if (c.size() > static_cast<std::size_t>(kMaxCoef))
      throw InputError("weight '" + w.name + "': more than 12 coefficients per piece for "
                       "the CUDA kernel");
    t.begin[t.np] = begin;
    t.e[t.np] = c.empty() ? 0 : e;
    t.nc[t.np] = static_cast<int>(c.size());
    for (std::size_t j = 0; j < c.size(); ++j) t.c[t.np][j] = c[j];
    if (!c.empty() && e < 0) t.negative_power = true;
    ++t.np;
  };
  for (const auto& piece : w.shape) {
    if (piece.r_begin >= 1) break;  // the support is [0, 1)
    if (piece.r_begin < cursor || !(piece.r_end > piece.r_begin))
      throw InputError("weight '" + w.name + "': pieces must be ascending and non-empty");
    if (piece.r_begin > cursor) add(cursor, 0, {});
    std::size_t j0 = 0, j1 = piece.c.size();
    while (j0 < j1 && piece.c[j0] == 0) ++j0;
    while (j1 > j0 && piece.c[j1 - 1] == 0) --j1;
    std::vector<double> c;
    for (std::size_t j = j0; j < j1; ++j) c.push_back(w.constant * piece.c[j]);
    add(piece.r_begin, piece.p_min + static_cast<int>(j0) - shift, c);
    cursor = piece.r_end;
  }
  if (t.np == 0) add(0, 0, {});
  if (cursor < 1) add(cursor, 0, {});
  return t;
}

// f(q) for 0 ≤ q < 1 (q > 0 where the table has a negative power).
GPM_HD inline double eval_pieces(const PieceTable& t, double q) {
  int p = 0;
  while (p + 1 < t.np && q >= t.begin[p + 1]) ++p;
  double s = 0;
  for (int j = t.nc[p] - 1; j >= 0; --j) s = s * q + t.c[p][j];
  int e = t.e[p];
  for (; e > 0; --e) s *= q;
  if (e < 0) {
    const double iq = 1.0 / q;
    for (; e < 0; ++e) s *= iq;
  }
  return s;
}

// The sorted particles and their cells (pointers into device or host memory).
struct GridView {
  const double* xs = nullptr;  // sorted coordinates and volumes, n entries
  const double* ys = nullptr;
  const double* Vs = nullptr;
  const int32_t* start = nullptr;  // nx·ny + 1 cell offsets (row-major cells)
  int64_t nx = 0, ny = 0;
  double x0 = 0, y0 = 0, c = 1, inv_c = 1;
  double margin = 0;  // rounding slack of the range queries (≥ CellList's)
  double h = 0, h2 = 0, inv_h = 0;
};

// The view of a CellList's sorted order (host pointers; the device code swaps in its own).
// The margin is at least CellList's (1e-10 × the largest of the cell size, the extent and
// the origin), so no range is narrower than the CPU kernel's.
inline GridView grid_view(const CellList& cl, const double* Vs, double h) {
  GridView g;
  g.xs = cl.xs();
  g.ys = cl.ys();
  g.Vs = Vs;
  g.start = cl.start().data();
  g.nx = cl.nx();
  g.ny = cl.ny();
  g.x0 = cl.x0();
  g.y0 = cl.y0();
  g.c = cl.cell_size();
  g.inv_c = 1.0 / g.c;
  const double ext = static_cast<double>(std::max(g.nx, g.ny)) * g.c;
  g.margin = 1e-10 * std::max({g.c, ext, std::abs(g.x0), std::abs(g.y0)});
  g.h = h;
  g.h2 = h * h;
  g.inv_h = 1.0 / h;
  return g;
}

// How ∇/Δ get G = w/q²: its own table without a divide (w = O(q²)), W·h²/r² from the Π
// value (Π evaluated anyway), or its own table with the divides.
enum GMode : int { kGOwnTable = 0, kGFromW = 1 };

GPM_HD inline int64_t clamp_cell(double t, int64_t n) {
  if (!(t >= 0)) return 0;  // also NaN
  if (t >= static_cast<double>(n - 1)) return n - 1;
  return static_cast<int64_t>(t);
}

// Every particle within h of the point (px, py), in slot order: f(slot, dx, dy, r²).  Per row
// of cells that can meet the disc, the contiguous slot range of the cells overlapping its
// chord (as CellList::for_each_range).
template <class F>
GPM_HD inline void for_each_in_disc(const GridView& g, double px, double py, F&& f) {
  const double hm = g.h + g.margin;
  const int64_t r0 = clamp_cell((py - hm - g.y0) * g.inv_c, g.ny);
  const int64_t r1 = clamp_cell((py + hm - g.y0) * g.inv_c, g.ny);
  for (int64_t cy = r0; cy <= r1; ++cy) {
    // Distance from py to the band of row cy, shrunk by the margin: a point assigned to this
    // row by rounding is never missed.
    const double ylo = g.y0 + static_cast<double>(cy) * g.c, yhi = ylo + g.c;
    double dyb = ylo - py > py - yhi ? ylo - py : py - yhi;
    dyb = dyb - g.margin > 0 ? dyb - g.margin : 0.0;
    if (dyb >= g.h) continue;
    const double half = std::sqrt(g.h2 - dyb * dyb) + g.margin;
    const int64_t c0 = clamp_cell((px - half - g.x0) * g.inv_c, g.nx);
    const int64_t c1 = clamp_cell((px + half - g.x0) * g.inv_c, g.nx);
    const int32_t b = g.start[cy * g.nx + c0], e = g.start[cy * g.nx + c1 + 1];
    for (int32_t k = b; k < e; ++k) {
      const double dx = g.xs[k] - px, dy = g.ys[k] - py;
      const double r2 = dx * dx + dy * dy;
      if (r2 < g.h2) f(k, dx, dy, r2);
    }
  }
}

// The four sums of one target (sorted slot `slot`) for field v (sorted order), scaled:
// out = {Π, ∂x ∇, ∂y ∇, Δ}; entries of operators not in OPS are 0.
template <unsigned OPS>
GPM_HD inline void target_sums(const GridView& g, const PieceTable& w, const PieceTable& gq,
                               int gmode, const double* v, int32_t slot, double out[4]) {
  constexpr bool kPi = (OPS & kOpInterp) != 0;
  constexpr bool kG = (OPS & (kOpGrad | kOpLap)) != 0;
  const double px = g.xs[slot], py = g.ys[slot], vt = v[slot];
  double api = 0, agx = 0, agy = 0, alap = 0;
  for_each_in_disc(g, px, py, [&](int32_t k, double dx, double dy, double r2) {
    const double q = std::sqrt(r2) * g.inv_h;
    const double Vk = g.Vs[k], vk = v[k];
    double W = 0;
    if (kPi || (kG && gmode == kGFromW)) W = eval_pieces(w, q);
    if constexpr (kPi) api += Vk * vk * W;
    if (kG && r2 > 0) {  // Λ excludes r = 0
      const double G = gmode == kGFromW ? W * (g.h2 / r2) : eval_pieces(gq, q);
      const double t = G * (Vk * (vk - vt));
      if constexpr ((OPS & kOpGrad) != 0) {
        agx += t * dx;
        agy += t * dy;
      }
      if constexpr ((OPS & kOpLap) != 0) alap += t;
    }
  });
  constexpr double kD = 2.0;
  const double h4 = g.h2 * g.h2;
  out[0] = api / g.h2;
  out[1] = kD * agx / h4;
  out[2] = kD * agy / h4;
  out[3] = 2.0 * kD * alap / h4;
}

// The G mode for a weight and the requested operators: a divide-free own table where
// w/q² is a polynomial, else W·h²/r² when Π is evaluated anyway, else the own table.
inline int g_mode(const PieceTable& gq, unsigned ops) {
  if (!gq.negative_power) return kGOwnTable;
  return (ops & kOpInterp) ? kGFromW : kGOwnTable;
}

// The run-time OPS dispatch of target_sums (the host emulation uses it; the device
// kernel is instantiated per OPS the same way).
inline void target_sums_any(unsigned ops, const GridView& g, const PieceTable& w,
                            const PieceTable& gq, int gmode, const double* v, int32_t slot,
                            double out[4]) {
  switch (ops & kOpAll) {
    case 1: return target_sums<1>(g, w, gq, gmode, v, slot, out);
    case 2: return target_sums<2>(g, w, gq, gmode, v, slot, out);
    case 3: return target_sums<3>(g, w, gq, gmode, v, slot, out);
    case 4: return target_sums<4>(g, w, gq, gmode, v, slot, out);
    case 5: return target_sums<5>(g, w, gq, gmode, v, slot, out);
    case 6: return target_sums<6>(g, w, gq, gmode, v, slot, out);
    default: return target_sums<7>(g, w, gq, gmode, v, slot, out);
  }
}

// ---------------------------------------------------------------------------------
// A study's fused pass: several weights and fields in one loop over the pairs (imoto's nine
// weights and one field; the thesis tables' up to six weights, three operators and their
// test functions).  Per pair the distance is computed once, per weight W and G once, per
// field the sums of the operators that weight asks for — the work gpm::FusedKernel does,
// summed in slot order (deterministic for a cell size).

constexpr int kMaxWeights = 9, kMaxFieldsDevice = 4;

// The fields of a pass as the device holds them: one after another in sorted order, field f
// at data + f·stride.  The stride is the gathered length — the particles and CellList's
// kPad padding slots after them — not the particle count: a stride of n put every field
// but the first kPad slots off (found on the first GPU run, 2026-12-05: Tables 4.1–4.3 at
// relative differences up to 22, imoto's one field exact).
struct SortedFields {
  std::vector<double> data;
  int64_t stride = 0;
};
inline SortedFields sorted_fields(const CellList& cl, const std::vector<std::vector<double>>& fields) {
  SortedFields s;
  for (auto& f : fields) {
    const std::vector<double> g = cl.gather(f, 0.0);
    s.stride = static_cast<int64_t>(g.size());
    s.data.insert(s.data.end(), g.begin(), g.end());
  }
  return s;
}
// v[f] = field f of a SortedFields' data (device or host memory).
GPM_HD inline void field_pointers(const double* data, int64_t stride, int nf, const double** v) {
  for (int f = 0; f < nf; ++f) v[f] = data + static_cast<int64_t>(f) * stride;
}

// One weight of the pass: its tables, G mode and operators (bits kOpInterp, kOpGrad, kOpLap).
struct WeightEntry {
  PieceTable w, gq;
  int gmode = kGOwnTable;
  unsigned ops = kOpAll;
};

inline WeightEntry weight_entry(const WeightFunction& w, unsigned ops) {
  WeightEntry e;
  e.w = piece_table(w, 0);
  e.gq = piece_table(w, 2);
  e.ops = ops & kOpAll;
  e.gmode = g_mode(e.gq, e.ops);
  return e;
}

// The sums of one target for every weight and field, scaled like target_sums:
// out[(wi·nf + f)·4 + c], c = Π, ∂x ∇, ∂y ∇, Δ (0 where weight wi does not ask for it).
// v[f]: field f in sorted order.  nw ≤ kMaxWeights, nf ≤ kMaxFieldsDevice.
GPM_HD inline void fused_target_sums(const GridView& g, const WeightEntry* we, int nw,
                                     const double* const* v, int nf, int32_t slot, double* out) {
  double acc[kMaxWeights * kMaxFieldsDevice * 4];
  for (int i = 0; i < nw * nf * 4; ++i) acc[i] = 0;
  double vt[kMaxFieldsDevice];
  for (int f = 0; f < nf; ++f) vt[f] = v[f][slot];
  const double px = g.xs[slot], py = g.ys[slot];
  for_each_in_disc(g, px, py, [&](int32_t k, double dx, double dy, double r2) {
    const double q = std::sqrt(r2) * g.inv_h;
    const double Vk = g.Vs[k];
    for (int wi = 0; wi < nw; ++wi) {
      const WeightEntry& E = we[wi];
      const bool pi = (E.ops & kOpInterp) != 0, gr = (E.ops & (kOpGrad | kOpLap)) != 0;
      double W = 0;
      if (pi || (gr && E.gmode == kGFromW)) W = eval_pieces(E.w, q);
      double G = 0;
      if (gr && r2 > 0) G = E.gmode == kGFromW ? W * (g.h2 / r2) : eval_pieces(E.gq, q);
      for (int f = 0; f < nf; ++f) {
        double* a = acc + (wi * nf + f) * 4;
        const double vk = v[f][k];
        if (pi) a[0] += Vk * vk * W;
        if (gr && r2 > 0) {  // Λ excludes r = 0
          const double t = G * (Vk * (vk - vt[f]));
          if (E.ops & kOpGrad) a[1] += t * dx, a[2] += t * dy;
          if (E.ops & kOpLap) a[3] += t;
        }
      }
    }
  });
  constexpr double kD = 2.0;
  const double h4 = g.h2 * g.h2;
  for (int i = 0; i < nw * nf; ++i) {
    out[4 * i + 0] = acc[4 * i + 0] / g.h2;
    out[4 * i + 1] = kD * acc[4 * i + 1] / h4;
    out[4 * i + 2] = kD * acc[4 * i + 2] / h4;
    out[4 * i + 3] = 2.0 * kD * acc[4 * i + 3] / h4;
  }
}

// Floating-point operations of fused_target_sums per accepted pair, counted from its code
// (an FMA or a multiply-add as 2, a square root or a divide as 1; the largest piece of each
// table): the numerator of a pass's FLOP rate, for its fraction of a device's fp64 peak.
inline double body_flops_per_pair(const std::vector<WeightEntry>& we, int nf) {
  auto table = [](const PieceTable& t) {
    double worst = 0;
    for (int p = 0; p < t.np; ++p)
      worst = std::max(worst, 2.0 * t.nc[p] + std::abs(static_cast<double>(t.e[p])));
    return worst;
  };
  double f = 2 + 3 + 1 + 1;  // dx, dy; r² = dx·dx + dy·dy; √r²; q = r/h
  for (const WeightEntry& E : we) {
    const bool pi = (E.ops & kOpInterp) != 0, gr = (E.ops & (kOpGrad | kOpLap)) != 0;
    if (pi || (gr && E.gmode == kGFromW)) f += table(E.w);  // W
    if (gr) f += E.gmode == kGFromW ? 2 : table(E.gq);     // G = W·h²/r² or its table
    if (pi) f += 3.0 * nf;                                  // V·v·W, added
    if (gr) f += 3.0 * nf;                                  // t = G·(V·(v − v_j))
    if (E.ops & kOpGrad) f += 4.0 * nf;                     // two multiply-adds
    if (E.ops & kOpLap) f += 1.0 * nf;                      // one add
  }
  return f;
}

}  // namespace gpm::cuda
