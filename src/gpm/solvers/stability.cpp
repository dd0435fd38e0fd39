#include "gpm/solvers/stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gpm/error.hpp"

namespace gpm {

namespace {

// Seeded uniform values in [−1, 1] (splitmix64): the same start vector on every machine.
Eigen::VectorXd random_vector(Eigen::Index n, uint64_t seed) {
  Eigen::VectorXd v(n);
  uint64_t s = seed * 0x9E3779B97F4A7C15ULL + 0x2545F4914F6CDD1DULL;
  for (Eigen::Index i = 0; i < n; ++i) {
    uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    v[i] = 2.0 * (static_cast<double>(z >> 11) * 0x1.0p-53) - 1.0;
  }
  return v;
}

Eigen::VectorXd unknown_volumes(const DiscreteLaplacian& L) {
  Eigen::VectorXd d(static_cast<Eigen::Index>(L.n_unknowns()));
  for (Eigen::Index k = 0; k < d.size(); ++k) d[k] = L.volumes()[L.omega()[k]];
  return d;
}

}  // namespace

LanczosResult largest_eigenvalue(const DiscreteLaplacian& L, double tol, int max_iter,
                                 uint64_t seed) {
  require_positive(tol, "Lanczos tolerance");
  const Eigen::Index n = static_cast<Eigen::Index>(L.n_unknowns());
  const Eigen::VectorXd sd = unknown_volumes(L).array().sqrt();
  // B x = D^{1/2} (−M) D^{-1/2} x: symmetric, same eigenvalues as −M.
  Eigen::VectorXd tmp(n), Mx(n);
  auto B = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    tmp = (x.array() / sd.array()).matrix();
    L.apply(tmp, Mx);
    y = (-(sd.array() * Mx.array())).matrix();
  };
  Eigen::VectorXd q = random_vector(n, seed), q_prev = Eigen::VectorXd::Zero(n), w(n);
  q /= q.norm();
  std::vector<double> alpha, beta;
  LanczosResult res;
  double beta_prev = 0;
  for (int j = 0; j < std::min<Eigen::Index>(max_iter, n); ++j) {
    B(q, w);
    w -= beta_prev * q_prev;
    const double a = q.dot(w);
    w -= a * q;
    const double b = w.norm();
    if (!std::isfinite(a) || !std::isfinite(b))
      throw NumericalError("Lanczos: non-finite value at iteration " + std::to_string(j + 1));
    alpha.push_back(a);
    beta.push_back(b);
    res.iterations = j + 1;
    // The Ritz values of the tridiagonal T_{j+1}; check often early, then every 5 steps.
    const int m = j + 1;
    const bool invariant = b <= 1e-14 * std::fabs(a);
    if (m >= 2 && (m < 40 || m % 5 == 0 || invariant || m == max_iter || m == n)) {
      Eigen::VectorXd dg = Eigen::Map<Eigen::VectorXd>(alpha.data(), m);
      Eigen::VectorXd sub = Eigen::Map<Eigen::VectorXd>(beta.data(), m - 1);
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
      es.computeFromTridiagonal(dg, sub, Eigen::ComputeEigenvectors);
      res.lambda_max = es.eigenvalues()[m - 1];
      res.residual = b * std::fabs(es.eigenvectors()(m - 1, m - 1));
      if (invariant || res.residual <= tol * std::fabs(res.lambda_max) || m == n) {
        res.converged = true;
        return res;
      }
    }
    q_prev = q;
    q = w / b;
    beta_prev = b;
  }
  throw NumericalError("Lanczos: largest eigenvalue not converged to relative residual " +
                       std::to_string(tol) + " in " + std::to_string(res.iterations) +
                       " iterations (now " + std::to_string(res.residual / res.lambda_max) + ")");
}

double theta_amplification(double mu, double theta) {
  return (1 - (1 - theta) * mu) / (1 + theta * mu);
}

double stability_limit(double lambda_max, double kappa, double theta) {
  if (theta >= 0.5) return std::numeric_limits<double>::infinity();
  return 2.0 / ((1 - 2 * theta) * kappa * lambda_max);
}

double thesis_bound_33(const WeightFunction& w, double h, double kappa, double theta,
                       double delta, int d) {
  if (!(theta >= 0 && theta < 1)) throw InputError("bound (3.3) needs theta in [0, 1)");
  const double cw = compute_properties(w).inv_r2_integral;
  if (!std::isfinite(cw))
    throw InputError("weight '" + w.name + "': the integral of w/|x|^2 diverges, (3.3) is void");
  return std::min(delta / (2 * d * kappa * (1 - theta) * cw) * h * h, 1 / (1 - theta));
}

double thesis_condition_37(const DiscreteLaplacian& L, double kappa, double theta) {
  const double dmax = L.diagonal().cwiseAbs().maxCoeff();
  return 1.0 / ((1 - theta) * kappa * dmax);
}

StabilityRun run_homogeneous(const DiscreteLaplacian& L, double kappa, double theta, double dt,
                             long max_steps, double stop_growth, uint64_t seed,
                             double cg_tol) {
  require_positive(dt, "time step");
  const Eigen::Index n = static_cast<Eigen::Index>(L.n_unknowns());
  const Eigen::VectorXd d = unknown_volumes(L);
  const double kdt = kappa * dt;
  auto normD = [&](const Eigen::VectorXd& u) {
    return std::sqrt((d.array() * u.array().square()).sum());
  };
  Eigen::VectorXd U = random_vector(n, seed), y(n), rhs(n), b(n), tmp(n);
  const double u0 = normD(U);
  auto A = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
    L.apply(x, tmp);
    out = (d.array() * (x.array() - theta * kdt * tmp.array())).matrix();
  };
  StabilityRun r;
  double prev = u0;
  long cg_total = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < max_steps; ++k) {
    rhs = U;
    if (theta < 1) {
      L.apply(U, y);
      rhs += (1 - theta) * kdt * y;
    }
    if (theta > 0) {
      b = (d.array() * rhs.array()).matrix();
      const CgResult c = conjugate_gradient(A, b, U, cg_tol, 20000,
                                            "stability run step " + std::to_string(k + 1));
      cg_total += c.iterations;
    } else {
      U = rhs;
    }
    const double un = normD(U);
    r.steps = k + 1;
    r.growth_final = un / u0;
    r.last_factor = un / prev;
    r.growth_max = std::max(r.growth_max, r.growth_final);
    prev = un;
    if (!std::isfinite(un) || un > stop_growth * u0) {
      r.grew = true;
      break;
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cg_mean_iterations = static_cast<double>(cg_total) / static_cast<double>(std::max(1L, r.steps));
  return r;
}

}  // namespace gpm
