// The finding on the thesis' conjecture (rate_levels.hpp): rates against level judged as
// approaching the theory's, staying away from it, or not decided, on sequences made for each
// branch of the rule; and the view of Table 4.4 read from a fixture store.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/judge/rate_levels.hpp"
#include "../temp_dir.hpp"

using namespace gpm;

TEST_CASE("rate levels: the trend rule, branch by branch", "[unit][rate_levels]") {
  const double tol = 0.15;
  // The last two within the tolerance of 2.
  CHECK(judge_trend({3.1, 2.1, 1.95}, 2, false, tol).trend == Trend::approaches);
  // Falling distance over the last three, the last within 0.3 (but the one before is not within tol).
  CHECK(judge_trend({3.4, 2.6, 2.25}, 2, true, tol).trend == Trend::approaches);
  // Falling, but the last still 0.5 away: a level further decides.
  const TrendFinding open = judge_trend({4.0, 3.0, 2.5}, 2, true, tol);
  CHECK(open.trend == Trend::not_decided);
  CHECK(open.why.find("a level further") != std::string::npos);
  // Beyond the documents, far and not nearer than before: stays away, with the number.
  const TrendFinding away = judge_trend({7.6, 6.9, 5.3, 5.4}, 2, true, tol);
  CHECK(away.trend == Trend::stays_away);
  CHECK(away.why.find("5.40") != std::string::npos);
  // Nearer by less than the tolerance still counts as not nearer.
  CHECK(judge_trend({7.0, 5.3, 5.2}, 2, true, tol).trend == Trend::stays_away);
  // Far, but nothing stored beyond the documents' levels: not decided, and why.
  const TrendFinding none = judge_trend({7.6, 6.9, 5.3}, 2, false, tol);
  CHECK(none.trend == Trend::not_decided);
  CHECK(none.why.find("beyond the documents") != std::string::npos);
  // Too few pairs, or a rate that is not a number.
  CHECK(judge_trend({2.0}, 2, true, tol).trend == Trend::not_decided);
  CHECK(judge_trend({2.0, std::nan("")}, 2, true, tol).trend == Trend::not_decided);
  CHECK(trend_name(Trend::stays_away) == "stays away");
}

TEST_CASE("rate levels: a band at the finest pair must agree with seed 1", "[unit][rate_levels]") {
  const double tol = 0.15;
  // Seed 1 approaches; the band's far end within 0.3 keeps it, and the why names the band.
  const TrendFinding kept = judge_trend({3.4, 2.6, 2.25}, 2, true, tol, {2.1, 2.29});
  CHECK(kept.trend == Trend::approaches);
  CHECK(kept.why.find("2.10 to 2.29") != std::string::npos);
  // A realization 0.35 off: not decided, saying how far.
  const TrendFinding spread = judge_trend({3.4, 2.6, 2.25}, 2, true, tol, {2.2, 2.35});
  CHECK(spread.trend == Trend::not_decided);
  CHECK(spread.why.find("0.35") != std::string::npos);
  // Below the theory counts the same as above.
  CHECK(judge_trend({3.1, 2.1, 1.95}, 2, false, tol, {1.65, 2.0}).trend == Trend::not_decided);
  // Stays away only if every realization is beyond the reach; a band holding the theory's
  // rate is not decided.
  CHECK(judge_trend({7.6, 6.9, 5.3, 5.4}, 2, true, tol, {4.9, 5.6}).trend == Trend::stays_away);
  CHECK(judge_trend({7.6, 6.9, 5.3, 5.4}, 2, true, tol, {1.9, 5.6}).trend == Trend::not_decided);
  CHECK(judge_trend({7.6, 6.9, 5.3, 5.4}, 2, true, tol, {2.25, 5.6}).trend == Trend::not_decided);
  // Not decided by seed 1 stays not decided whatever the band.
  CHECK(judge_trend({4.0, 3.0, 2.5}, 2, true, tol, {2.0, 2.1}).trend == Trend::not_decided);
}

namespace {

// A store file of (key columns, level, h, rel_error) rows: per series the errors at levels
// from `first` on with h halving per level, so the rate of the pair (k, k+1) is rates[k - first].
void write_series(std::ofstream& f, const std::string& key, int first, const std::vector<double>& rates) {
  double h = 1, e = 1;
  f << key << "\t" << first << "\t" << h << "\t" << e << "\n";
  for (std::size_t i = 0; i < rates.size(); ++i) {
    h /= 2, e /= std::exp2(rates[i]);
    f << key << "\t" << first + static_cast<int>(i) + 1 << "\t" << h << "\t" << e << "\n";
  }
}

}  // namespace

TEST_CASE("rate levels: Table 4.4 on a fixture store, one level past the thesis", "[unit][rate_levels]") {
  TempDir tmp("gpm_rate_levels_");
  const StudyRegistry& reg = study_registry();
  // The heat tables' files the view reads, empty: only Table 4.4 is judged here.
  for (const HeatTable& hp : heat_tables())
    for (const char* reading : {"h10", "h15_cell_exact"})
      std::ofstream(tmp.dir / (reg.study(heat_study_name(hp)).store_file_of(reading).name + ".tsv"))
          << "weight\ttheta\tlevel\th\trel_error\n";
  const RegisteredStudy& poisson = reg.study("thesis_table4_4");
  const std::string columns = "h_rule\tweight\tlevel\th\trel_error\n";
  {
    // Seed 1 (V_i = dx^2): levels 5-10, the thesis' pair 8/9, one pair beyond it.
    std::ofstream f(tmp.dir / (poisson.store_file_of("h15_cell").name + ".tsv"));
    f << columns;
    write_series(f, "h10\tquartic_polynomial", 5, {3.0, 2.2, 2.1, 2.05, 2.01});        // approaches
    write_series(f, "h15\tpiecewise_quintic_polynomial", 5, {9.0, 6.9, 5.3, 5.4, 5.4});  // stays away
    write_series(f, "h15\tquartic_polynomial", 5, {7.0, 5.0, 3.0, 2.6});                // levels 5-9 only
    write_series(f, "h10\tpiecewise_quintic_polynomial", 5, {3.0, 2.2, 2.1, 2.05, 2.01});  // seed 2 disagrees
  }
  {
    // A second realization of the quartic and the quintic under h10 at the thesis' pair and the one beyond.
    std::ofstream f(tmp.dir / "thesis_table4_4_cellvol_seed2.tsv");
    f << columns;
    write_series(f, "h10\tquartic_polynomial", 8, {2.3, 1.9});
    write_series(f, "h10\tpiecewise_quintic_polynomial", 8, {2.3, 2.4});
  }
  const RateLevels r = rate_levels(StoreSnapshot(tmp.dir.string()), std::string(GPM_SOURCE_DIR) + "/tables/published");
  auto finding = [&](const std::string& reading, const std::string& w) {
    for (std::size_t i = 0; i < r.findings.rows.size(); ++i)
      if (r.findings.text(i, "table") == "4.4" && r.findings.text(i, "reading") == reading &&
          r.findings.text(i, "weight") == w)
        return r.findings.text(i, "finding");
    return std::string("absent");
  };
  CHECK(finding("h10_cell", "quartic_polynomial") == "approaches");
  CHECK(finding("h15_cell", "piecewise_quintic_polynomial") == "stays away");
  CHECK(finding("h15_cell", "quartic_polynomial") == "not decided");
  CHECK(finding("h10_cell", "piecewise_cubic_polynomial") == "absent");  // no stored series
  // Seed 1 approaches, but the second realization's finest rate is 0.4 off.
  CHECK(finding("h10_cell", "piecewise_quintic_polynomial") == "not decided");
  // The thesis' pair carries the published rate (1.95) and the band of both realizations; the
  // pair past it is marked beyond the documents.
  int seen = 0;
  for (std::size_t i = 0; i < r.rates.rows.size(); ++i) {
    if (r.rates.text(i, "reading") != "h10_cell" || r.rates.text(i, "weight") != "quartic_polynomial") continue;
    const std::string pair = r.rates.text(i, "pair");
    if (pair == "2^-8/2^-9") {
      ++seen;
      CHECK(r.rates.number(i, r.rates.require_column("rate")) == Approx(2.05));
      CHECK(r.rates.number(i, r.rates.require_column("published")) == Approx(1.95));
      CHECK(r.rates.number(i, r.rates.require_column("band_hi")) == Approx(2.3));
      CHECK(r.rates.text(i, "seeds") == "2");
      CHECK(r.rates.text(i, "where") == "document");
    }
    if (pair == "2^-9/2^-10") {
      ++seen;
      CHECK(r.rates.number(i, r.rates.require_column("band_lo")) == Approx(1.9));
      CHECK(r.rates.text(i, "where") == "beyond");
    }
  }
  CHECK(seen == 2);
  // The documents' pair comes from the published file only: one without its rate_levels line
  // is refused, not judged at a typed default pair.
  const auto pub = tmp.dir / "published";
  std::filesystem::copy(std::string(GPM_SOURCE_DIR) + "/tables/published", pub);
  const auto table = pub / "thesis_table4_4_long.tsv";
  std::string kept, line;
  for (std::ifstream in(table); std::getline(in, line);)
    if (line.rfind("# rate_levels", 0) != 0) kept += line + "\n";
  std::ofstream(table) << kept;
  CHECK_THROWS_WITH(rate_levels(StoreSnapshot(tmp.dir.string()), pub.string()), Catch::Contains("rate_levels"));
}
