// The influence-radius rules (influence_radius.hpp), each checked against a value the
// documents state or imply.
#include <catch2/catch.hpp>

#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/influence_radius.hpp"

using namespace gpm;

TEST_CASE("influence radius rules", "[unit][radius]") {
  const double dx5 = std::ldexp(1.0, -5);
  // imoto §5: h = 2.6·2^-5 at Δx = 2^-5 for every m.
  for (double m : {1.0, 3.0, 5.0}) CHECK(imoto_h(m, dx5) == Approx(2.6 / 32).epsilon(1e-14));
  // thesis §4.1: printed and scaled coincide for p = 3; scaled gives 3.1·2^-5 at 2^-5.
  CHECK(thesis_h(HReading::printed, 3, 3, 1e-3) ==
        Approx(thesis_h(HReading::scaled, 3, 3, 1e-3)).epsilon(1e-14));
  CHECK(thesis_h(HReading::scaled, 4, 4, dx5) == Approx(3.1 / 32).epsilon(1e-14));
  // thesis §4.2–4.3: h15 = 2.6·2^-5 at 2^-5; h10 = 2^(5/4)·h15 at every Δx (h10 > H = 0.1
  // at 2^-5 … 2^-8, below it from 2^-9 on).
  CHECK(pde_h(HRule::h15, dx5) == Approx(2.6 / 32).epsilon(1e-14));
  for (int k = 5; k <= 12; ++k) {
    const double dx = std::ldexp(1.0, -k);
    CHECK(pde_h(HRule::h10, dx) == Approx(std::pow(2.0, 1.25) * pde_h(HRule::h15, dx)).epsilon(1e-14));
    CHECK((pde_h(HRule::h10, dx) > 0.1) == (k <= 8));
  }
  CHECK(pde_h_formula(HRule::h10) == "(2.6^4 2^-10 dx)^(1/4)");
  // The rule's name, both ways: what options and data files say.
  for (HRule r : pde_h_rules()) CHECK(parse_h_rule(h_rule_name(r)) == r);
  CHECK(h_rule_name(HRule::h15) == "h15");
  REQUIRE_THROWS_WITH(parse_h_rule("h12"), "--h-rule: 'h12' is not h10 or h15");
  REQUIRE_THROWS_AS(pde_h(HRule::h10, -1), InputError);
}

#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"
#include <numbers>

TEST_CASE("Laplacian smoothing error: small-kh limit and the quartic at the thesis' radii",
          "[unit][smoothing]") {
  // 1 − J₀(x) = x²/4 − x⁴/64 + …, so ε(kh) → (π/8)(kh)² ∫₀¹ s³ w(s) ds as kh → 0.
  const WeightFunction& w = weight("quartic_polynomial");
  double m3 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double s = (i + 0.5) / n;
    m3 += s * s * s * w.value(s) / n;
  }
  const double c = std::numbers::pi / 8 * m3;
  CHECK(laplacian_smoothing_error(w, 1e-2) / 1e-4 == Approx(c).epsilon(1e-3));
  // Rate 2 asymptotically; still ≈ 2 between the h10 radii of 2^-8 and 2^-9.
  const double h8 = pde_h(HRule::h10, std::ldexp(1.0, -8)), h9 = pde_h(HRule::h10, std::ldexp(1.0, -9));
  const double k = 2 * std::numbers::pi * std::sqrt(2.0);
  const double rate = std::log(laplacian_smoothing_error(w, k * h8) / laplacian_smoothing_error(w, k * h9)) /
                      std::log(h8 / h9);
  CHECK(rate == Approx(2.0).margin(0.05));
}

TEST_CASE("Gradient smoothing error: the Bessel form against direct quadrature of the operator",
          "[unit][smoothing]") {
  // The continuous gradient of operators.hpp at p = 0 on v = sin(k·x), k = (k₁, k₁):
  //   d ∫ (v(r) − v(0)) r/|r|² w_h(|r|) dr = d ∫∫ sin(k·r) (cos φ, sin φ) w_h(ρ) dρ dφ
  // (polar, ρ < h; smooth, no singularity), midpoint rule; ∇v(0) = k, so its x-component
  // must be k₁ (1 − ε_∇(|k|h)).
  const double k1 = 2 * std::numbers::pi, k = k1 * std::sqrt(2.0), h = 0.08;
  for (const char* name : {"quartic_polynomial", "piecewise_quintic_polynomial"}) {
    const WeightFunction& w = weight(name);
    const int nr = 1500, nphi = 1500;
    double gx = 0;
    for (int i = 0; i < nr; ++i) {
      const double rho = (i + 0.5) * h / nr, wh = w.value(rho / h) / (h * h);
      for (int j = 0; j < nphi; ++j) {
        const double phi = (j + 0.5) * 2 * std::numbers::pi / nphi;
        gx += std::sin(k1 * rho * (std::cos(phi) + std::sin(phi))) * std::cos(phi) * wh;
      }
    }
    gx *= 2 * (h / nr) * (2 * std::numbers::pi / nphi);  // d = 2, dρ dφ
    INFO(name);
    CHECK(gx / k1 == Approx(1 - gradient_smoothing_error(w, k * h)).epsilon(1e-7));
    // and ε_∇ ~ c (kh)² for small kh
    CHECK(gradient_smoothing_error(w, 2e-2) / gradient_smoothing_error(w, 1e-2) ==
          Approx(4.0).epsilon(1e-3));
  }
}

TEST_CASE("Smoothing errors at small kh: the series keeps every digit the closed form loses",
          "[unit][smoothing]") {
  for (const char* name : {"quartic_polynomial", "piecewise_cubic_polynomial", "cubic_spike"}) {
    INFO(name);
    const WeightFunction& w = weight(name);
    const double m2 = radial_moment(w, 2), m4 = radial_moment(w, 4);
    // Leading terms: ε = m₂(kh)²/16 − m₄(kh)⁴/576 + …, ε_∇ = m₂(kh)²/8 − m₄(kh)⁴/192 + …
    CHECK(radial_moment(w, 0) == Approx(1).epsilon(1e-14));  // normalized: the series' m₀ = 1
    for (double kh : {1e-4, 1e-10, 1e-100}) {
      INFO(kh);
      const double lap = m2 * kh * kh / 16 - m4 * std::pow(kh, 4) / 576;
      const double grad = m2 * kh * kh / 8 - m4 * std::pow(kh, 4) / 192;
      CHECK(laplacian_smoothing_error(w, kh) == Approx(lap).epsilon(1e-9).margin(1e-300));
      CHECK(gradient_smoothing_error(w, kh) == Approx(grad).epsilon(1e-9).margin(1e-300));
    }
    // Where the two forms meet, the series and the quadrature agree (to the quadrature's
    // absolute accuracy, ~1e-12: the cubic spike's ε is only 3e-7 there).
    const double below = std::nextafter(0.25, 0.0);
    CHECK(laplacian_smoothing_error(w, below) == Approx(laplacian_smoothing_error(w, 0.25)).epsilon(1e-8).margin(2e-12));
    CHECK(gradient_smoothing_error(w, below) == Approx(gradient_smoothing_error(w, 0.25)).epsilon(1e-8).margin(2e-12));
  }
  // kh outside what a double can carry or the quadrature resolve: refused.
  const WeightFunction& q = weight("quartic_polynomial");
  for (double kh : {1e-300, 1e4}) CHECK_THROWS_AS(laplacian_smoothing_error(q, kh), InputError);
}
