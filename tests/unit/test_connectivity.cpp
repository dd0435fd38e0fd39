// h-connectivity (thesis Definition 1.8): the breadth-first search from the particles
// outside Ω must find a planted isolated group, and only it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/connectivity.hpp"
#include "gpm/geometry/domain.hpp"

using namespace gpm;

namespace {
// The jittered grid with the annulus rho <= |x - c| < rho + h removed: the particles within
// rho of c can reach nothing outside the annulus in steps shorter than h.
Particles with_isolated_group(double dx, uint64_t seed, double cx, double cy, double rho,
                              double h, std::vector<int32_t>& planted) {
  const Particles full = jittered_grid(dx, seed);
  Particles p;
  for (std::size_t i = 0; i < full.size(); ++i) {
    const double d = std::hypot(full.x[i] - cx, full.y[i] - cy);
    if (d >= rho && d < rho + h) continue;
    if (d < rho) planted.push_back(static_cast<int32_t>(p.size()));
    p.push(full.x[i], full.y[i], full.gi[i], full.gj[i]);
  }
  return p;
}
}  // namespace

TEST_CASE("h-connectivity holds for a jittered grid with h > 2 r_c", "[unit][connectivity]") {
  // Lemma 1.10: h > 2 r_c suffices; r_c < 1.8 dx for these grids (core_voronoi), so 3.7 dx.
  for (uint64_t seed : {1u, 2u, 3u}) {
    const double dx = 1.0 / 32;
    const Particles p = jittered_grid(dx, seed);
    const auto r = h_connectivity(p, 3.7 * dx);
    CHECK(r.connected);
    CHECK(r.unconnected.empty());
    CHECK(r.n_sources == p.size() - p.count_in_omega());
    for (std::size_t i = 0; i < p.size(); ++i) CHECK((p.in_omega[i] ? r.hops[i] >= 1 : r.hops[i] == 0));
    CHECK(*std::min_element(r.hops.begin(), r.hops.end()) == 0);
  }
}

TEST_CASE("h-connectivity detects a planted isolated cluster", "[unit][connectivity]") {
  const double dx = 1.0 / 32, h = 2.4 * dx;
  for (uint64_t seed : {1u, 2u, 3u}) {
    std::vector<int32_t> planted;
    const Particles p = with_isolated_group(dx, seed, 0.3, 0.5, 1.3 * dx, h, planted);
    REQUIRE(planted.size() >= 3);  // a group, not a single particle
    const auto r = h_connectivity(p, h);
    CHECK_FALSE(r.connected);
    CHECK(r.unconnected == planted);  // exactly the group, nothing else
    for (int32_t i : planted) CHECK(r.hops[i] == -1);
    // The same distribution without the cut is connected: the cut is what fails it.
    CHECK(h_connectivity(jittered_grid(dx, seed), h).connected);
  }
}

TEST_CASE("h-connectivity: a radius below the spacing leaves every particle in Omega alone",
          "[unit][connectivity]") {
  const double dx = 1.0 / 16;
  const Particles p = jittered_grid(dx, 1);
  const auto r = h_connectivity(p, 0.2 * dx);  // nearest neighbours are ≥ dx/2 apart
  CHECK(r.unconnected.size() == p.count_in_omega());
  CHECK_THROWS_AS(h_connectivity(p, 0.0), InputError);
  CHECK_THROWS_AS(h_connectivity(p, std::nan("")), InputError);
}

TEST_CASE("neighbour_edges lists each pair within h once", "[unit][connectivity]") {
  const double dx = 1.0 / 16, h = 1.6 * dx;
  const Particles p = jittered_grid(dx, 4);
  const auto e = neighbour_edges(p, h);
  std::size_t brute = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      brute += std::hypot(p.x[i] - p.x[j], p.y[i] - p.y[j]) < h;
  CHECK(e.size() == brute);
  for (auto [i, j] : e) CHECK(i < j);
}
