// Domain and jittered-grid distribution: counts, bounds, determinism.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"

using namespace gpm;

TEST_CASE("jittered grid at dx = 2^-5 has the documents' N = 1,521", "[domain]") {
  // imoto Fig. 4 and thesis Fig. 4.1 both print N = 1,521 = 39².
  const auto p = jittered_grid(std::ldexp(1.0, -5), 1);
  CHECK(p.size() == 1521);
  const auto g = jittered_grid(std::ldexp(1.0, -5), 1, 0.0);
  CHECK(g.size() == 1521);
}

TEST_CASE("node count per axis follows the open square (-H, 1+H)", "[domain]") {
  const Domain dom;
  for (int k = 5; k <= 9; ++k) {
    const double dx = std::ldexp(1.0, -k);
    const auto a = grid_first(dx, dom), b = grid_last(dx, dom);
    CHECK(a * dx > dom.lo());
    CHECK((a - 1) * dx <= dom.lo());
    CHECK(b * dx < dom.hi());
    CHECK((b + 1) * dx >= dom.hi());
    CHECK(jittered_grid(dx, 7).size() == static_cast<std::size_t>((b - a + 1) * (b - a + 1)));
  }
}

TEST_CASE("every particle lies in Omega_H within a quarter spacing of its node", "[domain]") {
  const Domain dom;
  for (double dx : {std::ldexp(1.0, -5), std::ldexp(1.0, -7), 0.0123}) {
    const auto p = jittered_grid(dx, 42);
    for (std::size_t i = 0; i < p.size(); ++i) {
      REQUIRE(dom.in_omega_H(p.x[i], p.y[i]));
      REQUIRE(std::fabs(p.x[i] - p.gi[i] * dx) < 0.25 * dx);
      REQUIRE(std::fabs(p.y[i] - p.gj[i] * dx) < 0.25 * dx);
      REQUIRE(p.in_omega[i] == (Domain::in_omega(p.x[i], p.y[i]) ? 1 : 0));
    }
  }
}

TEST_CASE("jitter is a pure function of (seed, i, j): any thread order gives it", "[domain]") {
  const auto p = jittered_grid(std::ldexp(1.0, -6), 3);
  std::vector<double> x(p.size());
  const double dx = std::ldexp(1.0, -6);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
#pragma omp parallel for schedule(dynamic, 7)
    for (long i = 0; i < static_cast<long>(p.size()); ++i)
      x[i] = p.gi[i] * dx + jitter(3, p.gi[i], p.gj[i], 0) * dx;
    // Interior particles are never mirrored, so they equal the recomputed value exactly.
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.in_omega[i]) REQUIRE(x[i] == p.x[i]);
  }
  CHECK(jittered_grid(dx, 3).x == p.x);
  CHECK(jittered_grid(dx, 4).x != p.x);
}

TEST_CASE("jitter is uniform on (-1/4, 1/4)", "[domain]") {
  double sum = 0, sum2 = 0, mx = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const double e = jitter(9, k % 451, k / 451, k & 1);
    sum += e, sum2 += e * e, mx = std::max(mx, std::fabs(e));
  }
  CHECK(std::fabs(sum / n) < 0.002);
  CHECK(sum2 / n == Approx(1.0 / 48).epsilon(0.02));  // variance of U(-1/4,1/4)
  CHECK(mx < 0.25);
  CHECK(mx > 0.2499);
}

TEST_CASE("bad dx is refused with an InputError", "[domain]") {
  CHECK_THROWS_AS(jittered_grid(0.0, 1), InputError);
  CHECK_THROWS_AS(jittered_grid(-0.1, 1), InputError);
  CHECK_THROWS_AS(jittered_grid(std::nan(""), 1), InputError);
  CHECK_THROWS_AS(jittered_grid(0.7, 1), InputError);
  CHECK_THROWS_AS(jittered_grid(0.1, 1, 0.5), InputError);
}
