// Adding a study is one registry entry plus its unit body (docs/reference.md, "How to add"): this test
// registers a small example study beside the package's and checks that every part that
// should know it does, with no other file touched — the catalog (`gpm study`), the runner
// (its levels, columns, cache), the plan, the make rules (build/studies.mk, its figure's too) and the
// verdicts (store rates, boards).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/volumes.hpp"
#include "cli/make_rules.hpp"
#include "gpm/io/args.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/studies/judge/rates.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/plan/study_plan.hpp"
#include "gpm/studies/run/runner.hpp"
#include "gpm/studies/judge/verdicts.hpp"

using namespace gpm;
namespace fs = std::filesystem;

namespace {

double example_h(int k) { return 3.1 * std::ldexp(1.0, -k); }

// The entry: the interpolant of sin 2π(x+y) with the quartic weight on the plain grid,
// h = 3.1 Δx, judged against a made-up "published" rate of 2 (the smoothing order).
RegisteredStudy example_study() {
  RegisteredStudy s;
  s.name = s.program = "example_interpolant";
  s.item = "example: the interpolant's error on the plain grid";
  s.group = "example";
  s.levels = {{4, 5}, {4, 5, 6}};
  s.columns = {"weight", "level", "h", "rel_error", "pairs", "time_s"};
  s.recheck_levels = {4};
  s.files = {{.name = "example_interpolant",
              .rates = {{.name = "example_interpolant_rates", .input = "example_interpolant", .scored = true}}}};
  s.store_files = {{.name = "example_interpolant", .slice = "all", .coarse = {"--levels", "4"}}};
  s.published = PublishedRates{.table = "example_table", .file = "example_table.tsv", .key = {"weight"},
                               .printed_slice = "all"};
  s.figures = {{.name = "example_fig"}};
  // Its units: one fused pass per level, which the program runs and the plan prices.
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> u;
    for (int k : scope.levels) u.push_back({k, example_h(k), {"quartic_polynomial", fmt(k)}, "quartic"});
    return u;
  };
  s.price = [](UnitPricer& p, const StudyUnit& u) {
    p.add_fused("example_interpolant", u.variant, u.level, u.h, "imoto9");
  };
  s.recorded = [](const std::string&, const TsvTable& d, const PlannedPairs&, RecordedUnits& out) {
    for (std::size_t i = 0; i < d.rows.size(); ++i)
      out[{"quartic", static_cast<int>(d.number(i, d.require_column("level")))}] = {d.number(i, d.require_column("time_s")), d.number(i, d.require_column("pairs"))};
  };
  return s;
}

// The unit body, as the study's program would run it: one fused pass per level.
void run_example(const RegisteredStudy& s, const std::vector<std::string>& argv_text) {
  std::vector<std::string> text = argv_text;
  std::vector<char*> argv;
  for (auto& a : text) argv.push_back(a.data());
  StudyRunner run(s, "Example study: the interpolant's error on the plain grid.");
  run.parse(static_cast<int>(argv.size()), argv.data());
  UnitCache& cache = run.open({{"program", s.program}, {"seed", "1"}}, 2);
  for (const StudyUnit& u : run.units()) {
    if (cache.has(u.key) || !run.claim()) continue;
    const double dx = std::ldexp(1.0, -u.level);
    const Particles p = jittered_grid(dx, 1, 0.0);
    const FusedErrors e = fused_errors(p, uniform_volumes(p), u.h, {{"quartic_polynomial", Operator::interp}}, {"sin2pi"});
    TsvRow row = run.row();
    row["weight"] = "quartic_polynomial", row["level"] = fmt(u.level), row["h"] = fmt(u.h);
    row["rel_error"] = fmt(e.errors.at(0).rel_error), row["pairs"] = fmt(e.pairs);
    row["time_s"] = fmt(e.kernel_seconds);
    run.add(row);
    run.unit_done(0, "level " + fmt(u.level));
  }
  run.finish();
}

// The package's registry with the example added last.
StudyRegistry with_example() {
  StudyRegistry r = study_registry();
  r.add(example_study());
  return r;
}

}  // namespace

TEST_CASE("registry example: the catalog and the runner take the study from its entry", "[unit][registry]") {
  const StudyRegistry reg = with_example();
  const RegisteredStudy& s = reg.study("example_interpolant");
  CHECK(s.header().size() == s.columns.size() + row_provenance_columns().size());
  CHECK(reg.study_of_file("example_interpolant").name == "example_interpolant");
  CHECK_THROWS_AS(reg.study("example_interpolant_x"), InputError);
  // A second entry under the same name or writing the same file is refused.
  StudyRegistry twice = reg;
  CHECK_THROWS_AS(twice.add(example_study()), InputError);

  const fs::path dir = fs::temp_directory_path() / ("gpm_example_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string out = (dir / "example_interpolant.tsv").string();
  run_example(s, {"example_interpolant", "--profile", "quick", "--out", out});
  TsvTable d = TsvTable::load(out);
  REQUIRE(d.rows.size() == 2);  // the entry's quick levels 4, 5
  CHECK(d.text(0, "level") == "4");
  CHECK(d.text(1, "level") == "5");
  CHECK(d.columns == s.header());
  // A rerun finds both units cached and adds only the one more level it is asked for.
  run_example(s, {"example_interpolant", "--levels", "4,5,6", "--out", out});
  d = TsvTable::load(out);
  REQUIRE(d.rows.size() == 3);
  CHECK(d.text(2, "level") == "6");

  SECTION("the verdicts judge its stored rows against its published rate") {
    const fs::path pub = dir / "published";
    fs::create_directories(pub);
    for (auto& e : fs::directory_iterator(std::string(GPM_SOURCE_DIR) + "/tables/published"))
      fs::copy_file(e.path(), pub / e.path().filename(), fs::copy_options::overwrite_existing);
    std::ofstream(pub / "example_table.tsv") << "# rate_levels = 5,6\nweight\tnumerical\nquartic_polynomial\t2\n";
    const std::vector<StoreRate> rates = store_rates(StoreSnapshot(dir.string()), pub.string(), kRateTolerance, reg);
    REQUIRE(rates.size() == 1);  // the store holds the example's file only
    CHECK(rates[0].table == "example_table");
    CHECK(rates[0].levels == "5,6");
    const auto judged = judge_rates(rates, {}, {}, kRateTolerance, std::nullopt, reg);
    REQUIRE(judged.size() == 1);
    CHECK(judged[0].printed);
    CHECK(judged[0].verdict != Verdict::not_counted);
    // The printed board: the example's one rate beside every package table not computed.
    const TsvTable score = score_table(judged, pub.string(), reg);
    const TsvTable score_without = score_table({}, pub.string());
    const auto total = [](const TsvTable& t) {
      for (std::size_t i = 0; i < t.rows.size(); ++i)
        if (t.text(i, "table") == "total" && t.text(i, "slice") == "as printed") return t.number(i, t.require_column("rates"));
      return -1.0;
    };
    CHECK(total(score) == total(score_without) + 1);
  }
  fs::remove_all(dir);
}

TEST_CASE("registry example: the plan prices it and make gets its rules", "[unit][registry]") {
  const StudyRegistry reg = with_example();
  Calibration c;
  c.fused["imoto9"] = {1e-7, 1e-8};
  c.base_mib = 10;
  StudyRegistry only;
  only.add(example_study());
  const auto units = plan_units(Profile::paper, c, only);
  REQUIRE(units.size() == 3);
  // The plan prices the units the program runs: the entry's, level by level.
  for (std::size_t i = 0; i < units.size(); ++i) {
    CHECK(units[i].study == "example_interpolant");
    CHECK(units[i].level == 4 + static_cast<int>(i));
    CHECK(units[i].h == example_h(units[i].level));
    CHECK(units[i].time_s > 0);
  }
  const std::string mk = make_rules(reg);
  CHECK(mk.find("STUDIES_example := example_interpolant\n") != std::string::npos);
  CHECK(mk.find("$(DATA)/example_interpolant.tsv: $(BUILD)/example_interpolant\n") != std::string::npos);
  CHECK(mk.find("$(call store_recheck,$<,4)") != std::string::npos);
  CHECK(mk.find("$(DATA)/example_interpolant_rates.tsv: $(BUILD)/rate_table $(DATA)/example_interpolant.tsv "
                "tables/published/example_table.tsv\n") != std::string::npos);
  // Its figure, from the run's data and from the store.
  CHECK(mk.find("FIGFILES += $(FIGOUT)/example_fig.svg $(FIGOUT)/store_example_fig.svg\n") != std::string::npos);
  CHECK(mk.find("$(FIGOUT)/example_fig.svg: figures/example_fig.gp figures/style.gp $(DATA)/example_interpolant.tsv "
                "tables/published/example_table.tsv\n") != std::string::npos);
  CHECK(mk.find("$(FIGOUT)/store_example_fig.svg: figures/example_fig.gp figures/style.gp $(STORE)/example_interpolant.tsv "
                "tables/published/example_table.tsv\n") != std::string::npos);
  // On the front page's scoreboard list, after the package's own.
  const auto scored = mk.find("STUDY_SCORED_RATES := ");
  REQUIRE(scored != std::string::npos);
  const std::string line = mk.substr(scored, mk.find('\n', scored) - scored);
  CHECK(line.ends_with(" example_interpolant_rates"));
  // The package's rules are the registry's alone: without the example, nothing of it.
  CHECK(make_rules(study_registry()).find("example") == std::string::npos);
}
