// The documents' two-level rates joined with the published ones: the table behind every rate
// table of the package.  rate_table writes it to a file for one study; gpm store-rates
// (verdicts.hpp) builds it for every slice of the result store and judges its rows.
//
// Per published row (matched on the key columns), the documents' rate log(e₁/e₂)/log(h₁/h₂)
// between two levels; a least-squares slope with the half-width of its 95 % interval over the
// levels past the transition only (lsq_slope, lsq_half95, lsq_points, lsq_from: the finest run
// of levels whose two-level rates all lie within the tolerance of the finest pair's; NA under
// three levels), since through a curved series a line measures the curvature; the pair's h₁/h₂
// (h_ratio) and our rate one level coarser and one finer (rate_before, rate_after; NA where
// the store lacks the level); and a status:
//   other-levels   the rate comes from other levels than the document's (the published
//                  file's rate_levels): shown, not judged — a pre-asymptotic rate from
//                  coarser levels neither agrees nor differs with the document
//   agrees         |reproduced − published| ≤ tolerance
//   differs        otherwise (a reason counts only where a diagnostic computed from the data
//                  checks it: checked_reasons.hpp, for the paper-scale store)
//   undefined      the rate is not a number (an error ≤ 0 or not finite at one of the two
//                  levels): no agreement can be claimed
//   not-computed   the data have fewer than two levels for this setting.
#pragma once
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/evidence.hpp"  // cell_number, EvidenceSeries

namespace gpm {

// |reproduced − published| that still counts as agreement: rate_table's default, and the
// tolerance every verdict of the result store is judged with (one number, one place).
inline constexpr double kRateTolerance = 0.15;

// The documents' two rate levels, coarse first, from a published file's `rate_levels` line
// ("8,9"), as the judges read it (two other copies of the pair remain: HeatTable::rate_levels,
// which the heat mode model reads, and the thesis table specs; issue 57).  A file without the line, or with
// anything but two increasing levels, is refused (InputError naming the file).
std::pair<int, int> documents_levels(const TsvTable& published);
std::string documents_levels_text(const TsvTable& published);  // "8,9"


// A published `theoretical` cell as a rate; NaN where the document gives a word ("unstable":
// Table 4.6's explicit series) or nothing.
double theoretical_rate(const std::string& text);

struct RateJoin {
  std::vector<std::string> keys;  // key columns shared by the data and the published file
  std::string level = "level";    // the data's level column (Δx = 2^-level)
  std::string x = "h";            // abscissa of the rate (log e against log x)
  std::string y = "rel_error";    // error column
  std::string value = "numerical";  // the published file's rate column
  // The two levels of every rate: "A,B", "published" (the published file's rate_levels, the
  // document's) or empty (the two finest of each series).
  std::string levels;
  double tolerance = kRateTolerance;
};


// One published row joined with its stored series.  Numbers stay numbers: NaN (or -1 for a
// level) where rate_table writes NA; only write_joined formats them.
struct JoinedRate {
  std::vector<std::string> key;  // the published row's cells in RateJoin::keys' order
  double published = NAN;
  std::string theoretical = "NA";  // as printed: a rate, NA or a word ("unstable")
  bool computed = false;           // the series holds both levels of the pair
  int level_lo = -1, level_hi = -1;
  double reproduced = NAN, difference = NAN;  // difference: only where both rates are numbers
  // The least-squares slope over the levels past the transition (fitted: three levels at
  // least), the levels it had and the first of them.
  bool fitted = false;
  double lsq_slope = NAN, lsq_half95 = NAN;
  long long lsq_points = 0;
  int lsq_from = -1;
  double h_ratio = NAN, rate_before = NAN, rate_after = NAN;  // before/after: NaN where no level
  std::string status = "not-computed", reason = {};
};

struct JoinedRates {
  std::vector<std::string> keys;  // RateJoin::keys
  std::string fixed_levels;       // "A,B" where the join fixed them; empty: each series' finest
  std::vector<JoinedRate> rows;   // one per published row, in the published file's order
  std::map<std::string, int> counts;  // rows per status
  // The cell of key column `name` of a row (InputError where the join has no such key).
  const std::string& key(const JoinedRate& r, const std::string& name) const;
};

// The join: InputError (naming the file, by TsvTable::source) for a missing column, a cell
// that is no number, two data rows with the same key and level, or levels that are not two
// increasing ones.
JoinedRates join_rates(const TsvTable& data, const TsvTable& published, const RateJoin& join);

// The writer: appends to `out` the columns (the keys, then published, theoretical, reproduced,
// difference, lsq_slope, lsq_half95, lsq_points, lsq_from, levels, h_ratio, rate_before,
// rate_after, status, reason), one row per joined row, its rate_levels line (fixed levels)
// and count_<status> lines.
void write_joined(const JoinedRates& joined, TsvTable& out);

}  // namespace gpm
