// The seal of a result-store row, one definition for the store that writes it (studies/run/
// store.hpp) and the judges that read it (studies/judge/snapshot.hpp).
//
// 16 hex digits of a 64-bit FNV-1a hash of every cell but the seal (the study's cells, code,
// made_on, checked), each followed by a tab.  `row` holds all the columns of the store's
// provenance (the seal cell, last, is ignored).  A seal is a tripwire for accidents (an edit by
// hand, a cut row, a merge, a wrong line ending): anyone can recompute it after a deliberate
// edit, so it is no evidence against one; that evidence is git's history and recomputing the
// rows (--verify, tests/store/verify_store_full.sh).
#pragma once
#include <string>
#include <vector>

namespace gpm {

std::string row_seal(const std::vector<std::string>& row);
// The seal as written before 2026-12-03, which left `checked` out: read only by
// `gpm store-seal`, which verifies rows under it once and seals them anew.
std::string row_seal_without_checked(const std::vector<std::string>& row);

}  // namespace gpm
