#include "gpm/studies/judge/error_constants.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/text_format.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/judge/evidence.hpp"
#include "gpm/studies/judge/heat_mode_model.hpp"
#include "gpm/studies/judge/mode_constants.hpp"
#include "gpm/studies/judge/rates.hpp"
#include "gpm/studies/judge/verdicts.hpp"

namespace gpm {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
std::string pct(double q) { return std::isfinite(q) ? format_text("%.2f %%", 100 * q) : "NA"; }
std::string cell(double v) { return std::isfinite(v) ? fmt(v) : "NA"; }

// One stored error with its a-priori prediction (both relative errors, not yet over h^p).
struct Point {
  double h = 0, error = 0, predicted = 0;
  std::string solver;
};
// A series' points: realization (seed) → level → point.
using Realized = std::map<int, std::map<int, Point>>;
// Series by key: (h rule, weight) for Table 4.4, (weight, θ) for the heat tables.
using Key = std::pair<std::string, std::string>;
using SeriesPoints = std::map<Key, Realized>;

// The store files of a slice, its realizations and (Table 4.4) its τ-PCG companions, plain
// CG's first: a level both hold is read from plain CG (the reference).
std::vector<const StoreFile*> slice_files(const RegisteredStudy& study, const StoreFile& main) {
  std::vector<const StoreFile*> out = {&main};
  for (const StoreFile* f : realizations_of(study, main)) out.push_back(f);
  for (const StoreFile& f : study.store_files)
    if (file_seed(f) == file_seed(main) && file_solver(f) != file_solver(main) && setup_args(f) == setup_args(main)) {
      out.push_back(&f);
      for (const StoreFile* g : realizations_of(study, f)) out.push_back(g);
    }
  return out;
}

void add_point(SeriesPoints& s, const Key& key, int seed, int level, const Point& p) {
  s[key][seed].emplace(level, p);  // emplace: the first file (plain CG) wins
}

// Table 4.4 under V_i = Δx² (δ = 0), both h rules.
SeriesPoints poisson_points(const StoreSnapshot& store, const RegisteredStudy& study) {
  SeriesPoints s;
  for (const StoreFile* f : slice_files(study, study.store_file_of("h15_cell"))) {
    if (!store.has(f->name + ".tsv")) continue;
    const TsvTable& t = store.table(f->name + ".tsv", false);
    const std::string solver = t.get("solver") ? "tau" : "cg";
    const int cr = t.require_column("h_rule"), cw = t.require_column("weight"), cl = t.require_column("level"),
              ch = t.require_column("h"), ce = t.require_column("rel_error");
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const double e = t.number(i, ce), h = t.number(i, ch);
      if (!std::isfinite(e) || e <= 0) continue;
      add_point(s, {t.text(i, cr), t.text(i, cw)}, file_seed(*f), static_cast<int>(t.integer(i, cl)),
                {h, e, poisson_mode_error(weight(t.text(i, cw)), h, 0.0), solver});
    }
  }
  return s;
}

// A heat table under one reading: the one-mode model's prediction per row.
SeriesPoints heat_points(const StoreSnapshot& store, const RegisteredStudy& study, const std::string& reading) {
  SeriesPoints s;
  for (const StoreFile* f : slice_files(study, study.store_file_of(reading))) {
    if (!store.has(f->name + ".tsv")) continue;
    for (const ModeRow& r : mode_model(store.table(f->name + ".tsv", false)))
      if (std::isfinite(r.measured) && r.measured > 0)
        add_point(s, {r.weight, r.theta}, file_seed(*f), r.level, {r.h, r.measured, r.predicted, "cg"});
  }
  return s;
}

// thesis_mode_excess's projected excess by (weight, level), from one diagnostic file; empty
// where the file is absent.
using Projected = std::map<std::pair<std::string, int>, double>;
Projected projected_excess(const std::string& diagnostics, const std::string& name) {
  Projected out;
  const std::string path = diagnostics + "/" + name;
  if (diagnostics.empty() || !std::filesystem::exists(path)) return out;
  const TsvTable t = TsvTable::load(path);
  const int cw = t.require_column("weight"), cl = t.require_column("level"), cp = t.require_column("predicted_excess");
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    out[{t.text(i, cw), static_cast<int>(t.integer(i, cl))}] = t.number(i, cp);
  return out;
}

// What a series is called and what the documents say of it.
struct Label {
  std::string table, reading, weight, theta, theory_text;
  std::pair<int, int> doc;
  double limit = kNaN;
  const Projected* projected = nullptr;  // seed 1's projected excess, where measured
};

void add_series(ErrorConstants& out, const Label& label, const Realized& reals) {
  const double p = theoretical_rate(label.theory_text);
  if (!std::isfinite(p) || !reals.count(1)) return;
  // Every point's constant, model constant and relative excess.
  auto constant = [&](const Point& pt) { return error_constant({pt.h, pt.error}, p); };
  auto model = [&](const Point& pt) { return error_constant({pt.h, pt.predicted}, p); };
  auto excess = [&](const Point& pt) { return std::fabs(pt.error / pt.predicted - 1); };
  for (const auto& [seed, levels] : reals)
    for (const auto& [k, pt] : levels) {
      TsvRow row = out.constants.named_row();
      row["table"] = label.table, row["reading"] = label.reading, row["weight"] = label.weight;
      row["theta"] = label.theta, row["seed"] = fmt(seed), row["level"] = fmt(k), row["h"] = fmt(pt.h);
      row["rel_error"] = fmt(pt.error), row["solver"] = pt.solver, row["constant"] = fmt(constant(pt));
      row["model"] = fmt(model(pt)), row["limit"] = cell(label.limit);
      row["excess"] = fmt(pt.error / pt.predicted - 1);
      const auto pj = label.projected && seed == 1 ? label.projected->find({label.weight, k})
                                                    : Projected::const_iterator{};
      row["projected_excess"] = label.projected && seed == 1 && pj != label.projected->end() ? fmt(pj->second) : "NA";
      row["where"] = k == label.doc.first || k == label.doc.second ? "document"
                     : k > label.doc.second                         ? "beyond"
                                                                    : "coarser";
      out.constants.add_row(row);
    }
  // The finding at seed 1's finest level, over every realization that holds it and a level before.
  const int finest = reals.at(1).rbegin()->first;
  int counted = 0, approach = 0, away = 0;
  double c_lo = kNaN, c_hi = kNaN, q_max = 0, q_before_max = 0, decay_max = 0, m = kNaN;
  std::string why_one;
  for (const auto& [seed, levels] : reals) {
    const auto it = levels.find(finest);
    if (it == levels.end() || it == levels.begin()) continue;
    const Point &pt = it->second, &before = std::prev(it)->second;
    const double c = constant(pt), q = excess(pt), qb = excess(before);
    const TrendFinding f = judge_constant(qb, q);
    ++counted, approach += f.trend == Trend::approaches, away += f.trend == Trend::stays_away;
    if (counted == 1) why_one = f.why, c_lo = c_hi = c, m = model(pt);
    c_lo = std::min(c_lo, c), c_hi = std::max(c_hi, c);
    q_max = std::max(q_max, q), q_before_max = std::max(q_before_max, qb);
    decay_max = std::max(decay_max, qb > 0 ? q / qb : kNaN);
  }
  TrendFinding f{Trend::not_decided, "no realization holds a level before the finest"};
  if (counted > 0 && approach == counted)
    f = {Trend::approaches, counted == 1 ? why_one + " (one realization)" : "every one of " + fmt(counted) +
                                                                               " realizations within " + pct(q_max) +
                                                                               ", not growing"};
  else if (counted > 0 && away == counted)
    f = {Trend::stays_away, counted == 1 ? why_one + " (one realization)" : "every one of " + fmt(counted) +
                                                                               " realizations off by more than " +
                                                                               pct(kConstantReach)};
  else if (counted == 1)
    f = {Trend::not_decided, why_one + " (one realization)"};
  else if (counted > 1)
    f = {Trend::not_decided, "realizations differ: " + fmt(approach) + " approach, " + fmt(away) + " stay away, " +
                                 fmt(counted - approach - away) + " not decided, of " + fmt(counted)};
  TsvRow row = out.findings.named_row();
  row["table"] = label.table, row["reading"] = label.reading, row["weight"] = label.weight;
  row["theta"] = label.theta, row["theoretical"] = fmt(p), row["documents_levels"] = fmt(label.doc.first) + "," + fmt(label.doc.second);
  row["finest_level"] = fmt(finest), row["realizations"] = fmt(counted);
  row["constant_lo"] = cell(c_lo), row["constant_hi"] = cell(c_hi), row["model"] = cell(m);
  row["limit"] = cell(label.limit), row["excess_max"] = cell(q_max), row["excess_before_max"] = cell(q_before_max);
  row["decay_max"] = cell(decay_max), row["finding"] = trend_name(f.trend), row["why"] = f.why;
  out.findings.add_row(row);
}

}  // namespace

TrendFinding judge_constant(double q_before, double q_finest) {
  if (!std::isfinite(q_before) || !std::isfinite(q_finest))
    return {Trend::not_decided, "an excess is not a number"};
  const std::string said = "excess " + pct(q_before) + " then " + pct(q_finest);
  // Below the noise floor an excess counts as not growing (amendment, below).
  if (q_finest <= kConstantReach && q_finest <= std::max(q_before, kConstantFloor)) return {Trend::approaches, said};
  if (q_finest > kConstantReach && q_finest >= 0.9 * q_before) return {Trend::stays_away, said + ": settled off the model"};
  if (q_finest <= kConstantReach) return {Trend::not_decided, said + ": near the model but growing"};
  return {Trend::not_decided, said + ": off the model but still shrinking"};
}

ErrorConstants error_constants(const StoreSnapshot& store, const PublishedTables& published,
                               const std::string& diagnostics) {
  ErrorConstants out;
  out.constants.columns = {"table", "reading", "weight", "theta", "seed", "level", "h", "rel_error", "solver",
                           "constant", "model", "limit", "excess", "projected_excess", "where"};
  out.findings.columns = {"table", "reading", "weight", "theta", "theoretical", "documents_levels", "finest_level",
                          "realizations", "constant_lo", "constant_hi", "model", "limit", "excess_max",
                          "excess_before_max", "decay_max", "finding", "why"};
  const StudyRegistry& reg = study_registry();
  {  // Table 4.4, V_i = Δx² (the identified volumes), both h rules
    const RegisteredStudy& study = reg.study("thesis_table4_4");
    const TsvTable& pub = published.file(study.published->file);
    const SeriesPoints pts = poisson_points(store, study);
    const std::map<std::string, Projected> projected = {
        {"h10", projected_excess(diagnostics, "mode_excess_poisson_h10_cell.tsv")},
        {"h15", projected_excess(diagnostics, "mode_excess_poisson_h15_cell.tsv")}};
    for (std::size_t i = 0; i < pub.rows.size(); ++i) {
      const Key key{pub.text(i, "h_rule"), pub.text(i, "weight")};
      const auto pj = projected.find(key.first);
      const Label label{"4.4", key.first + "_cell", key.second, "NA", pub.text(i, "theoretical"),
                        documents_levels(pub), poisson_constant_limit(weight(key.second)),
                        pj == projected.end() || pj->second.empty() ? nullptr : &pj->second};
      if (pts.count(key)) add_series(out, label, pts.at(key));
    }
  }
  const Projected heat_projected = projected_excess(diagnostics, "mode_excess_heat_h15_cell.tsv");
  for (const HeatTable& hp : heat_tables()) {
    const RegisteredStudy& study = reg.study(heat_study_name(hp));
    const TsvTable& pub = published.file(study.published->file);
    for (const std::string reading : {"h10", "h15_cell_exact"}) {
      const SeriesPoints pts = heat_points(store, study, reading);
      for (std::size_t i = 0; i < pub.rows.size(); ++i) {
        const Key key{pub.text(i, "weight"), pub.text(i, "theta")};
        const double rate = theoretical_rate(pub.text(i, "theoretical"));
        const double limit = std::isfinite(rate) ? heat_constant_limit(weight(key.first), hp, pub.number(i, pub.require_column("theta")), rate) : kNaN;
        const Label label{hp.table, reading, key.first, key.second, pub.text(i, "theoretical"), documents_levels(pub), limit,
                          reading == "h15_cell_exact" && !heat_projected.empty() ? &heat_projected : nullptr};
        if (pts.count(key)) add_series(out, label, pts.at(key));
      }
    }
  }
  return out;
}

}  // namespace gpm
