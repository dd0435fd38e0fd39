#include "gpm/studies/judge/page_verdicts.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "gpm/error.hpp"
#include "gpm/io/text_format.hpp"

namespace gpm {

namespace {


// The words of `s` split at runs of blanks ("rates thesis_table4_1" → rule, argument).
std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  return w;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string::size_type start = 0;
  for (;;) {
    const auto end = s.find(sep, start);
    out.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) return out;
    start = end + 1;
  }
}

const PageVerdict kNotYet{"not yet computed", "-"};

// The verdict of a check that holds in `holds` of `n` cases: reproduced when it holds in all.
std::string all_hold(long long holds, long long n) { return holds == n ? "reproduced" : "published value wrong"; }

// The score's verdict columns in the order of the paper-scale chapter, with the words the
// evidence uses for them.
const std::vector<std::pair<std::string, std::string>>& verdict_words() {
  static const std::vector<std::pair<std::string, std::string>> w = {
      {"agrees", "agree"},           {"non_convergence", "non-convergence"},
      {"sign_only", "unstable, sign only"},  {"in_seed_band", "in seed band"}, {"fingerprint", "fingerprint"},
      {"checked_reason", "checked reason"}, {"explained_ours", "ours explained"},
      {"near_miss", "near miss"},     {"pre_asymptotic", "pre-asymptotic"},
      {"unexplained", "unexplained"}, {"consistent_spread", "consistent with the spread of realizations"},
      {"undefined", "undefined"},     {"not_computed", "not computed"}};
  return w;
}

// "3 agree, 9 non-convergence, 11 unexplained of 27": the verdicts of score row i that occur
// (each count as the score prints it).
std::string counts(const TsvTable& score, std::size_t i) {
  std::string out;
  for (auto& [column, word] : verdict_words())
    if (score.number(i, score.require_column(column)) > 0)
      out += (out.empty() ? "" : ", ") + score.text(i, column) + " " + word;
  return (out.empty() ? "none" : out) + " of " + score.text(i, "rates");
}

// The rates of score row i that reproduce a published one: agreements, reproduced
// non-convergence and rates inside the seed band.
double reproduced_rates(const TsvTable& score, std::size_t i) {
  const auto n = [&](const char* column) { return score.number(i, score.require_column(column)); };
  return n("agrees") + n("non_convergence") + n("in_seed_band");
}

}  // namespace

PageDataReader page_data_dir(const std::string& dir) {
  return [dir](const std::string& file) -> std::optional<TsvTable> {
    const std::string path = (std::filesystem::path(dir) / file).string();
    if (!std::filesystem::exists(path)) return std::nullopt;
    return TsvTable::load(path);
  };
}

PageVerdict rate_table_verdict(const TsvTable& score, const std::string& table) {
  const int tc = score.require_column("table"), pc = score.require_column("printed"),
            cc = score.require_column("counted");
  // The rows of each board: the printed one (as the text prints every set-up detail) and the
  // counted one (the identified reading, which decides); the last row of each counts.
  std::optional<std::size_t> printed, counted;
  for (std::size_t i = 0; i < score.rows.size(); ++i) {
    if (score.text(i, tc) != table) continue;  // the board totals are rows of table "total"
    if (score.text(i, pc) == "yes") printed = i;
    if (score.text(i, cc) == "yes") counted = i;
  }
  PageVerdict v;
  if (!printed)
    v.evidence = "no rows in the store";
  else if (counted && *counted == *printed)
    v.evidence = "both boards: " + counts(score, *counted);
  else
    v.evidence = (counted ? "identified: " + counts(score, *counted) : std::string("identified reading not stored")) +
                 "; printed: " + counts(score, *printed);
  auto n = [&](const char* column) { return score.number(*counted, score.require_column(column)); };
  if (!counted || n("not_computed") == n("rates")) {
    v.verdict = "not yet computed";
    return v;
  }
  const double total = n("rates"), good = reproduced_rates(score, *counted);
  const double checked = n("checked_reason");
  v.verdict = good == total ? "reproduced"
              : good > 0    ? "partial"
              : checked > 0 && checked + n("not_computed") == total ? "not reproduced (reason checked)"
                                                                     : "open";
  // A table the deciding reading does not reproduce may be reproduced under another reading
  // the text admits (Table 4.4 under h10 with V_i = Δx²): named, so page one does not hide it,
  // but it decides nothing (the set-up rule chose the counted reading before the rates).
  if (v.verdict != "reproduced") {
    const int sc = score.require_column("slice"), uc = score.require_column("setup");
    for (std::size_t i = 0; i < score.rows.size(); ++i) {
      if (score.text(i, tc) != table || score.text(i, uc) != "document" || counted == i || printed == i) continue;
      const double all = score.number(i, score.require_column("rates"));
      if (all > 0 && reproduced_rates(score, i) == all)
        v.evidence += "; reproduced under another reading, " + score.text(i, sc) + " (seed 1): " + counts(score, i);
    }
  }
  return v;
}

PageVerdict data_rule_verdict(const std::string& rule, const PageDataReader& data) {
  const std::vector<std::string> w = words(rule);
  const std::string kind = w.empty() ? "" : w[0], arg = w.size() > 1 ? w[1] : "";
  // A data file's rows, or none when it is not there (the check has not run).
  auto load = [&](const std::string& file) { return data(file).value_or(TsvTable{}); };
  if (kind == "cor71") {
    const TsvTable t = load("koba_sato_cor71.tsv");
    if (t.rows.empty()) return kNotYet;
    long long h = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) h += t.number(i, t.require_column("holds")) == 1;
    const long long n = static_cast<long long>(t.rows.size());
    return {all_hold(h, n), format_text("%lld of %lld printed coefficients hold", h, n)};
  }
  if (kind == "bounds") {
    const TsvTable t = load("koba_sato_bounds_summary.tsv");
    double n = 0, v = 0, m = 1e300;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      n += t.number(i, t.require_column("cases"));
      v += t.number(i, t.require_column("violations"));
      m = std::min(m, t.number(i, t.require_column("min_ratio")));
    }
    if (n == 0) return kNotYet;
    return {v == 0 ? "reproduced" : "published value wrong",
            format_text("bound below the measured error in %lld of %lld cases (smallest bound/error %.3g)",
                   static_cast<long long>(v), static_cast<long long>(n), m)};
  }
  if (kind == "covering") {
    const TsvTable t = load("imoto_regularity_cover.tsv");
    if (t.rows.empty()) return kNotYet;
    double h = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) h += t.number(i, t.require_column("claim_holds"));
    const long long n = static_cast<long long>(t.rows.size());
    return {h == static_cast<double>(n) ? "reproduced" : "published value wrong",
            format_text("the bound holds on %lld of %lld (level, seed) distributions", static_cast<long long>(h), n)};
  }
  if (kind == "fig3") {
    const TsvTable t = load("imoto_figs_fig3_discs.tsv");
    std::map<std::string, double> rn;  // r_N per distribution; the last row of each counts
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      rn[t.text(i, "distribution")] = t.number(i, t.require_column("r_N"));
    if (!rn.count("uniform")) return kNotYet;
    const double u = rn["uniform"], nu = rn.count("non-uniform") ? rn["non-uniform"] : 0;
    return {u < nu ? "reproduced" : "not reproduced",
            format_text("covering radius %.4g (uniform) against %.4g (non-uniform), same N", u, nu)};
  }
  if (kind == "count") {
    const TsvTable t = load("core_voronoi.tsv");
    std::optional<std::size_t> row;  // the jittered distribution at level 5; the last row counts
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      if (t.number(i, t.require_column("level")) == 5 && t.text(i, "distribution") == "jittered") row = i;
    if (!row) return kNotYet;
    const int nc = t.require_column("N");
    return {t.number(*row, nc) == 1521 ? "reproduced" : "not reproduced",
            format_text("N = %s at Δx = 2⁻⁵ (printed: 1521)", t.text(*row, nc).c_str())};
  }
  if (kind == "weights") {
    // Per name, the norm of the printed formula where it fails normalization, and the norm of
    // the corrected (plotted) weight.
    std::map<std::string, double> printed, corrected;
    const TsvTable errata = load("core_weights_errata.tsv");
    for (std::size_t i = 0; i < errata.rows.size(); ++i)
      printed[errata.text(i, "name")] = errata.number(i, errata.require_column("printed_norm"));
    const TsvTable weights = load("core_weights.tsv");
    for (std::size_t i = 0; i < weights.rows.size(); ++i)
      corrected[weights.text(i, "name")] = weights.number(i, weights.require_column("norm"));
    std::string wrong, ok;
    for (const std::string& name : split(arg, ',')) {
      std::string shown = name;  // "cubic bspline": a name a table cell can wrap between words
      for (char& c : shown)
        if (c == '_') c = ' ';
      if (printed.count(name)) wrong += format_text("%s%s %.4g", wrong.empty() ? "" : ", ", shown.c_str(), printed[name]);
      if (corrected.count(name)) ok += format_text("%s%s %.6g", ok.empty() ? "" : ", ", shown.c_str(), corrected[name]);
    }
    if (ok.empty()) return kNotYet;
    return {wrong.empty() ? "reproduced" : "published value wrong",
            (wrong.empty() ? "" : "the printed formulas, not the drawn curves, are wrong: norm as printed " + wrong + "; ") +
                "norm of the plotted (corrected) weights: " + ok};
  }
  if (kind == "drawn")
    return {"reproduced qualitatively", "illustrations drawn from the same definitions (no number to compare)"};
  return {"not yet computed", "unknown rule " + rule};
}

TsvTable page_verdicts(const TsvTable& items, const TsvTable& score, const PageDataReader& data) {
  const int dc = items.require_column("document"), ic = items.require_column("item"),
            sc = items.require_column("shows"), rc = items.require_column("rule"),
            xc = items.require_column("section");
  TsvTable out;
  out.columns = {"document", "item", "shows", "verdict", "evidence", "section"};
  struct Row {
    std::string document, item, shows, verdict, evidence, section, kind;
  };
  std::vector<Row> rows;
  // tab: the row of each rates table; pending: the ", Fig. N" of figures listed before it.
  std::map<std::string, std::size_t> tab;
  std::map<std::string, std::string> pending;
  for (std::size_t i = 0; i < items.rows.size(); ++i) {
    const std::vector<std::string> w = words(items.text(i, rc));
    const std::string kind = w.empty() ? "" : w[0], arg = w.size() > 1 ? w[1] : "";
    const std::string& document = items.text(i, dc);
    const std::string& item = items.text(i, ic);
    // A figure of a table's errors joins the table's row (drawn from the same rows).
    if (kind == "as") {
      if (tab.count(arg))
        rows[tab[arg]].item += ", " + item;
      else
        pending[arg] += ", " + item;
      continue;
    }
    // An illustration joins the row before it when that is an illustration of the same document.
    if (kind == "drawn" && !rows.empty() && rows.back().kind == "drawn" && rows.back().document == document) {
      rows.back().item += ", " + item;
      rows.back().shows += "; " + items.text(i, sc);
      continue;
    }
    const PageVerdict v = kind == "rates" ? rate_table_verdict(score, arg) : data_rule_verdict(items.text(i, rc), data);
    rows.push_back({document, item, items.text(i, sc), v.verdict, v.evidence, items.text(i, xc), kind});
    if (kind == "rates") {
      tab[arg] = rows.size() - 1;
      // The figures listed before their table (kept: a second rates row of the same table gets
      // them too, as the first did).
      if (pending.count(arg)) rows.back().item += pending[arg];
    }
  }
  for (auto& [table, figures] : pending)
    if (!tab.count(table))
      throw InputError((items.source.empty() ? std::string("items") : items.source) + ": a figure is drawn from " +
                       table + ", which items.tsv gives no rates row");
  for (const Row& r : rows) {
    TsvRow row = out.named_row();
    row["document"] = r.document;
    row["item"] = r.item;
    row["shows"] = r.shows;
    row["verdict"] = r.verdict;
    row["evidence"] = r.evidence;
    row["section"] = r.section;
    out.add_row(row);
  }
  return out;
}

}  // namespace gpm
