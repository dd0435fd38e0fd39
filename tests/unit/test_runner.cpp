// The study runner (src/gpm/studies/runner.hpp): the common options, the levels of a run, and
// a study of two units written, reused by a second run and checked by --verify.
#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/runner.hpp"
#include "../temp_dir.hpp"

using namespace gpm;

namespace {

// Runs StudyRunner::parse on a command line given as words (argv[0] first).
void parse(StudyRunner& run, std::vector<std::string> words) {
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  run.parse(static_cast<int>(argv.size()), argv.data());
}

// A study of levels 5 and 6, one row each (rel_error = 1/k); returns how many units it computed.
int run_study(const std::string& out, const std::string& mode_flag = "") {
  StudyRunner run("runner_test", "test study", "quick or paper");
  std::vector<std::string> words = {"runner_test", "--out", out};
  if (!mode_flag.empty()) words.push_back(mode_flag);
  parse(run, words);
  LevelCache& cache = run.open({{"program", "runner_test"}, {"seed", fmt(static_cast<long long>(run.seed()))}},
                               {"level", "rel_error", "time_s"}, 1);
  int computed = 0;
  for (int k : run.levels({5, 6}, {5, 6, 7})) {
    if (cache.has({fmt(k)})) continue;
    cache.add({fmt(k), fmt(1.0 / k), "0.5"});
    run.unit_done(1, "level " + fmt(k));
    ++computed;
  }
  run.finish();
  return computed;
}

}  // namespace

TEST_CASE("runner: common options and the levels of a run", "[unit][runner]") {
  {
    StudyRunner run("runner_test", "test study", "quick or paper");
    parse(run, {"runner_test", "--out", "x.tsv", "--profile", "paper", "--seed", "3"});
    CHECK(run.out() == "x.tsv");
    CHECK(run.profile() == Profile::paper);
    CHECK(run.seed() == 3);
    CHECK_FALSE(run.levels_given());
    CHECK(run.levels({5, 6}, {5, 6, 7}) == std::vector<int>{5, 6, 7});
  }
  {
    StudyRunner run("runner_test", "test study", "quick or paper");
    parse(run, {"runner_test", "--out", "x.tsv", "--levels", "8,6"});
    CHECK(run.levels_given());
    CHECK(run.levels({5, 6}, {5, 6, 7}) == std::vector<int>{8, 6});
  }
  {
    StudyRunner run("runner_test", "test study", "quick or paper");
    REQUIRE_THROWS_WITH(parse(run, {"runner_test"}), "--out PATH is required (see --help)");
  }
  {
    StudyRunner run("runner_test", "test study", "quick or paper");
    REQUIRE_THROWS_AS(parse(run, {"runner_test", "--out", "x.tsv", "--seed", "-1"}), InputError);
  }
  {
    // A study that is not cached per unit has neither --seed nor --verify.
    StudyRunner run("runner_test", "test study", "quick or paper", StudyRunner::Kind::whole_table);
    REQUIRE_THROWS_AS(parse(run, {"runner_test", "--out", "x.tsv", "--verify"}), InputError);
  }
}

TEST_CASE("runner: units written with wall time and memory, reused, verified", "[unit][runner]") {
  TempDir t("gpm_runner_");
  const std::string f = t.file("r.tsv");
  CHECK(run_study(f) == 2);
  const TsvTable tab = TsvTable::load(f);
  REQUIRE(tab.rows.size() == 2);
  CHECK(tab.text(1, "rel_error") == fmt(1.0 / 6));
  CHECK(tab.get("wall_time_s").has_value());
  CHECK(tab.get("peak_rss_mib").has_value());
  CHECK(run_study(f) == 0);           // every unit reused
  CHECK(run_study(f, "--verify") == 2);  // verify recomputes, and agrees (no throw)
}

// Several data files from one run (thesis_heat's readings): each file cached, written and
// verified as open()'s one; a unit of one file missing recomputes that file's unit only; a
// difference in any file fails --verify, after every file was compared.
namespace {
int run_two(const std::string& a, const std::string& b, const std::string& mode_flag = "",
            double b_value = 2) {
  StudyRunner run("runner_test", "test study", "quick or paper");
  std::vector<std::string> words = {"runner_test", "--out", a};
  if (!mode_flag.empty()) words.push_back(mode_flag);
  parse(run, words);
  const std::vector<LevelCache*> c = run.open_files(
      {{a, {{"program", "runner_test"}, {"variant", "a"}}}, {b, {{"program", "runner_test"}, {"variant", "b"}}}},
      {"level", "rel_error", "time_s"}, 1);
  int computed = 0;
  for (int k : run.levels({5, 6}, {5, 6, 7}))
    for (std::size_t f = 0; f < 2; ++f) {
      if (c[f]->has({fmt(k)})) continue;
      run.add(f, {fmt(k), fmt((f == 0 ? 1.0 : b_value) / k), "0.5"});
      run.unit_done(1, "level " + fmt(k));
      ++computed;
    }
  run.finish();
  return computed;
}
}  // namespace

TEST_CASE("runner: one run, several data files", "[unit][runner]") {
  TempDir t("gpm_runner_");
  const std::string a = t.file("a.tsv"), b = t.file("b.tsv");
  CHECK(run_two(a, b) == 4);
  const TsvTable ta = TsvTable::load(a), tb = TsvTable::load(b);
  REQUIRE(ta.rows.size() == 2);
  REQUIRE(tb.rows.size() == 2);
  CHECK(ta.get("variant") == std::optional<std::string>("a"));
  CHECK(tb.get("variant") == std::optional<std::string>("b"));
  CHECK(tb.text(1, "rel_error") == fmt(2.0 / 6));
  CHECK(run_two(a, b) == 0);             // every unit of both files reused
  CHECK(run_two(a, b, "--verify") == 4);  // both verified, agree
  CHECK_THROWS_AS(run_two(a, b, "--verify", 3), StoreMismatch);  // b differs
  CHECK_THROWS_AS(run_two(a, a), InputError);                     // one file named twice
}
