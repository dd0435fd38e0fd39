// Page one of the report: one verdict per item of the three documents (tables/items.tsv),
// each with the number that decides it, computed from the data files (`gpm verdicts`).  The
// table is compact: a figure drawn from a table's rows ("as T") shares that table's row, and
// neighbouring illustrations of one document share one row.  The rules (items.tsv's `rule`):
//   rates T    the paper-scale verdicts of T's published rates (store_score.tsv, the counted
//              setting): reproduced when every rate agrees, is inside the seed band or
//              reproduces non-convergence; partial when some do; open when none do (the
//              evidence says how each misses); "not reproduced (reason checked)" when every
//              rate has a checked reason or is not computed; not yet computed when the store
//              lacks the table or computed none.  Another reading of the text under which
//              every rate agrees is named in the evidence (it decides nothing);
//   as T       a figure of T's errors: merged into T's row, since it is drawn from the same rows;
//   cor71      Corollary 7.1: printed coefficients that hold (koba_sato_cor71.tsv, holds);
//   bounds     Theorems 1.3–1.6: cases where a bound falls below the measured error
//              (koba_sato_bounds_summary.tsv, violations);
//   covering   Imoto's covering bound: (level, seed) pairs where it holds (imoto_regularity_cover.tsv);
//   fig3       Imoto Fig. 3: r_N of the uniform against the non-uniform distribution
//              (imoto_figs_fig3_discs.tsv);
//   count      N of the distribution at Δx = 2⁻⁵ against the printed 1521 (core_voronoi.tsv);
//   weights W  the plotted weights (W: names joined by ','): printed formulas that fail
//              normalization (core_weights_errata.tsv) and the norm of the corrected ones
//              (core_weights.tsv);
//   drawn      an illustration drawn from the definitions: reproduced qualitatively.
// A rule whose data file is missing or holds no rows gives "not yet computed".  A rate table's
// evidence gives the counts of both boards (as identified, which decides the verdict, and as
// printed), naming only the verdicts that occur.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"

namespace gpm {

// A data file of the run by its name ("core_voronoi.tsv"); nullopt when it does not exist
// (the rule's verdict is then "not yet computed").
using PageDataReader = std::function<std::optional<TsvTable>(const std::string& file)>;

// The reader of the files in `dir` (TsvTable::load, so a malformed file is an InputError).
PageDataReader page_data_dir(const std::string& dir);

// The verdict and its evidence of one item's rule: rules "rates" and "as" are not data rules
// (they need the score, or merge) and are answered by page_verdicts; an unknown rule gives
// "not yet computed" with "unknown rule RULE".
struct PageVerdict {
  std::string verdict, evidence;
};
PageVerdict data_rule_verdict(const std::string& rule, const PageDataReader& data);

// The verdict of rates table `table` from the score (gpm store-rates --score: rows of table,
// printed, counted, rates and one count column per verdict).  The last counted row decides;
// the evidence names the counted row's counts and, where the printed board's row differs,
// those too.
PageVerdict rate_table_verdict(const TsvTable& score, const std::string& table);

// Page one's table (columns document, item, shows, verdict, evidence, section), rows in the
// order of `items` (columns document, item, shows, rule, section) with the merges above.
// InputError for a missing column, a count that is no number, or an "as T" figure whose T has
// no rates row in `items`.
TsvTable page_verdicts(const TsvTable& items, const TsvTable& score, const PageDataReader& data);

}  // namespace gpm
