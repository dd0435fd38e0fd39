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

// The program: the options read once; run() opens the cached data file and solves every
// registered unit (level, reading of h, weight) it lacks.
class PoissonTable {
 public:
  PoissonTable(int argc, char** argv)
      : run_(study_registry().study("thesis_table4_4"),
             "Discrete Poisson problem (thesis §4.2): relative l-infinity errors per weight,\n"
             "level and reading of h (Figure 4.8, Table 4.4).") {
    run_.args()
        .opt("tol", "1e-10", "CG relative residual on the symmetric form")
        .opt("storage", "auto", "Laplacian storage: auto, assembled, matrix_free")
        .opt("max-gb", "8", "memory budget of an assembled Laplacian (GB); above: matrix-free")
        .opt("volumes", "lattice", "lattice: V_i = |Omega_H|/N (thesis (A.10)); cell: V_i = dx^2\n"
                                   "  (the other reading of the volumes; the store's _cellvol file)")
        .opt("solver", "cg", "cg: plain conjugate gradients (the reference; every stored row);\n"
                             "  tau: preconditioned by the lattice's fast sine transform (tau_preconditioner.hpp)");
    run_.parse(argc, argv);
    volumes_ = parse_pde_volumes(run_.args().str("volumes"));
    solver_ = run_.args().str("solver");
    if (solver_ != "cg" && solver_ != "tau")
      throw InputError("--solver '" + solver_ + "' is not cg or tau");
    tol_ = run_.args().tolerance("tol");
    storage_ = parse_laplacian_storage(run_.args().str("storage"));
    max_bytes_ = run_.args().positive("max-gb") * 1e9;
    require_pde_levels_fit_memory(run_.levels(), pde_h_rules(), storage_, max_bytes_);
  }

  int run() {
    open_data_file();
    for (const StudyUnit& unit : run_.units()) solve(unit);
    run_.finish();
    return 0;
  }

 private:
  // The data file: one row per (reading of h, weight, level).  A preconditioned run names its
  // solver in the header, so its rows (other iteration counts, the same errors to the
  // tolerance) never mix with plain CG's in one file.
  void open_data_file() {
    std::vector<std::pair<std::string, std::string>> params = {
        {"program", "thesis_table4_4"}, {"profile", profile_name(run_.profile())},
        {"seed", fmt(static_cast<long long>(run_.seed()))}, {"tol", fmt(tol_)},
        {"function", "sin2pi"}, {"volumes", pde_volumes_description(volumes_)},
        {"error", "max_Omega|u-U| / max_Omega|u|"},
        {"h10", pde_h_formula(HRule::h10)}, {"h15", pde_h_formula(HRule::h15)}};
    if (solver_ == "tau") params.emplace_back("solver", "CG preconditioned by the lattice's tau (DST-I) matrix");
    cache_ = &run_.open(params, 3);
  }

  // A level's particles, volumes and data, shared by its units, made for the first one still
  // to compute.
  void particle_set(int k) {
    if (k == level_) return;
    const double dx = std::ldexp(1.0, -k);
    p_ = jittered_grid(dx, run_.seed());
    V_ = pde_volumes(volumes_, p_, dx, dom_);
    d_ = poisson_data(p_, test_function("sin2pi"));  // f = −Δu, g = u at every particle
    level_ = k;
  }

  // One unit (the registry's: h rule, weight, level): assemble −Δ_h (or keep it matrix-free),
  // solve by CG, measure the error in Ω.
  void solve(const StudyUnit& unit) {
    const int k = unit.level;
    const double dx = std::ldexp(1.0, -k), h = unit.h;
    const std::string &rule = unit.key[0], &wname = unit.key[1];  // the data file's h_rule, weight
    if (cache_->has(unit.key) || !run_.claim(poisson_unit_work(dx, h))) return;
    particle_set(k);
    const auto t0 = std::chrono::steady_clock::now();
    const DiscreteLaplacian L(p_, V_, weight(wname), h, storage_, max_bytes_);
    std::unique_ptr<TauPreconditioner> pc;
    if (solver_ == "tau") pc = std::make_unique<TauPreconditioner>(p_, L, weight(wname), dx);
    const PoissonResult r = naming_unit(rule + ", " + wname + ", level " + fmt(k), [&] {
      return solve_poisson(p_, L, d_.f, d_.g, tol_, 20000, true, pc.get());
    });
    double err = 0;
    for (std::size_t i = 0; i < p_.size(); ++i)
      if (p_.in_omega[i]) err = std::max(err, std::fabs(d_.g[i] - r.U[i]));
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    TsvRow row = run_.row();  // the entry's columns (poisson_table().columns), by name
    row["h_rule"] = rule, row["weight"] = wname, row["level"] = fmt(k), row["dx"] = fmt(dx);
    row["h"] = fmt(h), row["N"] = fmt(p_.size()), row["N_omega"] = fmt(L.n_unknowns());
    row["nnz"] = fmt(static_cast<long long>(L.nnz()));
    row["storage"] = L.assembled() ? "assembled" : "matrix_free";
    row["rel_error"] = fmt(err / d_.umax), row["cg_iterations"] = fmt(r.cg.iterations);
    row["rel_residual"] = fmt(r.cg.rel_residual), row["assembly_s"] = fmt(L.assembly_seconds());
    row["solve_s"] = fmt(r.solve_seconds), row["seconds"] = fmt(secs);
    run_.add(row);
    run_.unit_done(0, line_printf("%s %-28s dx=2^-%d h=%.4f N=%zu nnz=%.3g %s  err=%.4e  "
                                  "CG %d it (res %.1e)  %.1f s",
                                  rule.c_str(), wname.c_str(), k, h, p_.size(),
                                  static_cast<double>(L.nnz()),
                                  L.assembled() ? "assembled" : "matrix-free", err / d_.umax,
                                  r.cg.iterations, r.cg.rel_residual, secs));
  }

  StudyRunner run_;
  PdeVolumes volumes_ = PdeVolumes::lattice;
  std::string solver_;
  double tol_ = 0, max_bytes_ = 0;
  LaplacianStorage storage_ = LaplacianStorage::automatic;
  const Domain dom_;
  UnitCache* cache_ = nullptr;
  int level_ = 0;  // the level whose particles, volumes and data are held
  Particles p_;
  std::vector<double> V_;
  PoissonData d_;
};

int body(int argc, char** argv) { return PoissonTable(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_table4_4", body, argc, argv); }
