// Voronoi cells of Ω_H: areas tile Ω_H, the exact cells of the plain grid, the covering
// radius of the grid, a hand-checked case, a brute-force check, the polygon output,
// thread independence and refusal of bad input.
#include <catch2/catch.hpp>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/voronoi.hpp"

using namespace gpm;
using Catch::Matchers::Contains;

namespace {

Particles from_points(const std::vector<std::pair<double, double>>& pts) {
  Particles p;
  for (auto [x, y] : pts) p.push(x, y, 0, 0);
  return p;
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// max(Δx/2, g_lo, g_hi): the largest distance from a grid node to the edge of its
// clipped cell along one axis (see the derivation in the grid test below).
double grid_half_extent(double dx, const Domain& dom) {
  const double g_lo = grid_first(dx, dom) * dx - dom.lo();
  const double g_hi = dom.hi() - grid_last(dx, dom) * dx;
  return std::max({dx / 2, g_lo, g_hi});
}

}  // namespace

TEST_CASE("Voronoi areas of jittered grids sum to |Omega_H|", "[voronoi]") {
  const Domain dom;
  for (int level = 5; level <= 7; ++level)
    for (uint64_t seed : {1u, 2u, 3u, 17u}) {
      const double dx = std::ldexp(1.0, -level);
      const auto p = jittered_grid(dx, seed);
      const auto c = voronoi_cells(p, dom);
      INFO("level " << level << " seed " << seed);
      CHECK(rel(c.area_sum, dom.area_H()) < 1e-12);
      CHECK(c.area.size() == p.size());
      CHECK(*std::min_element(c.area.begin(), c.area.end()) > 0);
      CHECK(c.cover[c.worst] == c.covering_radius);
      CHECK(c.offset.empty());
      // Certain bounds (not the papers' claims): N discs of radius r_c cover Ω_H, so
      // π r_c² N ≥ |Ω_H|; and every y ∈ Ω_H is within √2·max(Δx/2, g) of a node
      // whose particle is within √2·Δx/4 of it (|η| < 1/4).
      CHECK(c.covering_radius >= std::sqrt(dom.area_H() / (M_PI * p.size())));
      CHECK(c.covering_radius < std::sqrt(2.0) * (grid_half_extent(dx, dom) + dx / 4));
    }
}

// The plain grid (amplitude 0).  Node i (per axis) has the cell [a_i, b_i] with
// a_i = iΔx − Δx/2, b_i = iΔx + Δx/2, except a_first = lo and b_last = hi (clipping by
// the edge of Ω_H), so its half-extent along that axis is e_i = max(iΔx − a_i, b_i − iΔx):
// Δx/2 inside, max(Δx/2, g_lo) for the first node, max(Δx/2, g_hi) for the last one, with
// g_lo = first·Δx − lo, g_hi = hi − last·Δx.  The cell is the rectangle of (i, j); its
// farthest point from the node is a corner, at distance √(e_i² + e_j²).  Both axes use
// the same nodes (the square is symmetric), so the maximum over (i, j) is attained with
// i = j = argmax e: r_c = √2·max(Δx/2, g_lo, g_hi), by an interior cell when Δx/2 wins,
// by the corner cell (first, first) or (last, last) when g_lo or g_hi wins.
TEST_CASE("Voronoi cells of the plain grid are the clipped squares", "[voronoi]") {
  const Domain dom;
  for (double dx : {std::ldexp(1.0, -5), std::ldexp(1.0, -6), std::ldexp(1.0, -7), 0.03, 0.07}) {
    INFO("dx = " << dx);
    const auto p = jittered_grid(dx, 1, 0.0);
    const auto c = voronoi_cells(p, dom, true);
    const int64_t first = grid_first(dx, dom), last = grid_last(dx, dom);
    const double g_lo = first * dx - dom.lo(), g_hi = dom.hi() - last * dx;
    auto extent = [&](int64_t i, bool upper) {  // from node to cell edge along one axis
      if (!upper && i == first) return g_lo;
      if (upper && i == last) return g_hi;
      return dx / 2;
    };
    double worst_err_area = 0, worst_err_cover = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      const int64_t i = p.gi[k], j = p.gj[k];
      const double wx = extent(i, false) + extent(i, true), wy = extent(j, false) + extent(j, true);
      const double ex = std::max(extent(i, false), extent(i, true));
      const double ey = std::max(extent(j, false), extent(j, true));
      worst_err_area = std::max(worst_err_area, rel(c.area[k], wx * wy));
      worst_err_cover = std::max(worst_err_cover, rel(c.cover[k], std::hypot(ex, ey)));
      if (i > first && i < last && j > first && j < last) {
        // interior: the square of side Δx; polygons merge the 4 coincident circumcentres
        REQUIRE(c.area[k] == Approx(dx * dx).epsilon(1e-10));
        REQUIRE(c.cover[k] == Approx(dx / std::sqrt(2.0)).epsilon(1e-10));
        REQUIRE(c.offset[k + 1] - c.offset[k] == 4);
      }
    }
    CHECK(worst_err_area < 1e-9);
    CHECK(worst_err_cover < 1e-9);
    const double predicted = std::sqrt(2.0) * grid_half_extent(dx, dom);
    CHECK(c.covering_radius == Approx(predicted).epsilon(1e-10));
    // The corner cells attain √2·max(Δx/2, g) on their own side.
    const std::size_t n1 = last - first + 1;
    CHECK(c.cover[0] == Approx(std::sqrt(2.0) * std::max(dx / 2, g_lo)).epsilon(1e-10));
    CHECK(c.cover[n1 * n1 - 1] == Approx(std::sqrt(2.0) * std::max(dx / 2, g_hi)).epsilon(1e-10));
    if (std::max(g_lo, g_hi) > dx / 2) {
      CHECK((c.worst == 0 || c.worst == n1 * n1 - 1));
    }
    CHECK(rel(c.area_sum, dom.area_H()) < 1e-12);
  }
}

TEST_CASE("Voronoi cells of small hand-checkable sets", "[voronoi]") {
  const Domain dom;  // Ω_H = (−0.1, 1.1)²
  SECTION("one particle owns Omega_H") {
    const auto c = voronoi_cells(from_points({{0.3, 0.4}}), dom);
    CHECK(c.area[0] == Approx(1.44).epsilon(1e-14));
    CHECK(c.covering_radius == Approx(std::hypot(0.8, 0.7)).epsilon(1e-14));  // to (1.1, 1.1)
  }
  SECTION("two particles: the bisector x = 0.4") {
    const auto c = voronoi_cells(from_points({{0.2, 0.5}, {0.6, 0.5}}), dom, true);
    CHECK(c.area[0] == Approx(0.5 * 1.2).epsilon(1e-13));
    CHECK(c.area[1] == Approx(0.7 * 1.2).epsilon(1e-13));
    CHECK(c.cover[0] == Approx(std::sqrt(0.45)).epsilon(1e-13));  // (−0.1, ±…)
    CHECK(c.cover[1] == Approx(std::sqrt(0.61)).epsilon(1e-13));  // (1.1, ±…)
    CHECK(c.worst == 1);
    CHECK(c.offset == std::vector<uint64_t>{0, 4, 8});
  }
  SECTION("four cocircular particles: four 0.6 x 0.6 squares") {
    const auto c =
        voronoi_cells(from_points({{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}}), dom);
    for (int k = 0; k < 4; ++k) {
      CHECK(c.area[k] == Approx(0.36).epsilon(1e-13));
      CHECK(c.cover[k] == Approx(0.35 * std::sqrt(2.0)).epsilon(1e-13));
    }
  }
  SECTION("three particles: a triangle's cells") {
    // (0.1,0.1), (0.9,0.1), (0.5,0.9).  The cell of p0 is {x < 0.5} (bisector with p1)
    // ∩ {0.4x + 0.8y < 0.52} (bisector with p2: y = 0.65 − x/2, which stays inside Ω_H
    // for x ∈ [−0.1, 0.5]), so |σ_0| = ∫_{−0.1}^{0.5} (0.65 − x/2 + 0.1) dx
    // = 0.75·0.6 − (0.5² − 0.1²)/4 = 0.39; σ_1 is its mirror image; σ_2 the rest.
    // σ_0 has the corners (−0.1,−0.1), (0.5,−0.1), (0.5,0.4), (−0.1,0.7): the farthest is
    // (−0.1, 0.7) at √0.4.  σ_2 has (−0.1,0.7), (0.5,0.4), (1.1,0.7), (1.1,1.1), (−0.1,1.1):
    // the farthest are (±0.6, −0.2) and (±0.6, 0.2) away, √0.4.
    const auto c = voronoi_cells(from_points({{0.1, 0.1}, {0.9, 0.1}, {0.5, 0.9}}), dom);
    CHECK(c.area[0] == Approx(0.39).epsilon(1e-13));
    CHECK(c.area[1] == Approx(0.39).epsilon(1e-13));
    CHECK(c.area[2] == Approx(1.44 - 0.78).epsilon(1e-13));
    CHECK(c.cover[0] == Approx(std::sqrt(0.40)).epsilon(1e-13));
    CHECK(c.cover[2] == Approx(std::sqrt(0.40)).epsilon(1e-13));
  }
}

TEST_CASE("Voronoi areas and covering distances agree with brute force", "[voronoi]") {
  const Domain dom;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(dom.lo() + 1e-3, dom.hi() - 1e-3);
  Particles p;
  for (int k = 0; k < 25; ++k) p.push(u(rng), u(rng), 0, 0);
  const auto c = voronoi_cells(p, dom);
  // Midpoint rule on an M×M pixel grid: each pixel goes to its nearest particle.
  const int M = 800;
  const double h = dom.side() / M;
  std::vector<double> area(p.size(), 0.0), far(p.size(), 0.0);
  for (int a = 0; a < M; ++a)
    for (int b = 0; b < M; ++b) {
      const double x = dom.lo() + (a + 0.5) * h, y = dom.lo() + (b + 0.5) * h;
      std::size_t best = 0;
      double bd = 1e300;
      for (std::size_t k = 0; k < p.size(); ++k) {
        const double d = std::hypot(x - p.x[k], y - p.y[k]);
        if (d < bd) bd = d, best = k;
      }
      area[best] += h * h;
      far[best] = std::max(far[best], bd);
    }
  for (std::size_t k = 0; k < p.size(); ++k) {
    INFO("particle " << k);
    CHECK(std::abs(area[k] - c.area[k]) < 4 * h * 1.2);  // boundary pixels: O(h·perimeter)
    CHECK(far[k] <= c.cover[k] + 1e-12);                   // samples never exceed the sup
    CHECK(far[k] >= c.cover[k] - 3 * h);                   // … and come within a few pixels
  }
}

TEST_CASE("Voronoi polygon output matches the areas and lies in Omega_H", "[voronoi]") {
  const Domain dom;
  const auto p = jittered_grid(std::ldexp(1.0, -6), 5);
  const auto c = voronoi_cells(p, dom, true);
  REQUIRE(c.offset.size() == p.size() + 1);
  REQUIRE(c.px.size() == c.offset.back());
  const double tol = 1e-14;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t b = c.offset[i], n = c.offset[i + 1] - b;
    REQUIRE(n >= 3);
    // same numbers as `area` (same formula, same origin)
    REQUIRE(polygon_area(&c.px[b], &c.py[b], n, p.x[i], p.y[i]) == c.area[i]);
    double r = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double x0 = c.px[b + k], y0 = c.py[b + k];
      const double x1 = c.px[b + (k + 1) % n], y1 = c.py[b + (k + 1) % n];
      // inside the closed square, convex and counter-clockwise: the particle is to the
      // left of every edge
      REQUIRE(x0 >= dom.lo() - tol);
      REQUIRE(x0 <= dom.hi() + tol);
      REQUIRE(y0 >= dom.lo() - tol);
      REQUIRE(y0 <= dom.hi() + tol);
      REQUIRE((x1 - x0) * (p.y[i] - y0) - (y1 - y0) * (p.x[i] - x0) > 0);
      r = std::max(r, std::hypot(x0 - p.x[i], y0 - p.y[i]));
    }
    REQUIRE(r == Approx(c.cover[i]).epsilon(1e-14));
  }
  const auto c2 = voronoi_cells(p, dom, false);
  CHECK(c2.area == c.area);
  CHECK(c2.cover == c.cover);
}

TEST_CASE("Voronoi results do not depend on the thread count", "[voronoi]") {
  const auto p = jittered_grid(std::ldexp(1.0, -7), 3);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto a = voronoi_cells(p, Domain{}, true);
  omp_set_num_threads(2);
  const auto b = voronoi_cells(p, Domain{}, true);
  omp_set_num_threads(saved);
  CHECK(a.area == b.area);
  CHECK(a.cover == b.cover);
  CHECK(a.offset == b.offset);
  CHECK(a.px == b.px);
  CHECK(a.py == b.py);
  CHECK(a.covering_radius == b.covering_radius);
  CHECK(a.worst == b.worst);
  CHECK(a.area_sum == b.area_sum);
}

TEST_CASE("Voronoi refuses duplicate, outside and empty input", "[voronoi]") {
  const Domain dom;
  CHECK_THROWS_AS(voronoi_cells(Particles{}, dom), InputError);
  CHECK_THROWS_WITH(voronoi_cells(from_points({{0.1, 0.2}, {0.5, 0.5}, {0.3, 0.3}, {0.5, 0.5}}), dom),
                    Contains("particles 1 and 3 coincide"));
  CHECK_THROWS_WITH(voronoi_cells(from_points({{0.1, 0.2}, {1.1, 0.5}}), dom),
                    Contains("particle 1"));
  CHECK_THROWS_AS(voronoi_cells(from_points({{0.1, 0.2}, {-0.2, 0.5}}), dom), InputError);
  CHECK_THROWS_AS(voronoi_cells(from_points({{std::nan(""), 0.2}}), dom), InputError);
  auto p = jittered_grid(std::ldexp(1.0, -5), 1);
  p.x[100] = p.x[7];
  p.y[100] = p.y[7];
  CHECK_THROWS_WITH(voronoi_cells(p, dom), Contains("particles 7 and 100 coincide"));
}
