// Rates of the thesis' truncation-error studies (Tables 4.1–4.3) at quick sizes.
//
// The thesis takes its rates at Δx = 2^-10…2^-12, beyond a test's budget; at the sizes here
// the rates are pre-asymptotic.  The bands below come from seeds 1–5 (measured 2026-11 with
// the table programs, --seed 1..5): the measured range, widened by about 0.3 on each side
// for seeds not measured.  What each band asserts, and why it can fail:
//  * Table 4.1 (Δx 2^-8→2^-9, Voronoi): the three order-1 weights converge at about h²
//    (measured 1.92–2.59); a wrong volume or weight would give ≤ 1 or no convergence.
//  * Table 4.2, scaled h (2^-7→2^-8): the order-1 weights again near 2 (measured 1.82–3.43);
//    the cubic spike (order 3) at 10.7–11.9: its error is still dominated by the quadrature
//    term of order (Δx)² ∝ h^10 with h ∝ Δx^(1/5), not yet the h⁴ term — the test pins that.
//  * Table 4.3, scaled h (2^-7→2^-8): gradient 2.56–6.33, Laplacian 5.67–9.69, both also
//    quadrature-dominated (h ∝ Δx^(1/4)).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/operators/norms.hpp"
#include "gpm/studies/define/thesis_tables.hpp"

using namespace gpm;

namespace {

// Rate between levels k1 < k2 of every request × case, Voronoi volumes.
std::map<std::string, double> rates(int c, int p, HReading reading,
                                    const std::vector<ErrorRequest>& req, int k1, int k2,
                                    uint64_t seed) {
  std::map<std::string, std::pair<double, double>> first;
  std::map<std::string, double> out;
  std::vector<std::string> fns;
  for (auto& tc : thesis_cases()) fns.push_back(tc.function);
  for (int k : {k1, k2}) {
    const double dx = std::ldexp(1.0, -k), h = thesis_h(reading, c, p, dx);
    const Particles pt = jittered_grid(dx, seed);
    const auto V = voronoi_cells(pt).area;
    for (auto& e : fused_errors(pt, V, h, req, fns, false).errors) {
      const std::string key = e.weight + "/" + operator_name(e.op) + "/" + e.function;
      REQUIRE(std::isfinite(e.rel_error));
      if (k == k1)
        first[key] = {h, e.rel_error};
      else
        out[key] = two_level_rate(first[key].first, first[key].second, h, e.rel_error);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("thesis h: the two readings agree for p = 3 and differ above H for p = 4, 5",
          "[quick][thesis]") {
  for (int k = 5; k <= 12; ++k) {
    const double dx = std::ldexp(1.0, -k);
    CHECK(thesis_h(HReading::printed, 3, 3, dx) ==
          Approx(thesis_h(HReading::scaled, 3, 3, dx)).epsilon(1e-14));
    CHECK(thesis_h(HReading::scaled, 3, 5, dx) < 0.1);
  }
  CHECK(thesis_h(HReading::printed, 3, 3, 1.0 / 32) == Approx(3.1 / 32).epsilon(1e-14));
  CHECK(thesis_h(HReading::scaled, 4, 4, 1.0 / 32) == Approx(3.1 / 32).epsilon(1e-14));
  // Printed: h > H = 0.1 up to 2^-11 (Table 4.2) and up to 2^-9 (Table 4.3).
  CHECK(thesis_h(HReading::printed, 3, 5, std::ldexp(1.0, -11)) > 0.1);
  CHECK(thesis_h(HReading::printed, 3, 5, std::ldexp(1.0, -12)) < 0.1);
  CHECK(thesis_h(HReading::printed, 4, 4, std::ldexp(1.0, -9)) > 0.1);
  CHECK(thesis_h(HReading::printed, 4, 4, std::ldexp(1.0, -10)) < 0.1);
  CHECK_THROWS(parse_h_reading("typed"));
}

TEST_CASE("Table 4.1 at quick sizes: order-1 interpolants converge at about h^2",
          "[quick][thesis]") {
  const std::vector<ErrorRequest> req = {{"quadratic_spike", Operator::interp},
                                         {"cubic_bspline", Operator::interp},
                                         {"quintic_bspline", Operator::interp}};
  for (uint64_t seed : {1u, 2u}) {
    for (auto& [key, r] : rates(3, 3, HReading::printed, req, 8, 9, seed)) {
      INFO(key << " seed " << seed << " rate " << r);
      CHECK(r > 1.6);
      CHECK(r < 2.9);
    }
  }
}

TEST_CASE("Table 4.2 at quick sizes (scaled h): order-1 near 2, cubic spike quadrature-bound",
          "[quick][thesis]") {
  const std::vector<ErrorRequest> req = {{"cubic_bspline", Operator::interp},
                                         {"quintic_bspline", Operator::interp},
                                         {"quadratic_spike", Operator::interp},
                                         {"cubic_spike", Operator::interp}};
  for (uint64_t seed : {1u, 2u}) {
    for (auto& [key, r] : rates(3, 5, HReading::scaled, req, 7, 8, seed)) {
      INFO(key << " seed " << seed << " rate " << r);
      if (key.rfind("cubic_spike", 0) == 0) {
        CHECK(r > 10.0);
        CHECK(r < 12.6);
      } else {
        CHECK(r > 1.5);
        CHECK(r < 3.8);
      }
    }
  }
}

TEST_CASE("Table 4.3 at quick sizes (scaled h): gradient and Laplacian converge",
          "[quick][thesis]") {
  std::vector<ErrorRequest> req;
  for (const char* w : {"quartic_polynomial", "piecewise_cubic_polynomial",
                        "piecewise_quintic_polynomial"})
    req.push_back({w, Operator::grad}), req.push_back({w, Operator::lap});
  for (uint64_t seed : {1u, 2u}) {
    for (auto& [key, r] : rates(4, 4, HReading::scaled, req, 7, 8, seed)) {
      INFO(key << " seed " << seed << " rate " << r);
      if (key.find("/grad/") != std::string::npos) {
        CHECK(r > 2.2);
        CHECK(r < 6.7);
      } else {
        CHECK(r > 5.3);
        CHECK(r < 10.1);
      }
    }
  }
}
