// The error constants (error_constants.hpp): the a-priori model checked against what it
// claims (u − φ solves the right Poisson problem; the model constants' limits), and the
// rule's every branch, both ways.
#include <catch2/catch.hpp>
#include <cmath>

#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/judge/error_constants.hpp"
#include "gpm/studies/judge/heat_mode_model.hpp"
#include "gpm/studies/judge/mode_constants.hpp"
#include "gpm/theory/smoothing.hpp"

using namespace gpm;

TEST_CASE("error constants: u - phi vanishes on the boundary and solves -Lap w = 8 pi^2 u", "[unit][error_constants]") {
  // Zero on the edges (away from the corners, where the series converges slowest).
  for (double t : {0.2, 0.5, 0.7}) {
    CHECK(std::fabs(poisson_boundary_defect(0, t)) < 1e-12);
    CHECK(std::fabs(poisson_boundary_defect(t, 1)) < 1e-3);
  }
  // -Δw = 8π² sin 2π(x+y) at interior points, by a five-point difference (step 1e-3: its own
  // error ~ h²/12 · w'''' ~ 1e-4 relative).
  const double d = 1e-3;
  for (auto [x, y] : {std::pair{0.3, 0.4}, std::pair{0.6, 0.25}, std::pair{0.5, 0.5}}) {
    const double lap = (poisson_boundary_defect(x + d, y) + poisson_boundary_defect(x - d, y) +
                        poisson_boundary_defect(x, y + d) + poisson_boundary_defect(x, y - d) -
                        4 * poisson_boundary_defect(x, y)) / (d * d);
    const double rhs = 8 * M_PI * M_PI * std::sin(2 * M_PI * (x + y));
    CHECK(-lap == Approx(rhs).margin(2e-2 * 8 * M_PI * M_PI));
  }
  // R = max|u − φ|: more than max|u| = 1 (the boundary's harmonic part lowers u in places).
  CHECK(poisson_boundary_factor() == Approx(1.171075).epsilon(1e-5));
}

TEST_CASE("error constants: the model constants tend to their limits", "[unit][error_constants]") {
  const WeightFunction& w = weight("piecewise_cubic_polynomial");
  // Table 4.4: predicted/h² at small h against the limit; at the thesis' radii within 2 %.
  const double lim = poisson_constant_limit(w);
  CHECK(poisson_mode_error(w, 1e-3, 0) / 1e-6 == Approx(lim).epsilon(1e-4));
  CHECK(poisson_mode_error(w, 0.08, 0) / 0.0064 == Approx(lim).epsilon(0.02));
  // A volume mismatch adds to the error at first order: δ = 1e-3 adds about R·1e-3.
  CHECK(poisson_mode_error(w, 0.05, 1e-3) - poisson_mode_error(w, 0.05, 0) ==
        Approx(-1e-3 * poisson_boundary_factor()).epsilon(0.05).margin(0) );
  // Heat, Table 4.5 θ = ½: the model at a fine level over h² approaches the limit.
  const HeatTable& t = heat_table("4.5");
  const double hl = heat_constant_limit(w, t, 0.5, 2);
  const double h = 0.01, dt = t.c * std::pow(h, t.p), mu = kHeatKappa * 2 * M_PI * M_PI;
  const double eps = laplacian_smoothing_error(w, M_PI * std::sqrt(2.0) * h);
  const double e = mode_error(0.5, mu * (1 - eps), dt, static_cast<long long>(std::ceil(kHeatT / dt - 1e-9)));
  CHECK(e / (h * h) == Approx(hl).epsilon(0.01));
}

TEST_CASE("error constants: the rule says yes and no", "[unit][error_constants]") {
  // Near the model and shrinking: approaches.
  CHECK(judge_constant(0.08, 0.03).trend == Trend::approaches);
  // Near and growing above the floor: not decided, saying so.
  const TrendFinding grow = judge_constant(0.015, 0.03);
  CHECK(grow.trend == Trend::not_decided);
  CHECK(grow.why.find("growing") != std::string::npos);
  // Near and "growing" under the 1 % floor: approaches (scatter, not a trend).
  CHECK(judge_constant(0.002, 0.008).trend == Trend::approaches);
  // Off and not shrinking by 10 %: stays away; off and shrinking: not decided.
  CHECK(judge_constant(0.20, 0.19).trend == Trend::stays_away);
  CHECK(judge_constant(0.20, 0.30).trend == Trend::stays_away);
  const TrendFinding still = judge_constant(0.30, 0.10);
  CHECK(still.trend == Trend::not_decided);
  CHECK(still.why.find("shrinking") != std::string::npos);
  CHECK(judge_constant(std::nan(""), 0.01).trend == Trend::not_decided);
}
