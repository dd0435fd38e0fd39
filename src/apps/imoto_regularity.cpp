// imoto_regularity: the two regularity indicators of imoto §3 for the setting of §5, measured
// against the document's claims
//   r_N ≤ √2(1+1/4)Δx/2          (covering radius, eq. (5))
//   d_N ≤ 64(1+√2)Δx/π           (Voronoi deviation, eq. (6))
// and the regularity ratio (r_N + d_N)/h_N^m of Definition 1 for m = 1, 3, 5.
//
// Three outputs:
//  --out          r_N for Δx = 2^-5 … 2^-10 and several seeds (CGAL Voronoi cells), with the
//                 farthest point of the worst cell — the witness of r_N;
//  --out-example  one concrete counter-example to the r_N claim: the cell, its particle and
//                 grid node, the Voronoi vertex y farthest from it, and the brute-force check
//                 that NO particle lies closer to y than the claimed bound;
//  --out-deviation d_N by the linear programme of Appendix B (GLPK simplex), with the
//                 transport a_ij restricted to pairs |x_i − x_j| < R, R widened until the
//                 optimum no longer changes, and (r_N + d_N)/h^m.
//
// The LP (Appendix B): variables a_ij ≥ 0 (the area of σ_i ∩ ξ_j) and q, with
//   Σ_j a_ij = |σ_i|,  Σ_i a_ij = V_j,  Σ_j (a_ij + a_ji)|x_i − x_j|/|σ_i| ≤ q  for all i,
// minimise q.  Every decomposition Ξ gives such an a, and every such a is realised by some Ξ
// (cut each σ_i into pieces of areas a_ij and let ξ_j be the union of its pieces), so the
// optimum is d_N exactly.  Areas are scaled by Δx², distances by Δx (q comes out as d_N/Δx).
#include <glpk.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/truncation.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/run/runner.hpp"

using namespace gpm;

namespace {

// Parameters.  The covering radius is cheap (CGAL, ~2 µs per particle): the same levels in
// both profiles.  The LP has (pairs within R) variables; GLPK's interior point needs about
// 50 s for 2^-5 (R = 1.5, 2, 3 Δx) and minutes per R at 2^-6 (44,000 variables at R = 1.5 Δx:
// 41 s, 69,000 at R = 2 Δx: 130 s on a quiet 2-core machine); both profiles run 2^-5 and
// 2^-6, the two levels the issue asks for (2^-6 converges at R = 2 Δx, about 3 minutes).
const std::vector<int> kCoverLevels = {5, 6, 7, 8, 9, 10};
const std::vector<int> kQuickLpLevels = {5, 6};
const std::vector<int> kPaperLpLevels = {5, 6};
const std::vector<double> kRadii = {1.5, 2, 3, 4, 6};  // transport radius R/Δx, widened in turn
const std::vector<double> kOrders = {1, 3, 5};
const double kClaimR = std::sqrt(2.0) * 1.25 / 2;          // r_N/Δx claimed in §5
const double kClaimD = 64 * (1 + std::sqrt(2.0)) / M_PI;  // d_N/Δx claimed in §5

// The cell's vertex farthest from its particle (the witness of cover[i]).
void farthest_vertex(const VoronoiCells& c, const Particles& p, std::size_t i, double& fx,
                     double& fy) {
  double best = -1;
  for (uint64_t k = c.offset[i]; k < c.offset[i + 1]; ++k) {
    const double d = std::hypot(c.px[k] - p.x[i], c.py[k] - p.y[i]);
    if (d > best) best = d, fx = c.px[k], fy = c.py[k];
  }
}

// Distance from y to the nearest particle, by brute force (an independent check).
double nearest_particle(const Particles& p, double yx, double yy, std::size_t& which) {
  double best = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double d = std::hypot(p.x[i] - yx, p.y[i] - yy);
    if (d < best) best = d, which = i;
  }
  return best;
}

struct LpResult {
  double d_over_dx = NAN;
  std::size_t variables = 0;
  std::string status;
  double seconds = 0;
};

// d_N/Δx by the LP of Appendix B with the transport restricted to |x_i − x_j| < R.
LpResult voronoi_deviation(const Particles& p, const VoronoiCells& c,
                           const std::vector<double>& V, double dx, double R, bool simplex) {
  const auto t0 = std::chrono::steady_clock::now();
  const int n = static_cast<int>(p.size());
  const double s2 = dx * dx;
  // Scaled areas; V rescaled so that Σ V = Σ|σ| exactly (they differ by rounding only).
  std::vector<double> sig(n), vol(n);
  double ssum = 0, vsum = 0;
  for (int i = 0; i < n; ++i) ssum += c.area[i] / s2, vsum += V[i] / s2;
  for (int i = 0; i < n; ++i) sig[i] = c.area[i] / s2, vol[i] = V[i] / s2 * (ssum / vsum);

  glp_prob* lp = glp_create_prob();
  glp_set_obj_dir(lp, GLP_MIN);
  // Rows 1..n: supply of σ_i; n+1..2n: demand of ξ_j; 2n+1..3n: cost of cell i minus q_i ≤ 0;
  // 3n+1..4n−1: q_i = q_{i+1}.  One q per cell, chained by equalities, instead of one q in
  // every cost row: a dense column would make the interior-point normal matrix dense.
  glp_add_rows(lp, 4 * n - 1);
  for (int i = 0; i < n; ++i) {
    glp_set_row_bnds(lp, 1 + i, GLP_FX, sig[i], sig[i]);
    glp_set_row_bnds(lp, 1 + n + i, GLP_FX, vol[i], vol[i]);
    glp_set_row_bnds(lp, 1 + 2 * n + i, GLP_UP, 0, 0);
    if (i + 1 < n) glp_set_row_bnds(lp, 1 + 3 * n + i, GLP_FX, 0, 0);
  }
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0};
  const CellList cells(p.x, p.y, R * dx);
  int col = 0;
  for (int i = 0; i < n; ++i) {
    for (int32_t j : cells.neighbours(p.x[i], p.y[i], R * dx)) {
      ++col;
      const double cij = std::hypot(p.x[i] - p.x[j], p.y[i] - p.y[j]) / dx;
      ia.push_back(1 + i), ja.push_back(col), ar.push_back(1.0);
      ia.push_back(1 + n + j), ja.push_back(col), ar.push_back(1.0);
      if (j != i) {
        ia.push_back(1 + 2 * n + i), ja.push_back(col), ar.push_back(cij / sig[i]);
        ia.push_back(1 + 2 * n + j), ja.push_back(col), ar.push_back(cij / sig[j]);
      }
    }
  }
  const int q0 = col + 1;  // columns q0 … q0+n−1: q_1 … q_n
  glp_add_cols(lp, col + n);
  for (int k = 1; k <= col + n; ++k) glp_set_col_bnds(lp, k, GLP_LO, 0, 0);
  glp_set_obj_coef(lp, q0, 1.0);
  for (int i = 0; i < n; ++i) {
    ia.push_back(1 + 2 * n + i), ja.push_back(q0 + i), ar.push_back(-1.0);
    if (i + 1 < n) {
      ia.push_back(1 + 3 * n + i), ja.push_back(q0 + i), ar.push_back(1.0);
      ia.push_back(1 + 3 * n + i), ja.push_back(q0 + i + 1), ar.push_back(-1.0);
    }
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  LpResult r;
  r.variables = static_cast<std::size_t>(col + 1);  // the a_ij and one q
  int rc = 0, st = 0;
  if (simplex) {
    glp_smcp parm;
    glp_init_smcp(&parm);
    parm.msg_lev = GLP_MSG_OFF;
    parm.presolve = GLP_ON;
    parm.meth = GLP_DUALP;
    rc = glp_simplex(lp, &parm);
    st = glp_get_status(lp);
  } else {
    glp_iptcp parm;
    glp_init_iptcp(&parm);
    parm.msg_lev = GLP_MSG_OFF;
    rc = glp_interior(lp, &parm);
    st = glp_ipt_status(lp);
  }
  if (rc == 0 && st == GLP_OPT) {
    r.status = "optimal";
    r.d_over_dx = simplex ? glp_get_obj_val(lp) : glp_ipt_obj_val(lp);
  } else if (rc == GLP_ENOPFS || rc == GLP_ENOFEAS || st == GLP_NOFEAS || st == GLP_INFEAS) {
    r.status = "infeasible";  // R too small to move the surplus area
  } else {
    glp_delete_prob(lp);
    throw NumericalError("GLPK " + std::string(simplex ? "simplex" : "interior point") +
                         " failed (code " + std::to_string(rc) + ", status " +
                         std::to_string(st) + ") at dx = " + fmt(dx) + ", R = " + fmt(R) + " dx");
  }
  glp_delete_prob(lp);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

// The program: the covering radius over levels and seeds (with the counter-example), then the
// Voronoi deviation by the LP per level; each unit a row of its file, skipped when stored.
class Regularity {
 public:
  // The runner owns the options, the three data files (cache, store checks, header stamp),
  // the progress lines and the closing lines; --out is the covering radii.
  Regularity(int argc, char** argv)
      : run_("imoto_regularity",
             "imoto Sec. 3/5 regularity indicators: covering radius r_N over levels and seeds\n"
             "with a counter-example to r_N <= sqrt(2)(1+1/4)dx/2, and the Voronoi deviation\n"
             "d_N by the LP of Appendix B (GLPK) with (r_N + d_N)/h^m for m = 1, 3, 5.",
             "quick or paper (both: r_N at 2^-5..2^-10, the LP at 2^-5 and 2^-6)",
             StudyRunner::Kind::units_without_seed) {
    Args& args = run_.args();
    args.output("out-example", "", "counter-example TSV (required)")
        .output("out-deviation", "", "Voronoi-deviation TSV (required)")
        .opt("seeds", "1,2,3,4,5", "comma-separated jitter seeds for r_N")
        .opt("lp-seed", "1", "jitter seed of the LP (the seed of imoto_fig5_table1)")
        .opt("lp-method", "interior", "interior (GLPK interior point) or simplex (slow; a check)")
        .opt("lp-levels", "", "comma-separated LP levels; default: by profile");
    run_.parse(argc, argv);
    for (const char* o : {"out-example", "out-deviation"}) args.required(o);
    cover_levels_ = run_.levels(kCoverLevels, kCoverLevels, 3, 12);
    seeds_ = args.seeds("seeds");
    lp_seed_ = args.seed("lp-seed");
    method_ = args.str("lp-method");
    if (method_ != "interior" && method_ != "simplex")
      throw InputError("--lp-method: unknown '" + method_ + "'; valid: interior, simplex");
    simplex_ = method_ == "simplex";
    lp_levels_ = pick(run_.profile(), kQuickLpLevels, kPaperLpLevels);
    if (!args.str("lp-levels").empty()) {
      lp_levels_.clear();
      for (double v : args.nums("lp-levels")) {
        if (v != std::floor(v) || v < 3 || v > 9)
          throw InputError("--lp-levels: " + fmt(v) + " is not an integer in [3, 9]");
        lp_levels_.push_back(static_cast<int>(v));
      }
    }
  }

  int run() {
    open_files();
    for (int level : cover_levels_)
      for (uint64_t seed : seeds_) covering_unit(level, seed);
    for (int level : lp_levels_) deviation_unit(level);
    run_.finish();
    return 0;
  }

 private:
  StudyRunner run_;
  std::vector<int> cover_levels_, lp_levels_;
  std::vector<uint64_t> seeds_;
  uint64_t lp_seed_ = 1;
  std::string method_;
  bool simplex_ = false;
  const Domain dom_{};
  UnitCache* cov_ = nullptr;  // covering radii
  UnitCache* ex_ = nullptr;   // the counter-example
  UnitCache* dev_ = nullptr;  // the Voronoi deviation
  static constexpr const char* kCases[] = {"worst cell", "worst cell of a particle in Omega"};

  // The data files: rows are reused where a file's parameters agree; every unit is keyed by
  // its first three columns: (level, dx, seed) of a covering radius and of a level's LP (all
  // its transport radii), (case, level, seed) of a counter-example row.
  void open_files() {
    const std::string jitter = "|eta| < 1/4, counter-based hash of (seed,i,j), mirrored at the edge";
    const std::vector<UnitCache*> files = run_.open_files(
        {{run_.out(), {{"program", "imoto_regularity"}, {"part", "covering radius"}, {"H", fmt(dom_.H)},
                      {"jitter", jitter}, {"claim_r_over_dx", fmt(kClaimR)}},
          {"level", "dx", "seed", "N", "r_N_over_dx", "r_N_omega_over_dx", "claim_over_dx", "claim_holds",
           "worst_x", "worst_y", "far_x", "far_y", "time_s"}},
         {run_.args().str("out-example"), {{"program", "imoto_regularity"}, {"part", "counter-example to the r_N claim"},
                                    {"H", fmt(dom_.H)}, {"jitter", jitter}, {"claim_r_over_dx", fmt(kClaimR)}},
          {"case", "level", "seed", "particle", "node_i", "node_j", "eta_1", "eta_2", "x", "y", "vertex_x",
           "vertex_y", "dist_over_dx", "nearest_over_dx", "claim_over_dx"}},
         {run_.args().str("out-deviation"),
          {{"program", "imoto_regularity"}, {"part", "Voronoi deviation"}, {"H", fmt(dom_.H)}, {"jitter", jitter},
           {"claim_d_over_dx", fmt(kClaimD)}, {"volumes", "V_i = |Omega_H|/N"},
           {"lp", "Appendix B; GLPK " + method_ + "; areas/dx^2, distances/dx; transport restricted to "
                  "|x_i - x_j| < R; converged: same optimum (1e-6 rel.) as the previous R"},
           {"ratio", "(r_N + d_N)/h^m with h = 2.6 * 2^(5/m-5) * dx^(1/m)"}},
          {"level", "dx", "seed", "N", "R_over_dx", "variables", "status", "d_N_over_dx", "converged",
           "r_N_over_dx", "claim_d_over_dx", "ratio_m1", "ratio_m3", "ratio_m5", "time_s"}}},
        {}, 3);
    cov_ = files[0], ex_ = files[1], dev_ = files[2];
  }

  // The covering radius of one (level, seed); the counter-example from the coarsest level's
  // first seed (its worst cell overall and in Omega).
  void covering_unit(int level, uint64_t seed) {
    const double dx = std::ldexp(1.0, -level);
    const std::string s = fmt(static_cast<long long>(seed));
    const bool example = level == cover_levels_.front() && seed == seeds_.front();
    const bool todo = !cov_->has({fmt(level), fmt(dx), s}) ||
                      (example && (!ex_->has({kCases[0], fmt(level), s}) || !ex_->has({kCases[1], fmt(level), s})));
    if (!todo || !run_.claim()) return;
    const auto t0 = std::chrono::steady_clock::now();
    const Particles p = jittered_grid(dx, seed, 0.25, dom_);
    const VoronoiCells c = voronoi_cells(p, dom_, true);
    std::size_t wo = 0;  // worst cell among the particles in Ω
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.in_omega[i] && (!p.in_omega[wo] || c.cover[i] > c.cover[wo])) wo = i;
    double fx = 0, fy = 0;
    farthest_vertex(c, p, c.worst, fx, fy);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    TsvRow row = run_.row(0);
    row["level"] = fmt(level), row["dx"] = fmt(dx), row["seed"] = s;
    row["N"] = fmt(p.size()), row["r_N_over_dx"] = fmt(c.covering_radius / dx);
    row["r_N_omega_over_dx"] = fmt(c.cover[wo] / dx), row["claim_over_dx"] = fmt(kClaimR);
    row["claim_holds"] = c.covering_radius / dx <= kClaimR ? "1" : "0";
    row["worst_x"] = fmt(p.x[c.worst]), row["worst_y"] = fmt(p.y[c.worst]);
    row["far_x"] = fmt(fx), row["far_y"] = fmt(fy), row["time_s"] = fmt(secs);
    run_.add(0, row);
    if (example)
      for (auto [name, i] : {std::pair<const char*, std::size_t>{kCases[0], c.worst}, {kCases[1], wo}}) {
        double vx = 0, vy = 0;
        farthest_vertex(c, p, i, vx, vy);
        std::size_t nearest = 0;
        const double dn = nearest_particle(p, vx, vy, nearest);
        TsvRow e = run_.row(1);
        e["case"] = name, e["level"] = fmt(level), e["seed"] = s;
        e["particle"] = fmt(i), e["node_i"] = fmt(p.gi[i]), e["node_j"] = fmt(p.gj[i]);
        e["eta_1"] = fmt(p.x[i] / dx - p.gi[i]), e["eta_2"] = fmt(p.y[i] / dx - p.gj[i]);
        e["x"] = fmt(p.x[i]), e["y"] = fmt(p.y[i]), e["vertex_x"] = fmt(vx), e["vertex_y"] = fmt(vy);
        e["dist_over_dx"] = fmt(std::hypot(vx - p.x[i], vy - p.y[i]) / dx);
        e["nearest_over_dx"] = fmt(dn / dx), e["claim_over_dx"] = fmt(kClaimR);
        run_.add(1, e);
      }
    run_.unit_done(0, line_printf("level %d seed %s N=%zu r_N/dx=%.4f (Omega %.4f) %.2fs", level, s.c_str(),
                                 p.size(), c.covering_radius / dx, c.cover[wo] / dx, secs));
  }

  // The Voronoi deviation of one level by the LP: the transport radius widened until the
  // optimum no longer changes.
  void deviation_unit(int level) {
    const double dx = std::ldexp(1.0, -level);
    if (dev_->has({fmt(level), fmt(dx), fmt(lp_seed_)}) || !run_.claim()) return;
    const Particles p = jittered_grid(dx, static_cast<uint64_t>(lp_seed_), 0.25, dom_);
    const VoronoiCells c = voronoi_cells(p, dom_, false);
    const std::vector<double> V = uniform_volumes(p, dom_);
    double prev = NAN, last = NAN, secs = 0;
    for (double R : kRadii) {
      const LpResult r = voronoi_deviation(p, c, V, dx, R, simplex_);
      secs += r.seconds, last = r.d_over_dx;
      // Converged: the optimum at this R equals the one at the previous R (the interior
      // point stops at a relative gap of ~1e-8, so 1e-6 relative; 1e-9 for the simplex_).
      const double tol = simplex_ ? 1e-9 : 1e-6;
      const bool conv = std::isfinite(prev) && std::isfinite(r.d_over_dx) &&
                        std::fabs(r.d_over_dx - prev) <= tol * std::fabs(prev);
      TsvRow row = run_.row(2);
      row["level"] = fmt(level), row["dx"] = fmt(dx), row["seed"] = fmt(lp_seed_);
      row["N"] = fmt(p.size()), row["R_over_dx"] = fmt(R), row["variables"] = fmt(r.variables);
      row["status"] = r.status, row["d_N_over_dx"] = fmt(r.d_over_dx), row["converged"] = conv ? "1" : "0";
      row["r_N_over_dx"] = fmt(c.covering_radius / dx), row["claim_d_over_dx"] = fmt(kClaimD);
      // ratio_m1, ratio_m3, ...: an order of kOrders without its column throws here.
      for (double m : kOrders)
        row["ratio_m" + fmt(m)] = fmt((c.covering_radius + r.d_over_dx * dx) / std::pow(imoto_h(m, dx), m));
      row["time_s"] = fmt(r.seconds);
      run_.add(2, row);
      // A level's LP takes minutes: a line per radius.
      std::fprintf(stderr, "[imoto_regularity] LP level %d R=%g dx: %zu variables, %s, d_N/dx=%.6g %.2fs\n",
                   level, R, r.variables, r.status.c_str(), r.d_over_dx, r.seconds);
      if (conv) break;
      prev = r.d_over_dx;
    }
    run_.unit_done(0, line_printf("LP level %d: d_N/dx = %.6g at the last radius, %.1fs", level, last, secs));
  }
};

int body(int argc, char** argv) { return Regularity(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("imoto_regularity", body, argc, argv); }
