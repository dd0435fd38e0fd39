// thesis_table4_4: the discrete Poisson problem of the thesis, §4.2 (Figure 4.8, Table 4.4).
//
//   −Δ_h U_i = f_i in Ω,  U_i = g̃_i outside,  u = g̃ = sin(2π(x+y)),  f = −Δu = 8π² u,
//   weights: quartic, piecewise cubic, piecewise quintic polynomial (= SPH bell, cubic and
//   quintic B-spline, thesis Appendix A.1), V_i = |Ω_H|/N (A.10) or, the other reading
//   (--volumes cell), V_i = Δx²; jittered grid Δx = 2^-k,
//   relative ℓ∞ error max_Ω|ũ − U| / max_Ω|ũ|; rates from the two finest levels.
//
// Two readings of the influence radius:
//   h10: h = (2.6⁴·2^-10·Δx)^{1/4}  as printed (h > H = 0.1 for Δx ≥ 2^-8);
//   h15: h = (2.6⁴·2^-15·Δx)^{1/4}  = imoto_h(4, Δx), h = 2.6·2^-5 at Δx = 2^-5.
//
//   thesis_table4_4 --profile quick --out data/quick/thesis_table4_4.tsv
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/poisson_probes.hpp"
#include "gpm/solvers/tau_preconditioner.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/cost_model.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/run/runner.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// The study's levels per profile and columns are its registry entry's (registry.hpp, from
// poisson_table()); the weights are pde_weights() (catalog.hpp).

int body(int argc, char** argv) {
  StudyRunner run(study_registry().study("thesis_table4_4"),
                  "Discrete Poisson problem (thesis §4.2): relative l-infinity errors per weight,\n"
                  "level and reading of h (Figure 4.8, Table 4.4).");
  run.args()
      .opt("tol", "1e-10", "CG relative residual on the symmetric form")
      .opt("storage", "auto", "Laplacian storage: auto, assembled, matrix_free")
      .opt("max-gb", "8", "memory budget of an assembled Laplacian (GB); above: matrix-free")
      .opt("volumes", "lattice", "lattice: V_i = |Omega_H|/N (thesis (A.10)); cell: V_i = dx^2\n"
                                 "  (the other reading of the volumes; the store's _cellvol file)")
      .opt("solver", "cg", "cg: plain conjugate gradients (the reference; every stored row);\n"
                           "  tau: preconditioned by the lattice's fast sine transform (tau_preconditioner.hpp)");
  run.parse(argc, argv);
  const PdeVolumes volumes = parse_pde_volumes(run.args().str("volumes"));
  const std::string solver = run.args().str("solver");
  if (solver != "cg" && solver != "tau")
    throw InputError("--solver '" + solver + "' is not cg or tau");
  const double tol = run.args().tolerance("tol");
  const auto storage = parse_laplacian_storage(run.args().str("storage"));
  const double max_bytes = run.args().positive("max-gb") * 1e9;
  const std::vector<int> levels = run.levels();
  require_pde_levels_fit_memory(levels, pde_h_rules(), storage, max_bytes);

  // --- The data file: one row per (reading of h, weight, level). ---------------------------
  // A preconditioned run names its solver in the header, so its rows (other iteration
  // counts, the same errors to the tolerance) never mix with plain CG's in one file.
  std::vector<std::pair<std::string, std::string>> params = {
      {"program", "thesis_table4_4"}, {"profile", profile_name(run.profile())},
      {"seed", fmt(static_cast<long long>(run.seed()))}, {"tol", fmt(tol)},
      {"function", "sin2pi"}, {"volumes", pde_volumes_description(volumes)},
      {"error", "max_Omega|u-U| / max_Omega|u|"},
      {"h10", pde_h_formula(HRule::h10)}, {"h15", pde_h_formula(HRule::h15)}};
  if (solver == "tau") params.emplace_back("solver", "CG preconditioned by the lattice's tau (DST-I) matrix");
  UnitCache& cache = run.open(params, 3);
  // --- The units: the registry's (one per level, reading of h and weight, in that order).
  // A level's particles, volumes and data are shared by its units, made for the first one
  // still to compute.
  const TestFunction& u = test_function("sin2pi");
  const Domain dom;
  int level = 0;
  Particles p;
  std::vector<double> V;
  PoissonData d;
  for (const StudyUnit& unit : run.units()) {
    const int k = unit.level;
    const double dx = std::ldexp(1.0, -k), h = unit.h;
    const std::string &rule = unit.key[0], &wname = unit.key[1];  // the data file's h_rule, weight
    if (cache.has(unit.key) || !run.claim(poisson_unit_work(dx, h))) continue;
    if (k != level) {
      p = jittered_grid(dx, run.seed());
      V = pde_volumes(volumes, p, dx, dom);
      d = poisson_data(p, u);  // f = −Δu, g = u at every particle
      level = k;
    }
    // Assemble −Δ_h (or keep it matrix-free), solve by CG, measure the error in Ω.
    const auto t0 = std::chrono::steady_clock::now();
    const DiscreteLaplacian L(p, V, weight(wname), h, storage, max_bytes);
    std::unique_ptr<TauPreconditioner> pc;
    if (solver == "tau") pc = std::make_unique<TauPreconditioner>(p, L, weight(wname), dx);
    const PoissonResult r = naming_unit(rule + ", " + wname + ", level " + fmt(k), [&] {
      return solve_poisson(p, L, d.f, d.g, tol, 20000, true, pc.get());
    });
    double err = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.in_omega[i]) err = std::max(err, std::fabs(d.g[i] - r.U[i]));
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    TsvRow row = run.row();  // the entry's columns (poisson_table().columns), by name
    row["h_rule"] = rule, row["weight"] = wname, row["level"] = fmt(k), row["dx"] = fmt(dx);
    row["h"] = fmt(h), row["N"] = fmt(p.size()), row["N_omega"] = fmt(L.n_unknowns());
    row["nnz"] = fmt(static_cast<long long>(L.nnz()));
    row["storage"] = L.assembled() ? "assembled" : "matrix_free";
    row["rel_error"] = fmt(err / d.umax), row["cg_iterations"] = fmt(r.cg.iterations);
    row["rel_residual"] = fmt(r.cg.rel_residual), row["assembly_s"] = fmt(L.assembly_seconds());
    row["solve_s"] = fmt(r.solve_seconds), row["seconds"] = fmt(secs);
    run.add(row);
    run.unit_done(0, line_printf("%s %-28s dx=2^-%d h=%.4f N=%zu nnz=%.3g %s  err=%.4e  "
                                 "CG %d it (res %.1e)  %.1f s",
                                 rule.c_str(), wname.c_str(), k, h, p.size(),
                                 static_cast<double>(L.nnz()),
                                 L.assembled() ? "assembled" : "matrix-free", err / d.umax,
                                 r.cg.iterations, r.cg.rel_residual, secs));
  }
  run.finish();
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_table4_4", body, argc, argv); }
