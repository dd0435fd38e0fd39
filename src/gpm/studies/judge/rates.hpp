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
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gpm/io/tsv.hpp"

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

// A study's published file read for a judge (`who` leads the message): InputError
// "<who>: no published file PATH" where it is absent.
TsvTable load_published(const std::string& path, const std::string& who);

// A cell read as a number, the one reader the judges share (issue 57): a plain decimal (an
// optional '-', digits and points, an optional exponent) and nothing else; false for NA, an
// empty cell, nan, inf or a word (a document's "unstable").
bool cell_number(const std::string& text, double& value);
// The same, `otherwise` where the cell holds no number.
double cell_number_or(const std::string& text, double otherwise);

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


// Appends to `out` the columns (the keys, then published, theoretical, reproduced,
// difference, lsq_slope, lsq_half95, lsq_points, lsq_from, levels, h_ratio, rate_before,
// rate_after, status, reason) and one row per published row, in the
// published file's order; sets `out`'s rate_levels (fixed levels) and count_<status> lines.
// Returns the rows per status.  InputError (naming the file, by TsvTable::source) for a
// missing column, a cell that is no number, two data rows with the same key and level, or
// levels that are not two increasing ones.
std::map<std::string, int> join_rates(const TsvTable& data, const TsvTable& published,
                                      const RateJoin& join, TsvTable& out);

}  // namespace gpm
