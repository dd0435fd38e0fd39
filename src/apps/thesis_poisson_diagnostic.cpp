// thesis_poisson_diagnostic: why Table 4.4 (thesis §4.2) is not reproduced at the thesis'
// levels 2^-8, 2^-9 (rates 1.02, 0.89, 0.38 with the printed h10, negative with h15, against
// the published 1.95, 1.99, 2.00).  For each reading of h, weight and level, the discrete
// Poisson problem of Table 4.4 is solved on six particle sets — the jittered grid with
// seeds 1, 2, 3 and the plain grid (jitter 0), all with the thesis' volumes (A.10)
// V_i = |Omega_H|/N, and seed 1 and the plain grid again with V_i = Δx² — and every row records
//   * the relative ℓ∞(Ω) error and the particle where it sits (its distance from ∂Ω in units
//     of h), and the same error over the particles at least h from ∂Ω (rel_error_inner);
//   * h/H: where h > H the stencils of particles near ∂Ω reach beyond Ω_H;
//   * the operator's consistency on u itself, measured and predicted.  For the Fourier mode
//     u = sin 2π(x+y) the discrete Laplacian is, before any particle effect,
//         Δ_h u ≈ (V_i/Δx²)(1 − ε(kh)) Δu,
//     ε the smoothing error (smoothing.hpp) and V_i/Δx² − 1 the volume mismatch (volumes.hpp):
//     tau_predicted = (V/Δx²)(1 − ε) − 1.  Measured: tau_fit = Σ τ_i Δu_i / Σ Δu_i² (signed,
//     τ_i = Δ_h u(x_i) − Δu(x_i) over Ω) and tau_max = max|τ_i| / max|Δu_i|.
// If the error follows |tau_predicted| at a constant ratio, the rates follow the volume
// mismatch and the smoothing error together, not h²; with V_i = Δx² the mismatch is gone.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/poisson_probes.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/run/runner.hpp"
#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// The measured consistency of Δ_h on u over Ω: the signed projection of τ = Δ_h u − Δu on Δu,
// and the max-norm ratio.
struct Consistency {
  double fit = 0, max = 0;
};
Consistency measured_consistency(const DiscreteLaplacian& L, const PoissonData& d) {
  const Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd>(d.g.data(), d.g.size());
  Eigen::VectorXd lap_h;
  L.apply_full(u, lap_h);
  double num = 0, den = 0, tmax = 0, lmax = 0;
  for (std::size_t q = 0; q < L.n_unknowns(); ++q) {
    const double lap = -d.f[L.omega()[q]];
    const double tau = lap_h[q] - lap;
    num += tau * lap, den += lap * lap;
    tmax = std::max(tmax, std::fabs(tau)), lmax = std::max(lmax, std::fabs(lap));
  }
  return {num / den, tmax / lmax};
}

// The program: the options read once; run() opens the cached data file and solves every
// registered unit (level, particle set, reading of h, weight) it lacks, among the weights and
// particle sets asked for.
class PoissonDiagnostic {
 public:
  // No --seed: the particle sets are the study's own variants (seeds 1-3, the plain grid).
  PoissonDiagnostic(int argc, char** argv)
      : run_(study_registry().study("thesis_poisson_diagnostic"),
             "Table 4.4 diagnostics: the Poisson error per reading of h, weight, level and particle\n"
             "set (seeds 1-3, plain grid), where its maximum sits, and the error away from the boundary.") {
    Args& a = run_.args();
    a.opt("weights", join(pde_weights(), ","), "comma-separated registry weights")
        .opt("variants", join(poisson_diagnostic().variant_names(), ","),
             "comma-separated particle sets (seedN: jitter 1/4 dx; plain: none; _cell: V_i = dx^2)")
        .opt("tol", "1e-10", "CG relative residual on the symmetric form");
    run_.parse(argc, argv);
    tol_ = a.tolerance("tol");
    weights_ = a.list("weights");
    for (auto& w : weights_) weight(w);  // InputError naming an unknown weight, before any work
    // The particle sets (the catalog's, poisson_diagnostic()): an unknown name is refused here.
    for (auto& name : a.list("variants")) variants_.push_back(poisson_diagnostic().variant(name));
  }

  int run() {
    open_data_file();
    for (const StudyUnit& unit : run_.units()) solve(unit);
    run_.finish();
    return 0;
  }

 private:
  // The data file: one row per (reading of h, weight, level, particle set).
  void open_data_file() {
    cache_ = &run_.open(
        {{"program", "thesis_poisson_diagnostic"}, {"profile", profile_name(run_.profile())},
         {"tol", fmt(tol_)}, {"function", "sin2pi"}, {"volumes", "uniform |Omega_H|/N"},
         {"h10", pde_h_formula(HRule::h10)}, {"h15", pde_h_formula(HRule::h15)},
         {"variants", "seed1, seed2, seed3: jitter 1/4 dx; plain: jitter 0; "
                      "_cell: V_i = dx^2 instead of |Omega_H|/N"},
         {"rel_error_inner", "max over particles at least h from the boundary of Omega"},
         {"volume_mismatch", "V_i/dx^2 - 1"},
         {"eps_smoothing", "smoothing error eps(kh), k = 2 pi sqrt 2 (gpm smoothing)"},
         {"tau_predicted", "(V_i/dx^2)(1 - eps) - 1"},
         {"tau_fit", "sum tau_i lap_i / sum lap_i^2 over Omega, tau = lap_h u - lap u"},
         {"tau_max", "max |tau_i| / max |lap u| over Omega"}},
        4);
  }

  // A particle set per (level, variant), shared by every reading and weight, made for the
  // first of its units still to compute.
  void particle_set(int k, const ParticleSet& var) {
    if (k == level_ && var.name == variant_) return;
    const double dx = std::ldexp(1.0, -k);
    p_ = jittered_grid(dx, var.seed, var.jitter, dom_);
    V_ = pde_volumes(var.volumes, p_, dx, dom_);
    d_ = poisson_data(p_, test_function("sin2pi"));
    level_ = k, variant_ = var.name;
  }

  // One unit (the registry's key: h rule, weight, level, particle set): the Laplacian, its
  // consistency on u, the CG solve and where the error sits.
  void solve(const StudyUnit& unit) {
    const std::string &rule = unit.key[0], &w = unit.key[1], &vname = unit.key[3];
    if (std::find(weights_.begin(), weights_.end(), w) == weights_.end()) return;
    const auto var = std::find_if(variants_.begin(), variants_.end(),
                                  [&](const ParticleSet& v) { return v.name == vname; });
    if (var == variants_.end() || cache_->has(unit.key) || !run_.claim()) return;
    const int k = unit.level;
    const double dx = std::ldexp(1.0, -k), h = unit.h;
    particle_set(k, *var);
    const double mismatch = V_.front() / (dx * dx) - 1;
    const auto t0 = std::chrono::steady_clock::now();
    const DiscreteLaplacian L(p_, V_, weight(w), h, LaplacianStorage::automatic);
    const Consistency tau = measured_consistency(L, d_);
    const double eps = laplacian_smoothing_error(weight(w), kSin2piWaveNumber * h);
    const PoissonResult r = solve_poisson(p_, L, d_.f, d_.g, tol_);
    const ErrorLocation e = locate_error(p_, d_.g, r.U, h);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    TsvRow row = run_.row();
    row["h_rule"] = rule, row["weight"] = w, row["level"] = fmt(k), row["variant"] = vname;
    row["dx"] = fmt(dx), row["h"] = fmt(h), row["h_over_H"] = fmt(h / dom_.H);
    row["N_omega"] = fmt(L.n_unknowns()), row["rel_error"] = fmt(e.rel_error);
    row["max_x"] = fmt(e.x), row["max_y"] = fmt(e.y);
    row["max_distance_over_h"] = fmt(e.distance_to_boundary / h);
    row["rel_error_inner"] = fmt(e.rel_error_inner), row["volume_mismatch"] = fmt(mismatch);
    row["eps_smoothing"] = fmt(eps), row["tau_predicted"] = fmt((1 + mismatch) * (1 - eps) - 1);
    row["tau_fit"] = fmt(tau.fit), row["tau_max"] = fmt(tau.max);
    row["cg_iterations"] = fmt(r.cg.iterations), row["seconds"] = fmt(secs);
    run_.add(row);
    run_.unit_done(0, line_printf("%s %-28s 2^-%d %-5s err=%.4e at (%.3f, %.3f) %.2f h from the "
                                  "boundary; inner %.4e; tau fit %+.4e predicted %+.4e  %.1f s",
                                  rule.c_str(), w.c_str(), k, vname.c_str(), e.rel_error, e.x, e.y,
                                  e.distance_to_boundary / h, e.rel_error_inner, tau.fit,
                                  (1 + mismatch) * (1 - eps) - 1, secs));
  }

  StudyRunner run_;
  double tol_ = 0;
  std::vector<std::string> weights_;
  std::vector<ParticleSet> variants_;
  const Domain dom_;
  UnitCache* cache_ = nullptr;
  // The particle set of the last unit computed (level, variant), its volumes and data.
  int level_ = 0;
  std::string variant_;
  Particles p_;
  std::vector<double> V_;
  PoissonData d_;
};

int body(int argc, char** argv) { return PoissonDiagnostic(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_poisson_diagnostic", body, argc, argv); }
