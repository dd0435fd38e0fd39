// rate_table — the table generator shared by every reproduced rate table.
//
// Reads a study's data file (one row per level and setting), computes per setting the
// documents' two-finest-level rate log(e₁/e₂)/log(h₁/h₂) and a least-squares slope over
// all levels, joins them with the published values (tables/published/*.tsv, long format,
// matched on the key columns), and marks each row
//   other-levels         the rate comes from other levels than the document's (the published
//                        file's rate_levels): it is shown, not judged — a pre-asymptotic
//                        rate from coarser levels neither agrees nor differs with the document
//   agrees               |reproduced − published| ≤ tolerance
//   differs              otherwise (a reason counts only where a diagnostic computed from the
//                        data checks it: tables/checked_reasons.sh, for the paper-scale store)
//   undefined            the rate is not a number (an error ≤ 0 or not finite at one of the
//                        two levels): no agreement can be claimed
//   not-computed         the data file has fewer than two levels for this setting.
// Two data rows with the same key and level are refused (one would silently replace the other).
// The output is a data file like any other: the report shows it, `make test-paper` checks it.
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/norms.hpp"

using namespace gpm;

namespace {

// The key of row i: its cells in the key columns, joined by '|'.
std::string key_of(const TsvTable& t, std::size_t i, const std::vector<int>& cols) {
  std::string s;
  for (std::size_t k = 0; k < cols.size(); ++k) s += (k ? "|" : "") + t.text(i, cols[k]);
  return s;
}

int body(int argc, char** argv) {
  Args a("rate_table",
         "Join a study's per-level errors with published rates: two-finest-level rate,\n"
         "least-squares slope, difference, status and reason (TSV).");
  a.opt("data", "", "the study's data file (rows: key columns, level, h, error)");
  a.opt("published", "", "published values, long format, with the key columns");
  a.opt("key", "", "comma-separated key columns shared by data and published files");
  a.opt("level", "level", "level column of the data file (Δx = 2^-level)");
  a.opt("x", "h", "abscissa of the rate (log e against log x)");
  a.opt("y", "rel_error", "error column");
  a.opt("value", "numerical", "published column holding the rate");
  a.opt("levels", "", "the two levels the rate comes from, e.g. 10,11, or 'published' for the\n"
                      "  published file's rate_levels (the document's); default: the two finest");
  a.opt("tolerance", "0.15", "|reproduced − published| that still counts as agreement, in (0, 1)");
  a.output("out", "", "output TSV");
  a.parse(argc, argv);
  for (const char* req : {"data", "published", "key", "out"})
    if (a.str(req).empty()) throw InputError(std::string("--") + req + " is required");
  const double tol = a.tolerance("tolerance");
  const auto keys = a.list("key");

  const TsvTable data = TsvTable::load(a.str("data"));
  const TsvTable pub = TsvTable::load(a.str("published"));
  std::vector<int> dk, pk;
  for (auto& k : keys) dk.push_back(data.require_column(k));
  for (auto& k : keys) pk.push_back(pub.require_column(k));
  const int cl = data.require_column(a.str("level"));
  const int cx = data.require_column(a.str("x"));
  const int cy = data.require_column(a.str("y"));
  const int cv = pub.require_column(a.str("value"));
  const int ct = pub.column("theoretical");

  // The document's two levels, where the published file names them.
  const std::string doc_levels = pub.get("rate_levels").value_or("");

  // Per key: (level, x, y) sorted by level; where each came from, for a duplicate's message.
  struct Point {
    double x, y;
    std::size_t row;
  };
  std::map<std::string, std::map<int, Point>> series;
  for (std::size_t i = 0; i < data.rows.size(); ++i) {
    const std::string key = key_of(data, i, dk);
    const long long level = data.integer(i, cl);
    const auto [it, fresh] = series[key].emplace(
        static_cast<int>(level), Point{data.number(i, cx), data.number(i, cy), i});
    if (!fresh)
      throw InputError(a.str("data") + ": key '" + key + "' has two rows at level " +
                       std::to_string(level) + " (data rows " + std::to_string(it->second.row + 1) +
                       " and " + std::to_string(i + 1) + ")");
  }

  TsvTable out;
  out.set("program", "rate_table");
  for (auto& [k, v] : a.values()) out.set(k, v);
  for (const char* k : {"profile", "git_revision", "seed", "program"})
    if (auto v = data.get(k)) out.set(std::string("data_") + k, *v);
  add_provenance(out);
  out.columns = keys;
  for (const char* c : {"published", "theoretical", "reproduced", "difference", "lsq_slope",
                        "levels", "status", "reason"})
    out.columns.push_back(c);
  // The two levels of every rate: fixed (the document's) or the finest two of each series.
  std::vector<int> fixed;
  if (!a.str("levels").empty()) {
    std::string lv = a.str("levels");
    if (lv == "published") {
      const auto v = pub.get("rate_levels");
      if (!v) throw InputError("--levels published: " + a.str("published") + " has no rate_levels");
      lv = *v;
    }
    std::stringstream ss(lv);
    for (std::string item; std::getline(ss, item, ',');)
      fixed.push_back(static_cast<int>(parse_integer(item, "--levels", 0, 63)));
    if (fixed.size() != 2 || !(fixed[0] < fixed[1]))
      throw InputError("--levels: '" + lv + "' is not two increasing levels");
    out.set("rate_levels", lv);
  }
  std::map<std::string, int> counts;
  for (std::size_t i = 0; i < pub.rows.size(); ++i) {
    const std::string key = key_of(pub, i, pk);
    const double published = pub.number(i, cv);
    std::string rep = "NA", diff = "NA", lsq = "NA", levels = "", status = "not-computed", why = "";
    auto it = series.find(key);
    const bool have = it != series.end() &&
                      (fixed.empty() ? it->second.size() >= 2
                                     : it->second.count(fixed[0]) && it->second.count(fixed[1]));
    if (have) {
      auto last = fixed.empty() ? std::prev(it->second.end()) : it->second.find(fixed[1]);
      auto prev = fixed.empty() ? std::prev(last) : it->second.find(fixed[0]);
      const double rate = two_level_rate(prev->second.x, prev->second.y, last->second.x,
                                         last->second.y);
      std::vector<double> xs, ys;
      for (auto& [lv, pt] : it->second) xs.push_back(pt.x), ys.push_back(pt.y);
      rep = fmt(rate);
      lsq = fmt(least_squares_rate(xs, ys));
      levels = std::to_string(prev->first) + "," + std::to_string(last->first);
      // NaN fails every comparison: tested first, or it would fall through to a reason.
      if (!std::isfinite(rate) || !std::isfinite(published)) {
        status = "undefined";
      } else {
        diff = fmt(rate - published);
        if (!doc_levels.empty() && levels != doc_levels) {
          status = "other-levels";
          why = "rate from levels " + levels + "; the document's are " + doc_levels;
        } else {
          status = std::fabs(rate - published) <= tol ? "agrees" : "differs";
        }
      }
    }
    ++counts[status];
    std::vector<std::string> row;
    for (int c : pk) row.push_back(pub.text(i, c));
    for (auto& s : {fmt(published), ct >= 0 ? pub.text(i, ct) : std::string("NA"), rep, diff, lsq,
                    levels, status, why})
      row.push_back(s);
    out.add_row(row);
  }
  for (auto& [s, n] : counts) out.set("count_" + s, fmt(n));
  out.save(a.str("out"));
  std::printf("rate_table: %s:", a.str("out").c_str());
  for (auto& [s, n] : counts) std::printf(" %s %d", s.c_str(), n);
  std::printf("\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("rate_table", body, argc, argv); }
