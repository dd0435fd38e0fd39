// The open rates grouped by cause (src/gpm/studies/judge/open_causes.hpp), on judged rates
// made in memory: another reading first, then a robust gap, the blow-up rate, one realization;
// a jitter realization is never "another reading"; rates that are not open are left out.
#include <catch2/catch.hpp>

#include "gpm/studies/judge/open_causes.hpp"

using namespace gpm;

namespace {

// A judged rate of table t, slice s, key k: published p, ours r; on the identified board
// with verdict v when `board`; band (lo, hi) of n seeds where n > 0.
JudgedRate judged(const std::string& t, const std::string& s, const std::string& k, const std::string& p,
                  const std::string& r, Verdict v = Verdict::not_counted, bool board = false, int n = 0,
                  double lo = 0, double hi = 0) {
  JudgedRate j;
  j.rate.table = t, j.rate.slice = s, j.rate.key = k, j.rate.published = cell_number_or(p, NAN);
  j.rate.reproduced = cell_number_or(r, NAN);
  j.rate.setup = s.find("seed") != std::string::npos ? kJitterSetup : kDocumentSetup;
  j.identified = board, j.verdict = v, j.verdict_identified = v;
  j.band_seeds = n, j.band_lo = lo, j.band_hi = hi;
  return j;
}

}  // namespace

TEST_CASE("open causes: each open rate by the first cause the data show", "[unit][verdicts]") {
  const Verdict U = Verdict::unexplained;
  const std::vector<JudgedRate> all = {
      // below every seed, but the delta-free reading gives it: a set-up question first
      judged("imoto", "all", "Pi1 5", "2", "1.72", U, true, 5, 1.68, 1.72),
      judged("imoto", "cellvol", "Pi1 5", "2", "2.10"),
      // above every seed; the other reading is far: a robust gap, nearest reading named
      judged("imoto", "all", "Pi3 5", "7.41", "9.48", U, true, 5, 9.10, 10.65),
      judged("imoto", "cellvol", "Pi3 5", "7.41", "9.17"),
      judged("imoto", "all", "Grad3 5", "7.69", "9.46", U, true, 5, 9.08, 9.68),
      // a seed near the published rate is a realization, not another reading; 3 seeds decide nothing
      judged("t42", "printed", "spike", "4", "22.4", U, true, 3, 20.0, 23.0),
      judged("t42", "printed_seed2", "spike", "4", "4.01"),
      // only the sign agrees
      judged("t46", "h10", "q 0", "-281", "-37.5", Verdict::sign_only, true),
      // not open: left out
      judged("t46", "h10", "q 1", "2", "2.01", Verdict::agrees, true),
      judged("t46", "h15", "q 0.5", "4.3", "2.5", U, false),
  };
  CHECK(open_cause(all[0], all, 0.15).cause == "another reading gives it: cellvol");
  CHECK(open_cause(all[0], all, 0.15).evidence ==
        "published 2, ours 1.72, band 1.68 to 1.72 (5 seeds); nearest other reading cellvol 2.10");
  CHECK(open_cause(all[2], all, 0.15).cause == "robust gap: every realization above the published rate");
  CHECK(open_cause(all[2], all, 0.15).evidence.find("nearest other reading cellvol 9.17") != std::string::npos);
  CHECK(open_cause(all[5], all, 0.15).cause == "one realization: too few seeds to tell");
  CHECK(open_cause(all[7], all, 0.15).cause == "blow-up rate: both unstable, sign only");

  const TsvTable t = open_causes(all, 0.15);
  REQUIRE(t.rows.size() == 4);
  CHECK(t.text(0, "cause") == "another reading gives it: cellvol");
  CHECK(t.text(1, "rates") == "2");
  CHECK(t.text(1, "keys") == "Pi3 5, Grad3 5");
  CHECK(t.text(2, "table") == "t42");
  CHECK(t.text(3, "keys") == "q 0");
  // Below the band on the other side: the word follows the data.
  JudgedRate low = judged("imoto", "all", "Grad1 5", "2.02", "1.76", U, true, 5, 1.65, 1.76);
  CHECK(open_cause(low, {low}, 0.15).cause == "robust gap: every realization below the published rate");
}
