// The fused kernel's dispatch: which compiled instantiation of a loop serves a weight
// (the block loops of kernel_blocks.hpp) or a pass (the range loops of kernel_pass.hpp and
// kernel_fused1.hpp).  The loops are templates on small counts (pieces, padded
// coefficients, fields, powers of 1/q, operators) so that each compiles to straight-line
// vector code; here the run-time counts pick one, once per weight or pass, never per pair.
//
// Every pick goes through choose() below: each template parameter is listed with the values
// it is compiled for, so a list here is the whole set of instantiations of that parameter.
// Private to the kernel: included by kernel.cpp only.
#pragma once
#include <algorithm>
#include <type_traits>

#include "gpm/kernel/kernel_blocks.hpp"
#include "gpm/kernel/kernel_fused1.hpp"
#include "gpm/kernel/kernel_pass.hpp"

namespace gpm {
namespace {

// One template parameter of a pick: the run-time value, and the values compiled for.  A
// value not in the list takes the LAST one (as a switch's `default:`), so the last entry
// is the fallback a caller relies on.  The value is held as long long, which every listed
// type (int, bool, the unsigned operator bits) converts to without a sign change.
template <auto... Vs>
struct Choice {
  long long value;
};

// f(std::integral_constant<…, V1>{}, …) with each Vi the compiled value of the i-th choice:
// every combination of the listed values is instantiated, one is called.
template <class F>
auto choose(F&& f) {
  return f();
}
template <class F, auto V, auto... Vs, class... More>
auto choose(F&& f, [[maybe_unused]] Choice<V, Vs...> c, More... more) {
  // This choice's compiled value v goes first; the remaining choices pick the rest.
  const auto rest = [&](auto v) {
    return choose([&](auto... later) { return f(v, later...); }, more...);
  };
  if constexpr (sizeof...(Vs) == 0) {
    return rest(std::integral_constant<decltype(V), V>{});
  } else {
    if (c.value == V) return rest(std::integral_constant<decltype(V), V>{});
    return choose(f, Choice<Vs...>{c.value}, more...);
  }
}

// ---------------------------------------------------------------------------------
// The block loops, one pick per weight and group of fields (1 or 2) when the kernel is built.

// Coefficient counts instantiated for the block loops (a polynomial is padded with zero
// coefficients).
constexpr int padded_nc(int nc) {
  return nc <= 2 ? 2 : nc <= 3 ? 3 : nc <= 4 ? 4 : nc <= 6 ? 6 : 8;
}

// ∇ and Δ as the loops' (GRAD, LAP) flags: the set {∇, Δ}, ∇ alone, else Δ alone.
using GradLap = Choice<kGrad | kLap, kGrad, kLap>;
constexpr unsigned grad_lap(unsigned ops) { return ops & (kGrad | kLap); }

// Π and ∇/Δ of one weight in one loop (G = W·(h/r)²); nullptr where not instantiated (then
// Π and G go separately).
BlockFn pick_pg(const PolyEval& pi, unsigned ops, int nf) {
  if (pi.nc > 8 || pi.np < 1 || pi.np > 3) return nullptr;
  return choose(
      [](auto NP, auto NC, auto GL, auto NF) -> BlockFn {
        return &pg_block<NP, NC, (GL & kGrad) != 0, (GL & kLap) != 0, NF>;
      },
      Choice<1, 2, 3>{pi.np}, Choice<2, 3, 4, 6, 8>{padded_nc(pi.nc)}, GradLap{grad_lap(ops)},
      Choice<1, 2>{nf});
}

// Π (pi) or ∇/Δ of one weight; nf: group size (1 or 2).  Returns nullptr where only the
// one-field fallback exists.
BlockFn pick(bool pi, const PolyEval& e, unsigned ops, int nf) {
  if (e.np > 3 || e.nc > 8) {  // more pieces or coefficients than instantiated
    if (nf != 1) return nullptr;
    if (pi) return &pi_generic;
    return choose(
        [](auto GL) -> BlockFn { return &g_generic<(GL & kGrad) != 0, (GL & kLap) != 0>; },
        GradLap{grad_lap(ops)});
  }
  const Choice<1, 2, 3> np{e.np};
  const Choice<2, 3, 4, 6, 8> nc{padded_nc(e.nc)};
  const Choice<1, 2> fields{nf};
  if (pi)
    return choose([](auto NP, auto NC, auto NF) -> BlockFn { return &pi_block<NP, NC, NF>; }, np,
                  nc, fields);
  return choose(
      [](auto NP, auto NC, auto M, auto GL, auto NF) -> BlockFn {
        return &g_block<NP, NC, M, (GL & kGrad) != 0, (GL & kLap) != 0, NF>;
      },
      np, nc, Choice<false, true>{e.m > 0}, GradLap{grad_lap(ops)}, fields);
}

// ---------------------------------------------------------------------------------
// The range loops, one pick per pass (FusedKernel::apply).

using RangeFn = KernelPass::RangeFn;

// The masked block path: NF fields (1, 2, or 0 = any number), POW the powers (1/q)^m the
// shared stage must provide (Σ 2^m), RSQRT (AVX-512 only) 1/√r² by rsqrt14 + Newton.
RangeFn pick_range(const KernelPass& k, int nf) {
  const int pow = (k.need_pow[1] ? 2 : 0) | (k.need_pow[2] ? 4 : 0) | (k.need_pow[3] ? 8 : 0);
  return choose(
      [&](auto NF, auto POW) -> RangeFn {
#if defined(__AVX512F__)
        if (k.opt.fast_rsqrt) return &KernelPass::masked_range_t<NF, POW, true>;
#endif
        return &KernelPass::masked_range_t<NF, POW, false>;
      },
      Choice<1, 2, 0>{nf}, Choice<0, 2, 4, 6, 8, 10, 12, 14>{pow});
}

// The fused single-weight loop where it applies (one weight, one field), else nullptr.
RangeFn pick_fused1(const KernelPass& k, int nf) {
  if (k.plans.size() != 1 || nf != 1 || !k.opt.fuse_single || k.opt.fast_rsqrt) return nullptr;
  const WPlan& w = k.plans[0];
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
  // The fused loop's own coefficient counts: 1 and 2 share NC = 2, 5 has its own (the block
  // loops pad it to 6), and anything else takes 8.  GM: with Π, 0 (no G), 1 (m = 0) or 5
  // (G from W); without Π, 1 + m.
  return choose(
      [&](auto NP, auto NC, auto PI) -> RangeFn {
        const auto loop = [=](auto GM) -> RangeFn {
          return &KernelPass::fused1_range<NP, NC, PI, GM>;
        };
        if constexpr (PI)
          return choose(loop, Choice<0, 1, 5>{gm});
        else
          return choose(loop, Choice<1, 2, 3, 4>{gm});
      },
      Choice<1, 2, 3>{np}, Choice<2, 3, 4, 5, 6, 8>{nc == 1 ? 2 : nc}, Choice<false, true>{pi});
}

}  // namespace
}  // namespace gpm
