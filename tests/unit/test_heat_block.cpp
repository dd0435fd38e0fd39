// solve_heat_block: several θ-method series on one Laplacian, sharing every product, each
// equal to solve_heat of its setting alone, bit for bit (heat.hpp).  Coarse levels of the
// thesis' heat problem (§4.3): θ = 0, ½, 1 and other time steps, uneven volumes.
#include <catch2/catch.hpp>
#include <cmath>

#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// Every field but the times (a joint run's time is shared by its series).
void check_same(const HeatResult& a, const HeatResult& b) {
  CHECK(a.K == b.K);
  CHECK(a.dt == b.dt);
  CHECK(a.steps_done == b.steps_done);
  CHECK(a.blew_up == b.blew_up);
  CHECK(a.blowup_step == b.blowup_step);
  CHECK(a.growth_max == b.growth_max);
  CHECK(a.mean_cg_iterations == b.mean_cg_iterations);
  CHECK(a.max_rel_residual == b.max_rel_residual);
  if (!a.blew_up) {
    CHECK(a.rel_error == b.rel_error);
    CHECK(a.rel_error_max == b.rel_error_max);
  } else {
    CHECK(a.growth == b.growth);
    CHECK(a.amplification == b.amplification);
  }
}

}  // namespace

TEST_CASE("heat series advanced together equal each series alone", "[heat][block]") {
  for (int level : {5, 6}) {
    const double dx = std::ldexp(1.0, -level), h = pde_h(HRule::h10, dx);
    const Particles p = jittered_grid(dx, 1);
    std::vector<double> V;
    for (std::size_t i = 0; i < p.size(); ++i)
      V.push_back(dx * dx * (0.9 + 0.2 * std::fabs(std::sin(3.0 * static_cast<double>(i)))));
    const DiscreteLaplacian L(p, V, weight("piecewise_cubic_polynomial"), h);
    std::vector<HeatSetting> settings;
    for (double th : {0.0, 0.5, 1.0}) {
      HeatSetting s;
      s.theta = th;
      s.dt_nominal = 0.5 * h * h;  // Table 4.6: θ = 0 grows here, θ > 0 needs CG
      settings.push_back(s);
    }
    // Other step counts in the same run: the series drop out at different steps.
    HeatSetting longer = settings[1];
    longer.dt_nominal = 0.2 * h * h;
    longer.fit_T = false;
    settings.push_back(longer);
    HeatSetting guarded = settings[0];
    guarded.blowup_factor = 5;  // θ = 0 grows past 5 here (×12 at 2^-5): it drops out
    settings.push_back(guarded);
    const std::vector<HeatResult> together = solve_heat_block(p, L, settings);
    REQUIRE(together.size() == settings.size());
    for (std::size_t i = 0; i < settings.size(); ++i) {
      INFO("level 2^-" << level << ", series " << i << ", theta " << settings[i].theta);
      check_same(together[i], solve_heat(p, L, settings[i]));
    }
    CHECK(together[1].mean_cg_iterations > 0);
    CHECK(together[4].blew_up);
    CHECK(together[3].K > together[1].K);
  }
}

// The extrapolated start 2U^k − U^{k−1} (an option, off by default): the same solution to
// the CG tolerance, in fewer iterations where U changes smoothly in time.  Measured here
// (2^-6, quartic): Δt₀ = 0.0025h², 3 → 2.0 iterations per step, errors 1e-7 apart
// (relative); Δt₀ = 0.5h², 14.1 → 13.5 (θ = ½) and 18 → 16.6 (θ = 1), 1e-11 apart.
TEST_CASE("heat: extrapolated CG starts save iterations, same errors", "[heat][block]") {
  const double dx = std::ldexp(1.0, -6), h = pde_h(HRule::h10, dx);
  const Particles p = jittered_grid(dx, 1);
  const std::vector<double> V(p.size(), Domain{}.area_H() / static_cast<double>(p.size()));
  const DiscreteLaplacian L(p, V, weight("quartic_polynomial"), h);
  std::vector<HeatSetting> settings;
  for (double c : {0.0025, 0.5})  // Δt₀ = c h² (Tables 4.5 and 4.6)
    for (double th : {0.5, 1.0})
      for (bool extrapolate : {false, true}) {
        HeatSetting s;
        s.theta = th;
        s.dt_nominal = c * h * h;
        s.extrapolate = extrapolate;
        settings.push_back(s);
      }
  const std::vector<HeatResult> r = solve_heat_block(p, L, settings);
  for (std::size_t i = 0; i < r.size(); i += 2) {
    INFO("dt " << r[i].dt << ", theta " << settings[i].theta << ": CG "
               << r[i].mean_cg_iterations << " -> " << r[i + 1].mean_cg_iterations << " it/step");
    CHECK(r[i + 1].mean_cg_iterations < r[i].mean_cg_iterations);
    CHECK(std::fabs(r[i + 1].rel_error - r[i].rel_error) <= 1e-6 * r[i].rel_error);
  }
}

// The reading matrix of the heat tables on one Laplacian: a series with other volumes
// (volumes_for: V_i = Δx² beside (A.10)'s, or uneven ones) advanced in the same block as the
// Laplacian's own equals a run on a Laplacian assembled with those volumes, bit for bit —
// the boundary block c = M_ΩB ŝ and the norms included.
TEST_CASE("heat series with other volumes on one Laplacian equal their own Laplacian's",
          "[heat][block]") {
  const int level = 5;
  const double dx = std::ldexp(1.0, -level), h = pde_h(HRule::h15, dx);
  const Particles p = jittered_grid(dx, 1);
  const WeightFunction& w = weight("quartic_polynomial");
  const std::vector<double> lattice(p.size(), Domain{}.area_H() / static_cast<double>(p.size()));
  const std::vector<double> cell(p.size(), dx * dx);
  std::vector<double> uneven;
  for (std::size_t i = 0; i < p.size(); ++i)
    uneven.push_back(dx * dx * (0.9 + 0.2 * std::fabs(std::sin(3.0 * static_cast<double>(i)))));
  const DiscreteLaplacian L(p, lattice, w, h, LaplacianStorage::assembled);
  const DiscreteLaplacian::Volumes vc = L.volumes_for(p, w, cell), vu = L.volumes_for(p, w, uneven);
  std::vector<HeatSetting> settings;
  for (const DiscreteLaplacian::Volumes* v : {static_cast<const DiscreteLaplacian::Volumes*>(nullptr), &vc, &vu})
    for (double th : {0.0, 0.5, 1.0})
      for (bool fit : {true, false}) {
        HeatSetting s;
        s.theta = th;
        s.dt_nominal = 0.5 * h * h;
        s.fit_T = fit;
        s.volumes = v;
        settings.push_back(s);
      }
  const std::vector<HeatResult> together = solve_heat_block(p, L, settings);
  const DiscreteLaplacian Lc(p, cell, w, h, LaplacianStorage::assembled);
  const DiscreteLaplacian Lu(p, uneven, w, h, LaplacianStorage::assembled);
  for (std::size_t i = 0; i < settings.size(); ++i) {
    HeatSetting alone = settings[i];
    alone.volumes = nullptr;
    const DiscreteLaplacian& own = i < 6 ? L : i < 12 ? Lc : Lu;
    INFO("series " << i << ", theta " << settings[i].theta);
    check_same(together[i], solve_heat(p, own, alone));
  }
  // The volumes matter: (A.10) and Δx² differ by 1+δ, and so do the errors.
  CHECK(together[2].rel_error != together[8].rel_error);
  // The boundary block with other volumes, alone: equal to the other Laplacian's.
  Eigen::VectorXd v(static_cast<Eigen::Index>(p.size())), a, b;
  for (std::size_t i = 0; i < p.size(); ++i) v[static_cast<Eigen::Index>(i)] = std::cos(7.0 * p.x[i]) + p.y[i];
  L.apply_full(v, a, &vu);
  Lu.apply_full(v, b);
  CHECK(a == b);
}
