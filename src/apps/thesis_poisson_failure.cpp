// thesis_poisson_failure: where the discrete Poisson problem (thesis (2.2)) stops working.
//
// The thesis proves two things about −Δ_h U = f in Ω, U = g̃ outside (Chapter 2):
//   Theorem 2.2  for a positive weight (Hypothesis 1.4) the problem has a unique solution
//                iff the distribution is h-connected (Definition 1.8);
//   Lemma 2.4    under the same two assumptions, −Δ_h v ≤ 0 in Ω implies
//                max_Ω v ≤ max_{Γ∪Γ_H} v (discrete maximum principle).
// This program breaks each assumption in turn and records what happens.
//
// (a) A weight that changes sign: the cubic spike 5/π (1−r)²(4−7r) is negative on
//     (4/7, 1), so Hypothesis 1.4 fails (and w/r² is unbounded at 0).  Beside it the positive
//     quartic polynomial, for which Lemma 2.4 must hold.  Per level and reading of h:
//       - sign pattern of M (the Ω × all matrix of Δ_h): share of off-diagonal entries < 0
//         (a positive weight has none) and share of rows that are not diagonally dominant;
//       - conjugate gradients on the symmetric form S = −D M_ΩΩ for u = sin 2π(x+y): the
//         outcome (ok, or the NumericalError's text, e.g. pᵀSp ≤ 0) and the error;
//       - two maximum-principle probes with f ≤ 0 (so max_Ω U ≤ max of the data outside Ω is
//         promised for a positive weight):
//           source:   f = −1 at the particle nearest (½, ½), 0 elsewhere; g̃ = 0.
//                     Violation = max_Ω U / max_Ω |U|   (> 0: U rose above the data);
//           boundary: f = 0; g̃ = −1 at the particle b outside Ω with the smallest column
//                     sum Σ_j M_jb (poisson_probes.hpp): for the spike, the particle of Γ_H
//                     that Ω sees mostly through the weight's negative part (r/h ∈ (4/7, 1)).
//                     Violation = max_Ω U / max_Ω |U|, and max_Ω U itself (the data's
//                     amplitude is 1, the promised bound 0);
//       - on the small levels (dense, N_Ω ≤ kQuickDenseMax / kPaperDenseMax): the smallest eigenvalue of −Δ_h on
//         the unknowns (2π² ≈ 19.74 for −Δ on the unit square), and the most negative entry
//         of the discrete Green's function (−M_ΩΩ)⁻¹ and of the discrete harmonic measure
//         (−M_ΩΩ)⁻¹ M_ΩB, each relative to the largest entry.  The maximum principle holds
//         for every f ≤ 0 and every g̃ iff both have no negative entry.
// (b) h below the h-connectivity threshold: for the quartic polynomial on jittered grids,
//     h = c·Δx for c from 2 down to 0.5.  Per (level, seed, c): is the distribution
//     h-connected, how many particles in Ω are unconnected or have no neighbour at all, what
//     solve_poisson reports (its refusal, verbatim), and what the same solve does with the
//     check switched off (the NumericalError's text, or the error and max |U| of what it
//     returns).  The threshold h* (smallest h that is h-connected, by bisection) per seed,
//     and more rows per seed just below and above h* (kNearThreshold).
//
//   thesis_poisson_failure --profile quick --out data/quick/thesis_poisson_failure.tsv
//       --out-sweep data/quick/thesis_poisson_failure_h.tsv      (one command line)
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/connectivity.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/poisson_probes.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/run/runner.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// --- Parameters --------------------------------------------------------------------------
// (a) weights, readings of h (as in thesis_table4_4) and levels.
const std::vector<std::string> kWeights = {"cubic_spike", "quartic_polynomial"};
// Quick: 2^-4 joins so that the errors against Δx are three points, not two.
const std::vector<int> kQuickLevels = {4, 5, 6};
const std::vector<int> kPaperLevels = {5, 6, 7, 8};
// Dense eigenvalues / inverse only up to this many unknowns (N_Ω ≈ 1,000 at 2^-5, 4,000 at
// 2^-6: the dense LU and eigen-solve at 2^-6 take tens of seconds, so only the paper profile
// does it).
const int kQuickDenseMax = 1500, kPaperDenseMax = 5000;
// (b) the h sweep: levels, seeds, h/Δx.
const std::vector<int> kQuickSweepLevels = {5};
const std::vector<int> kPaperSweepLevels = {5, 6, 7};
const std::vector<int> kQuickSeeds = {1, 2, 3, 4};
const std::vector<int> kPaperSeeds = {1, 2, 3, 4, 5, 6, 7, 8};
const std::vector<double> kRatios = {2.0, 1.8, 1.6, 1.5, 1.4, 1.3, 1.2, 1.1,
                                     1.0, 0.9, 0.8, 0.7, 0.6, 0.5};
// Radii near each grid's own threshold h*, added to the sweep per seed.
const std::vector<double> kNearThreshold = {0.98, 0.99, 0.995, 1.005, 1.02};
const std::string kSweepWeight = "quartic_polynomial";
const double kTol = 1e-10;   // CG relative residual (as thesis_table4_4)
const int kMaxIter = 20000;  // CG iterations before "did not converge" is reported

std::string seed_list(Profile prof) {
  std::string out;
  for (int s : pick(prof, kQuickSeeds, kPaperSeeds)) out += (out.empty() ? "" : ",") + fmt(s);
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// TSV cells may not hold tabs or newlines; the solver's messages have none, but be safe.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return s;
}

// A solve that may fail: what came back, in words and numbers.
struct Outcome {
  std::string status = "ok";  // ok | refused | not_positive_definite | unreachable_tolerance | no_convergence | non_finite
  std::string message = "-";  // the exception's text, verbatim
  int iterations = -1;
  std::vector<double> U;
};

std::string classify(const std::string& msg) {
  if (msg.find("not positive definite") != std::string::npos) return "not_positive_definite";
  if (msg.find("out of reach in double precision") != std::string::npos) return "unreachable_tolerance";
  if (msg.find("did not reach") != std::string::npos) return "no_convergence";
  if (msg.find("non-finite") != std::string::npos) return "non_finite";
  return "numerical_error";
}

Outcome try_solve(const Particles& p, const DiscreteLaplacian& L, const std::vector<double>& f,
                  const std::vector<double>& g, bool check) {
  Outcome o;
  try {
    PoissonResult r = solve_poisson(p, L, f, g, kTol, kMaxIter, check);
    o.iterations = r.cg.iterations;
    o.U = std::move(r.U);
  } catch (const InputError& e) {
    o.status = "refused";
    o.message = one_line(e.what());
  } catch (const NumericalError& e) {
    o.message = one_line(e.what());
    o.status = classify(o.message);
  }
  return o;
}

// max_Ω U / max_Ω |U|: > 0 means U rose above the (zero) data outside Ω.
double rise_above_zero(const Particles& p, const std::vector<double>& U) {
  double top = -1e300, big = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.in_omega[i]) top = std::max(top, U[i]), big = std::max(big, std::fabs(U[i]));
  return big > 0 ? top / big : 0;
}

std::size_t nearest(const Particles& p, double x, double y, bool inside) {
  std::size_t best = 0;
  double d2 = 1e300;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (static_cast<bool>(p.in_omega[i]) != inside) continue;
    const double d = (p.x[i] - x) * (p.x[i] - x) + (p.y[i] - y) * (p.y[i] - y);
    if (d < d2) d2 = d, best = i;
  }
  return best;
}

// Sign pattern of the assembled Ω × all matrix.
struct SignPattern {
  double negative_offdiag = 0;  // share of off-diagonal entries < 0
  double not_dominant = 0;      // share of rows with diag ≥ 0 or |diag| < Σ|off|
  double positive_diag = 0;     // share of rows with diag ≥ 0
};

SignPattern sign_pattern(const DiscreteLaplacian& L) {
  const auto& M = L.matrix();
  const auto& om = L.omega();
  SignPattern s;
  long long off = 0, neg = 0, nd = 0, pd = 0;
  for (int r = 0; r < M.rows(); ++r) {
    double diag = 0, sum = 0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(M, r); it; ++it) {
      if (it.col() == om[r]) {
        diag = it.value();
        continue;
      }
      ++off;
      neg += it.value() < 0;
      sum += std::fabs(it.value());
    }
    pd += diag >= 0;
    nd += diag >= 0 || std::fabs(diag) < sum * (1 - 1e-12);
  }
  s.negative_offdiag = off ? static_cast<double>(neg) / off : 0;
  s.not_dominant = static_cast<double>(nd) / M.rows();
  s.positive_diag = static_cast<double>(pd) / M.rows();
  return s;
}

// Dense spectral and inverse-sign facts about A = −M_ΩΩ (small levels only).
struct DenseFacts {
  double lambda_min = NAN, lambda_max = NAN;  // eigenvalues of −Δ_h on the unknowns
  double green_min = NAN;                     // min entry of A⁻¹ / max entry
  double harmonic_min = NAN;                  // min entry of A⁻¹ M_ΩB / max entry
};

DenseFacts dense_facts(const DiscreteLaplacian& L) {
  const auto& M = L.matrix();
  const auto& unk = L.unknown_of();
  const auto& om = L.omega();
  const auto& V = L.volumes();
  const int n = static_cast<int>(om.size());
  std::vector<int> bcol(L.n_particles(), -1);
  int nb = 0;
  for (std::size_t i = 0; i < L.n_particles(); ++i)
    if (unk[i] < 0) bcol[i] = nb++;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n), B = Eigen::MatrixXd::Zero(n, nb);
  for (int r = 0; r < n; ++r)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(M, r); it; ++it) {
      if (unk[it.col()] >= 0) A(r, unk[it.col()]) = -it.value();
      else B(r, bcol[it.col()]) = it.value();
    }
  // A is self-adjoint in the V-weighted inner product: D^{1/2} A D^{-1/2} is symmetric and
  // has A's eigenvalues.
  DenseFacts d;
  Eigen::VectorXd s(n);
  for (int k = 0; k < n; ++k) s[k] = std::sqrt(V[om[k]]);
  const Eigen::MatrixXd Sym = s.asDiagonal() * A * s.cwiseInverse().asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (Sym + Sym.transpose()),
                                                    Eigen::EigenvaluesOnly);
  d.lambda_min = es.eigenvalues().minCoeff();
  d.lambda_max = es.eigenvalues().maxCoeff();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  const Eigen::MatrixXd G = lu.inverse();
  d.green_min = G.minCoeff() / G.cwiseAbs().maxCoeff();
  const Eigen::MatrixXd H = lu.solve(B);
  d.harmonic_min = H.minCoeff() / H.cwiseAbs().maxCoeff();
  return d;
}

// The program: part (a) over levels, readings of h and weights, part (b) over levels, seeds and
// radii; each unit a row of its data file, skipped when the file has it (a rerun resumes).
class PoissonFailure {
 public:
  // The runner owns the options, both data files (cache, store checks, header stamp), the
  // progress lines and the closing lines; --out is part (a), --out-sweep part (b).
  PoissonFailure(int argc, char** argv)
      : run_("thesis_poisson_failure",
             "Where the discrete Poisson problem (thesis (2.2)) fails: (a) a weight that changes\n"
             "sign (cubic spike vs quartic polynomial): sign pattern, CG, maximum principle,\n"
             "smallest eigenvalue; (b) h below the h-connectivity threshold: refusal and the\n"
             "unchecked solve.  --seed and --levels are part (a)'s.",
             "quick (levels 4-6, sweep at 2^-5, 4 seeds) or paper (levels 5-8, sweep at "
             "2^-5..2^-7, 8 seeds)") {
    run_.args().output("out-sweep", "", "data file of part (b), the h sweep (required)");
    run_.parse(argc, argv);
    if (run_.args().str("out-sweep").empty()) throw InputError("--out-sweep PATH is required (see --help)");
    prof_ = run_.profile();
    seed_ = run_.seed();
    dense_max_ = prof_ == Profile::quick ? kQuickDenseMax : kPaperDenseMax;
  }

  int run() {
    open_files();
    weight_sign();
    h_sweep();
    run_.finish();
    return 0;
  }

 private:
  StudyRunner run_;
  Profile prof_{};
  uint64_t seed_ = 1;
  int dense_max_ = 0;
  const Domain dom_{};
  const TestFunction& u_ = test_function("sin2pi");
  UnitCache* ca_ = nullptr;  // part (a)'s rows
  UnitCache* cb_ = nullptr;  // part (b)'s rows

  // The data files, both opened at once (the runner keeps one set of files per run): (a) one
  // row per (reading of h, weight, level), (b) one row per (level, seed, h/dx); each cached,
  // so a rerun skips finished rows.
  void open_files() {
    const std::vector<UnitCache*> files = run_.open_files(
        {{run_.out(), {{"program", "thesis_poisson_failure"}, {"part", "a: weight sign"},
                   {"profile", profile_name(prof_)}, {"seed", fmt(static_cast<long long>(seed_))},
                   {"tol", fmt(kTol)}, {"max_iter", fmt(kMaxIter)},
                   {"dense_max_unknowns", fmt(dense_max_)}, {"function", "sin2pi"},
                   {"volumes", "uniform |Omega_H|/N"},
                   {"h10", "(2.6^4 2^-10 dx)^(1/4)"}, {"h15", "(2.6^4 2^-15 dx)^(1/4)"},
                   {"probe_source", "f=-1 at particle nearest (0.5,0.5), g=0; max_Omega U/max|U|"},
                   {"probe_boundary",
                    "f=0, g=-1 at the outside particle with the smallest column sum of M; "
                    "max_Omega U/max|U| (mp_boundary) and max_Omega U (mp_boundary_abs)"},
                   {"green_min", "min entry of (-M_OO)^-1 / max |entry| (dense levels)"},
                   {"harmonic_min", "min entry of (-M_OO)^-1 M_OB / max |entry| (dense levels)"}},
                  {"h_rule", "weight", "level", "dx", "h", "h_over_dx", "N", "N_omega",
                   "negative_offdiag", "not_dominant", "positive_diag", "cg_status",
                   "cg_iterations", "rel_error", "cg_message", "mp_source", "mp_boundary",
                   "mp_boundary_abs",
                   "lambda_min", "lambda_max", "green_min", "harmonic_min", "seconds"}},
         {run_.args().str("out-sweep"), {{"program", "thesis_poisson_failure"}, {"part", "b: h sweep"},
                   {"profile", profile_name(prof_)}, {"seed", seed_list(prof_)},
                   {"weight", kSweepWeight},
                   {"tol", fmt(kTol)}, {"max_iter", fmt(kMaxIter)}, {"function", "sin2pi"},
                   {"volumes", "uniform |Omega_H|/N"},
                   {"h_star", "smallest h with h-connectivity (50 bisection steps in [0.1,3] dx)"},
                   {"near_threshold", "rows at 0.98, 0.99, 0.995, 1.005, 1.02 h* per seed"},
                   {"true_residual", "|-Delta_h U - f|_2 / |f + M_OB g|_2 over Omega, recomputed"}},
                  {"level", "seed", "h_over_dx", "dx", "h", "N_omega", "h_star_over_dx",
                   "connected", "unconnected", "isolated", "checked_status", "checked_message",
                   "unchecked_status", "unchecked_iterations", "rel_error", "max_abs_U", "true_residual",
                   "unchecked_message", "seconds"}}},
        {}, 3);
    ca_ = files[0], cb_ = files[1];
  }

  // (a) A weight that changes sign: per level one particle set, volumes, data and probes,
  // shared by both weights and both readings of h.
  void weight_sign() {
    for (int k : run_.levels(kQuickLevels, kPaperLevels)) {
      const double dx = std::ldexp(1.0, -k);
      const Particles p = jittered_grid(dx, seed_);
      const auto V = uniform_volumes(p, dom_);
      const PoissonData problem = poisson_data(p, u_);
      std::vector<double> f_src(p.size(), 0.0);
      f_src[nearest(p, 0.5, 0.5, true)] = -1;
      for (HRule rule : pde_h_rules())
        for (const auto& wname : kWeights)
          if (!ca_->has({h_rule_name(rule), wname, fmt(k)}) && run_.claim())
            weight_sign_unit(k, p, V, problem, f_src, rule, wname);
    }
  }

  // One (level, reading of h, weight): sign pattern, the smooth problem of Table 4.4, the two
  // maximum-principle probes and, on small levels, the dense facts.
  void weight_sign_unit(int k, const Particles& p, const std::vector<double>& V, const PoissonData& problem,
                        const std::vector<double>& f_src, HRule rule_id, const std::string& wname) {
    const double dx = std::ldexp(1.0, -k);
    const std::string rule = h_rule_name(rule_id);  // the data file's h_rule
    const auto& [f, g, umax] = problem;
    const std::vector<double> zero(p.size(), 0.0);
    const auto t0 = std::chrono::steady_clock::now();
    const double h = pde_h(rule_id, dx);
    const DiscreteLaplacian L(p, V, weight(wname), h, LaplacianStorage::assembled);
    std::vector<double> g_bnd(p.size(), 0.0);
    g_bnd[most_negative_boundary_particle(L)] = -1;
    const SignPattern sp = sign_pattern(L);
    // The smooth problem of Table 4.4, then the two maximum-principle probes.
    const Outcome sol = try_solve(p, L, f, g, true);
    double err = NAN;
    if (sol.status == "ok") {
      err = 0;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.in_omega[i]) err = std::max(err, std::fabs(g[i] - sol.U[i]));
      err /= umax;
    }
    const Outcome src = try_solve(p, L, f_src, zero, true);
    const Outcome bnd = try_solve(p, L, zero, g_bnd, true);
    DenseFacts df;
    if (static_cast<int>(L.n_unknowns()) <= dense_max_) df = dense_facts(L);
    const double secs = seconds_since(t0);
    auto probe = [&](const Outcome& o) {
      return o.status == "ok" ? fmt(rise_above_zero(p, o.U)) : std::string("nan");
    };
    TsvRow row = run_.row(0);
    row["h_rule"] = rule, row["weight"] = wname, row["level"] = fmt(k), row["dx"] = fmt(dx);
    row["h"] = fmt(h), row["h_over_dx"] = fmt(h / dx), row["N"] = fmt(p.size());
    row["N_omega"] = fmt(L.n_unknowns()), row["negative_offdiag"] = fmt(sp.negative_offdiag);
    row["not_dominant"] = fmt(sp.not_dominant), row["positive_diag"] = fmt(sp.positive_diag);
    row["cg_status"] = sol.status, row["cg_iterations"] = fmt(sol.iterations);
    row["rel_error"] = fmt(err), row["cg_message"] = sol.message;
    row["mp_source"] = probe(src), row["mp_boundary"] = probe(bnd);
    row["mp_boundary_abs"] = bnd.status == "ok" ? fmt(omega_max(p, bnd.U)) : "nan";
    row["lambda_min"] = fmt(df.lambda_min), row["lambda_max"] = fmt(df.lambda_max);
    row["green_min"] = fmt(df.green_min), row["harmonic_min"] = fmt(df.harmonic_min);
    row["seconds"] = fmt(secs);
    run_.add(0, row);
    run_.unit_done(0, line_printf("(a) %s %-18s dx=2^-%d h/dx=%.2f neg.off=%.3f CG %s (%d it) "
                                 "err=%.3g  mp src=%s bnd=%s  lmin=%.4g green_min=%.3g  %.1f s",
                                 rule.c_str(), wname.c_str(), k, h / dx, sp.negative_offdiag,
                                 sol.status.c_str(), sol.iterations, err, probe(src).c_str(),
                                 probe(bnd).c_str(), df.lambda_min, df.green_min, secs));
  }

  // (b) h below the connectivity threshold: per level and seed, the grid's threshold h* and
  // radii on a fixed grid of h/dx and just below and above h*.
  void h_sweep() {
    for (int k : pick(prof_, kQuickSweepLevels, kPaperSweepLevels))
      for (int s : pick(prof_, kQuickSeeds, kPaperSeeds)) {
        const double dx = std::ldexp(1.0, -k);
        const Particles p = jittered_grid(dx, static_cast<uint64_t>(s));
        const auto V = uniform_volumes(p, dom_);
        const PoissonData problem = poisson_data(p, u_);
        const double h_star = h_connectivity_threshold(p, dx);
        std::vector<double> radii;
        for (double c : kRatios) radii.push_back(c * dx);
        for (double c : kNearThreshold) radii.push_back(c * h_star);
        for (double h : radii)
          if (!cb_->has({fmt(k), fmt(s), fmt(h / dx)}) && run_.claim()) sweep_unit(k, s, p, V, problem, h_star, h);
      }
  }

  // One (level, seed, h): connectivity, the checked solve (refuses) and the unchecked one.
  void sweep_unit(int k, int s, const Particles& p, const std::vector<double>& V, const PoissonData& problem,
                  double h_star, double h) {
    const double dx = std::ldexp(1.0, -k), c = h / dx;
    const auto& [f, g, umax] = problem;
    const auto t0 = std::chrono::steady_clock::now();
    const ConnectivityResult con = h_connectivity(p, h);
    const DiscreteLaplacian L(p, V, weight(kSweepWeight), h, LaplacianStorage::assembled);
    long long isolated = 0;  // rows of M that are all zero: no neighbour within h
    for (Eigen::Index r = 0; r < L.diagonal().size(); ++r) isolated += L.diagonal()[r] == 0;
    const Outcome chk = try_solve(p, L, f, g, true);
    const Outcome unc = try_solve(p, L, f, g, false);
    double err = NAN, big = NAN, true_res = NAN;
    if (unc.status == "ok") {
      // CG stops on its recursively updated residual; recompute ‖−Δ_h U − f‖₂ over Ω
      // relative to the right-hand side ‖f + M_ΩB g̃‖₂ (V is uniform, D cancels).
      Eigen::VectorXd full(static_cast<Eigen::Index>(p.size())), ghat(full.size()), mu, mg;
      for (std::size_t i = 0; i < p.size(); ++i)
        full[i] = unc.U[i], ghat[i] = p.in_omega[i] ? 0.0 : g[i];
      L.apply_full(full, mu);
      L.apply_full(ghat, mg);
      double rr = 0, bb = 0;
      for (std::size_t q = 0; q < L.omega().size(); ++q) {
        const double fq = f[L.omega()[q]];
        rr += (mu[q] + fq) * (mu[q] + fq);
        bb += (fq + mg[q]) * (fq + mg[q]);
      }
      true_res = std::sqrt(rr / bb);
      err = 0, big = 0;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.in_omega[i])
          err = std::max(err, std::fabs(g[i] - unc.U[i])),
          big = std::max(big, std::fabs(unc.U[i]));
      err /= umax;
    }
    const double secs = seconds_since(t0);
    TsvRow row = run_.row(1);
    row["level"] = fmt(k), row["seed"] = fmt(s), row["h_over_dx"] = fmt(c), row["dx"] = fmt(dx);
    row["h"] = fmt(h), row["N_omega"] = fmt(L.n_unknowns()), row["h_star_over_dx"] = fmt(h_star / dx);
    row["connected"] = con.connected ? "yes" : "no", row["unconnected"] = fmt(con.unconnected.size());
    row["isolated"] = fmt(isolated), row["checked_status"] = chk.status;
    row["checked_message"] = chk.message, row["unchecked_status"] = unc.status;
    row["unchecked_iterations"] = fmt(unc.iterations), row["rel_error"] = fmt(err);
    row["max_abs_U"] = fmt(big), row["true_residual"] = fmt(true_res);
    row["unchecked_message"] = unc.message, row["seconds"] = fmt(secs);
    run_.add(1, row);
    run_.unit_done(0, line_printf("(b) dx=2^-%d seed %d h/dx=%.2f (h*/dx=%.3f) %s, %zu unconnected, "
                                 "%lld isolated; checked: %s; unchecked: %s err=%.3g  %.2f s",
                                 k, s, c, h_star / dx, con.connected ? "connected" : "NOT connected",
                                 con.unconnected.size(), isolated, chk.status.c_str(), unc.status.c_str(),
                                 err, secs));
  }
};

int body(int argc, char** argv) { return PoissonFailure(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_poisson_failure", body, argc, argv); }
