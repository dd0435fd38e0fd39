#include "gpm/studies/judge/checked_reasons.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "gpm/error.hpp"
#include "gpm/io/text_format.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/studies/judge/rates.hpp"
#include "gpm/studies/judge/verdicts.hpp"
#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

namespace {

const char* pass_fail(bool ok) { return ok ? "pass" : "fail"; }
const char* yes_no(bool b) { return b ? "yes" : "no"; }

void add(TsvTable& out, const std::string& table, const std::string& slice, const std::string& key,
         const std::string& reason, const std::string& evidence, bool pass, bool restores) {
  TsvRow row = out.named_row();
  row["table"] = table, row["slice"] = slice, row["key"] = key, row["reason"] = reason;
  row["evidence"] = evidence, row["check"] = pass_fail(pass), row["restores"] = yes_no(restores);
  out.add_row(row);
}

// One Voronoi row of Tables 4.2/4.3 at a rate level: its h, measured error and the smoothing
// error the operator alone gives at that h.
struct SmoothingPoint {
  int level = 0;
  double h = 0, error = 0, smoothing = 0;
};

// Per weight (in byte order of its name) with a published value: its rows of the reading
// `reading`, Voronoi volumes, operator `op` and function `fn` at the two rate levels, coarse
// first, where there are exactly two; `smoothing(weight, h)` gives each one's smoothing part.
template <class Smoothing>
std::map<std::string, std::vector<SmoothingPoint>> voronoi_rows(const TsvTable& data, const std::string& reading,
                                                                const std::string& op, const std::string& fn,
                                                                std::pair<int, int> levels,
                                                                const std::map<std::string, std::string>& pub,
                                                                Smoothing smoothing) {
  const int cl = data.require_column("level"), ch = data.require_column("h"), ce = data.require_column("rel_error");
  std::map<std::string, std::vector<SmoothingPoint>> rows;
  for (std::size_t i = 0; i < data.rows.size(); ++i) {
    if (data.text(i, "h_reading") != reading || data.text(i, "volumes") != "voronoi" ||
        data.text(i, "operator") != op || data.text(i, "function") != fn)
      continue;
    const int level = static_cast<int>(data.integer(i, cl));
    if (level != levels.first && level != levels.second) continue;
    rows[data.text(i, "weight")].push_back({level, data.number(i, ch), data.number(i, ce), 0});
  }
  std::map<std::string, std::vector<SmoothingPoint>> out;
  for (auto& [w, v] : rows) {
    if (v.size() != 2 || !pub.count(w)) continue;
    std::stable_sort(v.begin(), v.end(), [](auto& a, auto& b) { return a.level < b.level; });
    for (SmoothingPoint& p : v) p.smoothing = smoothing(weight(w), p.h);
    out[w] = v;
  }
  return out;
}

}  // namespace

const std::vector<std::string>& checked_reason_columns() {
  static const std::vector<std::string> c = {"table", "slice", "key", "reason", "evidence", "check", "restores"};
  return c;
}

void add_volume_mismatch_reasons(const TsvTable& pub, const TsvTable& diag, double tol, TsvTable& out) {
  const auto [l1, l2] = documents_levels(pub);
  // (h_rule, weight, level, variant) -> its diagnostic row (the last one, where repeated);
  // cells are read only for the rows a published rate uses.
  std::map<std::tuple<std::string, std::string, std::string, std::string>, std::size_t> at;
  for (std::size_t i = 0; i < diag.rows.size(); ++i)
    at[{diag.text(i, "h_rule"), diag.text(i, "weight"), diag.text(i, "level"), diag.text(i, "variant")}] = i;
  const int c_err = diag.require_column("rel_error"), c_tau = diag.require_column("tau_predicted"),
            c_h = diag.require_column("h"), c_mm = diag.require_column("volume_mismatch"),
            c_eps = diag.require_column("eps_smoothing");
  const int c_pub = pub.require_column("numerical");
  for (std::size_t i = 0; i < pub.rows.size(); ++i) {
    const std::string& r = pub.text(i, "h_rule");
    const std::string& w = pub.text(i, "weight");
    auto find = [&](int level, const char* variant) {
      const auto it = at.find({r, w, fmt(level), variant});
      return it == at.end() ? std::optional<std::size_t>() : std::optional<std::size_t>(it->second);
    };
    const auto a1 = find(l1, "seed1"), a2 = find(l2, "seed1"), c1 = find(l1, "seed1_cell"), c2 = find(l2, "seed1_cell");
    if (!a1 || !a2 || !c1 || !c2) {
      add(out, "thesis_table4_4", r, w, "volume mismatch of (A.10)",
          format_text("diagnostic not yet at 2^-%d and 2^-%d", l1, l2), false, false);
      continue;
    }
    auto num = [&](std::optional<std::size_t> row, int col) { return diag.number(*row, col); };
    auto point = [&](std::optional<std::size_t> row, double value) { return EvidencePoint{num(row, c_h), value}; };
    const double rl = point_rate(point(a1, num(a1, c_err)), point(a2, num(a2, c_err)));
    const double rp = point_rate(point(a1, std::fabs(num(a1, c_tau))), point(a2, std::fabs(num(a2, c_tau))));
    const double rc = point_rate(point(c1, num(c1, c_err)), point(c2, num(c2, c_err)));
    const double p = pub.number(i, c_pub);
    const bool restores = std::fabs(rc - p) <= tol;
    add(out, "thesis_table4_4", r, w,
        format_text("volume mismatch of (A.10): V_i = |Omega_H|/N differs from dx^2 by %+.2f%% at 2^-%d and %+.2f%% at "
               "2^-%d (the grid does not tile Omega_H), which scales the discrete Laplacian and adds to the "
               "smoothing error",
               100 * num(a1, c_mm), l1, 100 * num(a2, c_mm), l2),
        format_text("consistency predicted from eps and the mismatch: %+.4f at 2^-%d, %+.4f at 2^-%d (eps alone %.4f, "
               "%.4f); error/|predicted| %.2f, %.2f; rate predicted %.2f, reproduced %.2f; with V_i = dx^2: rate "
               "%.2f (published %s)",
               num(a1, c_tau), l1, num(a2, c_tau), l2, num(a1, c_eps), num(a2, c_eps),
               num(a1, c_err) / std::fabs(num(a1, c_tau)), num(a2, c_err) / std::fabs(num(a2, c_tau)), rp, rl, rc,
               pub.text(i, c_pub).c_str()),
        std::fabs(rp - rl) <= tol && restores, restores);
  }
}

void add_gradient_smoothing_reasons(const TsvTable& pub, const TsvTable& data, const std::string& reading,
                                    double tol, TsvTable& out) {
  std::map<std::string, std::string> published;  // weight -> its Case 2 gradient rate
  for (std::size_t i = 0; i < pub.rows.size(); ++i)
    if (pub.text(i, "operator") == "grad" && pub.text(i, "function") == "case2")
      published[pub.text(i, "weight")] = pub.text(i, "numerical");
  const auto rows = voronoi_rows(data, reading, "grad", "case2", documents_levels(pub), published,
                                 [](const WeightFunction& w, double h) {
                                   return gradient_smoothing_error(w, kSin2piWaveNumber * h);
                                 });
  for (auto& [w, v] : rows) {
    const double q1 = v[0].error / v[0].smoothing, q2 = v[1].error / v[1].smoothing;
    const double rr = point_rate(v[0], v[1], &SmoothingPoint::error);
    const double re = point_rate(v[0], v[1], &SmoothingPoint::smoothing);
    const double p = cell_number_or(published.at(w), NAN);
    const bool own = std::fabs(q1 - 1) <= kGradientSmoothingShare && std::fabs(q2 - 1) <= kGradientSmoothingShare;
    const bool out_of_reach = std::fabs(p - re) > tol;
    add(out, "thesis_table4_3", reading + "_voronoi", w + " grad case2",
        "the error is the gradient operator's own smoothing error eps_grad(|k|h) of the mode sin 2pi(x+y), with "
        "no particle part left; its rate at these h is the operator's, and the published rate is out of its reach",
        format_text("error/eps_grad %.4f, %.4f at the rate levels; rate of eps_grad %.2f, reproduced %.2f (published %s)",
               q1, q2, re, rr, published.at(w).c_str()),
        own && out_of_reach, false);
  }
}

void add_interpolant_smoothing_reasons(const TsvTable& pub, const TsvTable& data, const std::string& reading,
                                       double tol, TsvTable& out) {
  std::map<std::string, std::string> published;  // weight -> its Case 1 rate
  for (std::size_t i = 0; i < pub.rows.size(); ++i)
    if (pub.text(i, "function") == "case1") published[pub.text(i, "weight")] = pub.text(i, "numerical");
  const auto levels = documents_levels(pub);
  const auto rows = voronoi_rows(data, reading, "interp", "case1", levels, published,
                                 [](const WeightFunction& w, double h) {
                                   return interpolant_smoothing_error_case1(w, h);
                                 });
  for (auto& [w, v] : rows) {
    const double q1 = v[0].smoothing / v[0].error, q2 = v[1].smoothing / v[1].error;
    const double rr = point_rate(v[0], v[1], &SmoothingPoint::error);
    const double rs = point_rate(v[0], v[1], &SmoothingPoint::smoothing);
    const double p = cell_number_or(published.at(w), NAN);
    // Checked when the smoothing part is a small share of the error at both levels and the
    // published rate is the smoothing part's own (what an error made of it alone would give).
    const bool ok = q1 <= kInterpolantSmoothingShare && q2 <= kInterpolantSmoothingShare &&
                    std::fabs(p - rs) <= tol && std::fabs(rr - rs) > tol;
    add(out, "thesis_table4_2", reading + "_voronoi", w + " case1",
        "the published rate is the order of the interpolant's smoothing part (closed form for v = X^4 + Y^4); at "
        "the rate levels that part is a small share of the measured error, which is the particle part, so the "
        "two-level rate measures how fast the particle part shrinks",
        format_text("smoothing part / error %.3f at 2^-%d, %.3f at 2^-%d; rate of the smoothing part %.2f, reproduced "
               "%.2f (published %s)",
               q1, levels.first, q2, levels.second, rs, rr, published.at(w).c_str()),
        ok, false);
  }
}

void add_heat_mode_reasons(const std::string& table, const std::string& slice, const TsvTable& pub,
                           const std::vector<ModeRate>& rates, double tol, TsvTable& out) {
  std::map<std::string, std::string> published;  // "weight theta" -> its rate
  for (std::size_t i = 0; i < pub.rows.size(); ++i)
    published[pub.text(i, "weight") + " " + pub.text(i, "theta")] = pub.text(i, "numerical");
  for (const ModeRate& r : rates) {
    const auto it = published.find(r.key);
    double p;  // a published rate; a word where the document prints none has nothing to check
    if (it == published.end() || !cell_number(it->second, p)) continue;
    const bool accounts = r.ratio_coarse >= kModeRatioLow && r.ratio_coarse <= kModeRatioHigh &&
                          r.ratio_fine >= kModeRatioLow && r.ratio_fine <= kModeRatioHigh &&
                          std::fabs(r.predicted - r.reproduced) <= tol;
    const bool restores = r.cell && std::fabs(*r.cell - p) <= tol;
    const std::string cell = r.cell ? format_text("%.2f", *r.cell) : "not run";
    add(out, table, slice, r.key,
        format_text("the error is the exact solution's one Fourier mode after K theta-steps at the discrete decay rate "
               "mu(1+delta)(1-eps): time step, smoothing error eps and the volume mismatch delta of (A.10), %+.2f%% "
               "and %+.2f%% at the rate levels",
               100 * r.mismatch_coarse, 100 * r.mismatch_fine),
        format_text("measured/predicted %.3f, %.3f; rate predicted %.2f, reproduced %.2f; without the mismatch the model "
               "gives %.2f; with V_i = dx^2 measured %s (published %s)",
               r.ratio_coarse, r.ratio_fine, r.predicted, r.reproduced, r.no_mismatch,
               cell.c_str(), it->second.c_str()),
        accounts && restores, restores);
  }
}

TsvTable checked_reasons(const StoreSnapshot& store, const PublishedTables& published_tables, double tol) {
  TsvTable out;
  out.columns = checked_reason_columns();
  auto stored = [&](const std::string& name) { return store.has(name); };
  auto load = [&](const std::string& name) -> const TsvTable& { return store.table(name); };
  auto published = [&](const std::string& table) -> const TsvTable& { return published_table(published_tables, table); };

  if (const std::string diagnostic = stored_file("thesis_poisson_diagnostic"); stored(diagnostic)) {
    const TsvTable& diag = load(diagnostic);
    // A diagnostic file from before the consistency prediction has nothing to check with.
    if (diag.column("tau_predicted") >= 0)
      add_volume_mismatch_reasons(published("thesis_table4_4"), diag, tol, out);
  }
  if (const std::string file = stored_file("thesis_table4_3"); stored(file)) {
    const TsvTable &data = load(file), pub = published("thesis_table4_3");
    for (const char* reading : {"printed", "scaled"}) add_gradient_smoothing_reasons(pub, data, reading, tol, out);
  }
  if (const std::string file = stored_file("thesis_table4_2"); stored(file)) {
    const TsvTable &data = load(file), pub = published("thesis_table4_2");
    for (const char* reading : {"printed", "scaled"}) add_interpolant_smoothing_reasons(pub, data, reading, tol, out);
  }
  for (const HeatTable& t : heat_tables()) {
    const std::string name = heat_study_name(t);
    const RegisteredStudy& study = study_registry().study(name);
    std::optional<TsvTable> pub;  // read once a reading of the table is stored
    for (const PdeReading& r : pde_reading_matrix({HRule::h10}, {PdeVolumes::lattice}, {DtRule::fit, DtRule::exact})) {
      const std::optional<std::string> named = reading_file(study, r.name());
      if (!named || !stored(*named)) continue;
      const std::string& file = *named;
      const TsvTable& data = load(file);
      if (!pub) pub = published(name);
      // The V_i = dx^2 run counts only under the same time-step rule as the data it is set
      // against (the files' `steps` lines agree; the later of the two candidates where both do).
      std::string cell;
      for (const PdeReading& c : pde_reading_matrix({HRule::h10}, {PdeVolumes::cell}, {DtRule::fit, DtRule::exact})) {
        const std::optional<std::string> candidate = reading_file(study, c.name());
        if (candidate && stored(*candidate) && store.table(*candidate, false).get("steps") == data.get("steps"))
          cell = *candidate;
      }
      const std::vector<ModeRow> cell_rows = cell.empty() ? std::vector<ModeRow>{} : mode_model(load(cell));
      add_heat_mode_reasons(name, r.name(), *pub, mode_rates(t, mode_model(data), cell_rows), tol, out);
    }
  }
  return out;
}

TsvTable reasons_by_mechanism(const TsvTable& checked) {
  for (const char* c : {"table", "slice", "key", "reason", "check", "restores"}) checked.require_column(c);
  // Per mechanism, in the order of first occurrence: its groups "table slice" (in that order
  // too), each with its rows, passes and the keys that passed.
  struct Group {
    std::string name;
    int rows = 0, passed = 0;
    std::vector<std::string> passed_keys;
  };
  struct Mechanism {
    std::string name;
    std::vector<Group> groups;
    int rows = 0, passed = 0, restores = 0;
  };
  std::vector<Mechanism> mechanisms;
  for (std::size_t i = 0; i < checked.rows.size(); ++i) {
    const std::string& reason = checked.text(i, "reason");
    const std::string name = reason.substr(0, reason.find_first_of(":;"));
    auto m = std::find_if(mechanisms.begin(), mechanisms.end(), [&](auto& x) { return x.name == name; });
    if (m == mechanisms.end()) m = mechanisms.insert(mechanisms.end(), Mechanism{name, {}, 0, 0, 0});
    const std::string group = checked.text(i, "table") + " " + checked.text(i, "slice");
    auto g = std::find_if(m->groups.begin(), m->groups.end(), [&](auto& x) { return x.name == group; });
    if (g == m->groups.end()) g = m->groups.insert(m->groups.end(), Group{group, 0, 0, {}});
    ++g->rows, ++m->rows;
    if (checked.text(i, "check") == "pass") {
      ++g->passed, ++m->passed;
      g->passed_keys.push_back(checked.text(i, "key"));
    }
    if (checked.text(i, "restores") == "yes") ++m->restores;
  }
  TsvTable out;
  out.columns = {"mechanism", "rows", "checked", "passed", "restores"};
  for (const Mechanism& m : mechanisms) {
    std::vector<std::string> list;
    for (const Group& g : m.groups) {
      const std::string detail = g.passed == 0         ? "none pass"
                                 : g.passed == g.rows ? "all pass"
                                                      : fmt(g.passed) + " pass (" + join(g.passed_keys, ", ") + ")";
      list.push_back(g.name + ": " + fmt(g.rows) + (g.rows == 1 ? " row, " : " rows, ") + detail);
    }
    TsvRow row = out.named_row();
    row["mechanism"] = m.name, row["rows"] = join(list, "; "), row["checked"] = fmt(m.rows);
    row["passed"] = fmt(m.passed), row["restores"] = fmt(m.restores);
    out.add_row(row);
  }
  return out;
}

}  // namespace gpm
