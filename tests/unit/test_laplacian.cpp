// The assembled Laplacian (the symmetric half, laplacian_matrix.hpp) against a brute-force
// double loop over all particle pairs, thesis (1.4):
//   (M v)_j = 2d Σ_{0<r<h} V_i (v_i − v_j) w(r/h)/(h² r²),   j in Ω.
// Uneven volumes, so that the half's volume factor is exercised; a level large enough for
// the threaded product (> 10⁶ stored entries) and a small one for the serial product.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

struct Setting {
  Particles p;
  std::vector<double> V, v;
  double h;
};

Setting setting(int level, double h) {
  Setting s{jittered_grid(std::ldexp(1.0, -level), 3), {}, {}, h};
  const double dx = std::ldexp(1.0, -level);
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    s.V.push_back(dx * dx * (0.8 + 0.4 * std::fabs(std::sin(7.0 * static_cast<double>(i)))));
    s.v.push_back(std::cos(3 * s.p.x[i]) * std::exp(s.p.y[i]) + 0.5);
  }
  return s;
}

// (M v)_j for every j in Ω, over all pairs.
std::vector<double> brute_force(const Setting& s, const WeightFunction& w) {
  std::vector<double> y;
  const double h = s.h;
  for (std::size_t j = 0; j < s.p.size(); ++j) {
    if (!s.p.in_omega[j]) continue;
    double acc = 0;
    for (std::size_t i = 0; i < s.p.size(); ++i) {
      const double dx = s.p.x[i] - s.p.x[j], dy = s.p.y[i] - s.p.y[j];
      const double r = std::sqrt(dx * dx + dy * dy);
      if (i == j || r >= h) continue;
      acc += s.V[i] * (s.v[i] - s.v[j]) * w.value(r / h) / (h * h * r * r);
    }
    y.push_back(4 * acc);
  }
  return y;
}

double max_rel_diff(const Eigen::VectorXd& a, const std::vector<double>& b) {
  double d = 0, m = 0;
  for (std::size_t k = 0; k < b.size(); ++k)
    d = std::max(d, std::fabs(a[static_cast<Eigen::Index>(k)] - b[k])), m = std::max(m, std::fabs(b[k]));
  return d / m;
}

}  // namespace

TEST_CASE("assembled Laplacian (symmetric half) equals the brute-force pair sum", "[laplacian]") {
  const WeightFunction& w = weight("quartic_polynomial");
  for (auto [level, h] : {std::pair{5, 0.2}, std::pair{7, 0.12}}) {
    INFO("level 2^-" << level << ", h = " << h);
    const Setting s = setting(level, h);
    const DiscreteLaplacian L(s.p, s.V, w, h, LaplacianStorage::assembled);
    const std::vector<double> ref = brute_force(s, w);
    REQUIRE(ref.size() == L.n_unknowns());
    // The threaded product only above 10⁶ stored entries: the finer level takes it.
    CHECK((L.stored_entries() > 1000000) == (level == 7));

    // apply_full: all columns, the boundary ones included.
    Eigen::VectorXd full(static_cast<Eigen::Index>(s.v.size())), y;
    for (std::size_t i = 0; i < s.v.size(); ++i) full[static_cast<Eigen::Index>(i)] = s.v[i];
    L.apply_full(full, y);
    CHECK(max_rel_diff(y, ref) < 1e-12);

    // apply: the Ω × Ω block, v = 0 outside Ω; the matrix-free kernel is the reference.
    const Eigen::VectorXd x = L.restrict_to_omega(s.v);
    const DiscreteLaplacian F(s.p, s.V, w, h, LaplacianStorage::matrix_free);
    Eigen::VectorXd ya, yf;
    L.apply(x, ya);
    F.apply(x, yf);
    CHECK((ya - yf).lpNorm<Eigen::Infinity>() / yf.lpNorm<Eigen::Infinity>() < 1e-12);

    // The full matrix rebuilt from the half: the same product, and nnz() its count.
    const auto& M = L.matrix();
    CHECK(M.nonZeros() == L.nnz());
    const Eigen::VectorXd ym = M * full;
    CHECK(max_rel_diff(ym, ref) < 1e-12);
    // The full storage (the one before the half): the same sums in another order.
    const DiscreteLaplacian Full(s.p, s.V, w, h, LaplacianStorage::full);
    CHECK(Full.nnz() == L.nnz());
    Eigen::VectorXd y_full;
    Full.apply_full(full, y_full);
    CHECK(max_rel_diff(y_full, ref) < 1e-12);
    Full.apply(x, yf);
    CHECK((ya - yf).lpNorm<Eigen::Infinity>() / yf.lpNorm<Eigen::Infinity>() < 1e-13);
    // Stored entries per non-zero: about half, within the budget rule's 0.6.
    const double ratio = static_cast<double>(L.stored_entries()) / static_cast<double>(L.nnz());
    CHECK(ratio > 0.5);
    CHECK(ratio < 0.6);
  }
}

TEST_CASE("assembled Laplacian: the same product for any number of threads", "[laplacian]") {
  const Setting s = setting(7, 0.12);
  const DiscreteLaplacian L(s.p, s.V, weight("piecewise_cubic_polynomial"), s.h,
                            LaplacianStorage::assembled);
  const Eigen::VectorXd x = L.restrict_to_omega(s.v);
  const int saved = omp_get_max_threads();
  Eigen::VectorXd y1, y2, y3;
  omp_set_num_threads(1);
  L.apply(x, y1);
  omp_set_num_threads(2);
  L.apply(x, y2);
  omp_set_num_threads(3);
  L.apply(x, y3);
  omp_set_num_threads(saved);
  CHECK((y1.array() == y2.array()).all());
  CHECK((y1.array() == y3.array()).all());
}

// The block product: every column of M·X equals the single product of that column, bit for
// bit, for the half (serial and threaded sizes) and the full CSR storage, block widths 1-12
// (vectors of four, padded; 20 in two passes), and 1, 2 or 3 threads.
TEST_CASE("block product: each column is the single product, bit for bit", "[laplacian][block]") {
  const WeightFunction& w = weight("quartic_polynomial");
  const int saved = omp_get_max_threads();
  for (auto [level, h] : {std::pair{5, 0.2}, std::pair{7, 0.12}})
    for (auto storage : {LaplacianStorage::assembled, LaplacianStorage::full}) {
      const Setting s = setting(level, h);
      const DiscreteLaplacian L(s.p, s.V, w, h, storage);
      const Eigen::VectorXd x = L.restrict_to_omega(s.v);
      const Eigen::Index n = x.size();
      for (int width : {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 20}) {
        DiscreteLaplacian::RowBlock X(n, width), Y;
        for (int c = 0; c < width; ++c)
          for (Eigen::Index k = 0; k < n; ++k)
            X(k, c) = x[k] * (1 + 0.1 * c) + std::sin(0.37 * static_cast<double>(k * (c + 1)));
        for (int threads : {1, 2, 3}) {
          INFO("level 2^-" << level << ", " << laplacian_storage_name(storage) << ", width "
                           << width << ", " << threads << " threads");
          omp_set_num_threads(threads);
          L.apply_block(X, Y);
          REQUIRE(Y.rows() == n);
          REQUIRE(Y.cols() == width);
          for (int c = 0; c < width; ++c) {
            Eigen::VectorXd y;
            L.apply(X.col(c), y);
            CHECK((Y.col(c).array() == y.array()).all());
          }
        }
      }
    }
  omp_set_num_threads(saved);
}

TEST_CASE("block product, matrix-free: column by column", "[laplacian][block]") {
  const Setting s = setting(5, 0.2);
  const DiscreteLaplacian L(s.p, s.V, weight("piecewise_cubic_polynomial"), s.h,
                            LaplacianStorage::matrix_free);
  const Eigen::VectorXd x = L.restrict_to_omega(s.v);
  DiscreteLaplacian::RowBlock X(x.size(), 3), Y;
  for (int c = 0; c < 3; ++c) X.col(c) = x * (c + 1.0);
  L.apply_block(X, Y);
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd y;
    L.apply(X.col(c), y);
    CHECK((Y.col(c).array() == y.array()).all());
  }
}

// Volumes per column: a column with other volumes V' equals the apply() of the Laplacian
// built with V', bit for bit (the diagonal summed in its assembly's order).  Uniform V'
// as in the heat readings (lattice |Ω_H|/N against cell Δx²), and uneven ones.
TEST_CASE("block product with volumes per column equals the Laplacian of those volumes",
          "[laplacian][block]") {
  const WeightFunction& w = weight("quartic_polynomial");
  for (auto [level, h] : {std::pair{5, 0.2}, std::pair{7, 0.12}}) {
    const Setting s = setting(level, h);
    const double dx = std::ldexp(1.0, -level);
    const std::vector<double> lattice(s.p.size(),
                                      Domain{}.area_H() / static_cast<double>(s.p.size()));
    const std::vector<double> cell(s.p.size(), dx * dx);
    const DiscreteLaplacian L(s.p, lattice, w, h, LaplacianStorage::assembled);
    const std::vector<std::vector<double>> others = {cell, s.V};
    std::vector<DiscreteLaplacian::Volumes> vols;
    for (const auto& V : others) vols.push_back(L.volumes_for(s.p, w, V));
    // Its own volumes give its own diagonal.
    CHECK((L.volumes_for(s.p, w, lattice).diagonal.array() == L.diagonal().array()).all());
    const Eigen::VectorXd x = L.restrict_to_omega(s.v);
    for (int width : {1, 3, 6}) {
      DiscreteLaplacian::RowBlock X(x.size(), width), Y;
      std::vector<const DiscreteLaplacian::Volumes*> per_column;
      for (int c = 0; c < width; ++c) {
        X.col(c) = x.array() * (1 + 0.1 * c);
        per_column.push_back(c % 3 == 2 ? nullptr : &vols[static_cast<std::size_t>(c % 3)]);
      }
      L.apply_block(X, Y, per_column);
      for (int c = 0; c < width; ++c) {
        INFO("level 2^-" << level << ", width " << width << ", column " << c);
        const auto& V = c % 3 == 2 ? lattice : others[static_cast<std::size_t>(c % 3)];
        const DiscreteLaplacian Lv(s.p, V, w, h, LaplacianStorage::assembled);
        Eigen::VectorXd y;
        Lv.apply(X.col(c), y);
        CHECK((Y.col(c).array() == y.array()).all());
      }
    }
  }
}

TEST_CASE("CG: p^T S p <= 0 at rounding level is an unreachable tolerance, above it an indefinite matrix",
          "[laplacian][cg]") {
  Eigen::VectorXd b(1), x = Eigen::VectorXd::Zero(1), q = Eigen::VectorXd::Zero(1);
  b[0] = 1;
  Eigen::VectorXd at_rounding(1), far(1);
  at_rounding[0] = 1 - 1e-14;  // the residual b - Sx0 is 1e-14 of b
  far[0] = 0.5;
  CgState stalled(b, at_rounding, 1e-16, 100, "Poisson solve");
  CHECK_THROWS_WITH(stalled.update(x, q), Catch::Contains("out of reach in double precision"));
  CgState indefinite(b, far, 1e-10, 100, "Poisson solve");
  CHECK_THROWS_WITH(indefinite.update(x, q), Catch::Contains("not positive definite"));
  // A unit's computation names the unit in its failure.
  CHECK_THROWS_WITH(naming_unit("h10, quartic_polynomial, level 9",
                                [&] { return indefinite.update(x, q), 0; }),
                    Catch::StartsWith("h10, quartic_polynomial, level 9: Poisson solve:"));
}
