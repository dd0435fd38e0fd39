#include "gpm/solvers/laplacian_matrix.hpp"

#include <cstdio>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/kernel/kernel.hpp"

namespace gpm {

namespace {

constexpr double kD = 2;  // space dimension

// G(q) = w(q)/q² from the pieces divided by q² (exact for w = O(q²) at 0, no cancellation).
struct RadialG {
  std::vector<PolyPiece> pieces;
  explicit RadialG(const WeightFunction& w) : pieces(w.divided_by_power(2)) {}
  double operator()(double q) const {
    if (!(q < 1)) return 0;
    for (auto& p : pieces)
      if (q < p.r_end) return q >= p.r_begin ? p.value(q) : 0;
    return 0;
  }
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

LaplacianStorage parse_laplacian_storage(const std::string& s) {
  if (s == "auto" || s == "automatic") return LaplacianStorage::automatic;
  if (s == "assembled") return LaplacianStorage::assembled;
  if (s == "matrix_free" || s == "matrix-free") return LaplacianStorage::matrix_free;
  throw InputError("unknown storage '" + s + "'; valid: auto, assembled, matrix_free");
}

std::string laplacian_storage_name(LaplacianStorage s) {
  switch (s) {
    case LaplacianStorage::automatic: return "auto";
    case LaplacianStorage::assembled: return "assembled";
    case LaplacianStorage::matrix_free: return "matrix_free";
  }
  return "?";
}

double estimated_laplacian_nnz(std::size_t n, std::size_t n_omega, double h, const Domain& dom) {
  return static_cast<double>(n_omega) *
         (1.0 + std::numbers::pi * h * h * static_cast<double>(n) / dom.area_H());
}

DiscreteLaplacian::DiscreteLaplacian(const Particles& p, const std::vector<double>& V,
                                     const WeightFunction& w, double h,
                                     LaplacianStorage storage, double max_bytes)
    : n_(p.size()), h_(h), V_(V) {
  require_positive(h, "h");
  if (V.size() != p.size())
    throw InputError("volumes: " + std::to_string(V.size()) + " values for " +
                     std::to_string(p.size()) + " particles");
  for (std::size_t i = 0; i < V.size(); ++i)
    if (!(V[i] > 0) || !std::isfinite(V[i]))
      throw InputError("volume of particle " + std::to_string(i) + " is not positive: " +
                       std::to_string(V[i]));
  unknown_.assign(n_, -1);
  for (std::size_t i = 0; i < n_; ++i)
    if (p.in_omega[i]) {
      unknown_[i] = static_cast<int32_t>(omega_.size());
      omega_.push_back(static_cast<int32_t>(i));
    }
  if (omega_.empty()) throw InputError("no particle lies inside Omega");

  nnz_estimate_ = estimated_laplacian_nnz(n_, omega_.size(), h);
  const auto t0 = std::chrono::steady_clock::now();
  const bool fits = 12.0 * nnz_estimate_ <= max_bytes && nnz_estimate_ < 2.0e9;
  if (storage == LaplacianStorage::assembled && !fits)
    throw InputError("the assembled Laplacian needs about " +
                     std::to_string(12.0 * nnz_estimate_ / 1e9) + " GB (budget " +
                     std::to_string(max_bytes / 1e9) + " GB); use matrix_free");
  if (storage == LaplacianStorage::assembled ||
      (storage == LaplacianStorage::automatic && fits)) {
    assemble(p, w);
  } else {
    kernel_ = std::make_unique<FusedKernel>(p, V_, h_, std::vector<KernelWeight>{{w, kLap}});
    compute_diagonal(p, w);
  }
  assembly_s_ = seconds_since(t0);
  work_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n_));
}

DiscreteLaplacian::~DiscreteLaplacian() = default;
DiscreteLaplacian::DiscreteLaplacian(DiscreteLaplacian&&) noexcept = default;

// Two passes over the rows: count the neighbours, then fill values and column indices in
// place (no per-row temporary lists: the matrix is the only large allocation).
void DiscreteLaplacian::assemble(const Particles& p, const WeightFunction& w) {
  const CellList cl(p.x, p.y, h_ / 2, Domain{}.lo(), Domain{}.lo());
  const auto& index = cl.index();
  const int64_t rows = static_cast<int64_t>(omega_.size());
  std::vector<int64_t> count(rows + 1, 0);
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t k = 0; k < rows; ++k) {
    const int32_t j = omega_[k];
    int64_t c = 0;
    cl.for_each_neighbour(p.x[j], p.y[j], h_, [&](int32_t, double, double, double) { ++c; });
    count[k + 1] = c;  // the target itself is counted: it holds the diagonal
  }
  for (int64_t k = 0; k < rows; ++k) count[k + 1] += count[k];
  if (count[rows] > 2147483647LL)
    throw InputError("the assembled Laplacian has more than 2^31 non-zeros; use matrix_free");

  M_.resize(rows, static_cast<Eigen::Index>(n_));
  M_.resizeNonZeros(count[rows]);
  int* outer = M_.outerIndexPtr();
  for (int64_t k = 0; k <= rows; ++k) outer[k] = static_cast<int>(count[k]);
  int* inner = M_.innerIndexPtr();
  double* val = M_.valuePtr();
  const RadialG G(w);
  const double scale = 2 * kD / (h_ * h_ * h_ * h_);  // 2d·w(q)/(h² r²) = 2d·G(q)/h⁴
  diag_.resize(rows);
#pragma omp parallel
  {
    std::vector<std::pair<int32_t, double>> row;
#pragma omp for schedule(dynamic, 64)
    for (int64_t k = 0; k < rows; ++k) {
      const int32_t j = omega_[k];
      row.clear();
      double d = 0;
      cl.for_each_neighbour(p.x[j], p.y[j], h_, [&](int32_t slot, double, double, double r2) {
        const int32_t i = index[slot];
        if (i == j) return;
        const double c = scale * V_[i] * G(std::sqrt(r2) / h_);
        row.emplace_back(i, c);
        d -= c;
      });
      row.emplace_back(j, d);
      std::sort(row.begin(), row.end());
      int64_t o = count[k];
      for (auto& [i, c] : row) inner[o] = i, val[o] = c, ++o;
      diag_[k] = d;
    }
  }
  assembled_ = true;
}

void DiscreteLaplacian::compute_diagonal(const Particles& p, const WeightFunction& w) {
  const CellList cl(p.x, p.y, h_ / 4, Domain{}.lo(), Domain{}.lo());
  const auto& index = cl.index();
  const RadialG G(w);
  const double scale = 2 * kD / (h_ * h_ * h_ * h_);
  const int64_t rows = static_cast<int64_t>(omega_.size());
  diag_.resize(rows);
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t k = 0; k < rows; ++k) {
    const int32_t j = omega_[k];
    double d = 0;
    cl.for_each_neighbour(p.x[j], p.y[j], h_, [&](int32_t slot, double, double, double r2) {
      const int32_t i = index[slot];
      if (i != j) d -= scale * V_[i] * G(std::sqrt(r2) / h_);
    });
    diag_[k] = d;
  }
}

int64_t DiscreteLaplacian::nnz() const {
  return assembled_ ? static_cast<int64_t>(M_.nonZeros()) : static_cast<int64_t>(nnz_estimate_);
}

double DiscreteLaplacian::bytes() const {
  return assembled_ ? 12.0 * static_cast<double>(M_.nonZeros()) + 4.0 * (M_.rows() + 1) : 0.0;
}

const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& DiscreteLaplacian::matrix() const {
  if (!assembled_) throw InputError("the Laplacian is matrix-free: no assembled matrix");
  return M_;
}

void DiscreteLaplacian::apply_full(const Eigen::VectorXd& v, Eigen::VectorXd& y) const {
  const int64_t rows = static_cast<int64_t>(omega_.size());
  if (v.size() != static_cast<Eigen::Index>(n_))
    throw InputError("apply_full: vector of size " + std::to_string(v.size()) + ", expected " +
                     std::to_string(n_));
  y.resize(rows);
  if (assembled_) {
    const int* outer = M_.outerIndexPtr();
    const int* inner = M_.innerIndexPtr();
    const double* val = M_.valuePtr();
    const double* x = v.data();
    // Threads only pay off for large products: a parallel region costs microseconds (and
    // much more on a loaded machine), a row of a small matrix nanoseconds.
    const bool threaded = M_.nonZeros() > 2000000;
#pragma omp parallel for schedule(static, 256) if (threaded)
    for (int64_t k = 0; k < rows; ++k) {
      double s = 0;
      for (int o = outer[k]; o < outer[k + 1]; ++o) s += val[o] * x[inner[o]];
      y[k] = s;
    }
    return;
  }
  // Matrix-free: the fused kernel's Δ_h at the particles in Ω.
  const std::vector<double> field(v.data(), v.data() + v.size());
  const KernelResult r = kernel_->apply(omega_, std::vector<std::vector<double>>{field});
  const auto lap = r.laplacian(0, 0);
  for (int64_t k = 0; k < rows; ++k) y[k] = lap[k];
}

void DiscreteLaplacian::apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  work_.setZero();
  for (std::size_t k = 0; k < omega_.size(); ++k) work_[omega_[k]] = x[static_cast<Eigen::Index>(k)];
  apply_full(work_, y);
}

Eigen::VectorXd DiscreteLaplacian::restrict_to_omega(const std::vector<double>& full) const {
  Eigen::VectorXd x(static_cast<Eigen::Index>(omega_.size()));
  for (std::size_t k = 0; k < omega_.size(); ++k) x[static_cast<Eigen::Index>(k)] = full[omega_[k]];
  return x;
}

Eigen::VectorXd DiscreteLaplacian::extend(const Eigen::VectorXd& x,
                                          const std::vector<double>& outside) const {
  Eigen::VectorXd v(static_cast<Eigen::Index>(n_));
  for (std::size_t i = 0; i < n_; ++i)
    v[static_cast<Eigen::Index>(i)] = unknown_[i] >= 0 ? x[unknown_[i]] : outside[i];
  return v;
}

void cg_check_true_residual(CgResult& res, const Eigen::VectorXd& b, const Eigen::VectorXd& Sx,
                            double tol, const std::string& what) {
  const double true_rel = (b - Sx).norm() / b.norm();
  if (!(true_rel <= std::max(1e3 * tol, 1e-10)))
    throw NumericalError(what + ": conjugate gradients stopped on a recursive residual of " +
                         cg_number(res.recursive_rel_residual) +
                         " but the true residual ||b - Sx||/||b|| is " + cg_number(true_rel) +
                         " after " + std::to_string(res.iterations) +
                         " iterations (singular or indefinite system?)");
  res.rel_residual = true_rel;
}

std::string cg_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace gpm
