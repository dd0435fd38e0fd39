// The τ preconditioner (solvers/tau_preconditioner.hpp): its eigenvalues against the
// stencil's symbol summed directly, its inverse on the sine modes of the plain grid, and
// preconditioned CG against plain CG on the thesis' Poisson problem (issue 58: the same
// solution, far fewer iterations).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/poisson_probes.hpp"
#include "gpm/solvers/tau_preconditioner.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

TEST_CASE("tau preconditioner: separable eigenvalues equal the stencil's symbol", "[tau]") {
  const double dx = std::ldexp(1.0, -5);
  const Particles p = jittered_grid(dx, 1);
  for (HRule rule : {HRule::h10, HRule::h15}) {
    const double h = pde_h(rule, dx);
    const DiscreteLaplacian L(p, std::vector<double>(p.size(), dx * dx), weight("quartic_polynomial"), h);
    const TauPreconditioner P(p, L, weight("quartic_polynomial"), dx);
    for (int a : {1, 2, P.nx() / 2, P.nx()})
      for (int b : {1, 3, P.ny()}) {
        const double direct = P.symbol(M_PI * a / (P.nx() + 1), M_PI * b / (P.ny() + 1));
        const double sep = P.eigenvalues()[static_cast<std::size_t>(a - 1) * P.ny() + (b - 1)];
        CHECK(sep == Approx(direct).epsilon(1e-12));
        CHECK(sep > 0);
      }
  }
}

TEST_CASE("tau preconditioner: inverts the tau matrix on the plain grid's sine modes", "[tau]") {
  // The plain grid's unknowns fill their lattice rectangle, so a sine mode v of it is an
  // eigenvector of T1 and P = D T1 D maps D^-1 v to lambda D v: P^-1 must undo that.
  const double dx = std::ldexp(1.0, -5);
  const Particles p = jittered_grid(dx, 1, 0.0);
  const WeightFunction& w = weight("piecewise_cubic_polynomial");
  const std::vector<double> V = pde_volumes(PdeVolumes::lattice, p, dx);
  const DiscreteLaplacian L(p, V, w, pde_h(HRule::h15, dx));
  for (double shift : {0.0, 3.0}) {
    const TauPreconditioner P(p, L, w, dx, shift, 0.5);
    REQUIRE(static_cast<std::size_t>(P.nx()) * P.ny() == L.n_unknowns());
    const auto& omega = L.omega();
    int i0 = p.gi[omega[0]], j0 = p.gj[omega[0]];
    for (int32_t k : omega) i0 = std::min(i0, p.gi[k]), j0 = std::min(j0, p.gj[k]);
    for (auto [a, b] : {std::pair{1, 1}, std::pair{2, 5}, std::pair{P.nx(), 3}}) {
      const double lam = shift + 0.5 * P.eigenvalues()[static_cast<std::size_t>(a - 1) * P.ny() + (b - 1)];
      Eigen::VectorXd r(static_cast<Eigen::Index>(omega.size())), want(r.size()), z;
      for (std::size_t u = 0; u < omega.size(); ++u) {
        const int32_t k = omega[u];
        const double v = std::sin(M_PI * a * (p.gi[k] - i0 + 1) / (P.nx() + 1)) *
                         std::sin(M_PI * b * (p.gj[k] - j0 + 1) / (P.ny() + 1));
        r[static_cast<Eigen::Index>(u)] = lam * V[k] * v;
        want[static_cast<Eigen::Index>(u)] = v / V[k];
      }
      P.apply(r, z);
      CHECK((z - want).norm() <= 1e-12 * want.norm());
    }
  }
}

TEST_CASE("tau preconditioner: refuses a bad set-up", "[tau]") {
  const double dx = std::ldexp(1.0, -4);
  const Particles p = jittered_grid(dx, 1);
  const WeightFunction& w = weight("quartic_polynomial");
  const DiscreteLaplacian L(p, pde_volumes(PdeVolumes::cell, p, dx), w, pde_h(HRule::h15, dx));
  CHECK_THROWS_AS(TauPreconditioner(p, L, w, 0.0), InputError);
  CHECK_THROWS_AS(TauPreconditioner(p, L, w, dx, -1.0), InputError);
  CHECK_THROWS_AS(TauPreconditioner(p, L, w, dx, 0.0, 0.0), InputError);
}

TEST_CASE("tau preconditioner: PCG solves the thesis' Poisson problem as plain CG does", "[tau]") {
  // Table 4.4's problem on the jittered grid, both h rules, every weight, both volume
  // readings: the solutions agree to the solver tolerance's reach and the iterations fall.
  const TestFunction& u = test_function("sin2pi");
  for (int k : {5, 6}) {
    const double dx = std::ldexp(1.0, -k);
    const Particles p = jittered_grid(dx, 2);
    const PoissonData d = poisson_data(p, u);
    for (PdeVolumes vol : {PdeVolumes::lattice, PdeVolumes::cell})
      for (HRule rule : {HRule::h10, HRule::h15})
        for (const char* wn : {"quartic_polynomial", "piecewise_cubic_polynomial",
                               "piecewise_quintic_polynomial"}) {
          INFO("level " << k << ", " << wn << ", h rule " << (rule == HRule::h10 ? "h10" : "h15")
                        << ", volumes " << pde_volumes_name(vol));
          const std::vector<double> V = pde_volumes(vol, p, dx);
          const DiscreteLaplacian L(p, V, weight(wn), pde_h(rule, dx));
          const PoissonResult plain = solve_poisson(p, L, d.f, d.g, 1e-12);
          const TauPreconditioner P(p, L, weight(wn), dx);
          const PoissonResult pre = solve_poisson(p, L, d.f, d.g, 1e-12, 20000, true, &P);
          double diff = 0;
          for (std::size_t i = 0; i < p.size(); ++i)
            diff = std::max(diff, std::fabs(plain.U[i] - pre.U[i]));
          CHECK(diff <= 1e-9 * d.umax);
          CHECK(pre.cg.rel_residual <= 1e-12 * 1e3);
          CHECK(pre.cg.iterations <= 30);
          CHECK(2 * pre.cg.iterations < plain.cg.iterations);
        }
  }
}

TEST_CASE("tau preconditioner: implicit heat steps give plain CG's errors in fewer iterations", "[tau]") {
  // Table 4.6's steps (dt0 = 0.5 h^2, the largest theta*kappa*dt of the stepped tables) at
  // theta = 1/2 and 1: P = D(I/V + theta kappa dt T1)D for the system D - theta kappa dt D M.
  const double dx = std::ldexp(1.0, -5);
  const Particles p = jittered_grid(dx, 1);
  const WeightFunction& w = weight("quartic_polynomial");
  const double h = pde_h(HRule::h15, dx);
  const std::vector<double> V = pde_volumes(PdeVolumes::lattice, p, dx);
  const DiscreteLaplacian L(p, V, w, h);
  for (double theta : {0.5, 1.0}) {
    HeatSetting s;
    s.theta = theta, s.dt_nominal = 0.5 * h * h, s.tol = 1e-12;
    const HeatResult plain = solve_heat(p, L, s);
    const double dt = s.T / static_cast<double>(heat_steps(s.T, s.dt_nominal));
    const TauPreconditioner P(p, L, w, dx, 1.0 / V[L.omega()[0]], theta * s.kappa * dt);
    s.pc = &P;
    const HeatResult pre = solve_heat(p, L, s);
    INFO("theta " << theta << ": CG " << plain.mean_cg_iterations << " its/step, PCG "
                  << pre.mean_cg_iterations);
    CHECK(pre.rel_error == Approx(plain.rel_error).epsilon(1e-9));
    CHECK(pre.mean_cg_iterations < plain.mean_cg_iterations);
  }
}
