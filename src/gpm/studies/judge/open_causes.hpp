// The open rates of the identified board (a near miss, a pre-asymptotic pair or a gross
// difference, each without a checked reason, or an unstable run whose rate agrees in sign only)
// grouped by what the stored data say about each, so that a reader sees
// the 20-odd open rates as a handful of questions (referee point 6).  The groups are measured,
// not guessed: for every open rate, in this order,
//   another reading    a stored reading of the same table other than the identified one (a
//                      set-up variant, δ-free volumes, the other h rule…) gives a rate within
//                      the tolerance of the published one: the gap is a set-up question;
//   robust gap         every stored jitter realization (at least kSeedBandDecides) lies on the
//                      same side of the published rate: no other particle set closes it;
//   blow-up rate       both runs unstable, only the sign of the rate agrees;
//   one realization    none of the above, and fewer seeds than decide: more seeds would tell.
// Each group row lists its rates' keys and, per rate, the numbers that put it there
// (published, ours, the band, the nearest other reading).
#pragma once
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/verdicts.hpp"

namespace gpm {

// The cause of one open rate and the numbers that decide it (above).
struct OpenCause {
  std::string cause;     // "another reading: h10_cell", "robust gap: every seed below", …
  std::string evidence;  // "published 2.00, ours 1.72, band 1.68-1.72 (5 seeds); nearest: cellvol 2.10"
};
OpenCause open_cause(const JudgedRate& open, const std::vector<JudgedRate>& judged, double tolerance);

// Whether a judged rate is open on the identified board.
bool open_on_identified_board(const JudgedRate& j);

// One row per (table, cause), in the order of the rates: columns table, cause, rates, keys,
// evidence (one clause per rate, "; " apart).
TsvTable open_causes(const std::vector<JudgedRate>& judged, double tolerance);

}  // namespace gpm
