// thesis_stability: where the θ-method of the thesis' heat problem (3.2) stops being stable,
// measured, against the time-step bound (3.3) of Theorem 3.1.
//
// For every weight of the heat study (quartic, piecewise cubic, piecewise quintic
// polynomial), each reading of h (h10, the printed (2.6⁴·2^-10·Δx)^{1/4}, and h15,
// (2.6⁴·2^-15·Δx)^{1/4}) and each level Δx = 2^-k, on the heat study's particles (jittered
// grid, seed 1) with V_i = |Ω_H|/N:
//   1. λ_max of −M_ΩΩ by Lanczos (stability.hpp), and the limits Δt* = 2/((1−2θ)κλ_max) for
//      θ = 0 and θ = ¼ (the θ-method's factor g(μ) = (1−(1−θ)μ)/(1+θμ) drops below −1 there);
//   2. the bound (3.3) with δ = 1 (the most permissive admissible value; the theorem asks
//      for some fixed δ ∈ (0, 1), so every admissible bound is smaller), c_w = ∫ w/|x|² dx
//      computed from the weight's pieces; and the discrete condition (3.7) that (3.3) is
//      meant to imply;
//   3. confirmation runs of the homogeneous θ-method (random U^0, zero boundary values) at
//      0.9·Δt* and 1.1·Δt*: below, the ℓ²(Ω_H) norm must never grow; above, it must grow
//      (the run stops once it exceeds --stop-growth, or after --steps steps).
// κ = 0.5 as in §4.3.  One row per (weight, h rule, level), cached.
//
//   thesis_stability --profile quick --out data/quick/thesis_stability.tsv
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
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/stability.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/define/cost_model.hpp"
#include "gpm/studies/run/runner.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// --- Parameters --------------------------------------------------------------------------
const std::vector<std::string>& kWeights = pde_weights();  // catalog.hpp
// The two readings of h are the PDE tables' (influence_radius.hpp): h10 as printed, h15.
// Quick: 2^-7 alone costs ~100 s per row on two shared cores (Lanczos needs hundreds of
// products there); the paper profile goes to 2^-9 (matrix-free at 2^-8, 2^-9 for h10).
// The quick profile adds the coarse 2^-4 so that its limits against Δx are a trend of
// three points, not a line through two (2^-7 would cost minutes).
const ProfileLevels kLevels = {{4, 5, 6}, {5, 6, 7, 8, 9}};  // quick, paper
constexpr double kKappa = 0.5;
constexpr double kThetaQ = 0.25;       // the implicit-but-not-unconditional case
constexpr double kBelow = 0.9, kAbove = 1.1;
constexpr double kTableT = 0.1;        // Table 4.6: Δt = T/⌈T/(0.5h²)⌉

// The program: the options read once; run() opens the cached data file and computes every
// (weight, h rule, level) row it lacks, one unit each.
class Stability {
 public:
  Stability(int argc, char** argv)
      : run_("thesis_stability",
             "Measured time-step limit of the theta-method (theta = 0 and 1/4) for the thesis'\n"
             "heat problem, from the largest eigenvalue of the discrete Laplacian (Lanczos),\n"
             "confirmed by runs at 0.9 and 1.1 times the limit, against the bound (3.3).\n"
             "--seed jitters the particles; the start vectors use seed 1.",
             kLevels.help()) {
    Args& a = run_.args();
    a.opt("tol", "1e-4", "Lanczos: stop when the Ritz residual <= tol * lambda_max")
        .opt("steps", "100", "confirmation runs: at most this many steps")
        .opt("stop-growth", "100", "confirmation runs: stop when ||U^k|| > this * ||U^0||")
        .opt("storage", "auto", "Laplacian storage: auto, assembled, matrix_free")
        .opt("max-gb", "4", "memory budget of an assembled Laplacian (GB)");
    run_.parse(argc, argv);
    prof_ = run_.profile();
    seed_ = run_.seed();
    tol_ = a.tolerance("tol"), stop_growth_ = a.positive("stop-growth");
    steps_ = static_cast<long>(a.integer("steps", 1, 1000000000));
    if (!(stop_growth_ > 1)) throw InputError("--stop-growth must exceed 1, got " + a.str("stop-growth"));
    storage_ = parse_laplacian_storage(a.str("storage"));
    max_bytes_ = a.positive("max-gb") * 1e9;
    levels_ = run_.levels(kLevels.quick, kLevels.paper);
  }

  int run() {
    open_data_file();
    for (int k : levels_) level(k);
    run_.finish();
    return 0;
  }

 private:
  // The data file: one row per (weight, h rule, level), its header naming every parameter.
  void open_data_file() {
    cache_ = &run_.open(
        {{"program", "thesis_stability"}, {"profile", profile_name(prof_)},
         {"seed", fmt(static_cast<long long>(seed_))}, {"kappa", fmt(kKappa)},
         {"theta_q", fmt(kThetaQ)}, {"lanczos_tol", fmt(tol_)},
         {"runs", "homogeneous theta-method, random U^0 (seed 1), zero boundary values, at " +
                      fmt(kBelow) + " and " + fmt(kAbove) + " x limit_dt"},
         {"steps", fmt(static_cast<long long>(steps_))}, {"stop_growth", fmt(stop_growth_)},
         {"cg_tol", "1e-10"}, {"delta", "1 (bound (3.3) at its most permissive)"},
         {"h10", pde_h_formula(HRule::h10)}, {"h15", pde_h_formula(HRule::h15)},
         {"volumes", "uniform |Omega_H|/N"},
         {"limit", "2/((1-2 theta) kappa lambda_max)"},
         {"table46_dt", "T/ceil(T/(0.5 h^2)), T = 0.1"}},
        {"weight", "h_rule", "level", "dx", "h", "N_omega", "storage", "lambda_max",
         "lanczos_iterations", "lanczos_residual", "bound_dt_0", "bound_dt_q", "cond37_dt_0",
         "limit_dt_0", "limit_dt_q", "bound_over_h2_0", "limit_over_h2_0", "bound_over_h2_q",
         "limit_over_h2_q", "ratio_0", "ratio_q", "delta_37", "table46_over_limit",
         "growth_below_0", "growth_above_0", "steps_above_0", "factor_above_0", "predicted_0",
         "growth_below_q", "growth_above_q", "steps_above_q", "factor_above_q", "predicted_q",
         "confirmed", "time_s"},
        3);
  }

  // One level: the particles built once, when the first of its units is not stored.
  void level(int k) {
    const double dx = std::ldexp(1.0, -k);
    bool built = false;
    Particles p;
    std::vector<double> V;
    for (HRule rule_id : pde_h_rules()) {
      const double h = pde_h(rule_id, dx);
      const std::string rule = h_rule_name(rule_id);  // the data file's h_rule
      for (const auto& wname : kWeights) {
        if (cache_->has({wname, rule, fmt(k)}) || !run_.claim(predicted_pairs(dx, h))) continue;
        if (!built) p = jittered_grid(dx, seed_), V = uniform_volumes(p, dom_), built = true;
        unit(wname, rule, k, dx, h, p, V);
      }
    }
  }

  // One unit: λ_max and the limits, the bound (3.3) and condition (3.7), and the runs just
  // below and just above each limit that confirm it.
  void unit(const std::string& wname, const std::string& rule, int k, double dx, double h, const Particles& p,
            const std::vector<double>& V) {
    const auto t0 = std::chrono::steady_clock::now();
    const WeightFunction& w = weight(wname);
    const DiscreteLaplacian L(p, V, w, h, storage_, max_bytes_);

    // λ_max and the limits.
    const LanczosResult lz = largest_eigenvalue(L, tol_);
    const double lim0 = stability_limit(lz.lambda_max, kKappa, 0);
    const double limq = stability_limit(lz.lambda_max, kKappa, kThetaQ);
    const double b0 = thesis_bound_33(w, h, kKappa, 0);
    const double bq = thesis_bound_33(w, h, kKappa, kThetaQ);
    const double c37 = thesis_condition_37(L, kKappa, 0);
    // The largest δ for which (3.3) still implies (3.7) on these particles.
    const double delta37 = c37 / thesis_bound_33(w, h, kKappa, 0);
    const double dt46 = kTableT / static_cast<double>(heat_steps(kTableT, 0.5 * h * h));

    // Confirmation runs just below and just above each limit.
    auto runs = [&](double theta, double dt) {
      return run_homogeneous(L, kKappa, theta, dt, steps_, stop_growth_, 1);
    };
    const StabilityRun s0 = runs(0, kBelow * lim0), u0 = runs(0, kAbove * lim0);
    const StabilityRun sq = runs(kThetaQ, kBelow * limq), uq = runs(kThetaQ, kAbove * limq);
    const double pred0 = std::fabs(theta_amplification(kAbove * 2, 0));
    const double predq = std::fabs(theta_amplification(kAbove * 2 / (1 - 2 * kThetaQ), kThetaQ));
    const bool confirmed = s0.growth_max <= 1 && sq.growth_max <= 1 && u0.growth_final > 1 &&
                           uq.growth_final > 1;
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double h2 = h * h;
    // The row, by column name: each number beside the name it is read by.
    TsvRow row = run_.row();
    row["weight"] = wname, row["h_rule"] = rule, row["level"] = fmt(k);
    row["dx"] = fmt(dx), row["h"] = fmt(h), row["N_omega"] = fmt(L.n_unknowns());
    row["storage"] = L.assembled() ? "assembled" : "matrix_free";
    row["lambda_max"] = fmt(lz.lambda_max), row["lanczos_iterations"] = fmt(lz.iterations);
    row["lanczos_residual"] = fmt(lz.residual);
    row["bound_dt_0"] = fmt(b0), row["bound_dt_q"] = fmt(bq), row["cond37_dt_0"] = fmt(c37);
    row["limit_dt_0"] = fmt(lim0), row["limit_dt_q"] = fmt(limq);
    row["bound_over_h2_0"] = fmt(b0 / h2), row["limit_over_h2_0"] = fmt(lim0 / h2);
    row["bound_over_h2_q"] = fmt(bq / h2), row["limit_over_h2_q"] = fmt(limq / h2);
    row["ratio_0"] = fmt(lim0 / b0), row["ratio_q"] = fmt(limq / bq);
    row["delta_37"] = fmt(delta37), row["table46_over_limit"] = fmt(dt46 / lim0);
    row["growth_below_0"] = fmt(s0.growth_max), row["growth_above_0"] = fmt(u0.growth_final);
    row["steps_above_0"] = fmt(static_cast<long long>(u0.steps));
    row["factor_above_0"] = fmt(u0.last_factor), row["predicted_0"] = fmt(pred0);
    row["growth_below_q"] = fmt(sq.growth_max), row["growth_above_q"] = fmt(uq.growth_final);
    row["steps_above_q"] = fmt(static_cast<long long>(uq.steps));
    row["factor_above_q"] = fmt(uq.last_factor), row["predicted_q"] = fmt(predq);
    row["confirmed"] = confirmed ? "yes" : "no", row["time_s"] = fmt(secs);
    run_.add(row);
    run_.unit_done(0, line_printf(
        "%-28s %-7s dx=2^-%d h=%.4f lambda_max=%.5g (%d it) limit/h^2 = %.4f (theta 0), "
        "%.4f (1/4); bound/h^2 = %.4f, %.4f; growth %.3g / %.3g (theta 0), %.3g / %.3g (1/4) "
        "%s  %.1f s",
        wname.c_str(), rule.c_str(), k, h, lz.lambda_max, lz.iterations, lim0 / h2,
        limq / h2, b0 / h2, bq / h2, s0.growth_max, u0.growth_final, sq.growth_max,
        uq.growth_final, confirmed ? "confirmed" : "NOT CONFIRMED", secs));
  }

  StudyRunner run_;
  Profile prof_ = Profile::quick;
  uint64_t seed_ = 1;
  double tol_ = 0, stop_growth_ = 0, max_bytes_ = 0;
  long steps_ = 0;
  LaplacianStorage storage_{};
  std::vector<int> levels_;
  const Domain dom_;
  UnitCache* cache_ = nullptr;
};

int body(int argc, char** argv) { return Stability(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_stability", body, argc, argv); }
