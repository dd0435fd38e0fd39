#include "gpm/solvers/tau_preconditioner.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "gpm/error.hpp"

namespace gpm {

// FFTW's planner is not thread-safe and its plans are reused: one plan per preconditioner,
// made in the constructor, executed on the preconditioner's own buffer.
struct TauPreconditioner::Plan {
  double* buf = nullptr;
  fftw_plan plan = nullptr;
  Plan(int nx, int ny) {
    buf = fftw_alloc_real(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
    if (!buf) throw NumericalError("tau preconditioner: cannot allocate its " +
                                   std::to_string(nx) + " x " + std::to_string(ny) + " grid");
    // FFTW_ESTIMATE: the plan is a fixed function of the sizes, so every run sums alike
    // (FFTW_MEASURE may pick another algorithm, and other roundings, from run to run).
    plan = fftw_plan_r2r_2d(nx, ny, buf, buf, FFTW_RODFT00, FFTW_RODFT00, FFTW_ESTIMATE);
    if (!plan) throw NumericalError("tau preconditioner: FFTW made no DST-I plan");
  }
  ~Plan() {
    if (plan) fftw_destroy_plan(plan);
    if (buf) fftw_free(buf);
  }
};

TauPreconditioner::TauPreconditioner(const Particles& p, const DiscreteLaplacian& L,
                                     const WeightFunction& w, double dx, double shift,
                                     double scale, const std::vector<double>* volumes) {
  if (!(dx > 0) || !std::isfinite(dx)) throw InputError("tau preconditioner: dx must be positive");
  if (!(shift >= 0) || !(scale > 0) || !std::isfinite(shift) || !std::isfinite(scale))
    throw InputError("tau preconditioner: shift must be >= 0 and scale > 0");
  const std::vector<double>& V = volumes ? *volumes : L.volumes();
  if (V.size() != p.size() || p.gi.size() != p.size())
    throw InputError("tau preconditioner: volumes and nodes must cover the particles");
  const auto& omega = L.omega();

  // The lattice rectangle of the unknowns' nodes.
  int32_t i0 = std::numeric_limits<int32_t>::max(), i1 = std::numeric_limits<int32_t>::min();
  int32_t j0 = i0, j1 = i1;
  for (int32_t k : omega) {
    i0 = std::min(i0, p.gi[k]), i1 = std::max(i1, p.gi[k]);
    j0 = std::min(j0, p.gj[k]), j1 = std::max(j1, p.gj[k]);
  }
  nx_ = i1 - i0 + 1, ny_ = j1 - j0 + 1;
  cell_.resize(omega.size());
  inv_v_.resize(static_cast<Eigen::Index>(omega.size()));
  std::vector<uint8_t> taken(static_cast<std::size_t>(nx_) * ny_, 0);
  for (std::size_t u = 0; u < omega.size(); ++u) {
    const int32_t k = omega[u];
    const int64_t c = static_cast<int64_t>(p.gi[k] - i0) * ny_ + (p.gj[k] - j0);
    if (taken[c]++) throw InputError("tau preconditioner: two unknowns on lattice node (" +
                                     std::to_string(p.gi[k]) + ", " + std::to_string(p.gj[k]) + ")");
    cell_[u] = c;
    inv_v_[static_cast<Eigen::Index>(u)] = 1.0 / V[k];
  }

  // The volume-free stencil c(m, n)/V² = 2d·w(q)/(h²r²), q = r/h < 1, of the plain lattice.
  const double h = L.h();
  const int M = static_cast<int>(std::floor(h / dx));
  for (int m = -M; m <= M; ++m)
    for (int n = -M; n <= M; ++n) {
      if (m == 0 && n == 0) continue;
      const double r = dx * std::sqrt(static_cast<double>(m) * m + static_cast<double>(n) * n);
      if (!(r < h)) continue;
      const double c = 2.0 * 2.0 * w.value(r / h) / (h * h * r * r);
      if (c == 0) continue;
      sm_.push_back(m), sn_.push_back(n), sc_.push_back(c);
    }

  // λ(a, b) = C − Σ_m cos mθ_a G(m, b),  G(m, b) = Σ_n c(m, n) cos nθ_b,  C = Σ c: separable,
  // O(M²·ny + M·nx·ny) instead of O(M²·nx·ny).
  double C = 0;
  for (double c : sc_) C += c;
  const int nm = 2 * M + 1;
  std::vector<double> G(static_cast<std::size_t>(nm) * ny_, 0.0);
  for (std::size_t s = 0; s < sc_.size(); ++s)
    for (int b = 0; b < ny_; ++b) {
      const double tb = M_PI * (b + 1) / (ny_ + 1);
      G[static_cast<std::size_t>(sm_[s] + M) * ny_ + b] += sc_[s] * std::cos(sn_[s] * tb);
    }
  lambda_.assign(static_cast<std::size_t>(nx_) * ny_, C);
  for (int m = -M; m <= M; ++m)
    for (int a = 0; a < nx_; ++a) {
      const double cm = std::cos(m * (M_PI * (a + 1) / (nx_ + 1)));
      const double* g = &G[static_cast<std::size_t>(m + M) * ny_];
      double* l = &lambda_[static_cast<std::size_t>(a) * ny_];
      for (int b = 0; b < ny_; ++b) l[b] -= cm * g[b];
    }
  // Two unnormalized DST-I give 2(n + 1) per axis: folded into the division.
  const double norm = 4.0 * (nx_ + 1) * (ny_ + 1);
  inv_diag_.resize(lambda_.size());
  for (std::size_t i = 0; i < lambda_.size(); ++i) {
    const double e = shift + scale * lambda_[i];
    if (!(e > 0) || !std::isfinite(e))
      throw NumericalError("tau preconditioner: eigenvalue " + std::to_string(e) + " at mode (" +
                           std::to_string(i / ny_ + 1) + ", " + std::to_string(i % ny_ + 1) +
                           ") is not positive (weight '" + w.name + "' negative somewhere?)");
    inv_diag_[i] = 1.0 / (e * norm);
  }
  plan_ = std::make_unique<Plan>(nx_, ny_);
}

TauPreconditioner::~TauPreconditioner() = default;

void TauPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  double* g = plan_->buf;
  std::fill(g, g + static_cast<std::size_t>(nx_) * ny_, 0.0);
  const Eigen::Index n = static_cast<Eigen::Index>(cell_.size());
  for (Eigen::Index u = 0; u < n; ++u) g[cell_[u]] = r[u] * inv_v_[u];
  fftw_execute(plan_->plan);
  for (std::size_t i = 0; i < inv_diag_.size(); ++i) g[i] *= inv_diag_[i];
  fftw_execute(plan_->plan);
  z.resize(n);
  for (Eigen::Index u = 0; u < n; ++u) z[u] = g[cell_[u]] * inv_v_[u];
}

double TauPreconditioner::symbol(double theta, double phi) const {
  double s = 0;
  for (std::size_t i = 0; i < sc_.size(); ++i)
    s += sc_[i] * (1 - std::cos(sm_[i] * theta) * std::cos(sn_[i] * phi));
  return s;
}

}  // namespace gpm
