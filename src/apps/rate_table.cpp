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

// The program: the options read once; run() reads the data and the published file, joins
// them and writes the table.
class RateTable {
 public:
  RateTable(int argc, char** argv)
      : a_("rate_table",
           "Join a study's per-level errors with published rates: two-finest-level rate,\n"
           "least-squares slope, difference, status and reason (TSV).") {
    a_.opt("data", "", "the study's data file (rows: key columns, level, h, error)");
    a_.opt("published", "", "published values, long format, with the key columns");
    a_.opt("key", "", "comma-separated key columns shared by data and published files");
    a_.opt("where", "", "keep only the data rows with these cells, e.g. h_reading=printed,volumes=voronoi\n"
                        "  (one reading of a study file); default: every row");
    a_.opt("level", "level", "level column of the data file (Δx = 2^-level)");
    a_.opt("x", "h", "abscissa of the rate (log e against log x)");
    a_.opt("y", "rel_error", "error column");
    a_.opt("value", "numerical", "published column holding the rate");
    a_.opt("levels", "", "the two levels the rate comes from, e.g. 10,11, or 'published' for the\n"
                         "  published file's rate_levels (the document's); default: the two finest");
    a_.opt("tolerance", fmt(kRateTolerance), "|reproduced − published| that still counts as agreement, in (0, 1)");
    a_.output("out", "", "output TSV");
    a_.parse(argc, argv);
    for (const char* req : {"data", "published", "key", "out"})
      if (a_.str(req).empty()) throw InputError(std::string("--") + req + " is required");
    join_.tolerance = a_.tolerance("tolerance");
    join_.keys = a_.list("key");
    for (const std::string& w : a_.list("where")) {
      const auto eq = w.find('=');
      if (eq == std::string::npos || eq == 0)
        throw InputError("--where '" + w + "' is not COLUMN=VALUE");
      where_.emplace_back(w.substr(0, eq), w.substr(eq + 1));
    }
    join_.level = a_.str("level"), join_.x = a_.str("x"), join_.y = a_.str("y"), join_.value = a_.str("value");
    join_.levels = a_.str("levels");
  }

  int run() {
    read_inputs();
    join_and_write();
    return 0;
  }

 private:
  // The data (the rows --where keeps) and the published rates.
  void read_inputs() {
    data_ = rows_where(TsvTable::load(a_.str("data")), where_);
    if (!where_.empty() && data_.rows.empty())
      throw InputError("--where " + a_.str("where") + ": no row of " + a_.str("data") + " matches");
    pub_ = TsvTable::load(a_.str("published"));
  }

  // The joined table, its header naming every option and the data's provenance, and a
  // one-line count per status.
  void join_and_write() {
    TsvTable out;
    out.set("program", "rate_table");
    for (auto& [k, v] : a_.values()) out.set(k, v);
    for (const char* k : {"profile", "git_revision", "seed", "program"})
      if (auto v = data_.get(k)) out.set(std::string("data_") + k, *v);
    add_provenance(out);
    const JoinedRates joined = join_rates(data_, pub_, join_);
    write_joined(joined, out);
    out.save(a_.str("out"));
    std::printf("rate_table: %s:", a_.str("out").c_str());
    for (auto& [s, n] : joined.counts) std::printf(" %s %d", s.c_str(), n);
    std::printf("\n");
  }

  Args a_;
  RateJoin join_;
  std::vector<std::pair<std::string, std::string>> where_;
  TsvTable data_, pub_;
};

int body(int argc, char** argv) { return RateTable(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("rate_table", body, argc, argv); }
