// rate_table — the table generator shared by every reproduced rate table.
//
// Reads a study's data file (one row per level and setting), computes per setting the
// documents' two-finest-level rate log(e₁/e₂)/log(h₁/h₂) and a least-squares slope over
// all levels, joins them with the published values (tables/published/*.tsv, long format,
// matched on the key columns), and marks each row
//   agrees               |reproduced − published| ≤ tolerance
//   differs-explained    otherwise, and tables/explained/<table>.tsv gives the reason
//   differs-unexplained  otherwise
//   not-computed         the data file has fewer than two levels for this setting.
// The output is a data file like any other: the report shows it, `make test-paper` checks it.
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include "gpm/args.hpp"
#include "gpm/error.hpp"
#include "gpm/norms.hpp"
#include "gpm/tsv.hpp"

using namespace gpm;

namespace {

int col(const TsvTable& t, const std::string& name, const std::string& file) {
  const int c = t.column(name);
  if (c < 0) throw InputError("column '" + name + "' not found in " + file);
  return c;
}

std::string join(const std::vector<std::string>& v, const char* sep = "|") {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

int body(int argc, char** argv) {
  Args a("rate_table",
         "Join a study's per-level errors with published rates: two-finest-level rate,\n"
         "least-squares slope, difference, status and reason (TSV).");
  a.opt("data", "", "the study's data file (rows: key columns, level, h, error)");
  a.opt("published", "", "published values, long format, with the key columns");
  a.opt("explained", "", "optional file of explained deviations: key columns + reason");
  a.opt("key", "", "comma-separated key columns shared by data and published files");
  a.opt("level", "level", "level column of the data file (Δx = 2^-level)");
  a.opt("x", "h", "abscissa of the rate (log e against log x)");
  a.opt("y", "rel_error", "error column");
  a.opt("value", "numerical", "published column holding the rate");
  a.opt("levels", "", "the two levels the rate comes from, e.g. 10,11, or 'published' for the\n"
                      "  published file's rate_levels (the document's); default: the two finest");
  a.opt("tolerance", "0.15", "|reproduced − published| that still counts as agreement");
  a.opt("out", "", "output TSV");
  a.parse(argc, argv);
  for (const char* req : {"data", "published", "key", "out"})
    if (a.str(req).empty()) throw InputError(std::string("--") + req + " is required");
  const double tol = a.positive("tolerance");
  const auto keys = a.list("key");

  const TsvTable data = TsvTable::load(a.str("data"));
  const TsvTable pub = TsvTable::load(a.str("published"));
  std::vector<int> dk, pk;
  for (auto& k : keys) dk.push_back(col(data, k, a.str("data")));
  for (auto& k : keys) pk.push_back(col(pub, k, a.str("published")));
  const int cl = col(data, a.str("level"), a.str("data"));
  const int cx = col(data, a.str("x"), a.str("data"));
  const int cy = col(data, a.str("y"), a.str("data"));
  const int cv = col(pub, a.str("value"), a.str("published"));
  const int ct = pub.column("theoretical");

  // Explained deviations: key columns + reason.
  std::map<std::string, std::string> reason;
  if (!a.str("explained").empty()) {
    const TsvTable ex = TsvTable::load(a.str("explained"));
    std::vector<int> ek;
    for (auto& k : keys) ek.push_back(col(ex, k, a.str("explained")));
    const int cr = col(ex, "reason", a.str("explained"));
    for (auto& r : ex.rows) {
      std::vector<std::string> kv;
      for (int c : ek) kv.push_back(r.at(c));
      reason[join(kv)] = r.at(cr);
    }
  }

  // Per key: (level, x, y) sorted by level.
  std::map<std::string, std::map<int, std::pair<double, double>>> series;
  for (auto& r : data.rows) {
    std::vector<std::string> kv;
    for (int c : dk) kv.push_back(r.at(c));
    const int level = std::stoi(r.at(cl));
    series[join(kv)][level] = {parse_number(r.at(cx), a.str("x")), parse_number(r.at(cy), a.str("y"))};
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
    for (std::string item; std::getline(ss, item, ',');) {
      const double k = parse_number(item, "--levels");
      if (k != std::floor(k)) throw InputError("--levels: '" + item + "' is not an integer");
      fixed.push_back(static_cast<int>(k));
    }
    if (fixed.size() != 2 || !(fixed[0] < fixed[1]))
      throw InputError("--levels: '" + lv + "' is not two increasing levels");
    out.set("rate_levels", lv);
  }
  std::map<std::string, int> counts;
  for (auto& r : pub.rows) {
    std::vector<std::string> kv;
    for (int c : pk) kv.push_back(r.at(c));
    const std::string key = join(kv);
    const double published = parse_number(r.at(cv), a.str("value"));
    std::string rep = "NA", diff = "NA", lsq = "NA", levels = "", status = "not-computed", why = "";
    auto it = series.find(key);
    const bool have = it != series.end() &&
                      (fixed.empty() ? it->second.size() >= 2
                                     : it->second.count(fixed[0]) && it->second.count(fixed[1]));
    if (have) {
      auto last = fixed.empty() ? std::prev(it->second.end()) : it->second.find(fixed[1]);
      auto prev = fixed.empty() ? std::prev(last) : it->second.find(fixed[0]);
      const double rate = two_level_rate(prev->second.first, prev->second.second,
                                         last->second.first, last->second.second);
      std::vector<double> xs, ys;
      for (auto& [lv, xy] : it->second) xs.push_back(xy.first), ys.push_back(xy.second);
      rep = fmt(rate);
      diff = fmt(rate - published);
      lsq = fmt(least_squares_rate(xs, ys));
      levels = std::to_string(prev->first) + "," + std::to_string(last->first);
      if (std::fabs(rate - published) <= tol) {
        status = "agrees";
      } else if (reason.count(key)) {
        status = "differs-explained";
        why = reason[key];
      } else {
        status = "differs-unexplained";
      }
    }
    ++counts[status];
    auto row = kv;
    for (auto& s : {fmt(published), ct >= 0 ? r.at(ct) : std::string("NA"), rep, diff, lsq,
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
