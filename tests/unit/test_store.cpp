// The result store's rules (src/gpm/studies/store.hpp), on small files written here: a unit is
// reused only when complete and computed by the current code; malformed and partial units
// are recomputed; a second writer is refused; --verify catches a changed number; --recheck
// carries rows of older code over only when the recomputed units agree.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "gpm/error.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/store.hpp"
#include "../temp_dir.hpp"

using namespace gpm;
namespace fs = std::filesystem;

namespace {

const std::vector<std::pair<std::string, std::string>> kParams = {{"program", "store_test"},
                                                                  {"seed", "1"}};
const std::vector<std::string> kColumns = {"level", "weight", "rel_error", "time_s"};

// A study of two units (levels 5, 6) with two rows each; `bump` changes level 6's numbers.
void run_study(const std::string& path, CacheMode mode, double bump = 0,
               std::vector<int> levels = {5, 6}) {
  LevelCache c(path, kParams, kColumns, 1, mode);
  for (int k : levels) {
    if (c.has({std::to_string(k)}, 2)) continue;
    for (const char* w : {"a", "b"})
      c.add({std::to_string(k), w, fmt(1.0 / k + (k == 6 ? bump : 0.0)), fmt(0.1 * k)});
    c.save();
  }
  c.finish();
}

std::vector<std::vector<std::string>> rows_of(const std::string& path) {
  return TsvTable::load(path).rows;
}

}  // namespace

TEST_CASE("store: rows carry the code fingerprint and are reused only under it", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  const TsvTable tab = TsvTable::load(f);
  REQUIRE(tab.rows.size() == 4);
  const int code = tab.column("code"), checked = tab.column("checked");
  REQUIRE(code >= 0);
  REQUIRE(tab.column("made_on") >= 0);
  for (auto& r : tab.rows) {
    CHECK(r[code] == code_fingerprint());
    CHECK(r[checked] == "computed");
  }
  {
    LevelCache c(f, kParams, kColumns, 1);
    CHECK(c.reused() == 4);
    CHECK(c.has({"5"}, 2));
    CHECK_FALSE(c.has({"5"}, 3));  // a unit needs all its rows
    CHECK_FALSE(c.has({"7"}));
  }
  // Rows of other code are kept in the file but not reused.
  auto tt = TsvTable::load(f);
  tt.rows[0][code] = "0123456789ab";
  tt.save(f);
  LevelCache c(f, kParams, kColumns, 1);
  CHECK(c.reused() == 3);
  CHECK_FALSE(c.has({"5"}, 2));
  CHECK(c.has({"6"}, 2));
}

TEST_CASE("store: partial and malformed units are recomputed, not reused", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  // Drop one row of level 5 and cut a cell from a row of level 6.
  std::ifstream in(f);
  std::string text, line;
  bool dropped = false, cut = false;
  while (std::getline(in, line)) {
    if (!dropped && line.rfind("5\ta\t", 0) == 0) {
      dropped = true;
      continue;
    }
    if (!cut && line.rfind("6\tb\t", 0) == 0) {
      line = line.substr(0, line.find('\t', 4));  // "6\tb": two cells
      cut = true;
    }
    text += line + "\n";
  }
  in.close();
  REQUIRE((dropped && cut));
  std::ofstream(f) << text;
  {
    LevelCache c(f, kParams, kColumns, 1);
    CHECK_FALSE(c.has({"5"}, 2));  // partial
    CHECK_FALSE(c.has({"6"}, 2));  // one row malformed, dropped
  }
  run_study(f, CacheMode::run);
  const auto rows = rows_of(f);
  REQUIRE(rows.size() == 4);  // each unit once, complete: no duplicate rows
  for (auto& r : rows) CHECK(r.size() == kColumns.size() + 3);
}

TEST_CASE("store: a second writer on one file is refused", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  LevelCache first(f, kParams, kColumns, 1);
  REQUIRE_THROWS_AS(LevelCache(f, kParams, kColumns, 1), InputError);
  REQUIRE_NOTHROW(LevelCache(f, kParams, kColumns, 1, CacheMode::verify));  // a reader
}

TEST_CASE("store: --out must be a regular file, and outputs distinct", "[unit][store]") {
  TempDir t("gpm_store_");
  REQUIRE_THROWS_AS(LevelCache(t.dir.string(), kParams, kColumns, 1), InputError);
  REQUIRE_THROWS_AS(require_distinct_paths({{"--out", t.file("a.tsv")},
                                            {"--cost", (t.dir / "." / "a.tsv").string()}}),
                    InputError);
  REQUIRE_NOTHROW(require_distinct_paths({{"--out", t.file("a.tsv")}, {"--cost", t.file("b.tsv")},
                                          {"--other", ""}}));
}

TEST_CASE("store: --verify compares and writes nothing; --recheck re-stamps only on agreement",
          "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  const auto before = fs::last_write_time(f);
  REQUIRE_NOTHROW(run_study(f, CacheMode::verify));
  REQUIRE_THROWS_AS(run_study(f, CacheMode::verify, 1e-6), StoreMismatch);
  REQUIRE_NOTHROW(run_study(f, CacheMode::verify, 1e-12));  // inside the 1e-9 tolerance
  CHECK(fs::last_write_time(f) == before);

  // Pretend level 6 was computed by older code; recheck only level 5.
  auto tt = TsvTable::load(f);
  const int code = tt.column("code"), checked = tt.column("checked");
  for (auto& r : tt.rows) r[code] = "0123456789ab";
  tt.save(f);
  run_study(f, CacheMode::recheck, 0, {5});
  for (auto& r : rows_of(f)) {
    CHECK(r[code] == code_fingerprint());
    if (r[0] == "6") CHECK(r[checked].find("recheck") == 0);
    if (r[0] == "5") CHECK(r[checked] == "computed");
  }
  // A recheck that disagrees re-stamps nothing and reports the difference.
  tt = TsvTable::load(f);
  for (auto& r : tt.rows) r[code] = "0123456789ab";
  tt.save(f);
  REQUIRE_THROWS_AS(run_study(f, CacheMode::recheck, 1e-3, {6}), StoreMismatch);
  for (auto& r : rows_of(f))
    CHECK((r[0] == "6") == (r[code] == code_fingerprint()));  // only the recomputed unit
}

TEST_CASE("store: rows of a file without provenance columns need a recheck", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  TsvTable old;
  for (auto& [k, v] : kParams) old.set(k, v);
  old.set("host", "elsewhere");
  old.columns = kColumns;
  for (int k : {5, 6})
    for (const char* w : {"a", "b"}) old.add_row({std::to_string(k), w, fmt(1.0 / k), "0.5"});
  old.save(f);
  {
    LevelCache c(f, kParams, kColumns, 1);
    CHECK(c.reused() == 0);
    CHECK_FALSE(c.has({"6"}));
  }
  run_study(f, CacheMode::recheck, 0, {5});
  const auto tab = TsvTable::load(f);
  for (auto& r : tab.rows) {
    CHECK(r[tab.column("code")] == code_fingerprint());
    if (r[0] == "6") {
      CHECK(r[tab.column("checked")].find("of code unrecorded") != std::string::npos);
      CHECK(r[tab.column("made_on")].find("elsewhere") != std::string::npos);
    }
  }
}

TEST_CASE("store: a recheck against the current code's own rows carries nothing over",
          "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  // Level 6 from older code, level 5 current: re-checking level 5 compares current rows with
  // the current code, which says nothing about level 6.
  auto tt = TsvTable::load(f);
  const int code = tt.column("code");
  for (auto& r : tt.rows)
    if (r[0] == "6") r[code] = "0123456789ab";
  tt.save(f);
  run_study(f, CacheMode::recheck, 0, {5});
  for (auto& r : rows_of(f))
    if (r[0] == "6") CHECK(r[code] == "0123456789ab");
}

// A solver residual (~1e-11) is compared absolutely (kStoreResidualAbsTol): its relative
// change from rounding alone (~1e-6) is not a change of the numerics; a residual that moves
// by more than the absolute tolerance still is.
TEST_CASE("store: residual columns are compared absolutely", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("r.tsv");
  const std::vector<std::string> cols = {"level", "rel_error", "max_rel_residual"};
  auto study = [&](CacheMode mode, double residual) {
    LevelCache c(f, kParams, cols, 1, mode);
    c.add({"5", fmt(0.125), fmt(residual)});
    c.save();
    c.finish();
  };
  study(CacheMode::run, 6.753016866560343e-11);
  REQUIRE_NOTHROW(study(CacheMode::verify, 6.753015449936592e-11));  // rounding: 2e-6 relative
  REQUIRE_THROWS_AS(study(CacheMode::verify, 6.753e-11 + 5 * kStoreResidualAbsTol), StoreMismatch);
}
