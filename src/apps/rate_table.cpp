// rate_table — the table generator shared by every reproduced rate table.
//
// Reads a study's data file (one row per level and setting), computes per setting the
// documents' two-finest-level rate log(e₁/e₂)/log(h₁/h₂) and a least-squares slope over
// all levels, joins them with the published values (tables/published/*.tsv, long format,
// matched on the key columns), and marks each row other-levels, agrees, differs, undefined
// or not-computed (the join and its statuses: src/gpm/studies/judge/rates.hpp).
// Two data rows with the same key and level are refused (one would silently replace the other).
// The output is a data file like any other: the report shows it, `make test-paper` checks it.
#include <cstdio>
#include <map>
#include <string>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/rates.hpp"

using namespace gpm;

namespace {

int body(int argc, char** argv) {
  Args a("rate_table",
         "Join a study's per-level errors with published rates: two-finest-level rate,\n"
         "least-squares slope, difference, status and reason (TSV).");
  a.opt("data", "", "the study's data file (rows: key columns, level, h, error)");
  a.opt("published", "", "published values, long format, with the key columns");
  a.opt("key", "", "comma-separated key columns shared by data and published files");
  a.opt("where", "", "keep only the data rows with these cells, e.g. h_reading=printed,volumes=voronoi\n"
                     "  (one reading of a study file); default: every row");
  a.opt("level", "level", "level column of the data file (Δx = 2^-level)");
  a.opt("x", "h", "abscissa of the rate (log e against log x)");
  a.opt("y", "rel_error", "error column");
  a.opt("value", "numerical", "published column holding the rate");
  a.opt("levels", "", "the two levels the rate comes from, e.g. 10,11, or 'published' for the\n"
                      "  published file's rate_levels (the document's); default: the two finest");
  a.opt("tolerance", fmt(kRateTolerance), "|reproduced − published| that still counts as agreement, in (0, 1)");
  a.output("out", "", "output TSV");
  a.parse(argc, argv);
  for (const char* req : {"data", "published", "key", "out"})
    if (a.str(req).empty()) throw InputError(std::string("--") + req + " is required");
  const double tol = a.tolerance("tolerance");
  const auto keys = a.list("key");

  std::vector<std::pair<std::string, std::string>> where;
  for (const std::string& w : a.list("where")) {
    const auto eq = w.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--where '" + w + "' is not COLUMN=VALUE");
    where.emplace_back(w.substr(0, eq), w.substr(eq + 1));
  }
  const TsvTable data = rows_where(TsvTable::load(a.str("data")), where);
  if (!where.empty() && data.rows.empty())
    throw InputError("--where " + a.str("where") + ": no row of " + a.str("data") + " matches");
  const TsvTable pub = TsvTable::load(a.str("published"));
  RateJoin join;
  join.keys = keys;
  join.level = a.str("level"), join.x = a.str("x"), join.y = a.str("y"), join.value = a.str("value");
  join.levels = a.str("levels");
  join.tolerance = tol;

  TsvTable out;
  out.set("program", "rate_table");
  for (auto& [k, v] : a.values()) out.set(k, v);
  for (const char* k : {"profile", "git_revision", "seed", "program"})
    if (auto v = data.get(k)) out.set(std::string("data_") + k, *v);
  add_provenance(out);
  const std::map<std::string, int> counts = join_rates(data, pub, join, out);
  out.save(a.str("out"));
  std::printf("rate_table: %s:", a.str("out").c_str());
  for (auto& [s, n] : counts) std::printf(" %s %d", s.c_str(), n);
  std::printf("\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("rate_table", body, argc, argv); }
