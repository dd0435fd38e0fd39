// The error constant c = e/h^p of every heat and Poisson series (issue 59): per level and
// jitter realization, beside the a-priori constant M of one Fourier mode (mode_constants.hpp,
// heat_mode_model.hpp) and its limit C∞, and a finding per series by the rule written down
// (and committed) on 2026-12-05 before the runs that test it
// (results/predictions/error_constants_2e-11.md):
//
//   q = |c − M|/M at a realization's finest stored level L and at its level before;
//   approaches    q_L ≤ 0.05 and q_L ≤ max(q_{L−1}, 0.01)   (near the model, the excess not
//                 growing; an excess under 1 % counts as not growing: amendment of 2026-12-05,
//                 made before the first 2^-11 row existed, for the realizations' scatter);
//   stays away    q_L > 0.05 and q_L ≥ 0.9 q_{L−1} (off, and shrinking less than 10 % a level);
//   not decided   otherwise (near but growing; off but still shrinking).
//
// A series' finding is its realizations' common one (every realization holding seed 1's finest
// level counts; Table 4.4's τ-PCG files are the same realizations at further levels); where
// they differ it is not decided.  A rate in h moves by 4× the noise of an error ratio when
// h ∝ Δx^{1/4}; the constant is the direct quantity.  Read from the store; nothing is run.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/rate_levels.hpp"  // Trend
#include "gpm/studies/judge/snapshot.hpp"

namespace gpm {

// The rule's fraction: how near the model's constant counts as near.
constexpr double kConstantReach = 0.05;
// Below it a relative excess counts as not growing: the jitter realizations scatter c by
// 1-2 % at 2^-9 and 2^-10 (Table 4.4 h15, Tables 4.5, 4.6), so a change below 1 % is not a trend.
constexpr double kConstantFloor = 0.01;

// One realization's finding from its relative excess at the level before and the finest.
TrendFinding judge_constant(double q_before, double q_finest);

// The constants (one row per table, reading, weight, θ, realization and level) and the
// findings (one per table, reading, weight and θ).  Columns: see error_constants.cpp.  Where
// `diagnostics` holds thesis_mode_excess's files (mode_excess_{heat,poisson}_<h rule>_cell.tsv,
// seed 1), each seed-1 row of that reading gets the excess they project (else NA).
struct ErrorConstants {
  TsvTable constants, findings;
};
ErrorConstants error_constants(const StoreSnapshot& store, const PublishedTables& published,
                               const std::string& diagnostics = "");

}  // namespace gpm
