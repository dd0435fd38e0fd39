// The study runner (src/gpm/studies/run/runner.hpp): the common options, the levels of a run, a
// study of two units written, reused by a second run and checked by --verify, several data
// files from one run, and a pass split into saved parts (--parts).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/run/runner.hpp"
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
  UnitCache& cache = run.open({{"program", "runner_test"}, {"seed", fmt(static_cast<long long>(run.seed()))}},
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
    // A study that names its particle sets itself has no --seed and no --parts, and is still
    // cached per unit (--verify).
    StudyRunner run("runner_test", "test study", "quick or paper", StudyRunner::Kind::units_without_seed);
    REQUIRE_THROWS_AS(parse(run, {"runner_test", "--out", "x.tsv", "--seed", "2"}), InputError);
  }
  {
    StudyRunner run("runner_test", "test study", "quick or paper", StudyRunner::Kind::units_without_seed);
    parse(run, {"runner_test", "--out", "x.tsv", "--verify"});
    CHECK(run.mode() == CacheMode::verify);
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
  const std::vector<UnitCache*> c = run.open_files(
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

// --parts K: a shared pass split into K parts on one process, each saved as it finishes
// (<out>.parts/), so that an interrupted unit resumes from its last saved part; the merged
// result is bitwise the one pass over all targets, and the parts go once the unit is written.
namespace {
struct PassSetup {
  Particles p = jittered_grid(std::ldexp(1.0, -5), 2);
  std::vector<double> V = std::vector<double>(p.size(), std::ldexp(1.0, -10));
  std::vector<ErrorRequest> req = {{"quartic_polynomial", Operator::interp},
                                   {"piecewise_cubic_polynomial", Operator::lap}};
  std::vector<std::string> fns = {"sin2pi"};
  double h = 0.15;
};
// One unit (level 5) through shared_pass; `calls` counts the parts computed; a part numbered
// `fail_at` throws (an interrupted run).
ErrorMaxima run_parts(const std::string& out, const std::string& parts, int& calls, int fail_at = -1) {
  static const PassSetup s;
  StudyRunner run("runner_test", "test study", "quick or paper");
  parse(run, {"runner_test", "--out", out, "--parts", parts});
  UnitCache& cache = run.open({{"program", "runner_test"}}, {"level", "rel_error", "time_s"}, 1);
  ErrorMaxima m;
  if (!cache.has({"5"}) && run.claim_shared()) {
    m = run.shared_pass("level 5/one", [&](TargetShare t) {
      if (t.part == fail_at) throw NumericalError("interrupted at part " + fmt(t.part));
      ++calls;
      return fused_error_maxima(s.p, s.V, s.h, s.req, s.fns, true, t);
    });
    cache.add({"5", fmt(m.error.at(0)), "0.5"});
    run.unit_done(1, "level 5");
  }
  run.finish();
  return m;
}
}  // namespace

TEST_CASE("runner: --parts saves a pass part by part and resumes it", "[unit][runner][parts]") {
  TempDir t("gpm_runner_parts_");
  const PassSetup s;
  const ErrorMaxima whole = fused_error_maxima(s.p, s.V, s.h, s.req, s.fns);
  const std::string out = t.file("p.tsv"), dir = out + ".parts";
  int calls = 0;
  // Interrupted at the third of four parts: the first two are saved, no row is written.
  CHECK_THROWS_AS(run_parts(out, "4", calls, 2), NumericalError);
  CHECK(calls == 2);
  CHECK(std::filesystem::exists(dir + "/level_5_one.0of4.tsv"));
  CHECK(std::filesystem::exists(dir + "/level_5_one.1of4.tsv"));
  CHECK_FALSE(std::filesystem::exists(out));
  // Resumed: only the last two parts are computed, and the merged maxima are the one pass's.
  calls = 0;
  const ErrorMaxima m = run_parts(out, "4", calls);
  CHECK(calls == 2);
  CHECK(m.error == whole.error);
  CHECK(m.exact == whole.exact);
  CHECK(m.worst == whole.worst);
  CHECK(m.pairs == whole.pairs);
  // The unit's row is written: its parts are gone.
  CHECK(TsvTable::load(out).text(0, "rel_error") == fmt(whole.error.at(0)));
  CHECK(std::filesystem::is_empty(dir));
  // Parts of another split are not reused: a run of 3 parts computes all 3.
  std::filesystem::remove(out);
  CHECK_THROWS_AS(run_parts(out, "4", calls = 0, 3), NumericalError);
  calls = 0;
  CHECK(run_parts(out, "3", calls).error == whole.error);
  CHECK(calls == 3);
  // A bad count is refused by name.
  for (const char* bad : {"0", "x", "-2", ""}) {
    StudyRunner run("runner_test", "test study", "quick or paper");
    CHECK_THROWS_WITH(parse(run, {"runner_test", "--out", out, "--parts", bad}),
                      Catch::Contains("--parts '" + std::string(bad) + "'"));
  }
}

TEST_CASE("runner: a part file edited or cut is named and computed again", "[unit][runner][parts]") {
  TempDir t("gpm_runner_parts_");
  const PassSetup s;
  const ErrorMaxima whole = fused_error_maxima(s.p, s.V, s.h, s.req, s.fns);
  const std::string out = t.file("p.tsv"), part = out + ".parts/level_5_one.0of4.tsv";
  int calls = 0;
  CHECK_THROWS_AS(run_parts(out, "4", calls, 2), NumericalError);  // parts 0 and 1 saved
  REQUIRE(std::filesystem::exists(part));
  // Part 0 loses its last row (or has a number changed): its seal no longer matches.
  TsvTable p = TsvTable::load(part);
  REQUIRE(p.get("seal"));
  p.rows.pop_back();
  std::filesystem::remove(part);
  p.save(part);
  calls = 0;
  const ErrorMaxima m = run_parts(out, "4", calls);
  CHECK(calls == 3);  // part 0 again, and parts 2 and 3
  CHECK(m.error == whole.error);
  CHECK(m.worst == whole.worst);
}
