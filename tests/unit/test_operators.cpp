// Reference operators (generalized, thesis, SPH, MPS forms) and the fused kernel.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/kernel/plain_baseline.hpp"
#include "gpm/operators/operators.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

struct Setup {
  Particles p;
  std::vector<double> V;
  double h;
  CellList cl;
  std::vector<int32_t> targets;
  Setup(double dx, double h_, double amplitude = 0.25)
      : p(jittered_grid(dx, 1, amplitude)),
        V(p.size(), Domain{}.area_H() / static_cast<double>(p.size())),
        h(h_),
        cl(p.x, p.y, h_ / 4),
        targets(omega_targets(p)) {}
  std::vector<double> sample(const std::string& name) const {
    const auto& f = test_function(name);
    std::vector<double> v(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) v[i] = f.v(p.x[i], p.y[i]);
    return v;
  }
  Vec2 at(int32_t j) const { return {p.x[j], p.y[j]}; }
};

// max_t |a_t − b_t| ≤ tol · max_t |b_t|   (norm-wise relative agreement)
void require_close(const std::vector<double>& a, const std::vector<double>& b, double tol,
                   const std::string& what) {
  REQUIRE(a.size() == b.size());
  double diff = 0, scale = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  INFO(what << ": max diff " << diff << ", max |ref| " << scale);
  REQUIRE(std::isfinite(diff));
  REQUIRE(diff <= tol * scale);
}

// A C¹ MPS-type weight (not normalized): w^M(r) = (1 − r)², as is common in MPS codes.
WeightFunction mps_c1_weight() {
  WeightFunction w;
  w.name = "mps_c1";
  w.constant = 1;
  PolyPiece p;
  p.r_begin = 0;
  p.r_end = 1;
  p.p_min = 0;
  p.c = {1, -2, 1};
  w.shape = {p};
  return w;
}

}  // namespace

// ---------------------------------------------------------------------------------
// Reference operators.

TEST_CASE("thesis forms (1.2)-(1.4) equal imoto (2)-(4) bitwise", "[operators]") {
  const Setup s(0x1p-5, 2.6 * 0x1p-5);
  const auto v = s.sample("sin2pi");
  for (const char* name : {"Pi2", "Grad1", "Grad2", "Lap3", "quintic_bspline"}) {
    const auto& w = weight(name);
    for (std::size_t t = 0; t < s.targets.size(); t += 3) {
      const int32_t j = s.targets[t];
      REQUIRE(interpolant(s.cl, s.V, v, w, s.h, s.at(j)) ==
              interpolant_thesis(s.cl, s.V, v, w, s.h, s.at(j)));
      const Vec2 a = gradient(s.cl, s.V, v, w, s.h, s.at(j), v[j]);
      const Vec2 b = gradient_thesis(s.cl, s.V, v, w, s.h, s.at(j), v[j]);
      REQUIRE(a.x == b.x);
      REQUIRE(a.y == b.y);
      REQUIRE(laplacian(s.cl, s.V, v, w, s.h, s.at(j), v[j]) ==
              laplacian_thesis(s.cl, s.V, v, w, s.h, s.at(j), v[j]));
    }
  }
}

TEST_CASE("SPH forms equal the generalized ones with w = -(r/d) dw^S/dr (A.9)",
          "[operators]") {
  const Setup s(0x1p-5, 0.1234);
  const auto v = s.sample("sin2pi");
  // (SPH weight, the registry's generalized counterpart)
  const std::vector<std::pair<std::string, std::string>> pairs{
      {"cubic_bspline", "piecewise_cubic_polynomial"},
      {"quintic_bspline", "piecewise_quintic_polynomial"},
      {"Pi2", "Grad2"}};
  for (const auto& [sph, gen] : pairs) {
    const auto& wS = weight(sph);
    const WeightFunction wA9 = sph_generalized_weight(wS);
    const auto& wG = weight(gen);
    // The substitution reproduces the registry's weight.
    for (double r = 0.0; r < 1.0; r += 0.01)
      REQUIRE(wA9.value(r) == Approx(wG.value(r)).margin(1e-14));
    std::vector<double> sg[3], gg[3], sl, gl, si, gi, s58x;
    for (std::size_t t = 0; t < s.targets.size(); t += 2) {
      const int32_t j = s.targets[t];
      const Vec2 a = sph_gradient(s.cl, s.V, v, wS, s.h, s.at(j), v[j]);
      const Vec2 b = gradient(s.cl, s.V, v, wG, s.h, s.at(j), v[j]);
      const Vec2 c = gradient(s.cl, s.V, v, wA9, s.h, s.at(j), v[j]);
      const Vec2 m = sph_gradient_imoto58(s.cl, s.V, v, wS, s.h, s.at(j), v[j]);
      sg[0].push_back(a.x), sg[1].push_back(a.y);
      gg[0].push_back(b.x), gg[1].push_back(b.y);
      gg[2].push_back(c.x), sg[2].push_back(a.x);
      s58x.push_back(-m.x);
      REQUIRE(-m.y == a.y);  // imoto (58) read literally is the negative
      sl.push_back(sph_laplacian(s.cl, s.V, v, wS, s.h, s.at(j), v[j]));
      gl.push_back(laplacian(s.cl, s.V, v, wG, s.h, s.at(j), v[j]));
      si.push_back(sph_interpolant(s.cl, s.V, v, wS, s.h, s.at(j)));
      gi.push_back(interpolant(s.cl, s.V, v, wS, s.h, s.at(j)));
    }
    require_close(sg[0], gg[0], 1e-12, sph + " grad x");
    require_close(sg[1], gg[1], 1e-12, sph + " grad y");
    require_close(sg[2], gg[2], 1e-12, sph + " grad x via (A.9) pieces");
    require_close(sl, gl, 1e-12, sph + " Laplacian");
    require_close(si, gi, 0, sph + " interpolant");
    require_close(s58x, sg[0], 0, sph + " imoto (58) sign");
  }
  // The SPH gradient approximates +∇v (thesis (A.7) sign), not −∇v.
  const auto& f = test_function("sin2pi");
  const int32_t j = s.targets[s.targets.size() / 2];
  const Vec2 g = sph_gradient(s.cl, s.V, v, weight("cubic_bspline"), s.h, s.at(j), v[j]);
  const double vx = f.vx(s.p.x[j], s.p.y[j]);
  INFO("SPH d/dx " << g.x << " exact " << vx);
  REQUIRE(std::abs(g.x - vx) < 0.2 * std::abs(vx));
}

TEST_CASE("MPS forms equal the generalized ones under (A.16)-(A.19)", "[operators]") {
  const Setup s(0x1p-5, 0.1234);
  const auto v = s.sample("quartic");
  const std::size_t N = s.p.size();
  const double area = Domain{}.area_H();
  for (const WeightFunction& wM : {mps_c1_weight(), weight("mps")}) {
    const double n0 = mps_n0(wM, N, area), l0 = mps_lambda0(wM, N, area, s.h);
    const WeightFunction wg = mps_gradient_weight(wM);
    const bool lap_ok = wM.name != "mps";  // r² w^M: fine for both; test both anyway
    const WeightFunction wl = mps_laplacian_weight(wM);
    REQUIRE(radial_moment(wg, 0) == Approx(1).epsilon(1e-14));
    REQUIRE(radial_moment(wl, 0) == Approx(1).epsilon(1e-14));
    std::vector<double> mx, gx, my, gy, ml, gl;
    for (std::size_t t = 0; t < s.targets.size(); t += 2) {
      const int32_t j = s.targets[t];
      const Vec2 a = mps_gradient(s.cl, v, wM, s.h, s.at(j), v[j], n0);
      const Vec2 b = gradient(s.cl, s.V, v, wg, s.h, s.at(j), v[j]);
      mx.push_back(a.x), my.push_back(a.y), gx.push_back(b.x), gy.push_back(b.y);
      ml.push_back(mps_laplacian(s.cl, v, wM, s.h, s.at(j), v[j], l0));
      gl.push_back(laplacian(s.cl, s.V, v, wl, s.h, s.at(j), v[j]));
    }
    require_close(mx, gx, 1e-12, wM.name + " MPS grad x");
    require_close(my, gy, 1e-12, wM.name + " MPS grad y");
    require_close(ml, gl, 1e-12, wM.name + " MPS Laplacian" + (lap_ok ? "" : " (1/r - 1)"));
  }
  // The representative-particle sums after (A.15) agree with (A.17) and with the
  // h²-corrected (A.19), not with (A.19) as printed.
  const WeightFunction wM = mps_c1_weight();
  const Setup fine(0x1p-7, 0.06);
  const Vec2 c{0.5 + 0.1 * 0x1p-7, 0.5};
  const double n0_sum = mps_n0_sum(fine.cl, wM, fine.h, c);
  const double l0_sum = mps_lambda0_sum(fine.cl, wM, fine.h, c);
  const std::size_t Nf = fine.p.size();
  CHECK(n0_sum == Approx(mps_n0(wM, Nf, area)).epsilon(0.03));
  CHECK(l0_sum == Approx(mps_lambda0(wM, Nf, area, fine.h)).epsilon(0.03));
  CHECK(l0_sum < 0.01 * mps_lambda0_printed(wM, Nf, area));
  // Exact moments of 1/r − 1: ∫w = π, ∫|x|² w = π/6.
  REQUIRE(radial_moment(weight("mps"), 0) == Approx(std::numbers::pi).epsilon(1e-14));
  REQUIRE(radial_moment(weight("mps"), 2) == Approx(std::numbers::pi / 6).epsilon(1e-14));
}

TEST_CASE("interpolant of a constant with a normalized weight is about 1", "[operators]") {
  const Setup s(0x1p-7, 0.1);
  const std::vector<double> one(s.p.size(), 1.0);
  for (const char* name : {"Pi1", "Pi2", "Pi3", "quintic_bspline", "quadratic_spike"}) {
    double worst = 0;
    for (std::size_t t = 0; t < s.targets.size(); t += 97) {
      const int32_t j = s.targets[t];
      worst = std::max(worst, std::abs(interpolant(s.cl, s.V, one, weight(name), s.h, s.at(j)) - 1));
    }
    INFO(name << ": max |Pi_h 1 - 1| = " << worst);
    CHECK(worst < 0.03);  // jittered quadrature error, ~(Δx/h)-ish
  }
  // Radial moments from the pieces: normalized weights integrate to 1.
  for (const char* name : {"Pi1", "Pi2", "Grad1", "Grad3", "Lap1", "Lap2", "quintic_bspline"})
    REQUIRE(radial_moment(weight(name), 0) == Approx(1).epsilon(1e-12));
}

TEST_CASE("exactness on a symmetric grid: linear and quadratic functions", "[operators]") {
  // Plain grid (no jitter): the lattice symmetry makes Σ V w_h e eᵀ = (S/2) I with
  // S = Σ_{r>0} V_i w_h(r_i), so ∇_h v = ∇v · S for linear v, Δ_h v = 0 for linear v
  // and Δ_h v = 2d · S = Δv · S for v = x² + y².
  const double dx = 0x1p-6;
  Setup s(dx, 5.3 * dx, 0.0);
  std::fill(s.V.begin(), s.V.end(), dx * dx);
  const auto lin = s.sample("linear");
  std::vector<double> quad(s.p.size());
  for (std::size_t i = 0; i < quad.size(); ++i)
    quad[i] = s.p.x[i] * s.p.x[i] + s.p.y[i] * s.p.y[i];
  const std::vector<double> one(s.p.size(), 1.0);
  for (const char* name : {"Grad1", "Grad2", "Grad3", "Lap1", "Lap2", "Lap3"}) {
    const auto& w = weight(name);
    for (std::size_t t = 0; t < s.targets.size(); t += 61) {
      const int32_t j = s.targets[t];
      const double S = interpolant(s.cl, s.V, one, w, s.h, s.at(j)) - s.V[j] * w.value(0) / (s.h * s.h);
      const Vec2 g = gradient(s.cl, s.V, lin, w, s.h, s.at(j), lin[j]);
      INFO(name << " target " << j << " S = " << S);
      REQUIRE(g.x == Approx(2 * S).epsilon(1e-12));
      REQUIRE(g.y == Approx(-3 * S).epsilon(1e-12));
      REQUIRE(std::abs(laplacian(s.cl, s.V, lin, w, s.h, s.at(j), lin[j])) < 1e-9);
      REQUIRE(laplacian(s.cl, s.V, quad, w, s.h, s.at(j), quad[j]) ==
              Approx(4 * S).epsilon(1e-11));
      CHECK(S == Approx(1).epsilon(0.05));
    }
  }
}

// ---------------------------------------------------------------------------------
// The fused kernel against the reference operators.

namespace {

struct RefCols {
  std::vector<double> pi, gx, gy, lap;
};

RefCols reference(const Setup& s, const std::vector<double>& v, const WeightFunction& w,
                  unsigned ops, const std::vector<int32_t>& targets) {
  RefCols r;
  for (auto j : targets) {
    if (ops & kInterp) r.pi.push_back(interpolant(s.cl, s.V, v, w, s.h, s.at(j)));
    if (ops & kGrad) {
      const Vec2 g = gradient(s.cl, s.V, v, w, s.h, s.at(j), v[j]);
      r.gx.push_back(g.x);
      r.gy.push_back(g.y);
    }
    if (ops & kLap) r.lap.push_back(laplacian(s.cl, s.V, v, w, s.h, s.at(j), v[j]));
  }
  return r;
}

std::vector<double> vec(std::span<const double> a) { return {a.begin(), a.end()}; }

std::vector<KernelWeight> kernel_weights() {
  return {{weight("Pi2"), kAllOps},                      // 2 pieces, G with 1/q²
          {weight("Grad1"), kGrad},                      // G = (1 − q)/q
          {weight("Lap1"), kLap | kInterp},              // p0 = 2: no divide
          {weight("quintic_bspline"), kAllOps},          // 3 pieces, degree 5
          {weight("piecewise_quintic_polynomial"), kGrad | kLap},
          {weight("Lap2"), kLap},
          {weight("mps"), kGrad | kLap}};                // p_min = −1: G = (1 − q)/q³
}

}  // namespace

TEST_CASE("fused kernel equals the reference operators", "[kernel]") {
  const Setup s(0x1p-5, 0.1234);
  const std::vector<std::vector<double>> fields{s.sample("sin2pi"), s.sample("quartic"),
                                                s.sample("linear")};
  const auto kw = kernel_weights();
  for (int mode = 0; mode < 3; ++mode) {
    KernelOptions opt;
    opt.compact = mode == 1;
    opt.fast_rsqrt = mode == 2;
    const FusedKernel K(s.p, s.V, s.h, kw, opt);
    REQUIRE(K.needs_divide());
    const KernelResult res = K.apply(s.targets, fields);
    REQUIRE(res.size() == s.targets.size());
    for (std::size_t w = 0; w < kw.size(); ++w)
      for (std::size_t f = 0; f < fields.size(); ++f) {
        const RefCols r = reference(s, fields[f], kw[w].weight, kw[w].ops, s.targets);
        const std::string tag = "mode " + std::to_string(mode) + " " + kw[w].weight.name +
                                " field " + std::to_string(f);
        const int wi = static_cast<int>(w), fi = static_cast<int>(f);
        if (kw[w].ops & kInterp) require_close(vec(res.interpolant(wi, fi)), r.pi, 1e-12, tag + " Pi");
        else REQUIRE_THROWS_AS(res.interpolant(wi, fi), InputError);
        if (kw[w].ops & kGrad) {
          require_close(vec(res.grad_x(wi, fi)), r.gx, 1e-12, tag + " grad x");
          require_close(vec(res.grad_y(wi, fi)), r.gy, 1e-12, tag + " grad y");
        }
        if (kw[w].ops & kLap) require_close(vec(res.laplacian(wi, fi)), r.lap, 1e-12, tag + " lap");
      }
  }
}

TEST_CASE("fused kernel: cell sizes, target lists, no-divide pass, baseline", "[kernel]") {
  const Setup s(0x1p-6, 0.07);
  const auto v = s.sample("sin2pi");
  // An arbitrary target list: boundary particles outside Ω, repeats, any order.
  std::vector<int32_t> targets{0, 17, static_cast<int32_t>(s.p.size() - 1), 17, 512, 3};
  for (std::size_t i = 0; i < s.p.size(); i += 13) targets.push_back(static_cast<int32_t>(i));
  const RefCols ref = reference(s, v, weight("Lap3"), kAllOps, targets);
  for (int cph : {1, 2, 4, 8}) {
    KernelOptions opt;
    opt.cells_per_h = cph;
    const FusedKernel K(s.p, s.V, s.h, {{weight("Lap3"), kAllOps}}, opt);
    REQUIRE_FALSE(K.needs_divide());  // w/q² of r²(1−r)(3−4r) is a polynomial
    const KernelResult res = K.apply(targets, {v});
    INFO("cells per h " << cph);
    require_close(vec(res.interpolant(0, 0)), ref.pi, 1e-12, "Pi");
    require_close(vec(res.grad_x(0, 0)), ref.gx, 1e-12, "grad x");
    require_close(vec(res.grad_y(0, 0)), ref.gy, 1e-12, "grad y");
    require_close(vec(res.laplacian(0, 0)), ref.lap, 1e-12, "lap");
    REQUIRE(res.interpolant(0, 0)[1] == res.interpolant(0, 0)[3]);  // the repeated target
  }
  // The plain baseline computes the same numbers.
  const RefCols ref2 = reference(s, v, weight("Pi2"), kAllOps, targets);
  const BaselineResult b = plain_baseline(s.p.x, s.p.y, s.V, v, weight("Pi2"), s.h, targets);
  require_close(b.interp, ref2.pi, 1e-12, "baseline Pi");
  require_close(b.grad_x, ref2.gx, 1e-12, "baseline grad x");
  require_close(b.grad_y, ref2.gy, 1e-12, "baseline grad y");
  require_close(b.lap, ref2.lap, 1e-12, "baseline lap");
}

TEST_CASE("fused kernel: 1 and 2 threads give bitwise identical results", "[kernel]") {
  const Setup s(0x1p-6, 0.05);
  const std::vector<std::vector<double>> fields2{s.sample("sin2pi"), s.sample("quartic")};
  // Modes: block path (masked), compact, rsqrt, and the fused single-weight loop.
  for (int mode = 0; mode < 4; ++mode) {
    KernelOptions o1, o2;
    o1.compact = o2.compact = mode == 1;
    o1.fast_rsqrt = o2.fast_rsqrt = mode == 2;
    o1.threads = 1;
    o2.threads = 2;
    o2.chunk = 3;
    const auto kw = mode == 3 ? std::vector<KernelWeight>{{weight("Pi2"), kAllOps}}
                              : kernel_weights();
    const std::vector<std::vector<double>> fields =
        mode == 3 ? std::vector<std::vector<double>>{s.sample("sin2pi")} : fields2;
    const int nf = static_cast<int>(fields.size());
    const KernelResult a = FusedKernel(s.p, s.V, s.h, kw, o1).apply(s.targets, fields);
    const KernelResult b = FusedKernel(s.p, s.V, s.h, kw, o2).apply(s.targets, fields);
    for (int w = 0; w < static_cast<int>(kw.size()); ++w)
      for (int f = 0; f < nf; ++f)
        for (KernelOp op : {kInterp, kGrad, kLap}) {
          if (!a.has(w, op)) continue;
          auto ca = op == kInterp ? a.interpolant(w, f) : op == kGrad ? a.grad_x(w, f) : a.laplacian(w, f);
          auto cb = op == kInterp ? b.interpolant(w, f) : op == kGrad ? b.grad_x(w, f) : b.laplacian(w, f);
          REQUIRE(std::equal(ca.begin(), ca.end(), cb.begin()));
          if (op == kGrad) {
            auto ya = a.grad_y(w, f), yb = b.grad_y(w, f);
            REQUIRE(std::equal(ya.begin(), ya.end(), yb.begin()));
          }
        }
  }
}

TEST_CASE("fused kernel: pair counts and input errors", "[kernel]") {
  const Setup s(0x1p-6, 0.05);
  const FusedKernel K(s.p, s.V, s.h, {{weight("Pi1"), kInterp}});
  const PairCount pc = K.count_pairs(s.targets);
  int64_t brute = 0;
  for (auto j : s.targets) brute += static_cast<int64_t>(s.cl.neighbours(s.p.x[j], s.p.y[j], s.h).size());
  REQUIRE(pc.accepted == brute);
  REQUIRE(pc.candidates >= pc.accepted);
  CHECK(double(pc.candidates) / double(pc.accepted) < 1.45);
  // The MPS weight is unbounded at 0: no interpolant.
  REQUIRE_THROWS_AS(FusedKernel(s.p, s.V, s.h, {{weight("mps"), kAllOps}}), InputError);
  REQUIRE_THROWS_AS(FusedKernel(s.p, s.V, -1.0, {{weight("Pi1"), kInterp}}), InputError);
  REQUIRE_THROWS_AS(K.apply({static_cast<int32_t>(s.p.size())}, {s.V}), InputError);
  REQUIRE_THROWS_AS(K.apply(s.targets, {std::vector<double>(3)}), InputError);
  const KernelResult r = K.apply({}, {s.V});
  REQUIRE(r.size() == 0);
}

TEST_CASE("fused kernel: the single-weight loop in every mode equals the reference",
          "[kernel]") {
  const Setup s(0x1p-5, 0.1111);
  const auto v = s.sample("sin2pi");
  // Targets: every 3rd particle (inside and outside Ω) and the particles in the first and
  // last sorted slots (their ranges reach the array ends and the padding).
  std::vector<int32_t> targets;
  for (std::size_t i = 0; i < s.p.size(); i += 3) targets.push_back(static_cast<int32_t>(i));
  const CellList cl4(s.p.x, s.p.y, s.h / 4);
  targets.push_back(cl4.index().front());
  targets.push_back(cl4.index().back());
  const std::vector<std::pair<std::string, unsigned>> cases{
      {"Pi2", kAllOps},                  // G = W·h²/r² from Π
      {"quintic_bspline", kAllOps},      // 3 pieces, 6 coefficients
      {"Lap1", kAllOps},                 // w/q² a polynomial: no divide
      {"Grad1", kGrad},                  // (1/q)^1
      {"Pi2", kLap},                     // (1/q)^2 without Π
      {"mps", kGrad | kLap},             // (1/q)^3
      {"Pi1", kInterp},                  // Π only
      {"Lap3", kGrad},                   // ∇ only, no divide
      {"piecewise_quintic_polynomial", kLap}};
  for (const auto& [name, ops] : cases) {
    const auto& w = weight(name);
    const RefCols ref = reference(s, v, w, ops, targets);
    KernelOptions fused, block;
    block.fuse_single = false;
    const KernelResult a = FusedKernel(s.p, s.V, s.h, {{w, ops}}, fused).apply(targets, {v});
    const KernelResult b = FusedKernel(s.p, s.V, s.h, {{w, ops}}, block).apply(targets, {v});
    const std::string tag = name + " ops " + std::to_string(ops);
    if (ops & kInterp) {
      require_close(vec(a.interpolant(0, 0)), ref.pi, 1e-12, tag + " Pi fused");
      require_close(vec(b.interpolant(0, 0)), ref.pi, 1e-12, tag + " Pi block");
    }
    if (ops & kGrad) {
      require_close(vec(a.grad_x(0, 0)), ref.gx, 1e-12, tag + " grad x fused");
      require_close(vec(a.grad_y(0, 0)), ref.gy, 1e-12, tag + " grad y fused");
      require_close(vec(b.grad_x(0, 0)), ref.gx, 1e-12, tag + " grad x block");
      if (!(ops & kLap)) REQUIRE_THROWS_AS(a.laplacian(0, 0), InputError);
    }
    if (ops & kLap) {
      require_close(vec(a.laplacian(0, 0)), ref.lap, 1e-12, tag + " lap fused");
      require_close(vec(b.laplacian(0, 0)), ref.lap, 1e-12, tag + " lap block");
    }
  }
}

TEST_CASE("fused kernel: result storage is reused across calls", "[kernel]") {
  const Setup s(0x1p-5, 0.09);
  auto v = s.sample("quartic");
  const FusedKernel K(s.p, s.V, s.h, {{weight("quadratic_spike"), kLap}});
  KernelResult r;
  K.apply(s.targets, {&v}, r);
  const std::vector<double> first = vec(r.laplacian(0, 0));
  for (auto& x : v) x *= 2;  // Δ_h is linear
  K.apply(s.targets, {&v}, r);
  const auto second = r.laplacian(0, 0);
  for (std::size_t i = 0; i < first.size(); ++i) REQUIRE(second[i] == 2 * first[i]);
}

TEST_CASE("fused kernel: h larger than the domain", "[kernel]") {
  const Setup s(0x1p-3, 1.7);  // every particle within h of every other
  const auto v = s.sample("sin2pi");
  std::vector<int32_t> all(s.p.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int32_t>(i);
  const std::vector<KernelWeight> kw{{weight("quintic_bspline"), kAllOps}, {weight("Grad3"), kGrad}};
  for (bool single : {true, false}) {
    const FusedKernel K(s.p, s.V, s.h, single ? std::vector<KernelWeight>{kw[0]} : kw);
    const KernelResult r = K.apply(all, {v});
    const RefCols ref = reference(s, v, kw[0].weight, kAllOps, all);
    require_close(vec(r.interpolant(0, 0)), ref.pi, 1e-12, "Pi");
    require_close(vec(r.grad_x(0, 0)), ref.gx, 1e-12, "grad x");
    require_close(vec(r.laplacian(0, 0)), ref.lap, 1e-12, "lap");
    REQUIRE(K.count_pairs(all).accepted == static_cast<int64_t>(all.size() * all.size()));
  }
}
