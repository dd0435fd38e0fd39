#include "gpm/solvers/heat.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

#include "gpm/error.hpp"

namespace gpm {

double heat_exact(double x, double y, double t, double kappa) {
  constexpr double pi = std::numbers::pi;
  return std::exp(-2 * kappa * pi * pi * t) * std::sin(pi * x) * std::sin(pi * y);
}

HeatExample heat_example(const Particles& p, const DiscreteLaplacian& L,
                         const DiscreteLaplacian::Volumes* volumes, double kappa) {
  HeatExample ex;
  ex.lambda = 2 * kappa * std::numbers::pi * std::numbers::pi;
  const auto& omega = L.omega();
  const auto& V = volumes ? volumes->all : L.volumes();
  const Eigen::Index n = static_cast<Eigen::Index>(omega.size());
  // The spatial profile s(x) = ũ(x, 0) at every particle, its boundary part ŝ and c = (M ŝ)_Ω.
  std::vector<double> prof(p.size());
  Eigen::VectorXd shat(static_cast<Eigen::Index>(p.size()));
  double all_l2sq = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    prof[i] = heat_exact(p.x[i], p.y[i], 0, kappa);
    shat[i] = p.in_omega[i] ? 0.0 : prof[i];
    all_l2sq += V[i] * prof[i] * prof[i];
    if (!p.in_omega[i]) ex.out_l2sq += V[i] * prof[i] * prof[i];
  }
  L.apply_full(shat, ex.c, volumes);
  ex.d.resize(n), ex.sk.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) ex.d[k] = V[omega[k]], ex.sk[k] = prof[omega[k]];
  for (Eigen::Index k = 0; k < n; ++k) ex.max_exact = std::max(ex.max_exact, std::fabs(ex.sk[k]));
  // Norms: ‖ũ^k‖_{ℓ²(Ω_H)} = e(t^k)·‖s‖ decreases, so its maximum is at k = 0.
  ex.ref_l2 = std::sqrt(all_l2sq);
  return ex;
}

namespace {

using RowBlock = DiscreteLaplacian::RowBlock;

// One series of the θ-method (one HeatSetting) on a shared Laplacian: its state between
// steps and the parts of a step between the products, so that several series can share
// every product M·x (solve_heat_block).  The caller computes MU = M U^k after each step
// (and once before the first) and, for an implicit step, the products M p of the CG.
class HeatSeries {
 public:
  HeatSeries(const Particles& p, const DiscreteLaplacian& L, const HeatSetting& s);
  bool running(long k) const { return k < res_.K && !res_.blew_up; }
  bool is_implicit() const { return th_ > 0; }
  // Whether step k needs M U^{k+1} afterwards: the next explicit part, or this CG's true
  // residual (cg_iterate / cg_check_true_residual).
  bool needs_product(long k) const { return is_implicit() || k + 1 < res_.K; }
  Eigen::VectorXd& U() { return U_; }
  Eigen::VectorXd& MU() { return MU_; }
  const DiscreteLaplacian::Volumes* volumes() const { return s_.volumes; }
  // Step k up to the solve: the right-hand side; explicit, U^{k+1} itself; implicit, the CG
  // started from U^k (warm start) with the residual from MU = M U^k.
  void begin_step(long k);
  CgState& cg() { return *cg_; }
  // A p from M p for the CG: A x = D(x − θκΔt Mx).
  void system_product(const Eigen::VectorXd& x, const Eigen::VectorXd& Mx,
                      Eigen::VectorXd& out) const {
    out = (d_.array() * (x.array() - th_ * kdt_ * Mx.array())).matrix();
  }
  // Step k after MU = M U^{k+1}: the solve's true residual, the blow-up check, the errors.
  void end_step(long k);
  // Its columns in the block products: its share of a joint run's time.
  void count_product() { ++products_; }
  long products() const { return products_; }
  HeatResult finish(double seconds);

 private:
  void extrapolate_start(long k);
  HeatSetting s_;
  HeatResult res_;
  double kdt_ = 0, th_ = 0, lambda_ = 0, ek1_ = 0;
  Eigen::VectorXd c_, d_, sk_, U_, MU_, rhs_, b_, y_;
  Eigen::VectorXd U_prev_, MU_prev_;  // U^{k−1} and M U^{k−1} (extrapolated starts only)
  double out_l2sq_ = 0, ref_l2_ = 0, max_exact_ = 0, u0_ = 0, prev_norm_ = 0;
  double err_l2_ = 0, err_max_ = 0;
  long cg_total_ = 0, products_ = 0;
  std::unique_ptr<CgState> cg_;
  std::string what_;

  double norm_l2(const Eigen::VectorXd& u, double e) const {
    return std::sqrt((d_.array() * u.array().square()).sum() + e * e * out_l2sq_);
  }
};

HeatSeries::HeatSeries(const Particles& p, const DiscreteLaplacian& L, const HeatSetting& s)
    : s_(s) {
  if (!(s.theta >= 0 && s.theta <= 1))
    throw InputError("theta must lie in [0, 1], got " + std::to_string(s.theta));
  require_positive(s.kappa, "kappa");
  res_.K = heat_steps(s.T, s.dt_nominal);
  res_.dt = s.fit_T ? s.T / static_cast<double>(res_.K) : s.dt_nominal;
  kdt_ = s.kappa * res_.dt, th_ = s.theta;
  HeatExample ex = heat_example(p, L, s.volumes, s.kappa);
  lambda_ = ex.lambda;
  c_ = std::move(ex.c), d_ = std::move(ex.d), sk_ = std::move(ex.sk);
  out_l2sq_ = ex.out_l2sq, ref_l2_ = ex.ref_l2, max_exact_ = ex.max_exact;
  U_ = sk_;
  u0_ = prev_norm_ = norm_l2(U_, 1.0);
}

void HeatSeries::begin_step(long k) {
  const double dt = res_.dt;
  const double ek = std::exp(-lambda_ * dt * k);
  ek1_ = std::exp(-lambda_ * dt * (k + 1));
  rhs_ = U_;
  if (th_ < 1) rhs_ += (1 - th_) * kdt_ * (MU_ + ek * c_);
  if (th_ > 0) {
    rhs_ += th_ * kdt_ * ek1_ * c_;
    b_ = (d_.array() * rhs_.array()).matrix();
    what_ = "heat step " + std::to_string(k + 1);
    if (s_.extrapolate) extrapolate_start(k);
    system_product(U_, MU_, y_);
    cg_ = std::make_unique<CgState>(b_, y_, s_.tol, s_.max_iter, what_, s_.pc);
  } else {
    U_ = rhs_;
  }
}

// U ← 2U^k − U^{k−1} and MU ← 2MU^k − MU^{k−1} (M is linear: no product), keeping U^k and
// M U^k for the next step.  The solve's true residual is still checked with a product.
void HeatSeries::extrapolate_start(long k) {
  if (k > 0) {
    std::swap(U_prev_, U_), std::swap(MU_prev_, MU_);
    U_ = 2 * U_prev_ - U_;
    MU_ = 2 * MU_prev_ - MU_;
  } else {
    U_prev_ = U_, MU_prev_ = MU_;
  }
}

void HeatSeries::end_step(long k) {
  if (th_ > 0) {
    CgResult r = cg_->result();
    system_product(U_, MU_, y_);
    cg_check_true_residual(r, b_, y_, s_.tol, what_);
    cg_total_ += r.iterations;
    res_.max_rel_residual = std::max(res_.max_rel_residual, r.rel_residual);
  }
  res_.steps_done = k + 1;
  if (s_.observe) s_.observe(k + 1, U_);
  // Blow-up check before the error: a growing unstable mode must stop the run.
  const double un = norm_l2(U_, ek1_);
  res_.growth_max = std::max(res_.growth_max, un / u0_);
  if (!std::isfinite(un) || un > s_.blowup_factor * u0_) {
    res_.blew_up = true;
    res_.blowup_step = k + 1;
    res_.growth = un / u0_;
    res_.amplification = un / prev_norm_;
    return;
  }
  prev_norm_ = un;
  double e2 = 0, em = 0;
  for (Eigen::Index j = 0; j < U_.size(); ++j) {
    const double e = ek1_ * sk_[j] - U_[j];
    e2 += d_[j] * e * e;
    em = std::max(em, std::fabs(e));
  }
  err_l2_ = std::max(err_l2_, std::sqrt(e2));
  err_max_ = std::max(err_max_, em);
}

HeatResult HeatSeries::finish(double seconds) {
  res_.seconds = seconds;
  res_.products = static_cast<double>(products_);
  res_.seconds_per_step = seconds / static_cast<double>(std::max(1L, res_.steps_done));
  res_.mean_cg_iterations =
      static_cast<double>(cg_total_) / static_cast<double>(std::max(1L, res_.steps_done));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  res_.rel_error = res_.blew_up ? nan : err_l2_ / ref_l2_;
  res_.rel_error_max = res_.blew_up ? nan : err_max_ / max_exact_;
  return res_;
}

// out_i = M_i in_i for the listed vectors, in one block product; M_i is the Laplacian of
// volumes vol[i] (nullptr: L's own).
void block_product(const DiscreteLaplacian& L, const std::vector<const Eigen::VectorXd*>& in,
                   const std::vector<Eigen::VectorXd*>& out,
                   const std::vector<const DiscreteLaplacian::Volumes*>& vol, RowBlock& X,
                   RowBlock& Y) {
  if (in.empty()) return;
  X.resize(static_cast<Eigen::Index>(L.n_unknowns()), static_cast<Eigen::Index>(in.size()));
  for (std::size_t c = 0; c < in.size(); ++c) X.col(static_cast<Eigen::Index>(c)) = *in[c];
  // Only where some series has other volumes (the matrix-free storage has none).
  const bool other = std::any_of(vol.begin(), vol.end(), [](auto* v) { return v != nullptr; });
  L.apply_block(X, Y, other ? vol : std::vector<const DiscreteLaplacian::Volumes*>{});
  for (std::size_t c = 0; c < out.size(); ++c) *out[c] = Y.col(static_cast<Eigen::Index>(c));
}

}  // namespace

HeatResult solve_heat(const Particles& p, const DiscreteLaplacian& L, const HeatSetting& s) {
  return solve_heat_block(p, L, {s}).front();
}

std::vector<HeatResult> solve_heat_block(const Particles& p, const DiscreteLaplacian& L,
                                         const std::vector<HeatSetting>& settings) {
  std::vector<HeatSeries> series;
  series.reserve(settings.size());
  long K = 0;
  for (const auto& s : settings) {
    series.emplace_back(p, L, s);
    K = std::max(K, heat_steps(s.T, s.dt_nominal));
  }
  RowBlock X, Y;
  std::vector<const Eigen::VectorXd*> in;
  std::vector<Eigen::VectorXd*> out;
  std::vector<const DiscreteLaplacian::Volumes*> vol;
  // M U for the listed series, one product for all of them.
  auto update_MU = [&](const std::vector<HeatSeries*>& list) {
    in.clear(), out.clear(), vol.clear();
    for (HeatSeries* h : list) {
      in.push_back(&h->U()), out.push_back(&h->MU()), vol.push_back(h->volumes());
      h->count_product();
    }
    block_product(L, in, out, vol, X, Y);
  };
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<HeatSeries*> running, solving, next;
  for (auto& h : series) running.push_back(&h);
  update_MU(running);
  std::vector<Eigen::VectorXd> Mp(series.size()), Ap(series.size());
  for (long k = 0; k < K; ++k) {
    running.clear(), solving.clear(), next.clear();
    for (auto& h : series)
      if (h.running(k)) running.push_back(&h);
    if (running.empty()) break;
    for (HeatSeries* h : running) {
      h->begin_step(k);
      if (h->is_implicit()) solving.push_back(h);
      if (h->needs_product(k)) next.push_back(h);
    }
    // The CG of the implicit series in lockstep: one block product per iteration for the
    // series not yet converged; a converged series keeps its iterate.
    for (;;) {
      in.clear(), out.clear(), vol.clear();
      std::vector<HeatSeries*> pending;
      for (HeatSeries* h : solving)
        if (!h->cg().done()) pending.push_back(h);
      if (pending.empty()) break;
      for (std::size_t i = 0; i < pending.size(); ++i) {
        in.push_back(&pending[i]->cg().direction()), out.push_back(&Mp[i]);
        vol.push_back(pending[i]->volumes());
        pending[i]->count_product();
      }
      block_product(L, in, out, vol, X, Y);
      for (std::size_t i = 0; i < pending.size(); ++i) {
        pending[i]->system_product(pending[i]->cg().direction(), Mp[i], Ap[i]);
        pending[i]->cg().update(pending[i]->U(), Ap[i]);
      }
    }
    update_MU(next);
    for (HeatSeries* h : running) h->end_step(k);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  long products = 0;
  for (auto& h : series) products += h.products();
  std::vector<HeatResult> results;
  for (auto& h : series)
    results.push_back(h.finish(seconds * static_cast<double>(h.products()) /
                               static_cast<double>(std::max(1L, products))));
  return results;
}

}  // namespace gpm
