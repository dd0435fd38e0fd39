// locate_error (poisson.hpp): the relative ℓ∞(Ω) error, the particle attaining it, its
// distance from ∂Ω, and the error away from the boundary layer — on a planted error.
#include <catch2/catch.hpp>

#include <cmath>

#include "gpm/geometry/domain.hpp"
#include "gpm/solvers/poisson.hpp"

using namespace gpm;

TEST_CASE("locate_error finds a planted error and separates the boundary layer", "[unit][poisson]") {
  const Particles p = jittered_grid(std::ldexp(1.0, -5), 1);
  std::vector<double> exact(p.size()), U(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) exact[i] = U[i] = 2.0;  // max |u| = 2
  // The largest error next to the boundary, a smaller one in the middle.
  std::size_t edge = 0, mid = 0;
  double best_edge = 1, best_mid = 1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.in_omega[i]) continue;
    const double d = std::min({p.x[i], 1 - p.x[i], p.y[i], 1 - p.y[i]});
    if (d < best_edge) best_edge = d, edge = i;
    const double c = std::hypot(p.x[i] - 0.5, p.y[i] - 0.5);
    if (c < best_mid) best_mid = c, mid = i;
  }
  U[edge] += 0.5;
  U[mid] -= 0.1;
  const double h = 0.1;
  const ErrorLocation e = locate_error(p, exact, U, h);
  CHECK(e.argmax == edge);
  CHECK(e.rel_error == Approx(0.25));
  CHECK(e.distance_to_boundary == Approx(best_edge));
  CHECK(e.rel_error_inner == Approx(0.05));  // only the middle error is ≥ h from ∂Ω
  // Outside Ω nothing counts.
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!p.in_omega[i]) U[i] += 10;
  CHECK(locate_error(p, exact, U, h).rel_error == Approx(0.25));
}

TEST_CASE("locate_error: a tie at rounding level goes to the first particle", "[unit][poisson]") {
  // Two errors that differ by 1e-13 relative (the size a change of summation order makes on
  // a symmetric setting): the lower index is named, whichever of the two is larger.
  const Particles p = jittered_grid(std::ldexp(1.0, -5), 1);
  std::vector<double> exact(p.size(), 1.0), U(p.size(), 1.0);
  std::size_t a = 0, b = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.in_omega[i]) (a == 0 ? a : b) = i;
  REQUIRE(a < b);
  for (double later : {1 + 1e-13, 1 - 1e-13}) {
    U[a] = 1.5, U[b] = 1 + 0.5 * later;
    CHECK(locate_error(p, exact, U, 0.1).argmax == a);
  }
  U[b] = 1 + 0.5 * (1 + 1e-6);  // a real difference still wins
  CHECK(locate_error(p, exact, U, 0.1).argmax == b);
}
