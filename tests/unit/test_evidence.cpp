// The judges' typed evidence (judge/evidence.hpp): a table's series by key, only finite and
// positive errors kept; a rate between two stored levels, NaN where one is missing; the error
// constant e/h^p.
#include <catch2/catch.hpp>

#include <cmath>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/evidence.hpp"

using namespace gpm;

TEST_CASE("evidence: series by key, rates between stored levels, error constants", "[unit][judge]") {
  TsvTable t;
  t.columns = {"weight", "theta", "level", "h", "rel_error"};
  t.rows = {{"a", "0.5", "5", "0.2", "0.04"},  {"a", "0.5", "6", "0.1", "0.01"},
            {"a", "0.5", "7", "0.05", "NA"},   {"a", "1", "5", "0.2", "0"},
            {"b", "0.5", "5", "0.2", "0.08"}};
  const EvidenceSeriesMap m = read_series(t, {"weight", "theta"});
  REQUIRE(m.size() == 2);  // (a, 1) holds no positive error: no series
  const EvidenceSeries& s = m.at({"a", "0.5"});
  REQUIRE(s.size() == 2);  // level 7's NA left out
  CHECK(series_rate(s, 5, 6) == Approx(2.0));
  CHECK(std::isnan(series_rate(s, 6, 7)));
  CHECK(error_constant(s.at(6), 2) == Approx(1.0));
  t.columns[3] = "radius";
  CHECK_THROWS(read_series(t, {"weight", "theta"}));  // no h column: refused, not guessed
}
