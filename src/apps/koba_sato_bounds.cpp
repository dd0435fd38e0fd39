// koba_sato_bounds: Koba & Sato's Theorems 1.3–1.6 on actual Voronoi cells.
//
// The paper proves bounds on the truncation error of its four operators (Definition 1.2)
// but evaluates none.  Here, on jittered-grid Voronoi tessellations of Ω_H, for particles
// a_k near the centre of Ω, a sweep of C* = h/r_σ and λ, the step weight of Section 7 and
// Lipschitz weights from the registry, the program measures the error of Π̃_h, ∇̃_h, Δ̃_h
// and □̃_h at a_k for test functions with known seminorms, and evaluates each theorem's
// right-hand side with the constants c₁ … c₁₂ computed from the cells (exact
// polygon–annulus integrals, src/gpm/theory/koba_sato.hpp).  δ = r_σ/2 as in Section 7 where
// B_{r_σ/2}(a_k) ⊂ σ_k, else the largest admissible δ = dist(a_k, ∂σ_k).
//
// Output: one row per (level, seed, site, C*, weight, λ, function) with error and bound
// of each operator; the paper's hypotheses checked on the cells; the constants at one
// particle; a summary (smallest bound/error ratio, violations, from the case rows); and the
// particles, cells and radii drawn in Figures 1–2.  A unit is one tessellation (level,
// seed): the runner (runner.hpp) caches the three data files' units, so a rerun computes
// only the missing ones, and --verify / --recheck compare them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/run/runner.hpp"
#include "gpm/theory/koba_sato.hpp"
#include "gpm/theory/koba_sato_cor71.hpp"

using namespace gpm;

namespace {

// Per profile: levels k (Δx = 2^-k), seeds, sites per tessellation, C* values.
// At level 8 r_σ ≈ 1.08Δx, so C* = 64 keeps B_{h+r_σ+δ}(a_k) inside Ω_H for a_k within 0.1
// of the centre.  Quick: ~10 s; paper: a few minutes.
const std::vector<int> kQuickLevels = {8}, kPaperLevels = {8, 9};
const char* kQuickSeeds = "1";
const char* kPaperSeeds = "1,2,3";
const long long kQuickSites = 4, kPaperSites = 8;
const char* kCStars = "2,2.8284271247461903,4,5.656854249746381,8,11.313708498984761,16,"
                      "22.627416997969522,32,45.254833995939045,64";

constexpr double kPi = 3.14159265358979323846;
const char* kOps[] = {"interpolant", "gradient", "laplacian", "laplacian_with_c8",
                      "box_laplacian"};
const char* kCorOps[] = {"interpolant", "gradient", "laplacian", "box_laplacian"};

std::string dir_of(const std::string& path) {
  const auto s = path.rfind('/');
  return s == std::string::npos ? "." : path.substr(0, s);
}
std::string sibling(const std::string& out, const std::string& suffix) {
  const std::string base = out.size() > 4 && out.substr(out.size() - 4) == ".tsv"
                               ? out.substr(0, out.size() - 4)
                               : out;
  return base + suffix;
}

// Four significant digits, for the "where" column.
std::string four_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// The particles nearest to K points on a circle of radius 0.1 around (½, ½) (K = 1: the
// centre): spread out, far enough from ∂Ω_H for C* = 64 at level 8.
std::vector<std::size_t> choose_sites(const Particles& p, long long K) {
  std::vector<std::size_t> out;
  for (long long j = 0; j < K; ++j) {
    const double a = 2 * kPi * (j + 0.25) / static_cast<double>(K), rad = K == 1 ? 0.0 : 0.1;
    const double tx = 0.5 + rad * std::cos(a), ty = 0.5 + rad * std::sin(a);
    std::size_t best = 0;
    double bd = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double d = std::hypot(p.x[i] - tx, p.y[i] - ty);
      if (d < bd) bd = d, best = i;
    }
    if (std::find(out.begin(), out.end(), best) == out.end()) out.push_back(best);
  }
  return out;
}

// The smallest bound/error ratio seen for one (operator, weight), and where.
struct Worst {
  long long cases = 0, violations = 0;
  double ratio = std::numeric_limits<double>::infinity();
  std::string where;
};

// Particles, cells and radii around one a_k, for Figures 1–2: computed before the study (it
// takes milliseconds and checks that --fig-level and --fig-cstar give a valid site), written
// after it.
struct FigureData {
  TsvTable particles, cells, circles;
};

FigureData figure_data(int level, uint64_t seed, double c_star, double lambda,
                       const std::vector<std::pair<std::string, std::string>>& hdr) {
  const Domain dom;
  const double dx = std::ldexp(1.0, -level);
  const Particles p = jittered_grid(dx, seed);
  const VoronoiCells cells = voronoi_cells(p, dom, true);
  const double r_sigma = cells.covering_radius;
  const std::size_t k = choose_sites(p, 1).front();
  const PolygonView ck = cell_polygon(cells, k);
  const double delta = std::min(r_sigma / 2, polygon_boundary_distance(ck, p.x[k], p.y[k]));
  const double h = c_star * r_sigma;
  const KsSite s = ks_site(p, cells, k, h, delta, r_sigma, dom);  // checks the assumptions
  std::vector<char> role(p.size(), 'o');
  role[k] = 'k';
  for (std::size_t i : s.idx) role[i] = 'R';
  auto header = [&](TsvTable& t, const std::string& what) {
    t.set("program", "koba_sato_bounds");
    t.set("figure_data", what);
    for (auto& [key, v] : hdr) t.set(key, v);
    t.set("fig_level", static_cast<double>(level));
    t.set("dx", dx);
    t.set("seed", static_cast<double>(seed));
    t.set("H", dom.H);
    t.set("k", static_cast<double>(k));
    t.set("a_k", fmt(p.x[k]) + ", " + fmt(p.y[k]));
    t.set("r_sigma", r_sigma);
    t.set("delta", delta);
    t.set("h", h);
    t.set("lambda_h", lambda * h);
    t.set("roles", "k = a_k, R = R(a_k, h), o = other");
    add_provenance(t);
  };
  FigureData fd;
  TsvTable& tp = fd.particles;
  header(tp, "particles");
  tp.columns = {"x", "y", "in_omega", "role"};
  for (std::size_t i = 0; i < p.size(); ++i)
    tp.add_row({fmt(p.x[i]), fmt(p.y[i]), p.in_omega[i] ? "1" : "0", std::string(1, role[i])});
  TsvTable& tc = fd.cells;
  header(tc, "Voronoi cells, one vertex per row, first vertex repeated to close the polygon");
  tc.columns = {"cell", "x", "y", "role"};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const PolygonView c = cell_polygon(cells, i);
    for (std::size_t j = 0; j <= c.n; ++j)
      tc.add_row({fmt(i), fmt(c.x[j % c.n]), fmt(c.y[j % c.n]), std::string(1, role[i])});
  }
  TsvTable& tr = fd.circles;
  header(tr, "circles around a_k");
  tr.columns = {"name", "x", "y", "r"};
  for (auto [name, r] : {std::pair<const char*, double>{"delta", delta}, {"r_sigma", r_sigma},
                         {"lambda_h", lambda * h}, {"h", h}})
    tr.add_row({name, fmt(p.x[k]), fmt(p.y[k]), fmt(r)});
  return fd;
}

const char* kFigureFiles[] = {"_particles.tsv", "_cells.tsv", "_circles.tsv"};

// The sweep of one run: what every (level, seed) unit computes.
struct Sweep {
  long long n_sites = 0;
  std::vector<double> cstars, lambdas;
  std::vector<std::string> weights;
  std::vector<const KsFunction*> funcs;
  double lambda_sample = 0.5;  // the λ of the constants table
};

// The three data files' columns; a unit is keyed by (level, seed), their first two.
const std::vector<std::string> kCaseColumns = {
    "level", "seed", "site", "k", "ak_x", "ak_y", "r_sigma", "delta", "C_star", "h",
    "n_R", "weight", "L_w", "lambda", "lambda_ok", "func", "err_pi", "bound_pi",
    "err_grad", "bound_grad", "err_lap", "bound_lap", "bound_lap_c8", "err_box",
    "bound_box", "cor_pi", "cor_grad", "cor_lap", "cor_box"};
const std::vector<std::string> kHypothesisColumns = {
    "level", "seed", "weight", "N", "r_sigma", "r_sigma_over_dx", "sites", "sites_delta_cor_ok",
    "R_empty", "cases", "covering_holds", "uncovered_rel_max", "eq_2_6_fails", "eq_2_6_ratio_max",
    "lambda_cases", "lambda_empty", "lemma_2_11_ratio_max"};
const std::vector<std::string> kConstantColumns = {
    "level", "seed", "weight", "C_star", "h", "delta", "r_sigma", "L_w", "c1", "c2", "c3", "c4", "c5",
    "c6", "c7", "c8", "c9", "c10", "c11", "c12", "c1_cor", "lemma_2_11_lhs", "lemma_2_11_rhs"};
enum File { kCases = 0, kHypotheses = 1, kConstants = 2 };

// One tessellation (level, seed): at each site a_k and C*, every weight, λ and function, the
// error of the four operators against each theorem's bound (rows of kCases), the paper's
// hypotheses checked on the cells (kHypotheses, one row per weight) and, where `sample`, the
// constants at site 0 and λ = lambda_sample (kConstants).  Returns the cases done.
long long run_unit(StudyRunner& run, int level, uint64_t seed, const Sweep& sw, bool sample) {
  const Domain dom;
  const double dx = std::ldexp(1.0, -level);
  const Particles p = jittered_grid(dx, seed);
  const VoronoiCells cells = voronoi_cells(p, dom, true);
  const double r_sigma = cells.covering_radius;
  const auto sites = choose_sites(p, sw.n_sites);
  struct HypCount {
    long long r_empty = 0, cases = 0, covering = 0, fails26 = 0, lam_cases = 0, lam_empty = 0, delta_ok = 0;
    double unc_max = 0, r26 = 0, l211 = 0;
  };
  std::map<std::string, HypCount> hyp;
  long long done = 0;
  for (std::size_t si = 0; si < sites.size(); ++si) {
    const std::size_t k = sites[si];
    const PolygonView ck = cell_polygon(cells, k);
    const double dmax = polygon_boundary_distance(ck, p.x[k], p.y[k]);
    const double delta = std::min(r_sigma / 2, dmax);
    for (auto& wn : sw.weights) hyp[wn].delta_ok += dmax >= r_sigma / 2;
    for (double cs : sw.cstars) {
      ++done;
      const double h = cs * r_sigma;
      const KsSite s = ks_site(p, cells, k, h, delta, r_sigma, dom);
      if (s.idx.empty()) {  // Assumption 1.1 (v) fails: no neighbour within h
        for (auto& wn : sw.weights) hyp[wn].r_empty++;
        continue;
      }
      // Function values at the neighbours, once per (site, C*).
      std::vector<std::vector<double>> fv(sw.funcs.size());
      for (std::size_t fi = 0; fi < sw.funcs.size(); ++fi)
        for (std::size_t i : s.idx) fv[fi].push_back(sw.funcs[fi]->d(0, 0, p.x[i], p.y[i]));
      for (auto& wn : sw.weights) {
        const KsWeight w = ks_weight(wn, delta, h);
        const auto wnb = ks_neighbour_weights(s, w);
        // (2.11): Σ_R ∫_{σ_i} w(a_k − y) dy against Σ_R V_i w(a_k − a_i).
        double sum_X = 0, sum_Y = 0;
        for (std::size_t j = 0; j < s.idx.size(); ++j) {
          sum_X += w.norm_polygon(0, cell_polygon(cells, s.idx[j]), s.ax, s.ay, delta, h);
          sum_Y += s.V[j] * wnb[j];
        }
        const double l211_lhs = std::abs(sum_X - sum_Y), l211_rhs = kPi * w.lipschitz * r_sigma * h * h;
        HypCount& hc = hyp[wn];
        hc.cases++;
        const double unc = s.uncovered / (kPi * h * h);
        hc.covering += unc <= 1e-12;
        hc.unc_max = std::max(hc.unc_max, unc);
        hc.fails26 += s.ratio_2_6 > 1;
        hc.r26 = std::max(hc.r26, s.ratio_2_6);
        hc.l211 = std::max(hc.l211, l211_rhs > 0 ? l211_lhs / l211_rhs : (l211_lhs > 1e-13 * sum_Y ? INFINITY : 0.0));
        std::vector<KsOps> ops(sw.funcs.size());
        for (std::size_t fi = 0; fi < sw.funcs.size(); ++fi)
          ops[fi] = ks_operators(s, wnb, fv[fi].data(), sw.funcs[fi]->d(0, 0, s.ax, s.ay));
        for (double lam : sw.lambdas) {
          const KsConstants c = ks_constants(s, wnb, w, ck, lam);
          hc.lam_cases++;
          hc.lam_empty += !c.lambda_ok;
          if (sample && si == 0 && lam == sw.lambda_sample) {
            TsvRow row = run.row(kConstants);
            row["level"] = fmt(level), row["seed"] = fmt(static_cast<long long>(seed));
            row["weight"] = wn, row["C_star"] = fmt(cs), row["h"] = fmt(h), row["delta"] = fmt(delta);
            row["r_sigma"] = fmt(r_sigma), row["L_w"] = fmt(w.lipschitz);
            for (int i = 1; i <= 12; ++i) row["c" + std::to_string(i)] = fmt(c.c[i]);
            row["c1_cor"] = fmt((r_sigma * r_sigma - delta * delta) / (h * h - delta * delta));
            row["lemma_2_11_lhs"] = fmt(l211_lhs), row["lemma_2_11_rhs"] = fmt(l211_rhs);
            run.add(kConstants, row);
          }
          const bool step = wn == "step";
          const auto cor = cor71_formula<double>(r_sigma, cs, lam);
          for (std::size_t fi = 0; fi < sw.funcs.size(); ++fi) {
            const KsFunction& f = *sw.funcs[fi];
            const auto& sn = f.seminorm;
            const KsBounds b = ks_bounds(c, h, r_sigma, lam, sn);
            const KsOps& o = ops[fi];
            const double gx = f.d(1, 0, s.ax, s.ay), gy = f.d(0, 1, s.ax, s.ay);
            const double lap = f.d(2, 0, s.ax, s.ay) + f.d(0, 2, s.ax, s.ay);
            const double cb[4] = {cor.pi_c1 * sn[1] + cor.pi_c0 * sn[0], cor.grad_c2 * sn[2] + cor.grad_c1 * sn[1],
                                  cor.lap_c3 * sn[3] + cor.lap_c1 * sn[1], cor.box_c3 * sn[3] + cor.box_c1 * sn[1]};
            auto cor_cell = [&](int i) { return step ? fmt(cb[i]) : std::string("NA"); };
            TsvRow row = run.row(kCases);  // by column name: error beside its bound
            row["level"] = fmt(level), row["seed"] = fmt(static_cast<long long>(seed));
            row["site"] = fmt(si), row["k"] = fmt(k), row["ak_x"] = fmt(s.ax), row["ak_y"] = fmt(s.ay);
            row["r_sigma"] = fmt(r_sigma), row["delta"] = fmt(delta), row["C_star"] = fmt(cs);
            row["h"] = fmt(h), row["n_R"] = fmt(s.idx.size()), row["weight"] = wn;
            row["L_w"] = fmt(w.lipschitz), row["lambda"] = fmt(lam);
            row["lambda_ok"] = fmt(c.lambda_ok ? 1 : 0), row["func"] = f.name;
            row["err_pi"] = fmt(std::abs(f.d(0, 0, s.ax, s.ay) - o.pi)), row["bound_pi"] = fmt(b.pi);
            row["err_grad"] = fmt(std::hypot(gx - o.gx, gy - o.gy)), row["bound_grad"] = fmt(b.grad);
            row["err_lap"] = fmt(std::abs(lap - o.lap)), row["bound_lap"] = fmt(b.lap);
            row["bound_lap_c8"] = fmt(b.lap_lemmas);
            row["err_box"] = fmt(std::abs(lap - o.box)), row["bound_box"] = fmt(b.box);
            row["cor_pi"] = cor_cell(0), row["cor_grad"] = cor_cell(1);
            row["cor_lap"] = cor_cell(2), row["cor_box"] = cor_cell(3);
            run.add(kCases, row);
          }
        }
      }
    }
  }
  for (auto& wn : sw.weights) {
    const HypCount& hc = hyp[wn];
    TsvRow row = run.row(kHypotheses);
    row["level"] = fmt(level), row["seed"] = fmt(static_cast<long long>(seed)), row["weight"] = wn;
    row["N"] = fmt(p.size()), row["r_sigma"] = fmt(r_sigma), row["r_sigma_over_dx"] = fmt(r_sigma / dx);
    row["sites"] = fmt(sites.size()), row["sites_delta_cor_ok"] = fmt(hc.delta_ok);
    row["R_empty"] = fmt(hc.r_empty), row["cases"] = fmt(hc.cases);
    row["covering_holds"] = fmt(hc.covering), row["uncovered_rel_max"] = fmt(hc.unc_max);
    row["eq_2_6_fails"] = fmt(hc.fails26), row["eq_2_6_ratio_max"] = fmt(hc.r26);
    row["lambda_cases"] = fmt(hc.lam_cases), row["lambda_empty"] = fmt(hc.lam_empty);
    row["lemma_2_11_ratio_max"] = fmt(hc.l211);
    run.add(kHypotheses, row);
  }
  return done;
}

// Per (operator, weight) over the case rows of the run's units (in loop order, so that of
// equal ratios the first is named): the cases, the violations (bound < error) and the
// smallest bound/error with where it sits.  Theorem 1.3 applies always, 1.4–1.6 only where
// R(a_k, λh) is not empty (lambda_ok); the step weight also against Corollary 7.1's formula.
TsvTable summary_of(const TsvTable& cases, const std::vector<int>& levels, const std::vector<uint64_t>& seeds,
                    const std::vector<std::string>& weights) {
  std::vector<std::size_t> order;
  for (int level : levels)
    for (uint64_t seed : seeds)
      for (std::size_t i = 0; i < cases.rows.size(); ++i)
        if (cases.text(i, "level") == fmt(level) && cases.text(i, "seed") == fmt(static_cast<long long>(seed)))
          order.push_back(i);
  std::map<std::string, Worst> worst;  // key: operator + "\t" + weight
  auto num = [&](std::size_t i, const char* c) { return cases.number(i, cases.require_column(c)); };
  for (std::size_t i : order) {
    const std::string wn = cases.text(i, "weight");
    const bool lambda_ok = cases.text(i, "lambda_ok") == "1";
    const std::string where = "level " + cases.text(i, "level") + ", seed " + cases.text(i, "seed") + ", site " +
                              cases.text(i, "site") + ", C* " + four_digits(num(i, "C_star")) + ", lambda " +
                              cases.text(i, "lambda") + ", " + cases.text(i, "func");
    auto tally = [&](const std::string& op, const std::string& wname, double err, double bound, bool applies) {
      if (!applies) return;
      Worst& W = worst[op + "\t" + wname];
      W.cases++;
      W.violations += bound < err;
      if (err > 0 && bound / err < W.ratio) W.ratio = bound / err, W.where = where;
    };
    const double errs[5] = {num(i, "err_pi"), num(i, "err_grad"), num(i, "err_lap"), num(i, "err_lap"), num(i, "err_box")};
    const double bnds[5] = {num(i, "bound_pi"), num(i, "bound_grad"), num(i, "bound_lap"), num(i, "bound_lap_c8"),
                            num(i, "bound_box")};
    for (int o = 0; o < 5; ++o) tally(kOps[o], wn, errs[o], bnds[o], o == 0 || lambda_ok);
    if (wn == "step") {
      const double cerr[4] = {errs[0], errs[1], errs[2], errs[4]};
      const double cb[4] = {num(i, "cor_pi"), num(i, "cor_grad"), num(i, "cor_lap"), num(i, "cor_box")};
      for (int o = 0; o < 4; ++o) tally(kCorOps[o], "step (Cor. 7.1 formula)", cerr[o], cb[o], o == 0 || lambda_ok);
    }
  }
  TsvTable ts;
  ts.set("ratio", "smallest bound/error over all cases (cases with error 0 excluded)");
  ts.set("cases", "Theorem 1.3 applies always; 1.4-1.6 only where R(a_k, lambda h) is not empty");
  ts.columns = {"operator", "weight", "cases", "violations", "min_ratio", "where", "verdict"};
  long long total_viol = 0;
  std::vector<std::string> names = weights;
  names.push_back("step (Cor. 7.1 formula)");
  for (const char* op : kOps)
    for (const std::string& wn : names) {
      const auto it = worst.find(std::string(op) + "\t" + wn);
      if (it == worst.end()) continue;
      const Worst& W = it->second;
      total_viol += W.violations;
      const std::string verdict =
          W.violations == 0 ? "bound >= error in all " + std::to_string(W.cases) + " cases"
                            : "bound < error in " + std::to_string(W.violations) + " of " +
                                  std::to_string(W.cases) + " cases";
      TsvRow row = ts.named_row();
      row["operator"] = op, row["weight"] = wn, row["cases"] = fmt(W.cases), row["violations"] = fmt(W.violations);
      row["min_ratio"] = fmt(W.ratio), row["where"] = W.where, row["verdict"] = verdict;
      ts.add_row(row);
    }
  ts.set("violations_total", static_cast<double>(total_viol));
  return ts;
}

// The program: the options and the sweep, then the data files, one unit per (level, seed),
// and the summary and Figures 1-2's data from the stored case rows.
class Bounds {
 public:
  // No --seed: the seeds are a list of the study's own (one unit per level and seed).
  Bounds(int argc, char** argv)
      : run_("koba_sato_bounds",
             "Koba & Sato Theorems 1.3-1.6 on jittered-grid Voronoi cells: the error of the four\n"
             "operators at a_k against the theorems' bounds with constants computed from the cells.",
             "quick (level 8, 1 seed, 4 sites) or paper (levels 8-9, 3 seeds, 8 sites)",
             StudyRunner::Kind::units_without_seed) {
    run_.args().opt("seeds", "", "comma-separated jitter seeds (default: by profile)")
        .opt("sites", "", "particles a_k per tessellation, 1..64 (default: by profile)")
        .opt("cstars", kCStars, "C* = h / r_sigma values (> 1)")
        .opt("lambdas", "0.25,0.5,0.75", "lambda values in (0,1)")
        .opt("weights", "step,Pi1,quadratic_spike", "step and/or registry weights, w(x) = W(|x|/h) on the annulus")
        .opt("functions", "sin2pi,wave,quartic,linear", "test functions")
        .output("summary", "", "summary TSV (default: OUT with _summary.tsv)")
        .output("constants", "", "constants TSV (default: OUT with _constants.tsv)")
        .output("hypotheses", "", "hypotheses TSV (default: OUT with _hypotheses.tsv)")
        .opt("fig-prefix", "", "prefix of the Figure 1-2 data files (default: DIR(OUT)/koba_sato_fig)")
        .opt("fig-level", "4", "level of the tessellation drawn in Figures 1-2, 2..10")
        .opt("fig-cstar", "3", "C* drawn in Figures 1-2 (> 1)");
    run_.parse(argc, argv);
    out_ = run_.out();
    const bool quick = run_.profile() == Profile::quick;
    const auto or_default = [&](const std::string& key, const std::string& def) {
      return args().str(key).empty() ? def : args().str(key);
    };
    summary_path_ = or_default("summary", sibling(out_, "_summary.tsv"));
    constants_path_ = or_default("constants", sibling(out_, "_constants.tsv"));
    hyp_path_ = or_default("hypotheses", sibling(out_, "_hypotheses.tsv"));
    fig_prefix_ = or_default("fig-prefix", dir_of(out_) + "/koba_sato_fig");

    // The sweep: levels and seeds (the units), sites, C*, λ, weights and functions.
    levels_ = run_.levels(kQuickLevels, kPaperLevels, 6, 10);
    seeds_ = parse_seeds(or_default("seeds", quick ? kQuickSeeds : kPaperSeeds), "--seeds");
    sw_.n_sites = args().str("sites").empty() ? (quick ? kQuickSites : kPaperSites) : args().integer("sites", 1, 64);
    sw_.cstars = args().nums("cstars"), sw_.lambdas = args().nums("lambdas");
    for (double c : sw_.cstars)
      if (!(c > 1)) throw InputError("--cstars: C* must exceed 1 (h > r_sigma), got " + fmt(c));
    for (double l : sw_.lambdas)
      if (!(l > 0 && l < 1)) throw InputError("--lambdas: lambda must lie in (0, 1), got " + fmt(l));
    sw_.weights = args().list("weights");
    for (auto& n : args().list("functions")) sw_.funcs.push_back(&ks_function(n));
    for (auto& n : sw_.weights) ks_weight(n, 0.1, 1.0);  // unknown or non-Lipschitz: fail now
    if (levels_.empty() || seeds_.empty() || sw_.cstars.empty() || sw_.lambdas.empty() || sw_.weights.empty() ||
        sw_.funcs.empty())
      throw InputError("every list option needs at least one value");
    sw_.lambda_sample =
        std::find(sw_.lambdas.begin(), sw_.lambdas.end(), 0.5) != sw_.lambdas.end() ? 0.5 : sw_.lambdas.front();
    const int fig_level = static_cast<int>(args().integer("fig-level", 2, 10));
    const double fig_cstar = args().num("fig-cstar");
    if (!(fig_cstar > 1))
      throw InputError("--fig-cstar: C* must exceed 1 (h > r_sigma), got " + args().str("fig-cstar"));
    // Every file of the run, the defaults derived from --out included, before any work.
    std::vector<std::pair<std::string, std::string>> outputs = {
        {"--out", out_}, {"--summary", summary_path_}, {"--constants", constants_path_}, {"--hypotheses", hyp_path_}};
    for (const char* f : kFigureFiles) outputs.emplace_back("--fig-prefix", fig_prefix_ + f);
    check_output_paths(outputs, run_.program());
    try {
      fig_ = figure_data(fig_level, seeds_.front(), fig_cstar, sw_.lambda_sample, args().values());
    } catch (const InputError& e) {
      throw InputError("--fig-level " + args().str("fig-level") + " with --fig-cstar " + args().str("fig-cstar") + ": " +
                       e.what());
    }
  }

  int run() {
    open_files();
    units();
    if (!run_.finish()) return 0;  // verify/recheck: nothing more is written
    write_summary_and_figures();
    return 0;
  }

 private:
  StudyRunner run_;
  std::string out_, summary_path_, constants_path_, hyp_path_, fig_prefix_;
  std::vector<int> levels_;
  std::vector<uint64_t> seeds_;
  Sweep sw_;
  FigureData fig_;
  const Domain dom_{};
  std::vector<std::pair<std::string, std::string>> params_;  // what a row depends on
  std::vector<UnitCache*> files_;

  Args& args() { return run_.args(); }

  // The data files: the cases, the hypotheses, the constants; what a row depends on.
  void open_files() {
    params_ = {
        {"program", "koba_sato_bounds"}, {"profile", profile_name(run_.profile())},
        {"sites", fmt(sw_.n_sites)}, {"cstars", args().str("cstars")}, {"lambdas", args().str("lambdas")},
        {"weights", args().str("weights")}, {"functions", args().str("functions")}, {"H", fmt(dom_.H)},
        {"particles", "jittered grid, |eta| < 1/4, mirrored into Omega_H (core)"},
        {"r_sigma", "max_i max_{y in sigma_i} |y - a_i| over ALL cells of Omega_H (the paper's definition)"},
        {"delta", "min(r_sigma/2, dist(a_k, boundary of sigma_k))"},
        {"sites_rule", "particles nearest to points on the circle |x - (1/2,1/2)| = 0.1"},
        {"error", "|f(a_k) - Pi f|, |grad f - grad~ f| (Euclidean), |lap f - lap~ f|, |lap f - box~ f|"},
        {"bound", "right-hand sides of Theorems 1.3-1.6 with c1..c12 from the cells; "
                  "laplacian_with_c8 adds 4 c8 |f|_C1 from Lemma 5.2 (5.4)"},
        {"cor_bound", "Corollary 7.1's general formulas at the measured r_sigma, C*, lambda "
                      "(step weight only; its assumptions are not those of real cells)"}};
    for (auto* f : sw_.funcs)
      params_.emplace_back("f_" + f->name, f->formula + "; |f|_C0..C3 = " + fmt(f->seminorm[0]) + ", " +
                                              fmt(f->seminorm[1]) + ", " + fmt(f->seminorm[2]) + ", " +
                                              fmt(f->seminorm[3]));
    auto with = [&](std::vector<std::pair<std::string, std::string>> extra) {
      auto p = params_;
      p.insert(p.end(), extra.begin(), extra.end());
      return p;
    };
    files_ = run_.open_files(
        {{out_, params_, kCaseColumns},
         {hyp_path_,
          with({{"covering", "B_h(a_k) covered by the closed cells of R-bar(a_k,h) iff uncovered area <= 1e-12 pi h^2"},
                {"eq_2_6", "(2.6): sup_{y in sigma_i}|y - a_i| <= |a_k - a_i| for i in R(a_k,h)"},
                {"lemma_2_11", "(2.11): |sum_R int_{sigma_i} w - sum_R V_i w(a_k - a_i)| <= pi L_w r_sigma h^2"}}),
          kHypothesisColumns},
         {constants_path_, with({{"sample", "first level, first seed, site 0, lambda = " + fmt(sw_.lambda_sample)}}),
          kConstantColumns}},
        kCaseColumns, 2);
  }

  // One tessellation per (level, seed); a unit is done when every file has it.
  void units() {
    run_.expect(static_cast<double>(levels_.size() * seeds_.size() * sw_.n_sites * sw_.cstars.size()), "cases");
    for (int level : levels_)
      for (uint64_t seed : seeds_) {
        const bool sample = level == levels_.front() && seed == seeds_.front();
        const std::vector<std::string> key = {fmt(level), fmt(static_cast<long long>(seed))};
        if ((files_[kCases]->has(key) && files_[kHypotheses]->has(key) && (!sample || files_[kConstants]->has(key))) ||
            !run_.claim())
          continue;
        const long long cases = run_unit(run_, level, seed, sw_, sample);
        run_.unit_done(static_cast<double>(cases),
                      line_printf("level %d seed %llu: %lld cases (sites x C*)", level,
                                  static_cast<unsigned long long>(seed), cases));
      }
  }

  // The summary (from the case rows) and Figures 1-2's data.
  void write_summary_and_figures() {
    TsvTable ts = summary_of(files_[kCases]->table(), levels_, seeds_, sw_.weights);
    ts.set("program", "koba_sato_bounds");
    for (auto& [k, v] : params_) ts.set(k, v);
    std::vector<std::string> lv, sd;  // the units summarized
    for (int l : levels_) lv.push_back(fmt(l));
    for (auto x : seeds_) sd.push_back(fmt(static_cast<long long>(x)));
    ts.set("levels_used", join(lv, ","));
    ts.set("seeds_used", join(sd, ","));
    add_provenance(ts);
    ts.save(summary_path_);
    fig_.particles.save(fig_prefix_ + kFigureFiles[0]);
    fig_.cells.save(fig_prefix_ + kFigureFiles[1]);
    fig_.circles.save(fig_prefix_ + kFigureFiles[2]);
    std::fprintf(stderr, "[koba_sato_bounds] %s bound violations -> %s\n",
                 ts.get("violations_total").value_or("?").c_str(), summary_path_.c_str());
  }
};

int body(int argc, char** argv) { return Bounds(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("koba_sato_bounds", body, argc, argv); }
