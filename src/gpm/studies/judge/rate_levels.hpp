// Rates against level: the thesis' conjecture tested (issue 40).  For Tables 4.5–4.7 the
// thesis finds rates far from Theorem 3.7's and suggests its levels were not yet asymptotic.
// This computes, per table, reading (the printed h10 and the identified h15_cell_exact),
// weight and θ (and for Table 4.4, the Poisson problem, per h rule with V_i = Δx² and
// weight: readings h10_cell and h15_cell, θ NA), the two-level rate log(e₁/e₂)/log(h₁/h₂) at every consecutive pair of stored
// levels, the band over the stored jitter realizations of that pair (seed 1 and every
// `<file>_seedN`), the published rate at the documents' pair and the theory's rate, and a
// finding per series:
//   approaches    the last two rates within the tolerance of the theory's, or the distance
//                 to it falling over the last three with the last within 0.3;
//   stays away    the finest pair lies beyond the documents, its rate is more than 0.3 from
//                 the theory's and no nearer than the pair before (by the tolerance);
//   not decided   otherwise, with what would decide it.
// Where other jitter realizations hold the finest pair, a verdict must hold for all of them:
// "approaches" needs the band's far end there within 0.3 of the theory's, "stays away" its near
// end beyond 0.3; a band straddling the reach is not decided (the band names the spread).
// Everything is read from the result store; nothing is run.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/snapshot.hpp"

namespace gpm {

enum class Trend { approaches, stays_away, not_decided };
std::string trend_name(Trend t);  // "approaches", "stays away", "not decided"

struct TrendFinding {
  Trend trend = Trend::not_decided;
  std::string why;
};

// The band over the jitter realizations (seed 1 included) at the finest pair; empty (NaN)
// where seed 1 alone holds it.
struct FinestBand {
  double lo = std::numeric_limits<double>::quiet_NaN(), hi = std::numeric_limits<double>::quiet_NaN();
};

// The finding for a series' rates in level order (seed 1), the theory's rate, whether the
// finest pair lies beyond the documents' levels, the agreement tolerance and the band at the
// finest pair.
TrendFinding judge_trend(const std::vector<double>& rates, double theory, bool finest_beyond,
                         double tolerance, FinestBand band = {});

// The rows (one per table, reading, weight, θ and pair of levels) and the findings (one per
// table, reading, weight and θ) of the store at `store` against `published`
// (thesis_table4_N_long.tsv), Table 4.4's rows first.  Columns: see rate_levels.cpp.
struct RateLevels {
  TsvTable rates, findings;
};
RateLevels rate_levels(const StoreSnapshot& store, const PublishedTables& published);

}  // namespace gpm
