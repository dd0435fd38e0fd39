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

// The program: the options read once; run() counts each rate table's statuses, adds the
// total and writes the board.
class Scoreboard {
 public:
  Scoreboard(int argc, char** argv)
      : a_("scoreboard", "Count agrees / differs / other-levels / undefined / not-computed over\n"
                         "the rate tables of one profile (TSV).") {
    a_.opt("tables", "", "comma-separated rate-table files (rate_table outputs)");
    a_.opt("profile", "quick", "profile the tables come from (recorded only)");
    a_.output("out", "", "output TSV");
    a_.parse(argc, argv);
    a_.required("out");
    files_ = a_.list("tables");
    if (files_.empty()) throw InputError("--tables names no file");
  }

  int run() {
    open_board();
    for (auto& f : files_) count(f);
    write_total();
    return 0;
  }

 private:
  void open_board() {
    out_.set("program", "scoreboard");
    for (auto& [k, v] : a_.values()) out_.set(k, v);
    add_provenance(out_);
    out_.columns = {"table", "rows"};
    for (auto s : kStatuses) out_.columns.push_back(s);
    out_.columns.push_back("levels");
  }

  // One rate table: its rows per status and the pairs of levels its rates come from.
  void count(const std::string& f) {
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
    for (auto s : kStatuses) row.push_back(fmt(n[s])), total_[s] += n[s];
    row.push_back(lv);
    total_rows_ += static_cast<int>(t.rows.size());
    out_.add_row(row);
  }

  void write_total() {
    std::vector<std::string> row = {"total", fmt(total_rows_)};
    for (auto s : kStatuses) row.push_back(fmt(total_[s]));
    row.push_back("");
    out_.add_row(row);
    out_.save(a_.str("out"));
    std::printf("scoreboard: %d published rates: %d agree, %d differ, %d from other levels than "
                "the document's (not judged), %d undefined, %d not computed\n",
                total_rows_, total_["agrees"], total_["differs"], total_["other-levels"],
                total_["undefined"], total_["not-computed"]);
  }

  Args a_;
  std::vector<std::string> files_;
  TsvTable out_;
  std::map<std::string, int> total_;
  int total_rows_ = 0;
};

int body(int argc, char** argv) { return Scoreboard(argc, argv).run(); }

}  // namespace

int main(int argc, char** argv) { return run_main("scoreboard", body, argc, argv); }
