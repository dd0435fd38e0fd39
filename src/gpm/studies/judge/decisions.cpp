#include "gpm/studies/judge/decisions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/io/text_format.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/judge/rates.hpp"
#include "gpm/studies/judge/verdicts.hpp"
#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

namespace {

namespace fs = std::filesystem;


// A cell as a number where one is needed for a comparison or a sum: "NA" (rate_table's not
// computed) counts 0, so a mean over a table's rows is over all of them.
double num(const std::string& s) { return cell_number_or(s, 0.0); }

std::optional<TsvTable> load_if(const std::string& path) {
  if (!fs::exists(path)) return std::nullopt;
  return TsvTable::load(path);
}

// A store file's table, none where the store does not hold it.
const TsvTable* stored_if(const StoreSnapshot& store, const std::string& name) {
  return store.has(name) ? &store.table(name) : nullptr;
}

// One row of the table, by column name: its columns are set in decisions() at the end of this
// file, while each question below writes its own row.
void add_question(TsvTable& out, const std::string& question, const std::string& evidence,
                  const std::string& decision) {
  TsvRow row = out.named_row();
  row["question"] = question, row["evidence"] = evidence, row["decision"] = decision;
  out.add_row(row);
}

// ------------------------------------------------------------------------------------------
// Table 4.7: dt = T/K or dt = dt0.

// The two-level rates at `levels` ("7,8") of a heat file's series that never blew up, joined
// with the published Table 4.7 rates (keys weight, theta).
JoinedRates heat_rates(const TsvTable& data, const TsvTable& published, const std::string& levels) {
  RateJoin join;
  join.keys = {"weight", "theta"};
  join.levels = levels;
  return join_rates(finite_series(data), published, join);
}

// A rate of a joined row as the sums below take it: 0 where it is no number (not computed).
double or_zero(double v) { return std::isfinite(v) ? v : 0; }

// "lo to hi" of `rate` (reproduced or published) over the computed rows at θ = theta; "none"
// without one.
std::string span(const JoinedRates& r, double JoinedRate::*rate, double theta) {
  int n = 0;
  double lo = 0, hi = 0;
  for (const JoinedRate& j : r.rows) {
    if (num(r.key(j, "theta")) != theta || j.status == "not-computed") continue;
    const double v = or_zero(j.*rate);
    if (n++ == 0 || v < lo) lo = v;
    if (n == 1 || v > hi) hi = v;
  }
  return n ? format_text("%.2f to %.2f", lo, hi) : "none";
}

// Mean |reproduced − published| over every joined row (a rate not computed counts 0).
double mean_distance(const JoinedRates& r) {
  double s = 0;
  for (const JoinedRate& j : r.rows) s += std::fabs(or_zero(j.reproduced) - or_zero(j.published));
  return s / static_cast<double>(r.rows.size());
}

void time_step_question(const StoreSnapshot& store, const PublishedTables& pub, TsvTable& out) {
  const RegisteredStudy& table47 = study_registry().study("thesis_table4_7");
  auto reading = [&](const std::string& name) {
    const std::optional<std::string> file = reading_file(table47, name);
    return file ? stored_if(store, *file) : nullptr;
  };
  const TsvTable *fit = reading("h10"), *ex = reading("h10_exact");
  if (!fit || !ex) {
    add_question(out, "Table 4.7 (dt = 0.5h, T = 0.1): dt = T/K or dt = dt0", "not yet in the store", "open");
    return;
  }
  const TsvTable& published = published_table(pub, "thesis_table4_7");
  std::string ev, verdict;
  for (const auto& [levels, shown] : {std::pair<std::string, std::string>{"7,8", "7/8"}, {"8,9", "8/9"}}) {
    const JoinedRates f = heat_rates(*fit, published, levels), e = heat_rates(*ex, published, levels);
    const std::string f1 = span(f, &JoinedRate::reproduced, 1), e1 = span(e, &JoinedRate::reproduced, 1);
    if (f1 == "none" || e1 == "none") {
      ev += " levels " + shown + ": not yet computed under both readings.";
      continue;
    }
    ev += " levels " + shown + ": theta=1 rates " + f1 + " with dt = T/K, " + e1 + " with dt = dt0 (published " +
          span(f, &JoinedRate::published, 1) + "); theta=1/2 " + span(f, &JoinedRate::reproduced, 0.5) + " and " +
          span(e, &JoinedRate::reproduced, 0.5) + " (published " + span(f, &JoinedRate::published, 0.5) + ").";
    const double a = mean_distance(f), b = mean_distance(e);
    verdict = format_text("at levels %s the closer reading is %s (mean |rate - published| %.2f against %.2f)",
                     shown.c_str(), b < a ? "dt = dt0" : "dt = T/K", b < a ? b : a, b < a ? a : b);
  }
  // The same set-up with V_i = dx^2 (the volume mismatch that sets Table 4.4's rates removed).
  for (const auto& [name, rule] : {std::pair<std::string, std::string>{"h10_cell", "dt = T/K"},
                                   {"h10_cell_exact", "dt = dt0"}}) {
    const TsvTable* file = reading(name);
    if (!file) continue;
    const JoinedRates c = heat_rates(*file, published, "8,9");
    ev += " With V_i = dx^2 (" + rule + "), levels 8/9: theta=1 " + span(c, &JoinedRate::reproduced, 1) +
          ", theta=1/2 " + span(c, &JoinedRate::reproduced, 0.5) + ".";
  }
  // The steps K of dt = T/K per level (the last row of a level names it).
  const TsvTable& t = *fit;
  const int cl = t.require_column("level"), ck = t.require_column("K");
  std::map<std::string, std::string> steps;
  for (std::size_t i = 0; i < t.rows.size(); ++i) steps[t.text(i, cl)] = t.text(i, ck);
  std::string k;
  for (int l = 5; l <= 9; ++l)
    if (steps.count(std::to_string(l)))
      k += format_text("%s2^-%d: %s", k.empty() ? "" : ", ", l, steps[std::to_string(l)].c_str());
  add_question(out,
               "Table 4.7 (dt = 0.5h, T = 0.1): dt = T/K with K = ceil(T/dt0) (the thesis defines dt = T/K), or "
               "dt = dt0 as prescribed",
               ev + " Steps K under dt = T/K: " + k + ".",
               "both readings kept; " + (verdict.empty() ? std::string("no level pair computed under both") : verdict));
}

// ------------------------------------------------------------------------------------------
// Table 4.4: what sets the error.

void poisson_volume_question(const StoreSnapshot& store, const PublishedTables& tables, TsvTable& out) {
  const TsvTable* diag = stored_if(store, stored_file("thesis_poisson_diagnostic"));
  if (!diag || diag->column("tau_predicted") < 0) {
    add_question(out, "Table 4.4: the volumes of (A.10)", "not yet in the store", "open");
    return;
  }
  const TsvTable& pub = published_table(tables, "thesis_table4_4");
  std::map<std::pair<std::string, std::string>, std::string> published;  // (h rule, weight)
  for (std::size_t i = 0; i < pub.rows.size(); ++i)
    published[{pub.text(i, "h_rule"), pub.text(i, "weight")}] = pub.text(i, "numerical");
  const TsvTable& d = *diag;
  const int cr = d.require_column("h_rule"), cw = d.require_column("weight"), cl = d.require_column("level"),
            cv = d.require_column("variant"), ce = d.require_column("rel_error"),
            ct = d.require_column("tau_predicted"), ch = d.require_column("h"),
            cm = d.require_column("volume_mismatch");
  std::set<std::string> rules;
  std::vector<std::string> weights;  // in the order they first occur
  std::map<std::pair<std::string, std::string>, double> qlo, qhi;  // (h rule, particle set)
  std::map<std::vector<std::string>, double> err;                  // (h rule, weight, level, variant)
  std::map<std::pair<std::string, std::string>, double> h;         // (h rule, level)
  std::map<std::pair<std::string, bool>, double> mismatch;         // (level, V_i = dx^2)
  for (std::size_t i = 0; i < d.rows.size(); ++i) {
    const std::string &r = d.text(i, cr), &w = d.text(i, cw), &l = d.text(i, cl), &v = d.text(i, cv);
    const double e = num(d.text(i, ce)), q = e / std::fabs(num(d.text(i, ct)));
    rules.insert(r);
    if (std::find(weights.begin(), weights.end(), w) == weights.end()) weights.push_back(w);
    const ParticleSet& set = poisson_diagnostic().variant(v);  // the variant's registered jitter and volumes
    const std::pair<std::string, std::string> g{r, set.jitter == 0 ? "plain grid" : "jittered grids"};
    if (!qlo.count(g) || q < qlo[g]) qlo[g] = q;
    if (!qhi.count(g) || q > qhi[g]) qhi[g] = q;
    err[{r, w, l, v}] = e;
    h[{r, l}] = num(d.text(i, ch));
    mismatch[{l, set.volumes == PdeVolumes::cell}] = num(d.text(i, cm));
  }
  auto at = [](const auto& m, const auto& k) {
    auto it = m.find(k);
    return it == m.end() ? 0.0 : it->second;
  };
  for (const std::string r : {"h10", "h15"}) {
    if (!rules.count(r)) continue;
    std::string ev = format_text(
        "error / |(V/dx^2)(1 - eps) - 1| over the weights and levels 2^-7..2^-9: plain grid %.2f to %.2f, "
        "jittered grids %.2f to %.2f; volume mismatch V/dx^2 - 1 of (A.10): %+.2f%% (2^-7), %+.2f%% (2^-8), "
        "%+.2f%% (2^-9).",
        at(qlo, std::pair<std::string, std::string>{r, "plain grid"}),
        at(qhi, std::pair<std::string, std::string>{r, "plain grid"}),
        at(qlo, std::pair<std::string, std::string>{r, "jittered grids"}),
        at(qhi, std::pair<std::string, std::string>{r, "jittered grids"}),
        100 * at(mismatch, std::pair<std::string, bool>{"7", false}),
        100 * at(mismatch, std::pair<std::string, bool>{"8", false}),
        100 * at(mismatch, std::pair<std::string, bool>{"9", false}));
    for (const std::string& w : weights) {
      std::string line;
      for (const char* v : {"seed1", "plain", "seed1_cell", "plain_cell"}) {
        auto e8 = err.find({r, w, "8", v}), e9 = err.find({r, w, "9", v});
        if (e8 == err.end() || e9 == err.end()) continue;
        line += format_text(" %s %.2f", v,
                            point_rate(EvidencePoint{at(h, std::pair<std::string, std::string>{r, "8"}), e8->second},
                                       EvidencePoint{at(h, std::pair<std::string, std::string>{r, "9"}), e9->second}));
      }
      if (line.empty()) continue;
      auto p = published.find({r, w});
      ev += format_text(" %s, rates 2^-8/2^-9:%s (published %s).", w.c_str(), line.c_str(),
                   p == published.end() ? "" : p->second.c_str());
    }
    add_question(out, "Table 4.4, " + r + ": the volumes (A.10) on the particles' lattice", ev,
                 "the error is the operator consistency error (V/dx^2)(1 - eps) - 1 carried through the solve; with "
                 "(A.10) on that lattice the volume mismatch changes sign between 2^-8 and 2^-9 and sets the rates; with "
                 "V_i = dx^2 the rates are those of eps alone (the readings with V_i = dx^2). Kept: (A.10) as the thesis prints it; "
                 "the published rates match V_i = dx^2");
  }
}

// ------------------------------------------------------------------------------------------
// Imoto Table 1, Lap1/Lap2 at m = 5.

// The stored Table 1 files of seed 1, seeds 2 and 3 and the plain grid that exist, with the
// name of each realization (the snapshot's tables, not copies).
std::vector<std::pair<std::string, const TsvTable*>> imoto_realizations(const StoreSnapshot& store) {
  std::vector<std::pair<std::string, const TsvTable*>> files;
  for (const auto& [slice, name] : std::vector<std::pair<std::string, std::string>>{
           {"", "seed1"}, {"seed2", "seed2"}, {"seed3", "seed3"}, {"plain", "plain"}})
    if (const TsvTable* t = stored_if(store, stored_file("imoto_fig5_table1", slice))) files.emplace_back(name, t);
  return files;
}

void imoto_smoothing_question(const StoreSnapshot& store, const PublishedTables& published, TsvTable& out) {
  if (!store.has(stored_file("imoto_fig5_table1", "plain"))) return;
  const auto files = imoto_realizations(store);
  const double area_H = Domain{}.area_H();
  const TsvTable& pub = published_table(published, "imoto_table1");
  for (const std::string w : {"Lap1", "Lap2"}) {
    // Per level: each realization's error, and h, N, dx (the last file's row of the level).
    std::map<std::pair<int, std::string>, double> e;
    std::map<int, double> h, N, dx;
    for (const auto& [v, file] : files) {
      const TsvTable& t = *file;
      const int cw = t.require_column("weight"), cm = t.require_column("m"), cl = t.require_column("level");
      for (std::size_t i = 0; i < t.rows.size(); ++i) {
        if (t.text(i, cw) != w || num(t.text(i, cm)) != 5 || num(t.text(i, cl)) < 9) continue;
        const int l = static_cast<int>(num(t.text(i, cl)));
        e[{l, v}] = num(t.text(i, "rel_error"));
        h[l] = num(t.text(i, "h")), N[l] = num(t.text(i, "N")), dx[l] = num(t.text(i, "dx"));
      }
    }
    if (h.empty()) continue;
    std::string pubrate;  // the published m = 5 rate of the weight
    for (std::size_t i = 0; i < pub.rows.size(); ++i)
      if (pub.text(i, "weight") == w && num(pub.text(i, "m")) == 5) pubrate = pub.text(i, "numerical");
    const WeightFunction& wf = weight(w);
    auto cell = [&](int l, const char* v) {
      auto it = e.find({l, v});
      return it == e.end() ? std::optional<double>{} : it->second;
    };
    std::string ev;
    std::map<int, double> pred, eps;
    for (int l = 9; l <= 12; ++l) {
      if (!h.count(l)) continue;
      eps[l] = laplacian_smoothing_error(wf, kSin2piWaveNumber * h[l]);
      const double delta = area_H / (N[l] * dx[l] * dx[l]) - 1;
      pred[l] = std::fabs((1 + delta) * (1 - eps[l]) - 1);
      auto shown = [&](const char* v, const char* none) {
        auto c = cell(l, v);
        return c ? format_text("%.3e", *c) : std::string(none);
      };
      ev += format_text(" 2^-%d: plain %s, predicted %.3e (eps %.3e, delta %+.2e); seeds %s %s %s;", l,
                   shown("plain", "not computed").c_str(), pred[l], eps[l], delta, shown("seed1", "-").c_str(),
                   shown("seed2", "-").c_str(), shown("seed3", "-").c_str());
    }
    auto rate_11_12 = [&](double e11, double e12) { return point_rate(EvidencePoint{h[11], e11}, EvidencePoint{h[12], e12}); };
    std::string r = " rates 2^-11/2^-12:";
    for (const char* v : {"seed1", "seed2", "seed3", "plain"})
      if (cell(11, v) && cell(12, v)) r += format_text(" %s %.2f", v, rate_11_12(*cell(11, v), *cell(12, v)));
    if (h.count(11) && h.count(12))
      r += format_text(", predicted (plain) %.2f, eps alone %.2f (published %s).", rate_11_12(pred[11], pred[12]),
                       rate_11_12(eps[11], eps[12]), pubrate.c_str());
    add_question(out, "Imoto Table 1, " + w + " at m = 5: smoothing, volume mismatch and particles", ev + r,
                 "the plain-grid error is the consistency error |(1 + delta)(1 - eps) - 1| of the operator (no "
                 "particle part); the jittered seeds add the particle part, which shrinks fastest between 2^-11 and "
                 "2^-12 and so steepens the two-level rate");
  }
}

// (A diagnostic of tables/imoto_where.sh, not a study's sealed store file: results/diagnostics.)
void imoto_where_question(const StoreSnapshot& store, const std::string& diagnostics, TsvTable& out) {
  const std::optional<TsvTable> where = load_if(diagnostics + "/imoto_m5_where.tsv");
  if (!where) return;
  const auto files = imoto_realizations(store);
  const TsvTable& t = *where;
  const int cw = t.require_column("weight"), cv = t.require_column("variant"), cl = t.require_column("level"),
            ce = t.require_column("rel_error"), cd = t.require_column("worst_to_boundary_over_h");
  for (const std::string w : {"Lap1", "Lap2"}) {
    std::map<std::pair<std::string, std::string>, double> e, stored;  // (realization, level)
    std::set<int> levels;
    int np = 0, nj = 0;
    double pmax = 0, jmin = 0, jmax = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      if (t.text(i, cw) != w) continue;
      e[{t.text(i, cv), t.text(i, cl)}] = num(t.text(i, ce));
      const double d = num(t.text(i, cd));
      if (t.text(i, cv) == "plain") {
        ++np;
        pmax = (np == 1 || d > pmax) ? d : pmax;
      } else {
        ++nj;
        jmin = (nj == 1 || d < jmin) ? d : jmin;
        jmax = (nj == 1 || d > jmax) ? d : jmax;
      }
      levels.insert(static_cast<int>(num(t.text(i, cl))));
    }
    for (const auto& [v, file] : files) {
      const TsvTable& s = *file;
      const int sw = s.require_column("weight"), sm = s.require_column("m"), sl = s.require_column("level");
      for (std::size_t i = 0; i < s.rows.size(); ++i)
        if (s.text(i, sw) == w && num(s.text(i, sm)) == 5) stored[{v, s.text(i, sl)}] = num(s.text(i, "rel_error"));
    }
    if (nj + np == 0) continue;
    std::string lv;
    for (int l = 1; l <= 20; ++l)
      if (levels.count(l)) lv += format_text("%s%d", lv.empty() ? " 2^-" : ", 2^-", l);
    int n = 0;
    double dev = 0;
    for (auto& [k, x] : e) {
      auto it = stored.find(k);
      if (it == stored.end()) continue;
      ++n;
      dev = std::max(dev, std::fabs(x / it->second - 1));
    }
    add_question(
        out, "Imoto Table 1, " + w + " at m = 5: where the maximum sits",
        format_text("jittered runs (%d, levels%s): the largest error sits %.1f h to %.1f h inside the boundary of Omega; "
                "plain grid (%d runs): its maximum lies within %.2f h of the boundary (it is attained along whole "
                "lines where |Lap u| is largest, so its place is not informative); the runs reproduce %d stored "
                "errors to %.1e (relative)",
                nj, lv.c_str(), jmin, jmax, np, pmax, n, dev),
        jmin >= 1 ? "the particle part of the error is an interior effect (no boundary layer): the steep "
                    "2^-11/2^-12 rate is not a boundary artefact"
                  : "the largest error sits within h of the boundary in some jittered run: a boundary effect "
                    "cannot be excluded");
  }
}

// ------------------------------------------------------------------------------------------
// The reading of each table's set-up, from the score.

void readings_question(const TsvTable& score, TsvTable& out) {
  const int ct = score.require_column("table"), cs = score.require_column("setup"), cl = score.require_column("slice"),
            cc = score.require_column("counted"), cr = score.require_column("rates"),
            cn = score.require_column("not_computed");
  std::vector<std::string> order;
  std::map<std::string, std::string> ev, pick;
  std::map<std::string, int> n;
  for (std::size_t i = 0; i < score.rows.size(); ++i) {
    const std::string& t = score.text(i, ct);
    if (score.text(i, cs) != "document" || t == "total") continue;
    double g = 0;  // reproduced: agrees, non-convergence, seed band or a checked reason
    for (const char* c : {"agrees", "non_convergence", "in_seed_band", "checked_reason"})
      g += score.number(i, score.require_column(c));
    ev[t] += format_text(" %s: %lld of %lld reproduced (%lld not yet computed);", score.text(i, cl).c_str(),
                    static_cast<long long>(g), static_cast<long long>(score.number(i, cr)),
                    static_cast<long long>(score.number(i, cn)));
    if (!n.count(t)) order.push_back(t);
    ++n[t];
    if (score.text(i, cc) == "yes") pick[t] = score.text(i, cl);
  }
  for (const std::string& t : order)
    if (n[t] >= 2)
      add_question(out, t + ": which reading of the set-up the document ran", ev[t],
                   "identified: " + pick[t] +
                       " (the rule of paper/04-setup-rule.md: the fingerprint where one decides, else as printed; "
                       "the judged rates play no part); every reading stays in the data");
}

// ------------------------------------------------------------------------------------------
// Omega_H: the square or the rounded H-neighbourhood; jittered particles mirrored or dropped.

// gpm particles' default jitter amplitude (a fraction of dx): the distributions of every study.
constexpr double kStudyJitter = 0.25;

// From the package's own plain grid at 2^-k: the nodes in the square Omega_H, those within H
// of Omega (the rounded H-neighbourhood the documents define), and the expected number of
// particles the jitter moves out of Omega_H (the thesis' X_{N,H} keeps only points in Omega_H;
// the package mirrors them back), with the volume mismatch of (A.10) either way.
std::string omega_h_level(int k) {
  const Domain dom;
  const double dx = std::ldexp(1.0, -k), H = dom.H, A = dom.area_H(), a = kStudyJitter;
  const Particles p = jittered_grid(dx, 1, 0.0, dom);
  long long n = 0, rounded = 0;
  double E = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.x[i], y = p.y[i];
    ++n;
    const double ox = x < 0 ? -x : (x > 1 ? x - 1 : 0), oy = y < 0 ? -y : (y > 1 ? y - 1 : 0);
    if (ox * ox + oy * oy < H * H) ++rounded;
    // Distance to the nearer edge of Omega_H per axis, and the chance the jitter crosses it.
    const double ex = x + H < 1 + H - x ? x + H : 1 + H - x, ey = y + H < 1 + H - y ? y + H : 1 + H - y;
    const double px = ex < a * dx ? (a * dx - ex) / (2 * a * dx) : 0, py = ey < a * dx ? (a * dx - ey) / (2 * a * dx) : 0;
    E += 1 - (1 - px) * (1 - py);
  }
  const double nd = static_cast<double>(n);
  return format_text("2^-%d: N = %lld in the square, %lld in the rounded neighbourhood; %.0f expected to leave; volume "
                "mismatch %+.3f%% mirrored, %+.3f%% dropped;",
                k, n, rounded, E, 100 * (A / (nd * dx * dx) - 1), 100 * (A / ((nd - E) * dx * dx) - 1));
}

void omega_h_question(TsvTable& out) {
  std::string ev;
  for (int k : {5, 7, 8, 9}) {
    ev += ' ';
    ev += omega_h_level(k);
  }
  add_question(out,
               "Omega_H: the square (-H, 1+H)^2 or the rounded H-neighbourhood of Omega; jittered particles that leave "
               "Omega_H mirrored back or dropped",
               ev,
               "the square: Imoto Sec. 5 sets Omega_H = (-0.1, 1.1)^2 in so many words, and its node count at 2^-5 is "
               "the N printed with Figure 4.1; particles mirrored (kept), the dropped alternative changes the volume "
               "mismatch by the amounts listed");
}

}  // namespace

TsvTable decisions(const StoreSnapshot& store, const PublishedTables& published, const std::string& diagnostics,
                   const std::optional<TsvTable>& score) {
  TsvTable out;
  out.columns = {"question", "evidence", "decision"};
  time_step_question(store, published, out);
  poisson_volume_question(store, published, out);
  imoto_smoothing_question(store, published, out);
  imoto_where_question(store, diagnostics, out);
  if (score) readings_question(*score, out);
  omega_h_question(out);
  // Decided by the documents' definitions (and checked by unit tests), not by stored runs.
  add_question(out, "w^bell of Sections 4.2-4.3: which registry weight",
               "thesis 4.1.2: the operators with the quartic polynomial are those of SPH with the bell-shaped kernel "
               "(Remark A.1: w = -(r/d) d/dr w^S); the unit test \"quartic_polynomial is -(r/2) d/dr of the "
               "bell-shaped kernel\" checks the registry weight against central differences of "
               "(5/pi)(1+3r)(1-r)^3 at r = 0.05..0.95",
               "quartic_polynomial (and piecewise cubic / quintic polynomial for w^cubic, w^quintic, by the same "
               "remark)");
  add_question(out, "Gradient error norm",
               "Imoto Sec. 1 defines |x| as the Euclidean norm; the thesis writes [l-inf(Omega)]^2 for vector fields; "
               "test \"gradient error: Euclidean norm, brute force reference\" checks the fused pass against a "
               "brute-force Euclidean evaluation and that the component-wise value differs",
               "Euclidean length of the error vector, maximum over particles in Omega (all gradient data since this "
               "change)");
  return out;
}

}  // namespace gpm
