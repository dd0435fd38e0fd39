// thesis_mode_excess: what the error constants' excess over the one-mode model is made of
// (issue 59, item 7).  The model (studies/judge/mode_constants.hpp) lets the exact solution's
// mode feel only the weight's continuous smoothing, Δ_h s ≈ (1 − ε)Δs.  On particles the
// operator is a sum, not an integral: the mode's effective symbol is measured here directly,
//   Q = Σ_j V_j s_j (Δ_h s)_j / Σ_j V_j s_j (Δs)_j   over the particles j in Ω,
// with s taken exactly at every particle (inside and outside Ω).  1 − Q is the mode's
// effective smoothing; the particle part is π = Q − (1 − ε).  If the error is this mode's,
// the excess of the error constant over the model is predicted as
//   heat:    (1 − Q)/ε − 1                       (the decay rate μQ instead of μ(1 − ε)),
//   Poisson: (1/Q − 1)/(1/(1 − ε) − 1) − 1        (U ≈ u/Q instead of u/(1 − ε)),
// and gpm store-rates' measured excess (error_constants.tsv) can be set beside it level by
// level.  The projection averages the particles' local errors away; their size is measured
// too: the particle part of the local truncation error, (Δ_h s)_j − (1 − ε)(Δs)_j, relative to
// max|Δs|, its maximum and root mean square over Ω, and ε beside it.  One Laplacian product
// per (level, weight); nothing is solved.
//
//   thesis_mode_excess --mode heat --levels 5,6,7,8,9,10 --out results/diagnostics/mode_excess_heat.tsv
#include <chrono>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// The two modes: the heat tables' sin πx sin πy and Table 4.4's sin 2π(x+y), with |k|.
struct Mode {
  double k;
  double (*s)(double, double);
};
Mode mode_named(const std::string& name) {
  if (name == "heat") return {M_PI * std::sqrt(2.0), [](double x, double y) { return std::sin(M_PI * x) * std::sin(M_PI * y); }};
  if (name == "poisson") return {2 * M_PI * std::sqrt(2.0), [](double x, double y) { return std::sin(2 * M_PI * (x + y)); }};
  throw InputError("--mode '" + name + "' is not heat or poisson");
}

// The program: the options read once; run() opens the table, measures every level's weights
// and writes the table.
class ModeExcess {
 public:
  ModeExcess(int argc, char** argv)
      : a_("thesis_mode_excess",
           "The particle part of the discrete Laplacian's symbol on the PDE tables' exact mode\n"
           "(heat: sin(pi x) sin(pi y); poisson: sin 2pi(x+y)), per level and weight, and the excess\n"
           "of the error constant over the one-mode model that it predicts.  Solves nothing.") {
    a_.opt("mode", "heat", "heat or poisson")
        .opt("levels", "5,6,7,8,9,10", "comma-separated levels k (dx = 2^-k)")
        .opt("seed", "1", "jitter seed")
        .opt("h-rule", "h15", "h10 or h15")
        .opt("volumes", "cell", "cell (V_i = dx^2) or lattice (|Omega_H|/N)")
        .output("out", "", "TSV: one row per level and weight (required)");
    a_.parse(argc, argv);
    out_ = a_.required("out");
    mode_ = mode_named(a_.str("mode"));
    heat_ = a_.str("mode") == "heat";
    rule_ = parse_h_rule(a_.str("h-rule"));
    volumes_ = parse_pde_volumes(a_.str("volumes"));
    seed_ = a_.seed("seed");
    for (double v : a_.nums("levels")) {
      if (v != std::floor(v) || v < 3 || v > 13) throw InputError("--levels: '" + fmt(v) + "' is not a level 3..13");
      levels_.push_back(static_cast<int>(v));
    }
    check_output_paths({{"--out", out_}});
  }

  int run() {
    open_table();
    for (int k : levels_) level(k);
    o_.save(out_);
    return 0;
  }

 private:
  // The table's header: every option, the quantities' definitions, the provenance.
  void open_table() {
    o_.set("program", "thesis_mode_excess");
    for (auto& [k, v] : a_.values()) o_.set(k, v);
    o_.set("Q", "sum_j V_j s_j (Lap_h s)_j / sum_j V_j s_j (Lap s)_j over the particles in Omega");
    o_.set("particle_part", "Q - (1 - eps(|k|h))");
    o_.set("predicted_excess", heat_ ? "(1 - Q)/eps - 1" : "(1/Q - 1)/(1/(1 - eps) - 1) - 1");
    add_provenance(o_);
    o_.set("local_max", "max_j |(Lap_h s)_j - (1 - eps)(Lap s)_j| / max_j |Lap s|, j in Omega");
    o_.set("local_rms", "the same residual's root mean square over Omega (volume-weighted) / max_j |Lap s|");
    o_.columns = {"weight", "level", "dx", "h", "N", "eps", "Q", "particle_part", "predicted_excess",
                  "local_max", "local_rms", "seconds"};
  }

  // One level: its particles, volumes and mode, then every weight.
  void level(int k) {
    const double dx = std::ldexp(1.0, -k), h = pde_h(rule_, dx);
    const Particles p = jittered_grid(dx, seed_);
    const std::vector<double> V = pde_volumes(volumes_, p, dx, dom_);
    Eigen::VectorXd s(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) s[i] = mode_.s(p.x[i], p.y[i]);
    for (const std::string& wname : pde_weights()) weight_row(k, dx, h, p, V, s, wname);
  }

  // One weight: the symbol's particle part Q on the mode, its local residual, and the excess
  // of the error constant it predicts.
  void weight_row(int k, double dx, double h, const Particles& p, const std::vector<double>& V,
                  const Eigen::VectorXd& s, const std::string& wname) {
    const auto t0 = std::chrono::steady_clock::now();
    const WeightFunction& w = weight(wname);
    const DiscreteLaplacian L(p, V, w, h);
    Eigen::VectorXd y;
    L.apply_full(s, y);
    const double eps = laplacian_smoothing_error(w, mode_.k * h);
    double num = 0, den = 0, lmax = 0, lsq = 0, vol = 0, lapmax = 0;
    for (std::size_t u = 0; u < L.omega().size(); ++u) {
      const int32_t j = L.omega()[u];
      const double lap = -mode_.k * mode_.k * s[j], r = y[u] - (1 - eps) * lap;
      num += V[j] * s[j] * y[u];
      den += V[j] * s[j] * lap;
      lmax = std::max(lmax, std::fabs(r)), lsq += V[j] * r * r, vol += V[j];
      lapmax = std::max(lapmax, std::fabs(lap));
    }
    const double Q = num / den;
    if (!std::isfinite(Q)) throw NumericalError("level " + fmt(k) + ", " + wname + ": Q is not finite");
    const double predicted = heat_ ? (1 - Q) / eps - 1 : (1 / Q - 1) / (1 / (1 - eps) - 1) - 1;
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    TsvRow row = o_.named_row();
    row["weight"] = wname, row["level"] = fmt(k), row["dx"] = fmt(dx), row["h"] = fmt(h);
    row["N"] = fmt(p.size()), row["eps"] = fmt(eps), row["Q"] = fmt(Q), row["particle_part"] = fmt(Q - (1 - eps));
    row["predicted_excess"] = fmt(predicted), row["local_max"] = fmt(lmax / lapmax);
    row["local_rms"] = fmt(std::sqrt(lsq / vol) / lapmax), row["seconds"] = fmt(secs);
    o_.add_row(row);
    std::printf("2^-%d %-28s h=%.4f eps=%.3e Q=%.8f particle part %+.3e predicted excess %+.4f "
                "local max %.3e rms %.3e (%.1f s)\n", k, wname.c_str(), h, eps, Q, Q - (1 - eps), predicted,
                lmax / lapmax, std::sqrt(lsq / vol) / lapmax, secs);
    std::fflush(stdout);
  }

  Args a_;
  std::string out_;
  Mode mode_{};
  bool heat_ = true;
  HRule rule_ = HRule::h15;
  PdeVolumes volumes_ = PdeVolumes::cell;
  uint64_t seed_ = 1;
  std::vector<int> levels_;
  const Domain dom_;
  TsvTable o_;
};

int body(int argc, char** argv) { return ModeExcess(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_mode_excess", body, argc, argv); }
