// Convergence smoke test of the whole chain (distribution → Voronoi volumes → fused
// kernel → relative ℓ∞ error): the interpolant with the quadratic spike, thesis §4.1.1
// setting h = (3.1³·2⁻¹⁰·Δx)^{1/3}, must improve from level to level (see below for
// the one pre-asymptotic step that does not).
// (Rates are asserted by the reproduction issues; this only guards the plumbing.)
#include <catch2/catch.hpp>
#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/operators/truncation.hpp"

using namespace gpm;

namespace {
double spike_error(const char* fn, int level, uint64_t seed = 1) {
  TruncationSetting s;
  s.op = Operator::interp;
  s.weight = "quadratic_spike";
  s.volumes = Volumes::voronoi;
  s.function = fn;
  s.seed = seed;
  s.dx = std::ldexp(1.0, -level);
  s.h = std::cbrt(3.1 * 3.1 * 3.1 * std::ldexp(1.0, -10) * s.dx);
  return truncation_error(s).rel_error;
}
}  // namespace

// Measured (seeds 1-5, foundation session): Case 1 (quartic) falls 0.06 → 0.024 → 0.012
// → 0.0062 from 2^-5 to 2^-8 for every seed.  Case 2 (sin2pi) does NOT fall from 2^-5 to
// 2^-6 (0.017–0.019 at both levels, h/Δx = 3.1 and 4.9): at 2^-5 the O(h²) smoothing
// error ≈ 0.2/4·h²·8π² ≈ 0.037 is partly cancelled by the quadrature error of the few
// particles per stencil; from 2^-6 on it falls at every level (0.019 → 0.014 → 0.0091).
// So Case 2 is checked from 2^-6 and overall from 2^-5 to 2^-7.
TEST_CASE("interpolant with quadratic spike and Voronoi volumes converges", "[quick][smoke]") {
  for (uint64_t seed : {1, 2}) {
    INFO("seed " << seed);
    const double q5 = spike_error("quartic", 5, seed), q6 = spike_error("quartic", 6, seed),
                 q7 = spike_error("quartic", 7, seed);
    CHECK(q6 < q5);
    CHECK(q7 < q6);
    const double s5 = spike_error("sin2pi", 5, seed), s6 = spike_error("sin2pi", 6, seed),
                 s7 = spike_error("sin2pi", 7, seed), s8 = spike_error("sin2pi", 8, seed);
    CHECK(s7 < s6);
    CHECK(s8 < s7);
    CHECK(s7 < s5);
  }
}

TEST_CASE("truncation_error refuses bad settings with an InputError", "[quick][smoke]") {
  TruncationSetting s;
  s.dx = std::ldexp(1.0, -5);
  s.h = -0.1;
  CHECK_THROWS_AS(truncation_error(s), InputError);
  s.h = 0.1;
  s.weight = "no_such_weight";
  CHECK_THROWS_AS(truncation_error(s), InputError);
  CHECK_THROWS_AS(parse_operator("div"), InputError);
  CHECK_THROWS_AS(parse_volumes("mass"), InputError);
  CHECK(imoto_h(3, std::ldexp(1.0, -5)) == Approx(2.6 / 32).epsilon(1e-14));
}
