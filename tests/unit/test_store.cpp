// The result store's rules (src/gpm/studies/run/store.hpp), on small files written here: a unit is
// reused only when complete and computed by the current code; partial units are recomputed;
// malformed, unsealed, tampered or duplicate rows and a file of other parameters are refused
// (the file untouched) unless --replace; a second writer is refused; --verify catches a
// changed number (and any non-finite one); --recheck carries rows of older code over only
// when the recomputed units agree; --census lists the missing units.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <unistd.h>

#include "gpm/error.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/io/seal.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/run/store.hpp"
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
  UnitCache c(path, kParams, kColumns, 1, mode);
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

// Rows edited here as if older code had written them: sealed again, as that code would have.
void save_resealed(TsvTable& t, const std::string& path) {
  for (auto& r : t.rows) r.back() = row_seal(r, path);
  t.save(path);
}

// The file's text with `edit` applied to each line.
template <class F>
void edit_lines(const std::string& path, F edit) {
  std::ifstream in(path);
  std::string text, line;
  while (std::getline(in, line)) text += edit(line);
  in.close();
  std::ofstream(path) << text;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
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
    UnitCache c(f, kParams, kColumns, 1);
    CHECK(c.reused() == 4);
    CHECK(c.has({"5"}, 2));
    CHECK_FALSE(c.has({"5"}, 3));  // a unit needs all its rows
    CHECK_FALSE(c.has({"7"}));
  }
  // Rows of other code are kept in the file but not reused (a unit's rows share one code).
  auto tt = TsvTable::load(f);
  tt.rows[0][code] = tt.rows[1][code] = "0123456789ab";
  save_resealed(tt, f);
  UnitCache c(f, kParams, kColumns, 1);
  CHECK(c.reused() == 2);
  CHECK_FALSE(c.has({"5"}, 2));
  CHECK(c.has({"6"}, 2));
}

TEST_CASE("store: a partial unit is recomputed; a malformed row is refused unless --replace",
          "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  // Drop one row of level 5: a partial unit, recomputed by a run.
  bool dropped = false;
  edit_lines(f, [&](const std::string& line) {
    if (!dropped && line.rfind("5\ta\t", 0) == 0) return dropped = true, std::string();
    return line + "\n";
  });
  REQUIRE(dropped);
  {
    UnitCache c(f, kParams, kColumns, 1);
    CHECK_FALSE(c.has({"5"}, 2));
    CHECK(c.has({"6"}, 2));
  }
  run_study(f, CacheMode::run);
  REQUIRE(rows_of(f).size() == 4);
  // Cut the last cells of a row of level 6: refused in every mode, the file untouched.
  edit_lines(f, [&](const std::string& line) {
    return (line.rfind("6\tb\t", 0) == 0 ? line.substr(0, line.find('\t', 4)) : line) + "\n";
  });
  const std::string cut = text_of(f);
  REQUIRE_THROWS_AS(run_study(f, CacheMode::run), InputError);
  REQUIRE_THROWS_AS(run_study(f, CacheMode::verify), InputError);
  REQUIRE_THROWS_AS(run_study(f, CacheMode::run, 0, {5}), InputError);  // another level too
  CHECK(text_of(f) == cut);
  run_study(f, CacheMode::replace);
  const auto rows = rows_of(f);
  REQUIRE(rows.size() == 4);  // each unit once, complete: no duplicate rows
  for (auto& r : rows) CHECK(r.size() == kColumns.size() + row_provenance_columns().size());
}

TEST_CASE("store: a changed cell breaks the row's seal, and the store refuses it", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  for (const char* mode : {"number", "code", "duplicate"}) {
    CAPTURE(mode);
    const std::string good = text_of(f);
    auto tt = TsvTable::load(f);
    if (std::string(mode) == "number") tt.rows[2][2] = fmt(0.851 * tt.number(2, 2));
    if (std::string(mode) == "code") tt.rows[2][tt.column("code")] = "0123456789ab";
    if (std::string(mode) == "duplicate") tt.rows.push_back(tt.rows[1]);
    tt.save(f);
    const std::string bad = text_of(f);
    REQUIRE_THROWS_AS(run_study(f, CacheMode::run), InputError);
    REQUIRE_THROWS_AS(run_study(f, CacheMode::verify), InputError);
    REQUIRE_THROWS_AS(run_study(f, CacheMode::recheck, 0, {5}), InputError);
    REQUIRE_THROWS_AS(run_study(f, CacheMode::census), InputError);
    CHECK(text_of(f) == bad);
    std::ofstream(f) << good;
  }
  REQUIRE_NOTHROW(run_study(f, CacheMode::verify));
}

TEST_CASE("store: other parameters, columns, CRLF or a BOM: refused, file untouched", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  const std::string good = text_of(f);
  auto refused = [&](const std::string& text, const std::string& says) {
    std::ofstream(f) << text;
    try {
      run_study(f, CacheMode::run);
      FAIL("not refused");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains(says));
    }
    CHECK(text_of(f) == text);
  };
  std::string crlf;
  for (char c : good) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  refused(crlf, "CRLF");
  refused("\xEF\xBB\xBF" + good, "byte-order mark");
  std::string other = good;
  other.replace(other.find("seed = 1"), 8, "seed = 2");
  refused(other, "parameter 'seed' differs (file: '2'; now: '1')");
  std::string cr = good;
  cr.replace(cr.find("store_test"), 10, "store_test\r");  // a \r inside a value, shown escaped
  // (the line then ends in CRLF: the line-ending check names it first)
  refused(cr, "CRLF");
  // A file that says it is of the quick profile is a cache only for a quick run (the test
  // below): this run has no quick profile, so it is refused like any other.
  refused(other + "# profile = quick\n", "parameter 'seed' differs");
}

TEST_CASE("store: a non-finite number never agrees", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  for (const char* v : {"inf", "1e999", "infinity", "nan", "-inf"}) {
    CAPTURE(v);
    auto tt = TsvTable::load(f);
    const std::string keep = tt.rows[2][2];
    tt.rows[2][2] = v;
    save_resealed(tt, f);  // even with a valid seal
    REQUIRE_THROWS_AS(run_study(f, CacheMode::verify), StoreMismatch);
    tt.rows[2][2] = keep;
    save_resealed(tt, f);
  }
}

TEST_CASE("store: --census lists the units a file lacks, computing nothing", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  REQUIRE_NOTHROW(run_study(f, CacheMode::census));
  REQUIRE_THROWS_AS(run_study(f, CacheMode::census, 0, {5, 6, 7}), StoreMismatch);
  CHECK(rows_of(f).size() == 4);
  // A unit of older code is present: the census passes (--verify is what judges the code).
  auto tt = TsvTable::load(f);
  for (auto& r : tt.rows) r[tt.column("code")] = "0123456789ab";
  save_resealed(tt, f);
  REQUIRE_NOTHROW(run_study(f, CacheMode::census));
}

TEST_CASE("store: a second writer on one file is refused", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  UnitCache first(f, kParams, kColumns, 1);
  REQUIRE_THROWS_AS(UnitCache(f, kParams, kColumns, 1), InputError);
  REQUIRE_NOTHROW(UnitCache(f, kParams, kColumns, 1, CacheMode::census));  // a reader
}

TEST_CASE("store: --out must be a regular file, and outputs distinct", "[unit][store]") {
  TempDir t("gpm_store_");
  REQUIRE_THROWS_AS(UnitCache(t.dir.string(), kParams, kColumns, 1), InputError);
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
  tt.rows[2][checked] = "recheck 2026-01-01 of code a: x; recheck 2026-01-02 of code b: y";
  save_resealed(tt, f);
  run_study(f, CacheMode::recheck, 0, {5});
  for (auto& r : rows_of(f)) {
    CHECK(r[code] == code_fingerprint());
    CHECK(r.back() == row_seal(r, f));  // sealed anew
    if (r[0] == "6") CHECK(r[checked].find("recheck") == 0);
    if (r[0] == "5") CHECK(r[checked] == "computed");
  }
  // The chain is cut to the last record and a count; the log beside the file keeps it.
  CHECK_THAT(rows_of(f)[2][checked], Catch::EndsWith("(+2 earlier)"));
  CHECK(text_of(t.file("rechecks.log")).find("s.tsv\trecheck") == 0);
  // A recheck that disagrees re-stamps nothing and reports the difference.
  tt = TsvTable::load(f);
  for (auto& r : tt.rows) r[code] = "0123456789ab";
  save_resealed(tt, f);
  REQUIRE_THROWS_AS(run_study(f, CacheMode::recheck, 1e-3, {6}), StoreMismatch);
  for (auto& r : rows_of(f))
    CHECK((r[0] == "6") == (r[code] == code_fingerprint()));  // only the recomputed unit
}

TEST_CASE("store: a file without its seal column is refused, and told to come back from git", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  auto tt = TsvTable::load(f);
  tt.columns.pop_back();
  for (auto& r : tt.rows) r.pop_back();
  fs::remove(f);  // (an unsealed table never replaces a sealed file)
  tt.save(f);
  try {
    run_study(f, CacheMode::run);
    FAIL("not refused");
  } catch (const InputError& e) {
    // No longer "seal it once with gpm store-seal": that blessed whatever was edited meanwhile.
    CHECK_THAT(e.what(), Catch::Contains("restore the file from git"));
    CHECK_THAT(e.what(), !Catch::Contains("gpm store-seal"));
  }
  REQUIRE_THROWS_AS(run_study(f, CacheMode::recheck, 0, {5}), InputError);
  run_study(f, CacheMode::replace);
  CHECK(TsvTable::load(f).column("seal") >= 0);
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
  save_resealed(tt, f);
  run_study(f, CacheMode::recheck, 0, {5});
  for (auto& r : rows_of(f))
    if (r[0] == "6") CHECK(r[code] == "0123456789ab");
}

// A solver residual (~1e-11) is compared on its own scale (kStoreResidualAbsTol, or
// kStoreResidualRelTol of it): its change from rounding alone (~1e-6 relative on one CPU, 4 %
// after 80 CG iterations on another vector width) is not a change of the numerics; a residual
// that moves by more than that still is.
TEST_CASE("store: residual columns are compared on their own scale", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("r.tsv");
  const std::vector<std::string> cols = {"level", "rel_error", "max_rel_residual"};
  auto study = [&](CacheMode mode, double residual) {
    UnitCache c(f, kParams, cols, 1, mode);
    c.add({"5", fmt(0.125), fmt(residual)});
    c.save();
    c.finish();
  };
  study(CacheMode::run, 6.753016866560343e-11);
  REQUIRE_NOTHROW(study(CacheMode::verify, 6.753015449936592e-11));  // rounding: 2e-6 relative
  REQUIRE_NOTHROW(study(CacheMode::verify, 6.753016866560343e-11 * 1.042));  // another CPU: 4.2 %
  REQUIRE_THROWS_AS(study(CacheMode::verify, 6.753016866560343e-11 * 1.2), StoreMismatch);
  REQUIRE_THROWS_AS(study(CacheMode::verify, 1e-9), StoreMismatch);  // a looser solve
}

// --- issue 58, item 3: --verify by another, cheaper path ------------------------------------
TEST_CASE("store: --verify by another solver or propagator compares at that path's tolerance",
          "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("p.tsv");
  const std::vector<std::string> cols = {"level", "propagator", "rel_error", "cg_mean_iterations"};
  // A file of plain CG (no solver line); a run names its solver, propagator, error and iterations.
  auto study = [&](CacheMode mode, const char* solver, const char* propagator, double err, double its) {
    auto params = kParams;
    if (solver) params.emplace_back("solver", solver);
    UnitCache c(f, params, cols, 1, mode);
    c.add({"5", propagator, fmt(err), fmt(its)});
    c.save();
    c.finish();
  };
  const double e = 0.125;
  study(CacheMode::run, nullptr, "stepped", e, 80);
  // Its own path: the iterations are compared, the error to 1e-9.
  REQUIRE_THROWS_AS(study(CacheMode::verify, nullptr, "stepped", e, 12), StoreMismatch);
  REQUIRE_THROWS_AS(study(CacheMode::verify, nullptr, "stepped", e * (1 + 1e-8), 80), StoreMismatch);
  // Another solver: iterations aside, the error to 1e-6; a 1e-5 edit is still a difference.
  REQUIRE_NOTHROW(study(CacheMode::verify, "tau", "stepped", e * (1 + 1e-7), 12));
  REQUIRE_THROWS_AS(study(CacheMode::verify, "tau", "stepped", e * (1 + 1e-5), 12), StoreMismatch);
  // Another propagator (the row's cell differs): the error to 1e-4; a 1e-3 edit differs.
  REQUIRE_NOTHROW(study(CacheMode::verify, nullptr, "krylov", e * (1 + 1e-5), 0));
  REQUIRE_THROWS_AS(study(CacheMode::verify, nullptr, "krylov", e * (1 + 1e-3), 0), StoreMismatch);
  // Only --verify takes another path: a run or a re-check with another solver is refused.
  REQUIRE_THROWS_AS(study(CacheMode::recheck, "tau", "stepped", e, 12), InputError);
  REQUIRE_THROWS_AS(study(CacheMode::run, "tau", "stepped", e, 12), InputError);
  // A file of the preconditioned solver verified by plain CG: another path as well.
  fs::remove(f);
  study(CacheMode::run, "tau", "stepped", e, 12);
  REQUIRE_NOTHROW(study(CacheMode::verify, nullptr, "stepped", e * (1 + 1e-7), 80));
  REQUIRE_THROWS_AS(study(CacheMode::verify, "tau", "stepped", e * (1 + 1e-7), 12), StoreMismatch);
  REQUIRE_THROWS_AS(study(CacheMode::run, nullptr, "stepped", e, 80), InputError);  // not its file
}

// --- issue 43: nothing the user does loses a stored row ---------------------------------

TEST_CASE("store: the seal covers `checked` too", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  auto tt = TsvTable::load(f);
  tt.rows[1][tt.column("checked")] = "recheck 2026-01-01 of code 0123456789ab: 1 units recomputed";
  tt.save(f);  // the cell edited, the seal left as it was
  REQUIRE_THROWS_AS(run_study(f, CacheMode::census), InputError);
  REQUIRE_THROWS_AS(run_study(f, CacheMode::run), InputError);
  // The seal before it covered `checked` (what `gpm store-seal` migrates): not the seal now.
  auto row = TsvTable::load(f).rows[0];
  CHECK(row_seal_without_checked(row) != row_seal(row, f));
}

TEST_CASE("store: the seal binds a row to its file's name", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv"), g = t.file("s_seed2.tsv");
  run_study(f, CacheMode::run);
  auto row = TsvTable::load(f).rows[0];
  CHECK(row.back() == row_seal(row, f));
  CHECK(row_seal(row, f) == row_seal(row, "elsewhere/s.tsv"));  // the name, not the folder
  CHECK(row_seal(row, f) != row_seal(row, g));
  CHECK(row_seal(row, f) != row_seal_unbound(row));
  // The file copied under another name: its rows are refused there, naming why.
  fs::copy_file(f, g);
  REQUIRE_THROWS_WITH(run_study(g, CacheMode::census), Catch::Contains("pasted from another file"));
  // Rows sealed under the unbound rule (before 2026-12-05): refused, pointing to gpm store-seal.
  auto tt = TsvTable::load(f);
  for (auto& r : tt.rows) r.back() = row_seal_unbound(r);
  tt.save(f);
  REQUIRE_THROWS_WITH(run_study(f, CacheMode::census), Catch::Contains("gpm store-seal"));
}

TEST_CASE("store: a header naming a key twice is refused, not obeyed", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  edit_lines(f, [](const std::string& line) {
    return line.rfind("# seed = ", 0) == 0 ? line + "\n# seed = 2\n" : line + "\n";
  });
  const std::string bad = text_of(f);
  REQUIRE_THROWS_WITH(run_study(f, CacheMode::run), Catch::Contains("names 'seed' twice"));
  REQUIRE_THROWS_AS(run_study(f, CacheMode::census), InputError);
  CHECK(text_of(f) == bad);
  run_study(f, CacheMode::replace);  // only --replace discards it
  CHECK(rows_of(f).size() == 4);
}

TEST_CASE("store: a quick-profile file is a cache for a quick run only", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  auto params = [](const char* profile, const char* seed) {
    return std::vector<std::pair<std::string, std::string>>{
        {"program", "store_test"}, {"profile", profile}, {"seed", seed}};
  };
  auto run = [&](const char* profile, const char* seed, CacheMode mode = CacheMode::run) {
    UnitCache c(f, params(profile, seed), kColumns, 1, mode);
    if (!c.has({"5"}, 1)) c.add({"5", "a", "0.2", "0.1"}), c.save();
  };
  run("quick", "1");
  const std::string quick = text_of(f);
  // A paper run never discards rows without --replace, whatever the header says.
  REQUIRE_THROWS_WITH(run("paper", "1"), Catch::Contains("parameter 'profile' differs"));
  CHECK(text_of(f) == quick);
  REQUIRE_NOTHROW(run("quick", "2"));  // a quick run replaces a quick cache
  CHECK(TsvTable::load(f).get("seed") == "2");
  REQUIRE_NOTHROW(run("paper", "1", CacheMode::replace));
  CHECK(TsvTable::load(f).get("profile") == "paper");
}

TEST_CASE("store: rows of one unit from two runs (a merge) are refused", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  auto tt = TsvTable::load(f);
  tt.rows[0][tt.column("made_on")] = "another machine, 2 threads, 2026-01-01";  // unit 5, row a
  save_resealed(tt, f);
  REQUIRE_THROWS_WITH(run_study(f, CacheMode::census), Catch::Contains("holds rows of two runs"));
  REQUIRE_THROWS_AS(run_study(f, CacheMode::run), InputError);
  run_study(f, CacheMode::replace);  // both copies dropped, the unit recomputed
  const auto again = TsvTable::load(f);
  REQUIRE(again.rows.size() == 4);
  for (auto& r : again.rows) CHECK(r[again.column("made_on")] != "another machine, 2 threads, 2026-01-01");
}

TEST_CASE("store: a removed lock file loses no rows: the lock is taken again and the file merged",
          "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  auto add_unit = [](UnitCache& c, int k) {
    for (const char* w : {"a", "b"}) c.add({std::to_string(k), w, fmt(1.0 / k), "0.1"});
    c.save();
  };
  auto levels_in = [&]() {
    std::set<std::string> l;
    for (auto& r : rows_of(f)) l.insert(r[0]);
    return l;
  };
  SECTION("the second writer is gone when the first saves: merged") {
    UnitCache first(f, kParams, kColumns, 1);
    add_unit(first, 5);
    fs::remove(f + ".lock");
    {
      UnitCache second(f, kParams, kColumns, 1);  // let in by the missing lock
      CHECK(second.has({"5"}, 2));
      add_unit(second, 6);
    }
    add_unit(first, 7);  // the lock taken again, the second writer's unit 6 kept
    CHECK(levels_in() == std::set<std::string>{"5", "6", "7"});
    CHECK(TsvTable::load(f).rows.size() == 6);
  }
  SECTION("the second writer still holds the new lock: the first writes nothing, keeps its rows") {
    UnitCache first(f, kParams, kColumns, 1);
    add_unit(first, 5);
    fs::remove(f + ".lock");
    UnitCache second(f, kParams, kColumns, 1);
    add_unit(second, 6);
    for (const char* w : {"a", "b"}) first.add({"7", w, "0.1", "0.1"});
    REQUIRE_THROWS_WITH(first.save(), Catch::Contains("another process holds the new one"));
    CHECK(levels_in() == std::set<std::string>{"5", "6"});
    bool rescued = false;
    for (auto& e : fs::directory_iterator(t.dir))
      rescued = rescued || e.path().filename().string().find(".rescued-") != std::string::npos;
    CHECK(rescued);
  }
  SECTION("a file rewritten meanwhile by hand (a git checkout): its units merged, not lost") {
    UnitCache first(f, kParams, kColumns, 1);
    add_unit(first, 5);
    auto tt = TsvTable::load(f);
    auto extra = tt.rows;
    for (auto& r : extra) r[0] = "9", r.back() = row_seal(r, f);
    tt.rows.insert(tt.rows.end(), extra.begin(), extra.end());
    tt.save(f);
    add_unit(first, 7);
    CHECK(levels_in() == std::set<std::string>{"5", "7", "9"});
  }
}

TEST_CASE("outputs: a sealed store file is written only by its own study", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  CHECK(sealed_file_program(f) == "store_test");
  CHECK_FALSE(sealed_file_program(t.file("none.tsv")));
  const std::string before = text_of(f);
  REQUIRE_THROWS_WITH(check_output_path("--out", f), Catch::Contains("sealed result-store file of store_test"));
  REQUIRE_NOTHROW(check_output_path("--out", f, "store_test"));
  REQUIRE_THROWS_AS(save_text(f, "x\n"), InputError);
  TsvTable other;
  other.set("program", "another");
  other.columns = {"a"};
  REQUIRE_THROWS_AS(other.save(f), InputError);
  REQUIRE_THROWS_WITH(UnitCache(f, {{"program", "another"}, {"seed", "1"}}, kColumns, 1, CacheMode::replace),
                      Catch::Contains("only that study writes it"));
  CHECK(text_of(f) == before);
}

TEST_CASE("outputs: control characters, read-only files, temp names", "[unit][store]") {
  TempDir t("gpm_store_");
  REQUIRE_THROWS_WITH(check_output_path("--out", t.file("a\nb.tsv")), Catch::Contains("control character"));
  REQUIRE_THROWS_AS(check_output_path("--out", t.file("a\tb.tsv")), InputError);
  // A read-only file is not replaced (the refusal holds for root too: the mode bits decide).
  const std::string ro = t.file("ro.tsv");
  std::ofstream(ro) << "x\n";
  fs::permissions(ro, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  REQUIRE_THROWS_WITH(save_text(ro, "y\n"), Catch::Contains("read-only (mode 0444)"));
  CHECK(text_of(ro) == "x\n");
  // A replaced file keeps its mode.
  const std::string kept = t.file("kept.tsv");
  std::ofstream(kept) << "x\n";
  fs::permissions(kept, fs::perms::owner_read | fs::perms::owner_write);
  save_text(kept, "y\n");
  CHECK(text_of(kept) == "y\n");
  CHECK((fs::status(kept).permissions() & fs::perms::all) == (fs::perms::owner_read | fs::perms::owner_write));
  // Cleanup touches only its own temp names of dead processes, never a user's file.
  for (const char* n : {"o.tsv.tmp.1234567", "o.tsv.gpm-tmp.1234567", "o.tsv.gpm-tmp.1234567.notahexnumber00"})
    std::ofstream(t.file(n)) << "mine\n";
  const std::string stale = t.file("o.tsv.gpm-tmp.999999999.0123456789abcdef");
  std::ofstream(stale) << "left by a killed run\n";
  save_text(t.file("o.tsv"), "z\n");
  for (const char* n : {"o.tsv.tmp.1234567", "o.tsv.gpm-tmp.1234567", "o.tsv.gpm-tmp.1234567.notahexnumber00"})
    CHECK(fs::exists(t.file(n)));
  CHECK_FALSE(fs::exists(stale));
}

TEST_CASE("store: a re-check whose record cannot be logged writes nothing", "[unit][store]") {
  TempDir t("gpm_store_");
  const std::string f = t.file("s.tsv");
  run_study(f, CacheMode::run);
  auto tt = TsvTable::load(f);
  for (auto& r : tt.rows) r[tt.column("code")] = "0123456789ab";  // rows of older code
  save_resealed(tt, f);
  const std::string before = text_of(f);
  fs::create_directory(t.file("rechecks.log"));  // the log cannot be appended to
  REQUIRE_THROWS_WITH(run_study(f, CacheMode::recheck, 0, {5}), Catch::Contains("cannot append to"));
  CHECK(text_of(f) == before);
}

TEST_CASE("store: the header is sealed; an edited line is refused, a missing seal in a store folder too",
          "[unit][store]") {
  TempDir t("gpm_store_");
  fs::create_directories(t.file("results/paper"));
  for (const std::string& f : {t.file("s.tsv"), t.file("results/paper/s.tsv")}) {
    CAPTURE(f);
    run_study(f, CacheMode::run);
    const auto written = TsvTable::load(f);
    REQUIRE(written.get("header_seal"));
    CHECK(header_seal_problem(written.meta, f).empty());
    // The same header under another file's name does not match: the seal binds the name.
    CHECK_FALSE(header_seal_problem(written.meta, t.file("other.tsv")).empty());
    const std::string good = text_of(f);
    // A provenance line no reader compares (issue 61, case 6.3), edited by hand.
    edit_lines(f, [](const std::string& l) {
      return (l.rfind("# git_revision = ", 0) == 0 ? std::string("# git_revision = 000000000000") : l) + "\n";
    });
    REQUIRE(text_of(f) != good);
    REQUIRE_THROWS_AS(run_study(f, CacheMode::verify), InputError);
    REQUIRE_THROWS_AS(run_study(f, CacheMode::census), InputError);
    // The seal line removed: tolerated outside a result store (files written before header
    // seals), refused inside one.
    std::ofstream(f) << good;
    edit_lines(f, [](const std::string& l) { return l.rfind("# header_seal = ", 0) == 0 ? "" : l + "\n"; });
    if (f.find("results/paper") == std::string::npos) {
      REQUIRE_NOTHROW(run_study(f, CacheMode::verify));
    } else {
      try {
        run_study(f, CacheMode::verify);
        FAIL("not refused");
      } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("no header_seal"));
      }
    }
    std::ofstream(f) << good;
    REQUIRE_NOTHROW(run_study(f, CacheMode::verify));
  }
}
