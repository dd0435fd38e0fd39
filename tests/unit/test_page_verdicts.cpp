// Page one's verdict table (src/gpm/studies/judge/page_verdicts.hpp) on small tables in memory: a
// figure drawn from a table joins that table's row whether it is listed before or after it,
// neighbouring illustrations of one document share a row (not across documents, not across
// another row), a rate table's evidence names only the verdicts that occur on each board, the
// data rules read their files (none: not yet computed), and an orphan figure is refused.
#include <catch2/catch.hpp>

#include <map>

#include "gpm/error.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/page_verdicts.hpp"

using namespace gpm;

namespace {

TsvTable table(std::vector<std::string> columns, std::vector<std::vector<std::string>> rows) {
  TsvTable t;
  t.columns = std::move(columns);
  for (auto& r : rows) t.add_row(std::move(r));
  return t;
}

TsvTable items(std::vector<std::vector<std::string>> rows) {
  return table({"document", "item", "shows", "rule", "section"}, std::move(rows));
}

// A score with one row per (table, slice): printed, counted, rates, then the counts
// agrees, non_convergence, in_seed_band, checked_reason, unexplained, not_computed, fingerprint,
// and optionally the setup (default "document").
TsvTable score(std::vector<std::vector<std::string>> rows) {
  TsvTable t;
  t.columns = {"table", "slice", "setup", "printed", "counted", "rates", "agrees", "non_convergence", "in_seed_band",
               "checked_reason", "explained_ours", "near_miss", "pre_asymptotic", "unexplained", "consistent_spread", "undefined",
               "not_computed", "fingerprint", "sign_only"};
  for (auto& r : rows) {
    TsvRow row = t.named_row();
    row["table"] = r[0], row["slice"] = r[1], row["printed"] = r[2], row["counted"] = r[3], row["rates"] = r[4];
    row["agrees"] = r[5], row["non_convergence"] = r[6], row["in_seed_band"] = r[7], row["checked_reason"] = r[8];
    row["unexplained"] = r[9], row["not_computed"] = r[10], row["fingerprint"] = r[11];
    row["setup"] = r.size() > 12 ? r[12] : std::string("document");
    for (const char* c : {"explained_ours", "near_miss", "pre_asymptotic", "consistent_spread", "undefined", "sign_only"})
      row[c] = std::string("0");
    t.add_row(row);
  }
  return t;
}

const PageDataReader kNoData = [](const std::string&) { return std::optional<TsvTable>{}; };

}  // namespace

TEST_CASE("page verdicts: figures join their table's row, illustrations merge", "[page_verdicts]") {
  const TsvTable it = items({{"Doc", "Fig. 1", "particles", "drawn", "ch"},
                             {"Doc", "Fig. 2", "cells", "drawn", "ch"},
                             {"Doc", "Fig. 3", "errors", "as t1", "ch"},
                             {"Doc", "Table 1", "rates", "rates t1", "ch"},
                             {"Doc", "Fig. 4", "errors", "as t1", "ch"},
                             {"Doc", "Fig. 5", "stencil", "drawn", "ch"},
                             {"Other", "Fig. 1", "cells", "drawn", "ch2"}});
  const TsvTable sc = score({{"t1", "all", "yes", "yes", "3", "2", "0", "0", "0", "1", "0", "0"},
                             {"total", "as printed", "yes", "no", "3", "2", "0", "0", "0", "1", "0", "0"}});
  const TsvTable page = page_verdicts(it, sc, kNoData);
  REQUIRE(page.columns == std::vector<std::string>{"document", "item", "shows", "verdict", "evidence", "section"});
  REQUIRE(page.rows.size() == 4);
  CHECK(page.rows[0] == std::vector<std::string>{"Doc", "Fig. 1, Fig. 2", "particles; cells", "reproduced qualitatively",
                                                 "illustrations drawn from the same definitions (no number to compare)",
                                                 "ch"});
  // The figure before the table and the one after it both join; the table's row keeps its place.
  CHECK(page.rows[1][1] == "Table 1, Fig. 3, Fig. 4");
  CHECK(page.rows[1][3] == "partial");
  CHECK(page.rows[1][4] == "both boards: 2 agree, 1 unexplained of 3");
  // An illustration after a table's row starts a row of its own, and so does another document's.
  CHECK(page.rows[2][1] == "Fig. 5");
  CHECK(page.rows[3][0] == "Other");
}

TEST_CASE("page verdicts: the two boards and the rate table's verdict", "[page_verdicts]") {
  // t2: printed and identified boards differ; the counted (identified) row decides.
  const TsvTable sc = score({{"t2", "printed", "yes", "no", "4", "0", "0", "0", "0", "4", "0", "0"},
                             {"t2", "id", "no", "yes", "4", "2", "1", "1", "0", "0", "0", "0"},
                             {"t3", "all", "yes", "yes", "2", "0", "0", "0", "1", "0", "1", "0"},
                             {"t4", "all", "yes", "yes", "2", "0", "0", "0", "1", "1", "0", "0"},
                             {"t5", "all", "yes", "yes", "2", "0", "0", "0", "0", "0", "2", "0"},
                             {"t6", "printed", "yes", "no", "2", "0", "0", "0", "0", "2", "0", "0"},
                             {"t7", "all", "yes", "yes", "2", "1", "0", "0", "0", "0", "0", "1"},
                             // t8: the deciding reading misses; another reading of the text
                             // reproduces every rate (named), a second jitter realization too (not).
                             {"t8", "h15", "yes", "yes", "2", "0", "0", "0", "0", "2", "0", "0"},
                             {"t8", "h10", "no", "no", "2", "2", "0", "0", "0", "0", "0", "0"},
                             {"t8", "h10_seed2", "no", "no", "2", "2", "0", "0", "0", "0", "0", "0",
                              "another jitter realization"},
                             {"t8", "h12", "no", "no", "2", "1", "0", "0", "0", "1", "0", "0"}});
  auto v = [&](const std::string& t) {
    const PageVerdict p = rate_table_verdict(sc, t);
    return p.verdict + " | " + p.evidence;
  };
  CHECK(v("t2") == "reproduced | identified: 2 agree, 1 non-convergence, 1 in seed band of 4; printed: 4 unexplained of 4");
  // A rate that identified the reading (fingerprint) is not one the documents' set-up reproduces.
  CHECK(v("t7") == "partial | both boards: 1 agree, 1 fingerprint of 2");
  CHECK(v("t3") == "not reproduced (reason checked) | both boards: 1 checked reason, 1 not computed of 2");
  CHECK(v("t4") == "open | both boards: 1 checked reason, 1 unexplained of 2");
  CHECK(v("t8") == "open | both boards: 2 unexplained of 2; reproduced under another reading, h10 (seed 1): 2 agree of 2");
  CHECK(v("t5") == "not yet computed | both boards: 2 not computed of 2");
  CHECK(v("t6") == "not yet computed | identified reading not stored; printed: 2 unexplained of 2");
  CHECK(v("t9") == "not yet computed | no rows in the store");
  // A count that is no number is refused, naming the cell.
  TsvTable bad = sc;
  bad.rows[2][bad.column("agrees")] = "many";
  CHECK_THROWS_AS(rate_table_verdict(bad, "t3"), InputError);
}

TEST_CASE("page verdicts: the data rules", "[page_verdicts]") {
  std::map<std::string, TsvTable> files;
  files["koba_sato_cor71.tsv"] = table({"coefficient", "holds"}, {{"a", "1"}, {"b", "0"}, {"c", "1"}});
  files["core_voronoi.tsv"] = table({"level", "distribution", "N"}, {{"5", "jittered", "1521"}, {"5", "plain", "1600"}});
  files["imoto_figs_fig3_discs.tsv"] = table({"distribution", "r_N"}, {{"uniform", "0.14142"}, {"non-uniform", "0.246"}});
  files["core_weights_errata.tsv"] = table({"name", "printed_norm"}, {{"cubic_bspline", "1.38123"}});
  files["core_weights.tsv"] = table({"name", "norm"}, {{"cubic_bspline", "1"}, {"quadratic_spike", "0.9999999"}});
  files["koba_sato_bounds_summary.tsv"] =
      table({"theorem", "cases", "violations", "min_ratio"}, {{"1.3", "10", "0", "4.56789"}, {"1.4", "5", "0", "3.7777"}});
  const PageDataReader data = [&](const std::string& f) -> std::optional<TsvTable> {
    if (!files.count(f)) return std::nullopt;
    return files[f];
  };
  auto v = [&](const std::string& rule) {
    const PageVerdict p = data_rule_verdict(rule, data);
    return p.verdict + " | " + p.evidence;
  };
  CHECK(v("cor71") == "published value wrong | 2 of 3 printed coefficients hold");
  CHECK(v("count") == "reproduced | N = 1521 at Δx = 2⁻⁵ (printed: 1521)");
  CHECK(v("fig3") == "reproduced | covering radius 0.1414 (uniform) against 0.246 (non-uniform), same N");
  CHECK(v("bounds") == "reproduced | bound below the measured error in 0 of 15 cases (smallest bound/error 3.78)");
  CHECK(v("weights cubic_bspline,quadratic_spike") ==
        "published value wrong | the printed formulas, not the drawn curves, are wrong: norm as printed cubic bspline 1.381; norm of the plotted (corrected) weights: "
        "cubic bspline 1, quadratic spike 1");
  CHECK(v("weights quadratic_spike") == "reproduced | norm of the plotted (corrected) weights: quadratic spike 1");
  CHECK(v("covering") == "not yet computed | -");  // its file is not there
  CHECK(v("weights quintic_spline") == "not yet computed | -");
  CHECK(v("oracle 7") == "not yet computed | unknown rule oracle 7");
}

TEST_CASE("page verdicts: a figure of a table without a rates row is refused", "[page_verdicts]") {
  const TsvTable it = items({{"Doc", "Fig. 3", "errors", "as t9", "ch"}});
  CHECK_THROWS_WITH(page_verdicts(it, score({}), kNoData), Catch::Contains("drawn from t9") && Catch::Contains("no rates row"));
  // A missing column of the items is named.
  TsvTable no_rule = table({"document", "item", "shows", "section"}, {});
  CHECK_THROWS_WITH(page_verdicts(no_rule, score({}), kNoData), Catch::Contains("no column 'rule'"));
}
