// The finding on the thesis' conjecture (rate_levels.hpp): rates against level judged as
// approaching the theory's, staying away from it, or not decided, on sequences made for each
// branch of the rule.
#include <catch2/catch.hpp>
#include <cmath>

#include "gpm/studies/judge/rate_levels.hpp"

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
