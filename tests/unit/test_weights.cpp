// The weight registry: normalizations, orders, positivity and regularity flags computed
// from the pieces, the errata, and the evaluation of w and w'.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "gpm/error.hpp"
#include "gpm/weights/weights.hpp"

using gpm::compute_properties;
using gpm::weight;

namespace {

const gpm::WeightErratum& erratum(const std::string& name) {
  static const auto errata = gpm::weight_errata();
  for (auto& e : errata)
    if (e.name == name) return e;
  FAIL("no erratum for " << name);
  return errata.front();
}

}  // namespace

TEST_CASE("every registry weight except mps normalizes to 1 in its dimension", "[weights]") {
  for (auto& w : gpm::weight_registry()) {
    INFO(w.name);
    const auto p = compute_properties(w);
    if (w.name == "mps") {
      // 2π ∫₀¹ r (1/r − 1) dr = π: not a normalized weight.
      CHECK(p.norm_2d == Approx(std::numbers::pi).epsilon(1e-12));
      CHECK_FALSE(p.admissible);
      CHECK_FALSE(p.continuous);
      continue;
    }
    CHECK(std::abs(p.norm(w.dimension) - 1) < 1e-12);
    CHECK(p.continuous);
    CHECK(p.admissible);
  }
}

TEST_CASE("the 3-D examples are normalized in 3-D, not in 2-D", "[weights]") {
  const auto q = compute_properties(weight("example17_quadratic_3d"));
  CHECK(weight("example17_quadratic_3d").dimension == 3);
  CHECK(std::abs(q.norm_3d - 1) < 1e-12);
  CHECK(q.norm_2d == Approx(1.25).epsilon(1e-12));  // 15/(2π)·2π·∫r(1−r)² = 15/12
  const auto c = compute_properties(weight("example17_cubic_3d"));
  CHECK(std::abs(c.norm_3d - 1) < 1e-12);
  CHECK(c.order_k == 3);
}

TEST_CASE("orders of Hypothesis 1.1", "[weights]") {
  CHECK(compute_properties(weight("cubic_spike")).order_k == 3);
  CHECK(compute_properties(weight("quadratic_spike")).order_k == 1);
  CHECK(compute_properties(weight("Pi3")).order_k == 3);
  CHECK(compute_properties(weight("Grad3")).order_k == 3);
  CHECK(compute_properties(weight("Lap3")).order_k == 3);
  CHECK(compute_properties(weight("Pi2")).order_k == 1);
  CHECK(compute_properties(weight("quintic_bspline")).order_k == 1);
}

TEST_CASE("positivity (Hypothesis 1.4) is decided from the roots", "[weights]") {
  CHECK(compute_properties(weight("quadratic_spike")).positive);
  CHECK_FALSE(compute_properties(weight("cubic_spike")).positive);  // 4 − 7r < 0 for r > 4/7
  CHECK_FALSE(compute_properties(weight("Pi3")).positive);          // 2 − 3r < 0 for r > 2/3
  CHECK(compute_properties(weight("quintic_bspline")).positive);
  CHECK(compute_properties(weight("piecewise_quintic_polynomial")).positive);
  CHECK(compute_properties(weight("mps")).positive);
  // Lemma 1.5: a positive weight cannot have order ≥ 2.
  for (auto& w : gpm::weight_registry()) {
    const auto p = compute_properties(w);
    INFO(w.name);
    if (p.positive) CHECK(p.order_k == 1);
  }
}

TEST_CASE("p0 and the regularity hypotheses", "[weights]") {
  // Grad1 = 6/π r(1−r): w/r = 6/π(1−r) has slope −6/π at r = 1⁻ but 0 beyond, so it does
  // not extend to C¹ — Hypothesis 1.2 fails even though p0 = 1.
  const auto g1 = compute_properties(weight("Grad1"));
  CHECK(g1.p0 == 1);
  CHECK(g1.imoto_hyp2_k == 0);
  CHECK(g1.continuous);
  CHECK_FALSE(g1.c1);
  CHECK_FALSE(g1.hyp_1_2);
  CHECK_FALSE(g1.hyp_1_3);
  // Lap1 = 10/π r²(1−r): imoto's lowest-order weight with Hypothesis 2, k = 1.
  const auto l1 = compute_properties(weight("Lap1"));
  CHECK(l1.p0 == 2);
  CHECK(l1.imoto_hyp2_k == 1);
  CHECK_FALSE(l1.hyp_1_2);
  CHECK_FALSE(l1.hyp_1_3);
  // The quartic polynomial r²(1−r)² is C¹ at 1, and so are w/r and w/r².
  const auto qp = compute_properties(weight("quartic_polynomial"));
  CHECK(qp.c1);
  CHECK(qp.hyp_1_2);
  CHECK(qp.hyp_1_3);
  // Grad2: 6r²−9r³ | 3r(1−r)²; w/r² = 3(1−r)²/r on [½,1) is a Laurent piece and still C¹.
  const auto g2 = compute_properties(weight("Grad2"));
  CHECK(g2.p0 == 2);
  CHECK(g2.hyp_1_2);
  CHECK(g2.hyp_1_3);
  CHECK(g2.imoto_hyp2_k == 1);
  // The spike has w(0) > 0: w/r is unbounded and ∫ w/r diverges.
  const auto qs = compute_properties(weight("quadratic_spike"));
  CHECK(qs.p0 == 0);
  CHECK(qs.imoto_hyp2_k == -1);
  CHECK_FALSE(qs.hyp_1_2);
  CHECK(std::isinf(qs.inv_r2_integral));
  // Pi1 = 3/π(1−r) is continuous but has w'(1⁻) = −3/π.
  CHECK_FALSE(compute_properties(weight("Pi1")).c1);
  CHECK(compute_properties(weight("cubic_bspline")).c1);
  CHECK(compute_properties(weight("quintic_bspline")).c1);
}

TEST_CASE("the integral of w/r matches the closed form", "[weights]") {
  // Grad1: 2π·(6/π)·∫(1−r) dr = 6.
  CHECK(compute_properties(weight("Grad1")).inv_r2_integral == Approx(6).epsilon(1e-12));
  // Lap1: 2π·(10/π)·∫ r(1−r) dr = 20/6.
  CHECK(compute_properties(weight("Lap1")).inv_r2_integral == Approx(20.0 / 6).epsilon(1e-12));
  CHECK(compute_properties(weight("mps")).inv_r2_integral == std::numeric_limits<double>::infinity());
}

TEST_CASE("the piecewise cubic polynomial equals (∇2) pointwise", "[weights]") {
  const auto& pcp = weight("piecewise_cubic_polynomial");
  const auto& g2 = weight("Grad2");
  for (int j = 0; j <= 200; ++j) {
    const double r = j / 200.0;
    INFO("r = " << r);
    CHECK(pcp.value(r) == Approx(g2.value(r)).margin(1e-14));
  }
}

TEST_CASE("values at the ends of the support", "[weights]") {
  CHECK(std::isinf(weight("mps").value(0)));
  CHECK(weight("mps").value(0) > 0);
  CHECK(weight("mps").value(0.5) == Approx(1));
  CHECK(weight("quadratic_spike").value(0) == Approx(6 / std::numbers::pi));
  for (auto& w : gpm::weight_registry()) {
    CHECK(w.value(1) == 0);
    CHECK(w.value(1.5) == 0);
    CHECK(w.derivative(1.5) == 0);
  }
  // The corrected cubic B-spline is continuous at ½: 1 − 6/4 + 6/8 = 2·(1/2)³.
  const auto& cb = weight("cubic_bspline");
  CHECK(cb.value(std::nextafter(0.5, 0.0)) == Approx(cb.value(0.5)).epsilon(1e-12));
}

TEST_CASE("the derivative matches a central finite difference", "[weights]") {
  const double h = 1e-6;
  for (auto& w : gpm::weight_registry()) {
    for (int j = 0; j < 50; ++j) {
      // Points (j + ½)/50 stay ≥ 0.003 away from the knots ⅓, ½, ⅔ and from 0 and 1.
      const double r = (j + 0.5) / 50;
      const double fd = (w.value(r + h) - w.value(r - h)) / (2 * h);
      INFO(w.name << " at r = " << r);
      CHECK(w.derivative(r) == Approx(fd).epsilon(1e-6).margin(1e-6));
    }
  }
}

TEST_CASE("unknown weight names are rejected with the valid list", "[weights]") {
  CHECK_THROWS_AS(weight("gaussian"), gpm::InputError);
  CHECK_THROWS_WITH(weight("gaussian"), Catch::Contains("unknown weight 'gaussian'") &&
                                            Catch::Contains("quadratic_spike"));
  CHECK(gpm::weight_names().size() == gpm::weight_registry().size());
}

TEST_CASE("errata: printed forms that do not normalize", "[weights]") {
  const auto& pi3 = erratum("Pi3");
  CHECK(std::abs(pi3.printed_norm_2d - 5.0 / 6) < 1e-12);
  CHECK(std::abs(pi3.corrected_norm_2d - 1) < 1e-12);

  const auto& cb = erratum("cubic_bspline");
  CHECK(cb.printed_norm_2d == Approx(29.0 / 21).epsilon(1e-12));  // 40/(7π)·2π·(1/10+…)
  CHECK(std::abs(cb.corrected_norm_2d - 1) < 1e-12);
  CHECK_THAT(cb.evidence, Catch::Contains("discontinuous"));

  const auto& qb = erratum("quintic_bspline");
  CHECK(std::abs(qb.printed_norm_2d - 1) > 0.5);
  CHECK(qb.printed_norm_2d == Approx(495.0 / 289).epsilon(1e-12));
  CHECK(std::abs(qb.corrected_norm_2d - 1) < 1e-12);
  CHECK(std::abs(compute_properties(weight("quintic_bspline")).norm_2d - 1) < 1e-12);

  // Every erratum is about a formula the registry holds in corrected form.
  for (auto& e : gpm::weight_errata()) {
    INFO(e.name);
    CHECK_NOTHROW(weight(e.name));
    CHECK(e.printed != e.corrected);
    CHECK_FALSE(e.evidence.empty());
  }
}

// w^bell of the thesis' §4.2–4.3 is SPH's bell-shaped (Lucy) kernel (5/π)(1+3r)(1−r)³; by
// Remark A.1 the generalized operators use w = −(r/d) d/dr w^bell (d = 2), and §4.1.2 says the
// quartic polynomial is that weight.  Checked here by central differences of the SPH kernel
// against the registry's quartic_polynomial, so the Poisson and heat studies' choice of
// quartic_polynomial for w^bell rests on a computation.
TEST_CASE("quartic_polynomial is -(r/2) d/dr of the bell-shaped kernel", "[weights]") {
  const auto bell = [](double r) { return r < 1 ? 5 / M_PI * (1 + 3 * r) * std::pow(1 - r, 3) : 0.0; };
  const gpm::WeightFunction& qp = weight("quartic_polynomial");
  const double e = 1e-6;
  for (double r = 0.05; r < 1; r += 0.05) {
    const double derived = -(r / 2) * (bell(r + e) - bell(r - e)) / (2 * e);
    CHECK(qp.value(r) == Approx(derived).epsilon(1e-8));
  }
}
