// scoreboard — how many published rates the run reproduced: reads every rate table that
// rate_table wrote into data/<profile>/ (files named in --tables) and counts their
// statuses, one row per table plus a total.  The report's front page shows it.
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"

using namespace gpm;

namespace {

const char* kStatuses[] = {"agrees", "differs", "other-levels", "undefined", "not-computed"};

int body(int argc, char** argv) {
  Args a("scoreboard", "Count agrees / differs / other-levels / undefined / not-computed over\n"
                       "the rate tables of one profile (TSV).");
  a.opt("tables", "", "comma-separated rate-table files (rate_table outputs)");
  a.opt("profile", "quick", "profile the tables come from (recorded only)");
  a.output("out", "", "output TSV");
  a.parse(argc, argv);
  a.required("out");
  const auto files = a.list("tables");
  if (files.empty()) throw InputError("--tables names no file");
  TsvTable out;
  out.set("program", "scoreboard");
  for (auto& [k, v] : a.values()) out.set(k, v);
  add_provenance(out);
  out.columns = {"table", "rows"};
  for (auto s : kStatuses) out.columns.push_back(s);
  out.columns.push_back("levels");
  std::map<std::string, int> total;
  int total_rows = 0;
  for (auto& f : files) {
    const TsvTable t = TsvTable::load(f);
    const int cs = t.column("status"), cl = t.column("levels");
    if (cs < 0) throw InputError(f + " has no status column (not a rate_table output)");
    std::map<std::string, int> n;
    std::map<std::string, int> levels;
    for (auto& r : t.rows) {
      ++n[r.at(cs)];
      if (cl >= 0 && !r.at(cl).empty()) ++levels[r.at(cl)];
    }
    std::string lv;
    for (auto& [l, c] : levels) lv += (lv.empty() ? "" : " ") + l;
    std::vector<std::string> row = {std::filesystem::path(f).stem().string(), fmt(t.rows.size())};
    for (auto s : kStatuses) row.push_back(fmt(n[s])), total[s] += n[s];
    row.push_back(lv);
    total_rows += static_cast<int>(t.rows.size());
    out.add_row(row);
  }
  std::vector<std::string> row = {"total", fmt(total_rows)};
  for (auto s : kStatuses) row.push_back(fmt(total[s]));
  row.push_back("");
  out.add_row(row);
  out.save(a.str("out"));
  std::printf("scoreboard: %d published rates: %d agree, %d differ, %d from other levels than "
              "the document's (not judged), %d undefined, %d not computed\n",
              total_rows, total["agrees"], total["differs"], total["other-levels"],
              total["undefined"], total["not-computed"]);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("scoreboard", body, argc, argv); }
