// The Krylov propagator (heat_krylov.hpp) against the stepper (heat.hpp), which stays the
// reference: the solution U^k of every step and the errors equal the stepped ones to 1e-9 of
// the series' largest error, for the three tables' time steps, both readings of Δt, θ = 0,
// ½, 1, uniform and uneven volumes (own and through volumes_for), and a guarded blow-up.
// The stepped reference solves each implicit step to 1e-14 (at the tables' 1e-10 the CG's
// own error is about 1e-7 of the error, test_heat_block).
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>

#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/heat_krylov.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

struct Trajectory {
  std::map<long, Eigen::VectorXd> U;
};

// ‖x‖ in the volume norm of the unknowns.
double vnorm(const Eigen::VectorXd& x, const Eigen::VectorXd& d) {
  return std::sqrt(d.dot(x.cwiseAbs2()));
}

// Both propagators on the same settings; every step's U compared.  Returns the largest
// difference of U relative to the largest ℓ² error over the series.
double compare(const Particles& p, const DiscreteLaplacian& L, std::vector<HeatSetting> settings,
               const Eigen::VectorXd& d) {
  std::vector<Trajectory> stepped(settings.size()), krylov(settings.size());
  std::vector<HeatSetting> ref = settings;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    ref[i].tol = 1e-14;
    ref[i].observe = [&stepped, i](long k, const Eigen::VectorXd& U) { stepped[i].U[k] = U; };
    settings[i].observe = [&krylov, i](long k, const Eigen::VectorXd& U) { krylov[i].U[k] = U; };
  }
  const auto a = solve_heat_block(p, L, ref);
  const auto b = propagate_heat(p, L, settings);
  double worst = 0;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    INFO("series " << i << ": theta " << settings[i].theta << ", dt0 " << settings[i].dt_nominal
                   << (settings[i].fit_T ? " fit" : " exact") << ", K " << a[i].K << ", m " << b[i].subspace);
    REQUIRE(a[i].K == b[i].K);
    CHECK(a[i].dt == b[i].dt);
    CHECK(a[i].steps_done == b[i].steps_done);
    CHECK(a[i].blew_up == b[i].blew_up);
    CHECK(a[i].blowup_step == b[i].blowup_step);
    CHECK(b[i].subspace > 0);
    CHECK(b[i].mean_cg_iterations == 0);
    CHECK(std::fabs(a[i].growth_max - b[i].growth_max) <= 1e-11 * a[i].growth_max);
    REQUIRE(stepped[i].U.size() == static_cast<std::size_t>(a[i].steps_done));
    REQUIRE(krylov[i].U.size() == stepped[i].U.size());
    // The error scale: the largest ℓ² error over the steps, in the volume norm on Ω.
    double err = 0, diff = 0;
    for (auto& [k, U] : stepped[i].U) {
      const double ek = std::exp(-2 * settings[i].kappa * M_PI * M_PI * a[i].dt * static_cast<double>(k));
      Eigen::VectorXd exact = Eigen::VectorXd::Zero(U.size());
      for (Eigen::Index j = 0; j < U.size(); ++j) {
        const auto pj = static_cast<std::size_t>(L.omega()[static_cast<std::size_t>(j)]);
        exact[j] = ek * heat_exact(p.x[pj], p.y[pj], 0, settings[i].kappa);
      }
      err = std::max(err, vnorm(exact - U, d));
      diff = std::max(diff, vnorm(krylov[i].U.at(k) - U, d));
    }
    INFO("largest error " << err << ", largest trajectory difference " << diff);
    CHECK(diff <= 1e-9 * err);
    worst = std::max(worst, diff / err);
    if (a[i].blew_up) {
      CHECK(std::fabs(a[i].growth - b[i].growth) <= 1e-9 * a[i].growth);
      CHECK(std::isnan(b[i].rel_error));
    } else {
      CHECK(std::fabs(a[i].rel_error - b[i].rel_error) <= 1e-9 * a[i].rel_error);
      CHECK(std::fabs(a[i].rel_error_max - b[i].rel_error_max) <= 1e-9 * a[i].rel_error_max);
    }
  }
  return worst;
}

// The tables' time steps (4.5: 0.0025h², 4.6: 0.5h², 4.7: 0.5h), both Δt readings, θ = 0, ½, 1.
std::vector<HeatSetting> table_settings(double h, bool with_table_4_5) {
  std::vector<HeatSetting> out;
  std::vector<double> dts = {0.5 * h * h, 0.5 * h};
  if (with_table_4_5) dts.insert(dts.begin(), 0.0025 * h * h);
  for (double dt0 : dts)
    for (bool fit : {true, false})
      for (double th : {0.0, 0.5, 1.0}) {
        if (dt0 == 0.5 * h && th == 0) continue;  // Table 4.7 has no θ = 0
        HeatSetting s;
        s.theta = th, s.dt_nominal = dt0, s.fit_T = fit;
        out.push_back(s);
      }
  return out;
}

}  // namespace

TEST_CASE("Krylov propagator equals the stepper: every time step, theta and volume", "[heat][krylov]") {
  const double dx = std::ldexp(1.0, -5);
  const Particles p = jittered_grid(dx, 1);
  for (HRule rule : {HRule::h15, HRule::h10}) {
    const double h = pde_h(rule, dx);
    const auto lattice = pde_volumes(PdeVolumes::lattice, p, dx);
    const auto cell = pde_volumes(PdeVolumes::cell, p, dx);
    const WeightFunction& w = weight("quartic_polynomial");
    const DiscreteLaplacian L(p, lattice, w, h, LaplacianStorage::assembled);
    INFO("h rule " << h_rule_name(rule));
    // (A.10)'s volumes, the Laplacian's own.
    Eigen::VectorXd d(static_cast<Eigen::Index>(L.n_unknowns()));
    for (Eigen::Index j = 0; j < d.size(); ++j) d[j] = lattice[static_cast<std::size_t>(L.omega()[static_cast<std::size_t>(j)])];
    CHECK(compare(p, L, table_settings(h, rule == HRule::h15), d) <= 1e-9);
    // V_i = Δx² on the same Laplacian (volumes_for), the identified reading's volumes.
    const auto other = L.volumes_for(p, w, cell);
    auto settings = table_settings(h, false);
    for (auto& s : settings) s.volumes = &other;
    CHECK(compare(p, L, settings, other.at_unknowns) <= 1e-9);
  }
}

TEST_CASE("Krylov propagator on uneven volumes and a guarded blow-up", "[heat][krylov]") {
  const double dx = std::ldexp(1.0, -5), h = pde_h(HRule::h10, dx);
  const Particles p = jittered_grid(dx, 2);
  std::vector<double> V;
  for (std::size_t i = 0; i < p.size(); ++i)
    V.push_back(dx * dx * (0.9 + 0.2 * std::fabs(std::sin(3.0 * static_cast<double>(i)))));
  const DiscreteLaplacian L(p, V, weight("piecewise_quintic_polynomial"), h);
  Eigen::VectorXd d(static_cast<Eigen::Index>(L.n_unknowns()));
  for (Eigen::Index j = 0; j < d.size(); ++j) d[j] = V[static_cast<std::size_t>(L.omega()[static_cast<std::size_t>(j)])];
  std::vector<HeatSetting> settings;
  for (double th : {0.0, 0.5, 1.0}) {
    HeatSetting s;
    s.theta = th, s.dt_nominal = 0.5 * h * h;
    settings.push_back(s);
  }
  HeatSetting guarded = settings[0];
  guarded.blowup_factor = 5;  // θ = 0 grows past 5 here: the run stops at that step
  settings.push_back(guarded);
  CHECK(compare(p, L, settings, d) <= 1e-9);
  const auto r = propagate_heat(p, L, {guarded});
  CHECK(r[0].blew_up);
  CHECK(r[0].growth > 5);
  CHECK(r[0].steps_done == r[0].blowup_step);
}

TEST_CASE("Krylov propagator: one subspace per operator, products counted", "[heat][krylov]") {
  const double dx = std::ldexp(1.0, -5), h = pde_h(HRule::h15, dx);
  const Particles p = jittered_grid(dx, 1);
  const auto V = pde_volumes(PdeVolumes::lattice, p, dx);
  const DiscreteLaplacian L(p, V, weight("piecewise_cubic_polynomial"), h);
  std::vector<HeatSetting> settings = table_settings(h, true);
  // Each larger size tried is reported (a run's progress lines): sizes growing, the last one
  // the subspace taken, whose change is the first within the tolerance.
  KrylovSettings ks;
  std::vector<KrylovTry> tried;
  ks.on_size = [&tried](const KrylovTry& t) { tried.push_back(t); };
  const auto r = propagate_heat(p, L, settings, ks);
  REQUIRE(tried.size() >= 2);
  for (std::size_t i = 1; i < tried.size(); ++i) CHECK(tried[i].m > tried[i - 1].m);
  for (std::size_t i = 0; i + 1 < tried.size(); ++i) CHECK(tried[i].change > ks.tol);
  CHECK(tried.back().m == r[0].subspace);
  CHECK(tried.back().change <= ks.tol);
  // Here the tolerance is reached while the change still falls fast: never a rounding stop.
  for (const KrylovTry& t : tried) CHECK_FALSE(t.rounding);
  // Every series of one operator shares one subspace: one dimension, equal shares of it.
  for (auto& x : r) {
    CHECK(x.subspace == r[0].subspace);
    CHECK(x.products * static_cast<double>(r.size()) == Approx(r[0].products * static_cast<double>(r.size())));
  }
  // Far fewer products than stepping Table 4.5's 6,000 steps.
  CHECK(r[0].products * static_cast<double>(r.size()) < 400);
  // The automatic choice: Table 4.5's thousands of steps to the subspace, Table 4.6's 31
  // explicit steps stepped (the subspace needs about 130 products here).
  CHECK(heat_stepped_products(dx, h, 0.0025 * h * h, 0.1, 0) > heat_krylov_products(dx, h));
  CHECK(heat_stepped_products(dx, h, 0.5 * h * h, 0.1, 0) < heat_krylov_products(dx, h));
  const auto mixed = run_heat(p, L, settings, {HeatPropagator::automatic}, dx);
  const auto stepped = solve_heat_block(p, L, settings);
  for (std::size_t i = 0; i < settings.size(); ++i) {
    INFO("series " << i);
    const bool k = heat_stepped_products(dx, h, settings[i].dt_nominal, 0.1, settings[i].theta) >
                   heat_krylov_products(dx, h);
    CHECK((mixed[i].subspace > 0) == k);
    CHECK(mixed[i].blew_up == stepped[i].blew_up);
    if (!stepped[i].blew_up) CHECK(mixed[i].rel_error == Approx(stepped[i].rel_error).epsilon(1e-6));
  }
  CHECK(parse_heat_propagator("auto") == HeatPropagator::automatic);
  CHECK_THROWS_AS(parse_heat_propagator("rk4"), InputError);
}

TEST_CASE("Krylov propagator: a tolerance below rounding stops where the change stalls", "[heat][krylov]") {
  const double dx = std::ldexp(1.0, -5), h = pde_h(HRule::h15, dx);
  const Particles p = jittered_grid(dx, 1);
  const auto V = pde_volumes(PdeVolumes::lattice, p, dx);
  const DiscreteLaplacian L(p, V, weight("piecewise_quintic_polynomial"), h);
  // Table 4.5's series (Δt = 0.0025h²) for each θ, as at the level where this stop was needed.
  std::vector<HeatSetting> settings;
  for (double th : {0.0, 0.5, 1.0}) {
    HeatSetting s;
    s.theta = th, s.dt_nominal = 0.0025 * h * h, s.fit_T = false;
    settings.push_back(s);
  }
  const auto reference = propagate_heat(p, L, settings);
  // 1e-30 of the error is far below what doubles resolve: the change stalls at rounding, and
  // the subspace where it stalls gives the errors of the default tolerance.
  KrylovSettings ks;
  ks.tol = 1e-30;
  std::vector<KrylovTry> tried;
  ks.on_size = [&tried](const KrylovTry& t) { tried.push_back(t); };
  const auto r = propagate_heat(p, L, settings, ks);
  REQUIRE(tried.size() >= 2);
  CHECK(tried.back().rounding);
  CHECK(tried.back().of_data <= ks.rounding);
  for (std::size_t i = 0; i + 1 < tried.size(); ++i) CHECK_FALSE(tried[i].rounding);
  CHECK(r[0].subspace >= reference[0].subspace);
  for (std::size_t i = 0; i < settings.size(); ++i) {
    INFO("series " << i);
    CHECK(r[i].blew_up == reference[i].blew_up);
    if (!reference[i].blew_up) CHECK(r[i].rel_error == Approx(reference[i].rel_error).epsilon(1e-8));
  }
  // Without the rounding stop the same tolerance is never met: a numerical failure, not a hang.
  ks.rounding = 0, ks.max_dim = 2 * r[0].subspace, ks.on_size = nullptr;
  CHECK_THROWS_AS(propagate_heat(p, L, settings, ks), NumericalError);
  ks.stall = 1;
  CHECK_THROWS_AS(propagate_heat(p, L, settings, ks), InputError);
}

// Issue 58, item 2: the three tables' series on one subspace, each table its own size group,
// give each table's numbers alone, bit for bit (the first m columns of a basis grown further
// are the basis grown to m); one size group for all would size every table's subspace by the
// most demanding one, and change the others' numbers.
TEST_CASE("Krylov propagator: size groups share a subspace and keep their own numbers", "[heat][krylov]") {
  const double dx = std::ldexp(1.0, -5), h = pde_h(HRule::h15, dx);
  const Particles p = jittered_grid(dx, 1);
  const auto V = pde_volumes(PdeVolumes::cell, p, dx);
  const DiscreteLaplacian L(p, V, weight("piecewise_quintic_polynomial"), h);
  std::vector<std::vector<HeatSetting>> tables;
  for (double dt0 : {0.0025 * h * h, 0.5 * h * h, 0.5 * h}) {
    std::vector<HeatSetting> t;
    for (double th : {0.0, 0.5, 1.0}) {
      if (dt0 == 0.5 * h && th == 0) continue;  // Table 4.7 has no θ = 0
      HeatSetting s;
      s.theta = th, s.dt_nominal = dt0, s.fit_T = false, s.size_group = static_cast<int>(tables.size());
      t.push_back(s);
    }
    tables.push_back(t);
  }
  std::vector<HeatSetting> all;
  std::vector<HeatResult> alone;
  KrylovSettings ks;
  long products_alone = 0;
  for (auto& t : tables) {
    const auto r = propagate_heat(p, L, t, ks);
    alone.insert(alone.end(), r.begin(), r.end());
    all.insert(all.end(), t.begin(), t.end());
    products_alone += std::lround(r[0].products * static_cast<double>(r.size()));
  }
  const auto shared = propagate_heat(p, L, all, ks);
  std::set<int> sizes;
  for (std::size_t i = 0; i < all.size(); ++i) {
    INFO("series " << i << ": table " << all[i].size_group << ", theta " << all[i].theta);
    CHECK(shared[i].subspace == alone[i].subspace);
    CHECK(shared[i].blew_up == alone[i].blew_up);
    CHECK(shared[i].steps_done == alone[i].steps_done);
    CHECK(shared[i].growth_max == alone[i].growth_max);
    if (!alone[i].blew_up) {
      CHECK(shared[i].rel_error == alone[i].rel_error);
      CHECK(shared[i].rel_error_max == alone[i].rel_error_max);
    }
    sizes.insert(alone[i].subspace);
  }
  // The case is one where sharing could go wrong: the tables settle at different sizes, and
  // the shared basis costs the largest one's products, not the sum.
  REQUIRE(sizes.size() >= 2);
  const long products_shared = std::lround(shared[0].products * static_cast<double>(shared.size()));
  CHECK(products_shared == *sizes.rbegin());
  CHECK(products_shared < products_alone);
  // One size group for all: the smaller tables take the largest size, and their numbers move.
  for (auto& s : all) s.size_group = 0;
  const auto merged = propagate_heat(p, L, all, ks);
  bool moved = false;
  for (std::size_t i = 0; i < all.size(); ++i) {
    CHECK(merged[i].subspace == *sizes.rbegin());
    moved = moved || (!alone[i].blew_up && merged[i].rel_error != alone[i].rel_error);
  }
  CHECK(moved);
}
