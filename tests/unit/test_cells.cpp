// Cell list: sorted structure, chord range queries against brute force.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/geometry/domain.hpp"

using namespace gpm;

namespace {

std::vector<int32_t> brute(const std::vector<double>& x, const std::vector<double>& y, double px,
                           double py, double h) {
  std::vector<int32_t> out;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (dist2(x[i] - px, y[i] - py) < h * h) out.push_back(static_cast<int32_t>(i));
  return out;
}

void check_structure(const CellList& cl, const std::vector<double>& x,
                     const std::vector<double>& y) {
  REQUIRE(cl.size() == x.size());
  REQUIRE(cl.start().size() == static_cast<std::size_t>(cl.cell_count() + 1));
  REQUIRE(cl.start().front() == 0);
  REQUIRE(cl.start().back() == static_cast<int32_t>(x.size()));
  for (std::size_t k = 0; k < cl.size(); ++k) {
    REQUIRE(cl.slot()[cl.index()[k]] == static_cast<int32_t>(k));
    REQUIRE(cl.xs()[k] == x[cl.index()[k]]);
    REQUIRE(cl.ys()[k] == y[cl.index()[k]]);
  }
  for (int64_t c = 0; c < cl.cell_count(); ++c) {
    REQUIRE(cl.start()[c] <= cl.start()[c + 1]);
    for (int32_t k = cl.start()[c]; k < cl.start()[c + 1]; ++k) {
      REQUIRE(cl.row(cl.ys()[k]) * cl.nx() + cl.column(cl.xs()[k]) == c);
      if (k > cl.start()[c]) REQUIRE(cl.index()[k - 1] < cl.index()[k]);  // stable
    }
  }
  for (int p = 0; p < CellList::kPad; ++p)  // padding repeats the last point: finite
    REQUIRE(cl.xs()[cl.size() + p] == cl.xs()[cl.size() - 1]);
}

}  // namespace

TEST_CASE("cell list matches brute force on random points", "[cells]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), uq(-0.6, 1.6);
  std::vector<double> x(1500), y(1500);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = u(rng);
    y[i] = u(rng);
  }
  for (double cell : {0.013, 0.05, 0.0371, 0.3, 2.5}) {
    const CellList cl(x, y, cell);
    check_structure(cl, x, y);
    for (double h : {0.011, 0.05, 0.1234567, 0.25, 1.5, 3.0}) {
      for (int q = 0; q < 60; ++q) {
        // Query points: particles, random points, points outside the box.
        double px, py;
        if (q < 20) {
          px = x[q * 37];
          py = y[q * 37];
        } else {
          px = uq(rng);
          py = uq(rng);
        }
        const auto got = cl.neighbours(px, py, h);
        const auto want = brute(x, y, px, py, h);
        INFO("cell " << cell << " h " << h << " p (" << px << ", " << py << ")");
        REQUIRE(got == want);
        // Every neighbour lies in exactly one visited range; the ranges never overlap.
        std::vector<int> seen(cl.size(), 0);
        cl.for_each_range(px, py, h, [&](int32_t b, int32_t e) {
          REQUIRE(b < e);
          for (int32_t k = b; k < e; ++k) ++seen[k];
        });
        for (auto s : seen) REQUIRE(s <= 1);
        for (auto i : want) REQUIRE(seen[cl.slot()[i]] == 1);
      }
    }
  }
}

TEST_CASE("cell list: points exactly on cell borders, h a multiple of the cell size",
          "[cells]") {
  // A lattice of spacing 1/8 with cells of 1/8: every point sits on a cell corner.
  const double c = 0.125;
  std::vector<double> x, y;
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 16; ++j) {
      x.push_back(i * c);
      y.push_back(j * c);
    }
  for (double cell : {c, c / 2, 0.1}) {
    const CellList cl(x, y, cell);
    check_structure(cl, x, y);
    for (double h : {c, 2 * c, 0.2, 0.3, 3 * c, 5.0}) {
      for (std::size_t q = 0; q < x.size(); q += 5) {
        for (double off : {0.0, c / 2}) {
          const double px = x[q] + off, py = y[q];
          INFO("cell " << cell << " h " << h << " p (" << px << ", " << py << ")");
          REQUIRE(cl.neighbours(px, py, h) == brute(x, y, px, py, h));
        }
      }
    }
  }
  // r < h is strict: at h = c a lattice point has only itself.
  const CellList cl(x, y, c);
  REQUIRE(cl.neighbours(0.5, 0.5, c).size() == 1);
  REQUIRE(cl.neighbours(0.5, 0.5, c * (1 + 1e-12)).size() == 5);
}

TEST_CASE("cell list: jittered grid, chord ranges are tight", "[cells]") {
  const Particles p = jittered_grid(0x1p-6, 3);
  const double h = 0.08;
  const CellList fine(p.x, p.y, h / 4), coarse(p.x, p.y, h);
  int64_t cand_fine = 0, cand_coarse = 0, acc = 0;
  for (std::size_t i = 0; i < p.size(); i += 7) {
    if (!p.in_omega[i]) continue;
    const auto n = fine.neighbours(p.x[i], p.y[i], h);
    REQUIRE(n == brute(p.x, p.y, p.x[i], p.y[i], h));
    REQUIRE(n == coarse.neighbours(p.x[i], p.y[i], h));
    acc += static_cast<int64_t>(n.size());
    cand_fine += fine.candidates(p.x[i], p.y[i], h);
    cand_coarse += coarse.candidates(p.x[i], p.y[i], h);
  }
  const double r_fine = double(cand_fine) / double(acc), r_coarse = double(cand_coarse) / double(acc);
  INFO("candidates per neighbour: h/4 cells " << r_fine << ", h cells " << r_coarse);
  CHECK(r_fine < 1.45);
  CHECK(r_coarse < 2.8);  // chord of ≤ 3 cells per row: below the 3×3 block's 9/π
}

TEST_CASE("cell list: gather and scatter, origin, errors", "[cells]") {
  std::vector<double> x{0.5, 0.1, 0.9, 0.1}, y{0.5, 0.2, 0.9, 0.2};
  const CellList cl(x, y, 0.25, -0.1, -0.1);
  REQUIRE(cl.x0() == -0.1);
  std::vector<double> payload{1, 2, 3, 4};
  const auto s = cl.gather(payload, -1);
  REQUIRE(s.size() == 4 + CellList::kPad);
  REQUIRE(s[4] == -1);
  REQUIRE(cl.scatter(s) == payload);
  // Duplicate points are both found, including at distance 0.
  REQUIRE(cl.neighbours(0.1, 0.2, 1e-9) == std::vector<int32_t>{1, 3});
  REQUIRE_THROWS_AS(CellList(x, y, 0.0), InputError);
  REQUIRE_THROWS_AS(CellList(x, y, -1.0), InputError);
  REQUIRE_THROWS_AS(CellList(x, y, 1e-9), InputError);  // too many cells
  REQUIRE_THROWS_AS(CellList(x, y, 0.25, 0.2, 0.0), InputError);  // point below origin
  std::vector<double> bad{0.1, NAN, 0.2, 0.3};
  REQUIRE_THROWS_AS(CellList(bad, y, 0.25), InputError);
  const CellList empty(std::vector<double>{}, std::vector<double>{}, 0.1);
  REQUIRE(empty.neighbours(0, 0, 1).empty());
}
