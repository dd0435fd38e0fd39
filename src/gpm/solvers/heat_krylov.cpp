#include "gpm/solvers/heat_krylov.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "gpm/error.hpp"

namespace gpm {

namespace {

using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;
using RowBlock = DiscreteLaplacian::RowBlock;

// An orthonormal basis of the Krylov space of Ã = S M S⁻¹ from two start vectors, grown a
// block at a time, and the projections T(i, j) = q_iᵀÃq_j of every vector whose product is
// known.  Vectors that fall below a relative 1e-12 after orthogonalization are dropped
// (deflation); when a whole block drops, the space is invariant and the basis exact.
class KrylovBasis {
 public:
  KrylovBasis(const DiscreteLaplacian& L, const DiscreteLaplacian::Volumes* vol, Vec s,
              const Vec& a, const Vec& b)
      : L_(L), vol_(vol), s_(std::move(s)) {
    const Eigen::Index n = s_.size();
    Q_.resize(n, 64);
    T_ = Mat::Zero(64, 64), known_ = Eigen::MatrixXi::Zero(64, 64);
    za_ = Vec::Zero(64), zb_ = Vec::Zero(64);
    Vec h;
    double beta;
    Vec w = a;
    if (add(w, h, beta) < 0) throw NumericalError("Krylov propagator: the initial value is zero");
    za_[0] = beta;
    w = b;
    const int ib = add(w, h, beta);
    zb_.head(h.size()) = h;
    if (ib >= 0) zb_[ib] = beta;
  }

  // Grows until `m` vectors have their product (or the space is exhausted).
  void grow_to(int m) {
    while (applied_ < m && !exhausted_) step();
  }
  int applied() const { return applied_; }
  bool exhausted() const { return exhausted_; }
  long products() const { return products_; }
  const Mat& Q() const { return Q_; }
  // T restricted to the first m vectors, symmetric (the entry computed where only one of
  // (i, j), (j, i) was, their mean where both were).
  Mat T(int m) const {
    Mat t(m, m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        const bool a = known_(i, j), b = known_(j, i);
        t(i, j) = a && b ? 0.5 * (T_(i, j) + T_(j, i)) : a ? T_(i, j) : T_(j, i);
      }
    return t;
  }
  // The start vectors' coordinates in the basis (exact: they span its first block).
  Vec za(int m) const { return za_.head(m); }
  Vec zb(int m) const { return zb_.head(m); }

 private:
  // Ã on the columns [applied_, nq_): one block product of M.
  void step() {
    const int first = applied_, width = nq_ - applied_;
    if (width == 0) {
      exhausted_ = true;
      return;
    }
    RowBlock X(Q_.rows(), width), Y;
    for (int c = 0; c < width; ++c) X.col(c) = Q_.col(first + c).cwiseQuotient(s_);
    if (vol_) L_.apply_block(X, Y, std::vector<const DiscreteLaplacian::Volumes*>(width, vol_));
    else L_.apply_block(X, Y);
    products_ += width;
    const int before = nq_;
    for (int c = 0; c < width; ++c) {
      Vec w = Y.col(c).cwiseProduct(s_);
      if (!w.allFinite())
        throw NumericalError("Krylov propagator: a non-finite Laplacian product at dimension " +
                             std::to_string(nq_));
      Vec h;
      double beta;
      const int at = add(w, h, beta);
      const int j = first + c;
      for (Eigen::Index i = 0; i < h.size(); ++i) T_(i, j) = h[i], known_(i, j) = 1;
      if (at >= 0) T_(at, j) = beta, known_(at, j) = 1;
    }
    applied_ = first + width;
    if (nq_ == before) exhausted_ = true;
  }

  // w orthogonalized against the basis (classical Gram–Schmidt, twice): h the coefficients,
  // beta the norm left; appended (normalized) unless it deflates.  Returns its column or −1.
  int add(Vec& w, Vec& h, double& beta) {
    const double before = w.norm();
    h = Vec::Zero(nq_);
    for (int pass = 0; pass < 2 && nq_ > 0; ++pass) {
      const Vec g = Q_.leftCols(nq_).transpose() * w;
      w.noalias() -= Q_.leftCols(nq_) * g;
      h += g;
    }
    beta = w.norm();
    if (!(beta > 1e-12 * before)) return -1;
    reserve(nq_ + 1);
    Q_.col(nq_) = w / beta;
    return nq_++;
  }

  void reserve(int m) {
    if (m <= Q_.cols()) return;
    const int cap = std::max<int>(m, static_cast<int>(Q_.cols()) * 3 / 2);
    Mat q(Q_.rows(), cap);
    q.leftCols(nq_) = Q_.leftCols(nq_);
    Q_.swap(q);
    Mat t = Mat::Zero(cap, cap);
    Eigen::MatrixXi k = Eigen::MatrixXi::Zero(cap, cap);
    t.topLeftCorner(T_.rows(), T_.cols()) = T_;
    k.topLeftCorner(known_.rows(), known_.cols()) = known_;
    T_.swap(t), known_.swap(k);
    Vec a = Vec::Zero(cap), b = Vec::Zero(cap);
    a.head(za_.size()) = za_, b.head(zb_.size()) = zb_;
    za_.swap(a), zb_.swap(b);
  }

  const DiscreteLaplacian& L_;
  const DiscreteLaplacian::Volumes* vol_;
  Vec s_;
  Mat Q_, T_;
  Eigen::MatrixXi known_;
  Vec za_, zb_;
  int nq_ = 0, applied_ = 0;
  long products_ = 0;
  bool exhausted_ = false;
};

// The subspace of size m diagonalized: eigenvalues μ, eigenvectors W, the start vectors in
// eigen-coordinates.
struct Modes {
  int m = 0;
  Vec mu, xi0, eta;
  Mat W;
};

Modes modes_of(const KrylovBasis& B, int m) {
  Eigen::SelfAdjointEigenSolver<Mat> es(B.T(m));
  if (es.info() != Eigen::Success)
    throw NumericalError("Krylov propagator: the projected matrix (m = " + std::to_string(m) +
                         ") could not be diagonalized");
  Modes md;
  md.m = m, md.mu = es.eigenvalues(), md.W = es.eigenvectors();
  md.xi0 = md.W.transpose() * B.za(m);
  md.eta = md.W.transpose() * B.zb(m);
  return md;
}

// One series' constants: K, Δt and the per-mode factors of the recurrence.
struct Series {
  const HeatSetting* s = nullptr;
  long K = 0;
  double dt = 0, a = 0, lambda = 0;
};

// Runs the scalar recurrences of one series in the modes md, in chunks of steps, calling
// visit(k0, X) with X's column c the coordinates ξ^{k0+c} (k0 ≥ 1).  Stops after the step
// whose ‖U‖_{ℓ²(Ω_H)} is not finite or exceeds the guard; returns that step, or 0 if none.
template <class Visit>
long run_modes(const Series& sr, const Modes& md, double out_l2sq, double u0, Visit&& visit) {
  const double th = sr.s->theta, a = sr.a;
  const Eigen::Index m = md.m;
  Vec r(m), g(m);
  for (Eigen::Index j = 0; j < m; ++j) {
    const double den = 1 - th * a * md.mu[j];
    r[j] = (1 + (1 - th) * a * md.mu[j]) / den;
    g[j] = a / den * md.eta[j];
  }
  constexpr long kChunk = 512;
  Mat X(m, kChunk);
  Vec xi = md.xi0;
  long k0 = 1;
  for (long k = 0; k < sr.K;) {
    const long width = std::min(kChunk, sr.K - k);
    long blown = 0, c = 0;
    for (; c < width; ++c, ++k) {
      const double ek = std::exp(-sr.lambda * sr.dt * static_cast<double>(k));
      const double ek1 = std::exp(-sr.lambda * sr.dt * static_cast<double>(k + 1));
      xi = r.cwiseProduct(xi) + ((1 - th) * ek + th * ek1) * g;
      X.col(c) = xi;
      const double un = std::sqrt(xi.squaredNorm() + ek1 * ek1 * out_l2sq);
      if (!std::isfinite(un) || un > sr.s->blowup_factor * u0) {
        blown = k + 1;
        ++c;
        break;
      }
    }
    visit(k0, X.leftCols(c));
    if (blown) return blown;
    k0 += c;
  }
  return 0;
}

double decay(const Series& sr, long k) {
  return std::exp(-sr.lambda * sr.dt * static_cast<double>(k));
}

// How far the series' coefficient trajectories in the basis move from modes `lo` to `hi`,
// max_k ‖W_hi ξ_hi^k − W_lo ξ_lo^k‖, relative to its largest ℓ² error max_k ‖e^k ξ⁰ − ξ^k‖
// (`rel`) and to its largest value max(‖S U⁰‖, max_k ‖ξ^k‖) (`of_data`: the scale of its
// rounding), over the steps both run without a blow-up; a different blow-up step is a change
// of 1.
struct Change {
  double rel = 0, of_data = 0;
};
Change trajectory_change(const Series& sr, const Modes& lo, const Modes& hi, double out_l2sq,
                         double u0) {
  std::vector<Mat> zlo;
  const long blo = run_modes(sr, lo, out_l2sq, u0, [&](long, const auto& X) { zlo.push_back(lo.W * X); });
  double change = 0, err = 0, size = u0;
  std::size_t chunk = 0;
  const long bhi = run_modes(sr, hi, out_l2sq, u0, [&](long k0, const auto& X) {
    if (chunk >= zlo.size()) return;
    const Mat Z = hi.W * X;
    const Mat& Zl = zlo[chunk++];
    const Eigen::Index cols = std::min(Z.cols(), Zl.cols());
    for (Eigen::Index c = 0; c < cols; ++c) {
      const double d2 = (Z.col(c).head(lo.m) - Zl.col(c)).squaredNorm() + Z.col(c).tail(hi.m - lo.m).squaredNorm();
      change = std::max(change, std::sqrt(d2));
      err = std::max(err, (decay(sr, k0 + c) * hi.xi0 - X.col(c)).norm());
      size = std::max(size, X.col(c).norm());
    }
  });
  if (blo != bhi || !std::isfinite(change) || !std::isfinite(err) || !std::isfinite(size)) return {1, 1};
  return {err > 0 ? change / err : change, change / size};
}

// max_k ‖V z_k‖_∞ over the columns of Z, exactly, evaluating only the columns whose bound
// from an evaluated neighbour reaches the running maximum (header).
double linf_max(const Mat& V, const Vec& colmax, const Eigen::Ref<const Mat>& Z) {
  const long S = Z.cols();
  if (S == 0) return 0;
  std::vector<double> exact(static_cast<std::size_t>(S), -1);
  auto evaluate = [&](const std::vector<long>& idx) {
    constexpr std::size_t kBatch = 64;
    for (std::size_t i0 = 0; i0 < idx.size(); i0 += kBatch) {
      const std::size_t w = std::min(kBatch, idx.size() - i0);
      Mat sel(Z.rows(), static_cast<Eigen::Index>(w));
      for (std::size_t c = 0; c < w; ++c) sel.col(static_cast<Eigen::Index>(c)) = Z.col(idx[i0 + c]);
      const Mat Y = V * sel;
      for (std::size_t c = 0; c < w; ++c)
        exact[static_cast<std::size_t>(idx[i0 + c])] = Y.col(static_cast<Eigen::Index>(c)).cwiseAbs().maxCoeff();
    }
  };
  std::vector<long> candidates(static_cast<std::size_t>(S));
  for (long i = 0; i < S; ++i) candidates[static_cast<std::size_t>(i)] = i;
  double best = 0;
  for (long stride : {64L, 8L, 1L}) {
    std::vector<long> pick;
    for (long i : candidates)
      if (exact[static_cast<std::size_t>(i)] < 0 && (i % stride == 0 || i == S - 1 || stride == 1))
        pick.push_back(i);
    evaluate(pick);
    std::vector<long> refs;
    for (long i = 0; i < S; ++i)
      if (exact[static_cast<std::size_t>(i)] >= 0) {
        refs.push_back(i);
        best = std::max(best, exact[static_cast<std::size_t>(i)]);
      }
    if (stride == 1) break;
    std::vector<long> next;
    for (long i : candidates) {
      if (exact[static_cast<std::size_t>(i)] >= 0) continue;
      const auto it = std::lower_bound(refs.begin(), refs.end(), i);
      double bound = std::numeric_limits<double>::infinity();
      for (auto r : {it != refs.begin() ? *(it - 1) : -1L, it != refs.end() ? *it : -1L}) {
        if (r < 0) continue;
        bound = std::min(bound, exact[static_cast<std::size_t>(r)] +
                                    colmax.dot((Z.col(i) - Z.col(r)).cwiseAbs()));
      }
      // The bound holds in exact arithmetic; the margin covers the rounding of both sides.
      if (bound * (1 + 1e-10) >= best) next.push_back(i);
    }
    candidates.swap(next);
    if (candidates.empty()) break;
  }
  return best;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The ℓ∞ errors' map from eigen-coordinates to the unknowns, S⁻¹ Q W, and its columns' maxima.
// Formed in place (no temporary of the product): at 2^-10 each N×m matrix is gigabytes.
void evaluate_map(const KrylovBasis& B, const Modes& md, const Vec& s, Mat& V, Vec& colmax) {
  V.resize(B.Q().rows(), md.m);
  V.noalias() = B.Q().leftCols(md.m) * md.W;
  V.array().colwise() /= s.array();
  colmax = V.cwiseAbs().colwise().maxCoeff().transpose();
}

// One series through the modes md: its errors (4.2), growth and blow-up; `sharing` series
// share the basis' products and its build time (`build_s`).
HeatResult finish_series(const Series& sr, const Modes& md, const HeatExample& ex, double u0, const Mat& V,
                         const Vec& colmax, const KrylovBasis& B, std::size_t sharing, double build_s) {
  const auto t1 = std::chrono::steady_clock::now();
  HeatResult res;
  res.K = sr.K, res.dt = sr.dt, res.subspace = md.m;
  res.products = static_cast<double>(B.products()) / static_cast<double>(sharing);
  // The error coordinates e^k ξ⁰ − ξ^k of every step, the norms, the blow-up guard.
  Mat Z(md.m, sr.K);
  double err_l2 = 0, prev = u0;
  long done = 0;
  run_modes(sr, md, ex.out_l2sq, u0, [&](long k0, const auto& X) {
    for (Eigen::Index c = 0; c < X.cols(); ++c) {
      const long k = k0 + c;
      const double ek = decay(sr, k);
      const double un = std::sqrt(X.col(c).squaredNorm() + ek * ek * ex.out_l2sq);
      res.growth_max = std::max(res.growth_max, un / u0);
      if (sr.s->observe) sr.s->observe(k, V * X.col(c));
      done = k;
      if (!std::isfinite(un) || un > sr.s->blowup_factor * u0) {
        res.blew_up = true, res.blowup_step = k, res.growth = un / u0, res.amplification = un / prev;
        return;
      }
      prev = un;
      Z.col(k - 1) = ek * md.xi0 - X.col(c);
      err_l2 = std::max(err_l2, Z.col(k - 1).norm());
    }
  });
  res.steps_done = done;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  res.rel_error = res.blew_up ? nan : err_l2 / ex.ref_l2;
  res.rel_error_max = res.blew_up ? nan : linf_max(V, colmax, Z.leftCols(done)) / ex.max_exact;
  res.seconds = build_s / static_cast<double>(sharing) + seconds_since(t1);
  res.seconds_per_step = res.seconds / static_cast<double>(std::max(1L, res.steps_done));
  return res;
}

// The series of one operator (one choice of volumes) through one subspace.
void propagate_group(const Particles& p, const DiscreteLaplacian& L,
                     const std::vector<const HeatSetting*>& group, const KrylovSettings& ks,
                     std::vector<HeatResult>& out) {
  const auto t0 = std::chrono::steady_clock::now();
  const DiscreteLaplacian::Volumes* vol = group.front()->volumes;
  const HeatExample ex = heat_example(p, L, vol, group.front()->kappa);
  const Vec s = ex.d.cwiseSqrt();
  const double u0 = std::sqrt(ex.d.dot(ex.sk.cwiseAbs2()) + ex.out_l2sq);
  std::vector<Series> series;
  for (const HeatSetting* hs : group) {
    if (!(hs->theta >= 0 && hs->theta <= 1))
      throw InputError("theta must lie in [0, 1], got " + std::to_string(hs->theta));
    if (hs->kappa != group.front()->kappa)
      throw InputError("Krylov propagator: series of one subspace need one kappa");
    Series sr;
    sr.s = hs;
    sr.K = heat_steps(hs->T, hs->dt_nominal);
    sr.dt = hs->fit_T ? hs->T / static_cast<double>(sr.K) : hs->dt_nominal;
    sr.a = hs->kappa * sr.dt, sr.lambda = ex.lambda;
    series.push_back(sr);
  }
  // The subspace: grown until every series' trajectories stop moving (header).  Each size
  // group (HeatSetting::size_group) settles on its own and keeps the modes of the size it
  // settled at, so it takes the size it would take alone; the basis grows for the last one.
  std::map<int, std::vector<std::size_t>> sets;
  for (std::size_t i = 0; i < group.size(); ++i) sets[group[i]->size_group].push_back(i);
  std::map<int, Modes> taken;
  KrylovBasis B(L, vol, s, s.cwiseProduct(ex.sk), s.cwiseProduct(ex.c));
  const int limit = std::min<int>(ks.max_dim, static_cast<int>(s.size()));
  int m = std::min(ks.first, limit);
  B.grow_to(m);
  Modes lo = modes_of(B, std::min(m, B.applied()));
  std::vector<double> last(series.size(), std::numeric_limits<double>::infinity());
  while (taken.size() < sets.size()) {
    if (B.exhausted()) break;
    if (m >= limit)
      throw NumericalError("Krylov propagator: no convergence to " + std::to_string(ks.tol) +
                           " within a subspace of dimension " + std::to_string(m));
    m = std::min(limit, m + std::max(16, m / 6));
    m += m % 2;
    B.grow_to(m);
    Modes hi = modes_of(B, std::min(m, B.applied()));
    // A group is settled when each of its series is, within the tolerance or at its rounding
    // (header).
    KrylovTry t;
    t.m = m;
    for (auto& [g, idx] : sets) {
      if (taken.count(g)) continue;
      bool settled = true, rounding = false;
      for (std::size_t i : idx) {
        const Change c = trajectory_change(series[i], lo, hi, ex.out_l2sq, u0);
        t.change = std::max(t.change, c.rel), t.of_data = std::max(t.of_data, c.of_data);
        const bool stalled = c.of_data <= ks.rounding && c.of_data * ks.stall > last[i];
        if (c.rel > ks.tol) rounding = true, settled = settled && stalled;
        last[i] = c.of_data;
      }
      if (!settled) continue;
      t.rounding = t.rounding || rounding;
      taken.emplace(g, B.exhausted() ? modes_of(B, B.applied()) : hi);
    }
    lo = std::move(hi);
    if (ks.on_size) ks.on_size(t);
  }
  // An exhausted space is exact: the groups not yet settled take all of it.
  for (auto& [g, idx] : sets)
    if (!taken.count(g)) taken.emplace(g, modes_of(B, B.applied()));
  const double build_s = seconds_since(t0);
  // Each group through its modes, the groups of one size on one map from eigen-coordinates to
  // the unknowns.
  int mapped = -1;
  Mat V;
  Vec colmax;
  for (auto& [g, idx] : sets) {
    const Modes& md = taken.at(g);
    if (md.m != mapped) evaluate_map(B, md, s, V, colmax), mapped = md.m;
    for (std::size_t i : idx) out[i] = finish_series(series[i], md, ex, u0, V, colmax, B, series.size(), build_s);
  }
}

}  // namespace

std::vector<HeatResult> propagate_heat(const Particles& p, const DiscreteLaplacian& L,
                                       const std::vector<HeatSetting>& settings,
                                       const KrylovSettings& ks) {
  if (!(ks.tol > 0) || !(ks.rounding >= 0) || !(ks.stall > 1) || ks.first < 2 || ks.max_dim < ks.first)
    throw InputError("Krylov propagator: tol must be positive, rounding non-negative, stall above 1 and 2 <= first <= max_dim");
  // One subspace per operator: the series grouped by their volumes.
  std::map<const DiscreteLaplacian::Volumes*, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < settings.size(); ++i) groups[settings[i].volumes].push_back(i);
  std::vector<HeatResult> results(settings.size());
  for (auto& [vol, idx] : groups) {
    std::vector<const HeatSetting*> group;
    for (std::size_t i : idx) group.push_back(&settings[i]);
    std::vector<HeatResult> out(idx.size());
    propagate_group(p, L, group, ks, out);
    for (std::size_t j = 0; j < idx.size(); ++j) results[idx[j]] = out[j];
  }
  return results;
}

HeatPropagator parse_heat_propagator(const std::string& s) {
  if (s == "stepped") return HeatPropagator::stepped;
  if (s == "krylov") return HeatPropagator::krylov;
  if (s == "auto") return HeatPropagator::automatic;
  throw InputError("--propagator: '" + s + "' is not stepped, krylov or auto");
}

std::string heat_propagator_name(HeatPropagator p) {
  switch (p) {
    case HeatPropagator::stepped: return "stepped";
    case HeatPropagator::krylov: return "krylov";
    case HeatPropagator::automatic: return "auto";
  }
  return "?";
}

std::vector<HeatResult> run_heat(const Particles& p, const DiscreteLaplacian& L,
                                 const std::vector<HeatSetting>& settings,
                                 const std::vector<HeatPropagator>& hows, double dx,
                                 const KrylovSettings& ks) {
  if (hows.size() != 1 && hows.size() != settings.size())
    throw std::logic_error("run_heat: one propagator, or one per series");
  std::vector<HeatSetting> stepped, krylov;
  std::vector<std::pair<bool, std::size_t>> where;
  for (const HeatSetting& s : settings) {
    const HeatPropagator how = hows[hows.size() == 1 ? 0 : where.size()];
    bool k = how == HeatPropagator::krylov;
    if (how == HeatPropagator::automatic)
      k = heat_stepped_products(dx, L.h(), s.dt_nominal, s.T, s.theta) > heat_krylov_products(dx, L.h());
    where.push_back({k, k ? krylov.size() : stepped.size()});
    (k ? krylov : stepped).push_back(s);
  }
  const std::vector<HeatResult> a = stepped.empty() ? std::vector<HeatResult>{} : solve_heat_block(p, L, stepped);
  const std::vector<HeatResult> b = krylov.empty() ? std::vector<HeatResult>{} : propagate_heat(p, L, krylov, ks);
  std::vector<HeatResult> out;
  for (auto [k, i] : where) out.push_back(k ? b[i] : a[i]);
  return out;
}

}  // namespace gpm
