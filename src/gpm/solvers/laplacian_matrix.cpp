#include "gpm/solvers/laplacian_matrix.hpp"

#include <cstdio>
#include <cstring>

#include <omp.h>
#ifdef __FMA__
#include <immintrin.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <type_traits>
#include <utility>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/kernel/device_pass.hpp"
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

// A row's sum over its stored entries in an order fixed by the source, not by the compiler
// (an `omp simd reduction` leaves it to the vectorizer): entry j of the row goes to partial
// sum j mod kLanes, and the partial sums are added pairwise.  Each term is an explicit fma
// (contraction is otherwise the compiler's choice, which differed between the full
// storage's single and block loops).  The single and the block product both sum this way,
// so each column of the block is the single product bit for bit.
constexpr int kLanes = 8;
inline double lane_total(const double* a, std::ptrdiff_t stride) {
  return ((a[0] + a[stride]) + (a[2 * stride] + a[3 * stride])) +
         ((a[4 * stride] + a[5 * stride]) + (a[6 * stride] + a[7 * stride]));
}

// d − sv·g rounded once: a term of the diagonal, spelled out so that the assembly and
// diagonal_with() (volumes_for) sum it identically; left to the compiler, one fused it and
// the other did not.
inline double diagonal_term(double d, double sv, double g) { return std::fma(-sv, g, d); }

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

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
  const double need = (storage == LaplacianStorage::full ? 12.0 : kAssembledBytesPerNonzero) *
                      nnz_estimate_;
  const bool fits = need <= max_bytes && (storage != LaplacianStorage::full || nnz_estimate_ < 2e9);
  if ((storage == LaplacianStorage::assembled || storage == LaplacianStorage::full) && !fits)
    throw InputError("the assembled Laplacian needs about " + std::to_string(need / 1e9) +
                     " GB (budget " +
                     std::to_string(max_bytes / 1e9) + " GB); use matrix_free");
  if (storage == LaplacianStorage::full) {
    assemble_full(p, w);
  } else if (storage == LaplacianStorage::assembled ||
             (storage == LaplacianStorage::automatic && fits)) {
    assemble(p, w);
  } else {
    if (using_device())
      device_ = make_device_pass(p, V_, h_, std::vector<KernelWeight>{{w, kLap}});
    else
      kernel_ = std::make_unique<FusedKernel>(p, V_, h_, std::vector<KernelWeight>{{w, kLap}});
    diag_ = diagonal_with(p, w, V_, h_ / 4);
  }
  assembly_s_ = seconds_since(t0);
  work_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n_));
}

DiscreteLaplacian::~DiscreteLaplacian() = default;
DiscreteLaplacian::DiscreteLaplacian(DiscreteLaplacian&&) noexcept = default;

// Two passes over the rows: count the entries of each part, then fill values and column
// indices in place (no per-row lists kept: the storage is the only large allocation).  The
// diagonal is summed as before, over every neighbour in the cell list's order.
void DiscreteLaplacian::assemble(const Particles& p, const WeightFunction& w) {
  const CellList cl(p.x, p.y, h_ / 2, Domain{}.lo(), Domain{}.lo());
  const auto& index = cl.index();
  const int64_t rows = static_cast<int64_t>(omega_.size());
  std::vector<int64_t> up(rows + 1, 0), bd(rows + 1, 0), all(rows, 0);
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t k = 0; k < rows; ++k) {
    const int32_t j = omega_[k];
    int64_t cu = 0, cb = 0, ca = 0;
    cl.for_each_neighbour(p.x[j], p.y[j], h_, [&](int32_t slot, double, double, double) {
      const int32_t i = index[slot];
      ++ca;  // the target itself is counted: it holds the diagonal
      if (i == j) return;
      if (unknown_[i] < 0) ++cb;
      else if (i > j) ++cu;
    });
    up[k + 1] = cu, bd[k + 1] = cb, all[k] = ca;
  }
  nnz_ = 0;
  for (int64_t k = 0; k < rows; ++k) up[k + 1] += up[k], bd[k + 1] += bd[k], nnz_ += all[k];
  up_ptr_ = up, b_ptr_ = bd;
  up_col_.resize(static_cast<std::size_t>(up[rows]));
  up_val_.resize(up_col_.size());
  b_col_.resize(static_cast<std::size_t>(bd[rows]));
  b_val_.resize(b_col_.size());

  const RadialG G(w);
  const double scale = 2 * kD / (h_ * h_ * h_ * h_);  // 2d·w(q)/(h² r²) = 2d·G(q)/h⁴
  diag_.resize(rows);
#pragma omp parallel
  {
    std::vector<std::pair<int32_t, double>> row_up, row_b;
#pragma omp for schedule(dynamic, 64)
    for (int64_t k = 0; k < rows; ++k) {
      const int32_t j = omega_[k];
      row_up.clear(), row_b.clear();
      double d = 0;
      cl.for_each_neighbour(p.x[j], p.y[j], h_, [&](int32_t slot, double, double, double r2) {
        const int32_t i = index[slot];
        if (i == j) return;
        const double g = G(std::sqrt(r2) / h_);
        const double c = scale * V_[i] * g;
        d = diagonal_term(d, scale * V_[i], g);
        if (unknown_[i] < 0) row_b.emplace_back(i, c);
        else if (i > j) row_up.emplace_back(unknown_[i], scale * g);
      });
      std::sort(row_up.begin(), row_up.end());
      std::sort(row_b.begin(), row_b.end());
      int64_t o = up[k];
      for (auto& [l, c] : row_up) up_col_[o] = l, up_val_[o] = c, ++o;
      o = bd[k];
      for (auto& [i, c] : row_b) b_col_[o] = i, b_val_[o] = c, ++o;
      diag_[k] = d;
    }
  }
  vol_.resize(rows);
  for (int64_t k = 0; k < rows; ++k) vol_[k] = V_[omega_[k]];
  plan_blocks();
  assembled_ = true;
}

// The full Ω × all matrix (LaplacianStorage::full), as the solvers stored it before the half:
// two passes, count then fill in place; each row sorted by column.
void DiscreteLaplacian::assemble_full(const Particles& p, const WeightFunction& w) {
  const CellList cl(p.x, p.y, h_ / 2, Domain{}.lo(), Domain{}.lo());
  const auto& index = cl.index();
  const int64_t rows = static_cast<int64_t>(omega_.size());
  std::vector<int64_t> count(rows + 1, 0);
#pragma omp parallel for schedule(dynamic, 64)
  for (int64_t k = 0; k < rows; ++k) {
    const int32_t j = omega_[k];
    int64_t c = 0;
    cl.for_each_neighbour(p.x[j], p.y[j], h_, [&](int32_t, double, double, double) { ++c; });
    count[k + 1] = c;
  }
  for (int64_t k = 0; k < rows; ++k) count[k + 1] += count[k];
  nnz_ = count[rows];
  full_ = std::make_unique<Eigen::SparseMatrix<double, Eigen::RowMajor, int>>(
      rows, static_cast<Eigen::Index>(n_));
  auto& M = *full_;
  M.resizeNonZeros(nnz_);
  int* outer = M.outerIndexPtr();
  for (int64_t k = 0; k <= rows; ++k) outer[k] = static_cast<int>(count[k]);
  int* inner = M.innerIndexPtr();
  double* val = M.valuePtr();
  const RadialG G(w);
  const double scale = 2 * kD / (h_ * h_ * h_ * h_);
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
  assembled_ = full_storage_ = true;
}

// Fixed blocks of about equal stored entries, their count set by the matrix alone (never by
// the threads): at most 32, at least 256 rows each.  A block's partial sums reach from its
// first row to the largest column any of its rows touches (made non-decreasing over the
// blocks, so that the blocks covering an unknown are consecutive).
void DiscreteLaplacian::plan_blocks() {
  const int64_t rows = static_cast<int64_t>(omega_.size());
  const int64_t blocks = std::clamp<int64_t>(rows / 256, 1, 32);
  const double per_block = static_cast<double>(up_ptr_[rows]) / static_cast<double>(blocks);
  block_row_.assign(1, 0);
  for (int64_t k = 0; k < rows; ++k)
    if (static_cast<int64_t>(block_row_.size()) < blocks &&
        static_cast<double>(up_ptr_[k + 1]) >= per_block * static_cast<double>(block_row_.size()) &&
        k + 1 < rows)
      block_row_.push_back(k + 1);
  block_row_.push_back(rows);
  const std::size_t nb = block_row_.size() - 1;
  block_reach_.assign(nb, 0);
  block_offset_.assign(nb + 1, 0);
  int64_t reach = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    reach = std::max(reach, block_row_[b + 1] - 1);
    for (int64_t o = up_ptr_[block_row_[b]]; o < up_ptr_[block_row_[b + 1]]; ++o)
      reach = std::max<int64_t>(reach, up_col_[o]);
    block_reach_[b] = reach;
    block_offset_[b + 1] = block_offset_[b] + (reach - block_row_[b] + 1);
  }
  part_.assign(static_cast<std::size_t>(block_offset_[nb]), 0.0);
  first_block_.assign(static_cast<std::size_t>(rows), 0);
  std::size_t b = 0;
  for (int64_t k = 0; k < rows; ++k) {
    while (block_reach_[b] < k) ++b;
    first_block_[k] = static_cast<int32_t>(b);
  }
}

Eigen::VectorXd DiscreteLaplacian::diagonal_with(const Particles& p, const WeightFunction& w,
                                                 const std::vector<double>& V, double cell,
                                                 std::vector<double>* boundary) const {
  const CellList cl(p.x, p.y, cell, Domain{}.lo(), Domain{}.lo());
  const auto& index = cl.index();
  const RadialG G(w);
  const double scale = 2 * kD / (h_ * h_ * h_ * h_);
  const int64_t rows = static_cast<int64_t>(omega_.size());
  Eigen::VectorXd diag(rows);
  if (boundary) boundary->assign(b_col_.size(), 0.0);
#pragma omp parallel
  {
    std::vector<std::pair<int32_t, double>> row_b;
#pragma omp for schedule(dynamic, 64)
    for (int64_t k = 0; k < rows; ++k) {
      const int32_t j = omega_[k];
      double d = 0;
      row_b.clear();
      cl.for_each_neighbour(p.x[j], p.y[j], h_, [&](int32_t slot, double, double, double r2) {
        const int32_t i = index[slot];
        if (i == j) return;
        const double g = G(std::sqrt(r2) / h_);
        d = diagonal_term(d, scale * V[i], g);
        if (boundary && unknown_[i] < 0) row_b.emplace_back(i, scale * V[i] * g);  // as assemble()
      });
      diag[k] = d;
      if (!boundary) continue;
      // assemble() sorts the row's boundary entries by particle: the same order here.
      std::sort(row_b.begin(), row_b.end());
      int64_t o = b_ptr_[k];
      for (auto& [i, c] : row_b) (*boundary)[static_cast<std::size_t>(o++)] = c;
    }
  }
  return diag;
}

DiscreteLaplacian::Volumes DiscreteLaplacian::volumes_for(const Particles& p,
                                                          const WeightFunction& w,
                                                          const std::vector<double>& V) const {
  if (!assembled_ || full_storage_)
    throw InputError("volumes_for: only for the assembled (half) storage");
  if (V.size() != n_)
    throw InputError("volumes_for: " + std::to_string(V.size()) + " volumes for " +
                     std::to_string(n_) + " particles");
  Volumes v;
  v.at_unknowns.resize(static_cast<Eigen::Index>(omega_.size()));
  for (std::size_t k = 0; k < omega_.size(); ++k)
    v.at_unknowns[static_cast<Eigen::Index>(k)] = V[omega_[k]];
  v.diagonal = diagonal_with(p, w, V, h_ / 2, &v.boundary);  // the cells of assemble()
  v.all = V;
  return v;
}

int64_t DiscreteLaplacian::nnz() const {
  return assembled_ ? nnz_ : static_cast<int64_t>(nnz_estimate_);
}

int64_t DiscreteLaplacian::stored_entries() const {
  if (full_storage_) return nnz_;
  return assembled_ ? static_cast<int64_t>(up_col_.size() + b_col_.size() + omega_.size()) : 0;
}

double DiscreteLaplacian::bytes() const {
  if (!assembled_) return 0.0;
  const double rows = static_cast<double>(omega_.size());
  if (full_storage_) return 12.0 * static_cast<double>(nnz_) + 4.0 * (rows + 1);
  return 12.0 * static_cast<double>(up_col_.size() + b_col_.size()) + 16.0 * (rows + 1) +
         16.0 * rows + 8.0 * static_cast<double>(part_.size()) + 4.0 * rows;
}

const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& DiscreteLaplacian::matrix() const {
  if (!assembled_) throw InputError("the Laplacian is matrix-free: no assembled matrix");
  if (!full_) {
    // M_kl = K_kl V_l and M_lk = K_kl V_k from the half; the Ω × B block as stored.
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(nnz_));
    const int64_t rows = static_cast<int64_t>(omega_.size());
    for (int64_t k = 0; k < rows; ++k) {
      t.emplace_back(static_cast<int>(k), omega_[k], diag_[k]);
      for (int64_t o = up_ptr_[k]; o < up_ptr_[k + 1]; ++o) {
        const int32_t l = up_col_[o];
        t.emplace_back(static_cast<int>(k), omega_[l], up_val_[o] * vol_[l]);
        t.emplace_back(l, omega_[k], up_val_[o] * vol_[k]);
      }
      for (int64_t o = b_ptr_[k]; o < b_ptr_[k + 1]; ++o)
        t.emplace_back(static_cast<int>(k), b_col_[o], b_val_[o]);
    }
    full_ = std::make_unique<Eigen::SparseMatrix<double, Eigen::RowMajor, int>>(
        rows, static_cast<Eigen::Index>(n_));
    full_->setFromTriplets(t.begin(), t.end());
  }
  return *full_;
}

// y = M_ΩΩ x from the half: every stored K_kl gives K_kl z_l to row k and K_kl z_k to row l
// (z = V x).  Block b adds both into its own partial sums; a row's total is its diagonal
// term plus the partial sums of the blocks that reach it, in block order (sum_blocks).
void DiscreteLaplacian::apply_assembled(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  const int64_t rows = static_cast<int64_t>(omega_.size());
  z_ = (vol_.array() * x.array()).matrix();
  const double* z = z_.data();
  const int64_t* ptr = up_ptr_.data();
  const int32_t* col = up_col_.data();
  const double* val = up_val_.data();
  const int64_t nb = static_cast<int64_t>(block_reach_.size());
#pragma omp parallel for schedule(dynamic, 1) if (threaded())
  for (int64_t b = 0; b < nb; ++b) {
    double* t = part_.data() + block_offset_[b] - block_row_[b];  // t[k], k ∈ [row, reach]
    std::fill(t + block_row_[b], t + block_reach_[b] + 1, 0.0);
    for (int64_t k = block_row_[b]; k < block_row_[b + 1]; ++k) {
      const double zk = z[k];
      alignas(64) double acc[kLanes] = {};
      // A row's columns are distinct, so its scatter into t has no conflicts: vectors of
      // gathers and scatters (AVX-512), one lane per partial sum.
      auto entry = [&](int64_t o, int q) {
        const int32_t l = col[o];
        acc[q] = std::fma(val[o], z[l], acc[q]);
        t[l] = std::fma(val[o], zk, t[l]);
      };
      int64_t o = ptr[k];
      for (; o + kLanes <= ptr[k + 1]; o += kLanes) {
#pragma omp simd
        for (int q = 0; q < kLanes; ++q) entry(o + q, q);
      }
      for (int q = 0; o + q < ptr[k + 1]; ++q) entry(o + q, q);
      t[k] += lane_total(acc, 1);
    }
  }
  y.resize(rows);
  const double* diag = diag_.data();
  sum_blocks(x.data(), part_.data(), 1, 1, &diag, y.data());
}

// Four doubles as one value (the GCC/Clang vector extension): the block's columns go in
// groups of four, each loaded, multiplied and added as one vector.
typedef double Quad __attribute__((vector_size(32)));

// v·z + a rounded once, lane by lane: the single product's std::fma.  Spelled out, since
// the compiler's contraction of v * z + a is a tuning choice (GCC for Zen leaves a
// loop-carried chain unfused: the full storage's loops came out different).
inline Quad fma4(double v, Quad z, Quad a) {
#ifdef __FMA__
  return _mm256_fmadd_pd(_mm256_set1_pd(v), z, a);
#else
  return Quad{std::fma(v, z[0], a[0]), std::fma(v, z[1], a[1]), std::fma(v, z[2], a[2]),
              std::fma(v, z[3], a[3])};
#endif
}

// Row k of the block product, P = 4W interleaved columns: entry j of the row adds its terms
// to lane j mod kLanes of the row sums and scatters the transposed terms into t, as the
// single product does per column.  The lanes go to sums[q·P + c].
template <int W>
void block_row(int64_t begin, int64_t end, const int32_t* col, const double* val,
               const double* z, const double* zk, double* t, double* sums) {
  constexpr int P = 4 * W;
  Quad a[kLanes][W] = {}, kq[W];
  std::memcpy(kq, zk, sizeof kq);
  auto entry = [&](int64_t o, int q) {
    const double v = val[o];
    const int64_t l = static_cast<int64_t>(col[o]) * P;
    for (int w = 0; w < W; ++w) {
      Quad zl, tl;
      std::memcpy(&zl, z + l + 4 * w, sizeof zl);
      std::memcpy(&tl, t + l + 4 * w, sizeof tl);
      a[q][w] = fma4(v, zl, a[q][w]);
      tl = fma4(v, kq[w], tl);
      std::memcpy(t + l + 4 * w, &tl, sizeof tl);
    }
  };
  int64_t o = begin;
  for (; o + kLanes <= end; o += kLanes) {
#pragma GCC unroll 8
    for (int q = 0; q < kLanes; ++q) entry(o + q, q);
  }
  for (int q = 0; o + q < end; ++q) entry(o + q, q);
  std::memcpy(sums, a, sizeof a);
}

// Y = M_ΩΩ X for s ≤ P = 4W columns, the loop of apply_assembled on interleaved rows of P
// values (the columns past s are zero): per entry the values of z_l and of t_l are adjacent.
template <int W>
void DiscreteLaplacian::apply_assembled_block(const RowBlock& X, RowBlock& Y,
                                              const std::vector<const Volumes*>& per_column) const {
  constexpr int P = 4 * W;
  const int64_t rows = static_cast<int64_t>(omega_.size());
  const int s = static_cast<int>(X.cols());
  z_block_.setZero(rows, P);
  std::vector<const double*> diag(static_cast<std::size_t>(s), diag_.data());
  for (int c = 0; c < s; ++c) {
    const Volumes* v = per_column.empty() ? nullptr : per_column[static_cast<std::size_t>(c)];
    z_block_.col(c) = (v ? v->at_unknowns : vol_).cwiseProduct(X.col(c));
    if (v) diag[static_cast<std::size_t>(c)] = v->diagonal.data();
  }
  const double* z = z_block_.data();
  const int64_t nb = static_cast<int64_t>(block_reach_.size());
  part_block_.resize(part_.size() * P);
#pragma omp parallel if (threaded())
  {
    alignas(64) double sums[kLanes * P];
#pragma omp for schedule(dynamic, 1)
    for (int64_t b = 0; b < nb; ++b) {
      double* t = part_block_.data() + (block_offset_[b] - block_row_[b]) * P;
      std::fill(t + block_row_[b] * P, t + (block_reach_[b] + 1) * P, 0.0);
      for (int64_t k = block_row_[b]; k < block_row_[b + 1]; ++k) {
        block_row<W>(up_ptr_[k], up_ptr_[k + 1], up_col_.data(), up_val_.data(), z, z + k * P,
                     t, sums);
        for (int c = 0; c < s; ++c) t[k * P + c] += lane_total(sums + c, P);
      }
    }
  }
  Y.resize(rows, s);
  sum_blocks(X.data(), part_block_.data(), s, P, diag.data(), Y.data());
}

// y_k = M_kk x_k plus the partial sums of the blocks that reach row k, in block order, for
// s interleaved columns (t's rows hold tw ≥ s values).
void DiscreteLaplacian::sum_blocks(const double* x, const double* t, int s, int tw,
                                   const double* const* diag, double* y) const {
  const int64_t rows = static_cast<int64_t>(omega_.size());
  const int64_t nb = static_cast<int64_t>(block_reach_.size());
#pragma omp parallel for schedule(static, 1024) if (threaded())
  for (int64_t k = 0; k < rows; ++k)
    for (int c = 0; c < s; ++c) {
      double sum = diag[c][k] * x[k * s + c];
      for (int64_t b = first_block_[k]; b < nb && block_row_[b] <= k; ++b)
        sum += t[(block_offset_[b] + k - block_row_[b]) * tw + c];
      y[k * s + c] = sum;
    }
}

// The full CSR storage: row sums in stored order, as apply_full, P = 4W columns side by
// side (X over all particles, zero outside Ω and past column s).
template <int W>
void DiscreteLaplacian::apply_full_block(const RowBlock& X, RowBlock& Y) const {
  constexpr int P = 4 * W;
  const int64_t rows = static_cast<int64_t>(omega_.size());
  const Eigen::Index s = X.cols();
  work_block_.setZero(static_cast<Eigen::Index>(n_), P);
  for (int64_t k = 0; k < rows; ++k) work_block_.row(omega_[k]).head(s) = X.row(k);
  Y.resize(rows, s);
  const int* outer = full_->outerIndexPtr();
  const int* inner = full_->innerIndexPtr();
  const double* val = full_->valuePtr();
  const double* x = work_block_.data();
#pragma omp parallel for schedule(static, 256) if (threaded())
  for (int64_t k = 0; k < rows; ++k) {
    Quad a[W] = {};
    for (int o = outer[k]; o < outer[k + 1]; ++o) {
      const double v = val[o];
      const double* xl = x + static_cast<int64_t>(inner[o]) * P;
      for (int w = 0; w < W; ++w) {
        Quad xq;
        std::memcpy(&xq, xl + 4 * w, sizeof xq);
        a[w] = fma4(v, xq, a[w]);
      }
    }
    double sums[P];
    std::memcpy(sums, a, sizeof a);
    for (Eigen::Index c = 0; c < s; ++c) Y(k, c) = sums[c];
  }
}

namespace {

// f(std::integral_constant<int, W>) for the W = ⌈s/4⌉ vectors of four that hold s ≤ 16
// columns: the block kernels' width fixed at compile time.
template <class F>
void with_quads(Eigen::Index s, F&& f) {
  switch ((s + 3) / 4) {
    case 1: return f(std::integral_constant<int, 1>{});
    case 2: return f(std::integral_constant<int, 2>{});
    case 3: return f(std::integral_constant<int, 3>{});
    default: return f(std::integral_constant<int, 4>{});
  }
}

}  // namespace

void DiscreteLaplacian::apply_block(const RowBlock& X, RowBlock& Y) const {
  apply_block(X, Y, {});
}

void DiscreteLaplacian::apply_block(const RowBlock& X, RowBlock& Y,
                                    const std::vector<const Volumes*>& per_column) const {
  if (X.rows() != static_cast<Eigen::Index>(omega_.size()))
    throw InputError("apply_block: " + std::to_string(X.rows()) + " rows, expected " +
                     std::to_string(omega_.size()));
  if (!per_column.empty() && (!assembled_ || full_storage_ ||
                              per_column.size() != static_cast<std::size_t>(X.cols())))
    throw InputError("apply_block: volumes per column need the assembled (half) storage and "
                     "one entry per column");
  if ((X.cols() == 1 && per_column.empty()) || !assembled_) {
    // One column: the single product itself.  Matrix-free: no shared pass (the kernel
    // recomputes the weights on every product anyway), column by column.
    Y.resize(X.rows(), X.cols());
    Eigen::VectorXd x, y;
    for (Eigen::Index c = 0; c < X.cols(); ++c) {
      x = X.col(c);
      apply(x, y);
      Y.col(c) = y;
    }
    return;
  }
  // Up to 16 columns in one pass, in vectors of four; a wider block in passes of 16.
  constexpr Eigen::Index kMaxPass = 16;
  if (X.cols() > kMaxPass) {
    Y.resize(X.rows(), X.cols());
    RowBlock Xp, Yp;
    std::vector<const Volumes*> vp;
    for (Eigen::Index c0 = 0; c0 < X.cols(); c0 += kMaxPass) {
      const Eigen::Index m = std::min(kMaxPass, X.cols() - c0);
      Xp = X.middleCols(c0, m);
      if (!per_column.empty()) vp.assign(per_column.begin() + c0, per_column.begin() + c0 + m);
      apply_block(Xp, Yp, vp);
      Y.middleCols(c0, m) = Yp;
    }
    return;
  }
  with_quads(X.cols(), [&](auto w) {
    constexpr int W = decltype(w)::value;
    full_storage_ ? apply_full_block<W>(X, Y) : apply_assembled_block<W>(X, Y, per_column);
  });
}

void DiscreteLaplacian::apply_full(const Eigen::VectorXd& v, Eigen::VectorXd& y) const {
  const int64_t rows = static_cast<int64_t>(omega_.size());
  if (v.size() != static_cast<Eigen::Index>(n_))
    throw InputError("apply_full: vector of size " + std::to_string(v.size()) + ", expected " +
                     std::to_string(n_));
  y.resize(rows);
  if (full_storage_) {
    const int* outer = full_->outerIndexPtr();
    const int* inner = full_->innerIndexPtr();
    const double* val = full_->valuePtr();
    const double* x = v.data();
#pragma omp parallel for schedule(static, 256) if (threaded())
    for (int64_t k = 0; k < rows; ++k) {
      double s = 0;
      for (int o = outer[k]; o < outer[k + 1]; ++o) s = std::fma(val[o], x[inner[o]], s);
      y[k] = s;
    }
    return;
  }
  if (assembled_) {
    // The Ω × Ω part from the half, then the boundary columns.
    Eigen::VectorXd x(rows);
    for (int64_t k = 0; k < rows; ++k) x[k] = v[omega_[k]];
    apply_assembled(x, y);
    for (int64_t k = 0; k < rows; ++k)
      for (int64_t o = b_ptr_[k]; o < b_ptr_[k + 1]; ++o) y[k] += b_val_[o] * v[b_col_[o]];
    return;
  }
  // Matrix-free: the fused kernel's Δ_h at the particles in Ω (or the device's).
  const std::vector<double> field(v.data(), v.data() + v.size());
  if (device_) {
    const DeviceColumns c = device_->apply(omega_, std::vector<std::vector<double>>{field});
    const double* lap = c.column(0, 0, 3);
    for (int64_t k = 0; k < rows; ++k) y[k] = lap[k];
    return;
  }
  const KernelResult r = kernel_->apply(omega_, std::vector<std::vector<double>>{field});
  const auto lap = r.laplacian(0, 0);
  for (int64_t k = 0; k < rows; ++k) y[k] = lap[k];
}

void DiscreteLaplacian::apply_full(const Eigen::VectorXd& v, Eigen::VectorXd& y,
                                   const Volumes* other) const {
  if (!other) return apply_full(v, y);
  if (!assembled_ || full_storage_)
    throw InputError("apply_full: other volumes need the assembled (half) storage");
  if (v.size() != static_cast<Eigen::Index>(n_))
    throw InputError("apply_full: vector of size " + std::to_string(v.size()) + ", expected " +
                     std::to_string(n_));
  // The Ω × Ω part as one column of apply_block with the other volumes (bit for bit that
  // Laplacian's apply()), then its boundary columns, as apply_full sums them.
  const int64_t rows = static_cast<int64_t>(omega_.size());
  RowBlock X(rows, 1), Y;
  for (int64_t k = 0; k < rows; ++k) X(k, 0) = v[omega_[k]];
  apply_block(X, Y, {other});
  y = Y.col(0);
  for (int64_t k = 0; k < rows; ++k)
    for (int64_t o = b_ptr_[k]; o < b_ptr_[k + 1]; ++o)
      y[k] += other->boundary[static_cast<std::size_t>(o)] * v[b_col_[o]];
}

void DiscreteLaplacian::apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  if (assembled_ && !full_storage_) return apply_assembled(x, y);
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

CgState::CgState(const Eigen::VectorXd& b, const Eigen::VectorXd& Sx0, double tol,
                 int max_iter, std::string what, const Preconditioner* pc)
    : pc_(pc), bnorm_(b.norm()), tol_(tol), max_iter_(max_iter), what_(std::move(what)) {
  if (!std::isfinite(bnorm_)) throw NumericalError(what_ + ": non-finite right-hand side");
  r_ = b - Sx0;
  rr_ = r_.squaredNorm();
  if (pc_) {
    pc_->apply(r_, z_);
    p_ = z_;
    rz_ = r_.dot(z_);
  } else {
    p_ = r_;
  }
  stop_ = tol * tol * bnorm_ * bnorm_;
}

bool CgState::done() const {
  if (rr_ <= stop_) return true;
  if (iterations_ >= max_iter_)
    throw NumericalError(what_ + ": conjugate gradients did not reach the relative residual " +
                         cg_number(tol_) + " in " + std::to_string(max_iter_) +
                         " iterations (now " + cg_number(std::sqrt(rr_) / bnorm_) + ")");
  return false;
}

void CgState::update(Eigen::VectorXd& x, const Eigen::VectorXd& q) {
  const double pq = p_.dot(q);
  if (!std::isfinite(pq))
    throw NumericalError(what_ + ": non-finite value p^T S p = " + cg_number(pq) +
                         " at iteration " + std::to_string(iterations_));
  if (!(pq > 0)) {
    // p^T S p <= 0 once the residual sits at rounding level is rounding, not a property of
    // S: the tolerance asked for is below what double precision reaches for this system.
    const double rel = std::sqrt(rr_) / bnorm_;
    if (rel <= 1e-12)
      throw NumericalError(what_ + ": the relative residual " + cg_number(tol_) +
                           " is out of reach in double precision (it stalled at " + cg_number(rel) +
                           " by iteration " + std::to_string(iterations_) + ", where p^T S p = " +
                           cg_number(pq) + " is rounding); ask for a larger --tol");
    throw NumericalError(what_ + ": the matrix is not positive definite (p^T S p = " +
                         cg_number(pq) + " at iteration " + std::to_string(iterations_) +
                         ", relative residual " + cg_number(rel) + ")");
  }
  const double alpha = (pc_ ? rz_ : rr_) / pq;
  x += alpha * p_;
  r_ -= alpha * q;
  const double rr_new = r_.squaredNorm();
  if (!std::isfinite(rr_new))
    throw NumericalError(what_ + ": non-finite residual at iteration " +
                         std::to_string(iterations_));
  if (pc_) {
    pc_->apply(r_, z_);
    const double rz_new = r_.dot(z_);
    if (!(rz_new >= 0) || !std::isfinite(rz_new))
      throw NumericalError(what_ + ": the preconditioner is not positive definite (r^T P^-1 r = " +
                           cg_number(rz_new) + " at iteration " + std::to_string(iterations_) + ")");
    p_ = z_ + (rz_new / rz_) * p_;
    rz_ = rz_new;
  } else {
    p_ = r_ + (rr_new / rr_) * p_;
  }
  rr_ = rr_new;
  ++iterations_;
}

CgResult CgState::result() const {
  CgResult res;
  res.iterations = iterations_;
  res.recursive_rel_residual = std::sqrt(rr_) / bnorm_;
  return res;
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
