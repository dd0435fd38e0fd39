// The cost model's pair prediction against counted pairs (cost_model.hpp).
//
// Spread measured over seeds 1-5, levels 5-7 and the studies' h rules (imoto m = 1, 3, 5, the
// thesis' printed h of Table 4.2, h > H on the coarse levels, and the Poisson/heat h10): see
// the tolerance comment of the second test case.  About 6 s on 2 cores.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/operators/truncation.hpp"
#include "gpm/studies/define/cost_model.hpp"
#include "gpm/studies/define/thesis_tables.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {
double counted_pairs(const Particles& p, double h) {
  const std::vector<double> V = uniform_volumes(p);
  const FusedKernel k(p, V, h, {{weight("Pi2"), kInterp}});
  return static_cast<double>(k.count_pairs(omega_targets(p)).accepted);
}
double h10(double dx) { return pde_h(HRule::h10, dx); }
}  // namespace

TEST_CASE("mean disc area: pi h^2 inside, boundary cut above H", "[cost_model]") {
  CHECK(mean_disc_area(0.05) == Approx(M_PI * 0.0025).epsilon(1e-12));
  // Just above H the cut is negligible; at h = 2H it is a visible fraction.  The
  // quadrature agrees with a brute-force Monte-Carlo-free grid average over x in Omega.
  const double h = 0.2;
  const int n = 400;
  double s = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5) / n, y = (j + 0.5) / n;
      // area of B((x,y), h) ∩ (−H, 1+H)² by a fine sub-grid
      const int m = 40;
      int in = 0;
      for (int a = 0; a < m; ++a)
        for (int b = 0; b < m; ++b) {
          const double u = -h + 2 * h * (a + 0.5) / m, v = -h + 2 * h * (b + 0.5) / m;
          if (u * u + v * v < h * h && x + u > -0.1 && x + u < 1.1 && y + v > -0.1 && y + v < 1.1) ++in;
        }
      s += in * (4 * h * h) / (m * m);
    }
  const double brute = s / (n * n);
  CHECK(mean_disc_area(h) == Approx(brute).epsilon(0.01));  // sub-grid area error ~0.3 %
  CHECK(mean_disc_area(h) < 0.99 * M_PI * h * h);
  CHECK_THROWS(mean_disc_area(-1));
}

TEST_CASE("predicted pairs match counted pairs on the studies' levels and h", "[cost_model]") {
  // Tolerance 5 %.  Measured ratio counted/predicted over seeds 1-5, levels 5-7 and the five
  // h rules below (75 cases): worst |ratio − 1| = 0.019, so 5 % is 2.6 times the worst case.
  // The remaining error is the lattice-point error of a disc (Gauss circle problem: O(h/Δx)
  // points on ~πh²/Δx²) and the jitter, largest for the smallest h/Δx (imoto m = 1:
  // h/Δx = 2.6 on every level).  A model without the boundary cut fails the h > H cases by
  // more than 5 % (next test case).
  double worst = 0;
  for (int k = 5; k <= 7; ++k) {
    const double dx = std::ldexp(1.0, -k);
    for (uint64_t seed = 1; seed <= 5; ++seed) {
      const Particles p = jittered_grid(dx, seed);
      for (double h : {imoto_h(1, dx), imoto_h(3, dx), imoto_h(5, dx),
                       thesis_h(HReading::printed, 3, 5, dx), h10(dx)}) {
        const double r = counted_pairs(p, h) / predicted_pairs(dx, h);
        worst = std::max(worst, std::fabs(r - 1));
        INFO("level " << k << " seed " << seed << " h " << h << " ratio " << r);
        CHECK(std::fabs(r - 1) < 0.05);
      }
    }
  }
  std::fprintf(stderr, "[cost_model] worst |counted/predicted - 1| = %.4f\n", worst);
}

TEST_CASE("the boundary cut matters where h > H", "[cost_model]") {
  // Table 4.2's printed h at 2^-5 is 0.25 > H: the plain N_Ω πh²/Δx² over-counts; the
  // cut-corrected prediction does not.
  const double dx = std::ldexp(1.0, -5), h = thesis_h(HReading::printed, 3, 5, dx);
  REQUIRE(h > 0.2);
  const Particles p = jittered_grid(dx, 1);
  const double counted = counted_pairs(p, h);
  const double plain = (1 / (dx * dx)) * M_PI * h * h / (dx * dx);
  INFO("plain/counted " << plain / counted << ", predicted/counted "
                         << predicted_pairs(dx, h) / counted);
  // Measured: plain/counted = 1.066, predicted/counted = 1.00 (seed 1).
  CHECK(plain / counted > 1.04);
  CHECK(predicted_pairs(dx, h) / counted == Approx(1).epsilon(0.02));
}

TEST_CASE("pass cost fit recovers a linear model", "[cost_model]") {
  const PassCost c = PassCost::fit(1000, 1e5, 1000 * 2e-6 + 1e5 * 3e-9, 1e6, 1000 * 2e-6 + 1e6 * 3e-9);
  CHECK(c.per_target_s == Approx(2e-6));
  CHECK(c.per_pair_s == Approx(3e-9));
  // A negative intercept from timer noise: slope through the larger pass, no intercept.
  const PassCost d = PassCost::fit(1000, 1e5, 1e-5, 1e6, 1e-3);
  CHECK(d.per_target_s == 0);
  CHECK(d.per_pair_s == Approx(1e-9));
  CHECK_THROWS(PassCost::fit(1000, 1e6, 1, 1e5, 2));
}
