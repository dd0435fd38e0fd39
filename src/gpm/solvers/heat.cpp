#include "gpm/solvers/heat.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "gpm/error.hpp"

namespace gpm {

long heat_steps(double T, double dt_nominal) {
  require_positive(T, "T");
  require_positive(dt_nominal, "time step");
  const double r = T / dt_nominal;
  if (r > 1e9) throw InputError("time step " + std::to_string(dt_nominal) + " gives more than 1e9 steps");
  return std::max(1L, static_cast<long>(std::ceil(r * (1 - 1e-12))));
}

double heat_exact(double x, double y, double t, double kappa) {
  constexpr double pi = std::numbers::pi;
  return std::exp(-2 * kappa * pi * pi * t) * std::sin(pi * x) * std::sin(pi * y);
}

HeatResult solve_heat(const Particles& p, const DiscreteLaplacian& L, const HeatSetting& s) {
  if (!(s.theta >= 0 && s.theta <= 1))
    throw InputError("theta must lie in [0, 1], got " + std::to_string(s.theta));
  require_positive(s.kappa, "kappa");
  HeatResult res;
  res.K = heat_steps(s.T, s.dt_nominal);
  res.dt = s.fit_T ? s.T / static_cast<double>(res.K) : s.dt_nominal;
  const double dt = res.dt, kdt = s.kappa * dt, th = s.theta;
  const double lambda = 2 * s.kappa * std::numbers::pi * std::numbers::pi;
  const auto& omega = L.omega();
  const auto& V = L.volumes();
  const Eigen::Index n = static_cast<Eigen::Index>(omega.size());

  // The spatial profile s(x) = ũ(x, 0) at every particle, its boundary part ŝ and c = (M ŝ)_Ω.
  std::vector<double> prof(p.size());
  Eigen::VectorXd shat(static_cast<Eigen::Index>(p.size()));
  double out_l2sq = 0, all_l2sq = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    prof[i] = heat_exact(p.x[i], p.y[i], 0, s.kappa);
    shat[i] = p.in_omega[i] ? 0.0 : prof[i];
    all_l2sq += V[i] * prof[i] * prof[i];
    if (!p.in_omega[i]) out_l2sq += V[i] * prof[i] * prof[i];
  }
  Eigen::VectorXd c;
  L.apply_full(shat, c);
  Eigen::VectorXd d(n), sk(n);
  for (Eigen::Index k = 0; k < n; ++k) d[k] = V[omega[k]], sk[k] = prof[omega[k]];
  double max_exact = 0;
  for (Eigen::Index k = 0; k < n; ++k) max_exact = std::max(max_exact, std::fabs(sk[k]));

  // Norms: ‖ũ^k‖_{ℓ²(Ω_H)} = e(t^k)·‖s‖ decreases, so its maximum is at k = 0.
  const double ref_l2 = std::sqrt(all_l2sq);
  Eigen::VectorXd U = sk, rhs(n), y(n), b(n), tmp;
  auto norm_l2 = [&](const Eigen::VectorXd& u, double e) {
    return std::sqrt((d.array() * u.array().square()).sum() + e * e * out_l2sq);
  };
  const double u0 = norm_l2(U, 1.0);
  double prev_norm = u0, err_l2 = 0, err_max = 0;
  // A = D − θκΔt D M_ΩΩ (symmetric positive definite for θ > 0 and a positive weight):
  // A x = D(x − θκΔt Mx), written once here for a product Mx already at hand.
  auto A_with = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& Mx, Eigen::VectorXd& out) {
    out = (d.array() * (x.array() - th * kdt * Mx.array())).matrix();
  };
  auto A = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
    L.apply(x, tmp);
    A_with(x, tmp, out);
  };
  long cg_total = 0;
  const auto t0 = std::chrono::steady_clock::now();
  // MU = M_ΩΩ U^k, one product per step: it gives the explicit part of the right-hand side,
  // the initial CG residual b − A U^k = b − D(U^k − θκΔt MU), and, computed after the
  // solve, the true residual of that solve (cg_iterate / cg_check_true_residual).
  Eigen::VectorXd MU;
  L.apply(U, MU);
  for (long k = 0; k < res.K; ++k) {
    const double ek = std::exp(-lambda * dt * k), ek1 = std::exp(-lambda * dt * (k + 1));
    rhs = U;
    if (th < 1) rhs += (1 - th) * kdt * (MU + ek * c);
    if (th > 0) {
      rhs += th * kdt * ek1 * c;
      b = (d.array() * rhs.array()).matrix();
      const std::string what = "heat step " + std::to_string(k + 1);
      A_with(U, MU, y);
      CgResult r = cg_iterate(A, b, U, y, s.tol, s.max_iter, what);
      L.apply(U, MU);
      A_with(U, MU, y);
      cg_check_true_residual(r, b, y, s.tol, what);
      cg_total += r.iterations;
      res.max_rel_residual = std::max(res.max_rel_residual, r.rel_residual);
    } else {
      U = rhs;
      if (k + 1 < res.K) L.apply(U, MU);
    }
    res.steps_done = k + 1;
    // Blow-up check before the error: a growing unstable mode must stop the run.
    const double un = norm_l2(U, ek1);
    res.growth_max = std::max(res.growth_max, un / u0);
    if (!std::isfinite(un) || un > s.blowup_factor * u0) {
      res.blew_up = true;
      res.blowup_step = k + 1;
      res.growth = un / u0;
      res.amplification = un / prev_norm;
      break;
    }
    prev_norm = un;
    double e2 = 0, em = 0;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double e = ek1 * sk[j] - U[j];
      e2 += d[j] * e * e;
      em = std::max(em, std::fabs(e));
    }
    err_l2 = std::max(err_l2, std::sqrt(e2));
    err_max = std::max(err_max, em);
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.seconds_per_step = res.seconds / static_cast<double>(std::max(1L, res.steps_done));
  res.mean_cg_iterations = static_cast<double>(cg_total) / static_cast<double>(std::max(1L, res.steps_done));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  res.rel_error = res.blew_up ? nan : err_l2 / ref_l2;
  res.rel_error_max = res.blew_up ? nan : err_max / max_exact;
  return res;
}

}  // namespace gpm
