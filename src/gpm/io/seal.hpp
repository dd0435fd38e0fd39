// The seal of a result-store row, one definition for the store that writes it (studies/run/
// store.hpp) and the judges that read it (studies/judge/snapshot.hpp).
//
// 16 hex digits of a 64-bit FNV-1a hash of the file's name (its stem: no folder, no ".tsv")
// and then every cell but the seal (the study's cells, code, made_on, checked), each followed
// by a tab.  The name binds a row to its file: rows pasted from another file (another jitter
// realization, another reading) or a file copied over another's name no longer match (issue
// 61).  `row` holds all the columns of the store's provenance (the seal cell, last, is
// ignored).  A seal is a tripwire for accidents (an edit by hand, a cut or pasted row, a merge,
// a wrong line ending): anyone can recompute it after a deliberate edit, so it is no evidence
// against one; that evidence is git's history and recomputing the rows (--verify,
// tests/store/verify_store_full.sh).
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace gpm {

// The seal of `row` in the file at `path` (its stem is what is bound).
std::string row_seal(const std::vector<std::string>& row, const std::string& path);
// The name a seal binds: the stem of `path` ("results/paper/x.tsv" -> "x").
std::string sealed_name(const std::string& path);

// The header's seal (the `# header_seal = …` line of a store file, issue 61 case 6.3): the same
// hash over the file's stem and every header line but its own, key then value, in order.  An
// edited parameter or provenance line (command, git_revision, host) no longer matches; the
// writer renews it at each save, with the header it writes.
using HeaderLines = std::vector<std::pair<std::string, std::string>>;
std::string header_seal(const HeaderLines& meta, const std::string& path);
// "" when `meta` carries its matching seal; else what is wrong ("no header_seal line", or the
// seal does not match).
std::string header_seal_problem(const HeaderLines& meta, const std::string& path);

// The seals written before: without the file's name (2026-12-03 to 2026-12-05), and before
// 2026-12-03 also without `checked`.  Read only by `gpm store-seal`, which verifies rows under
// them once and seals them anew, and by the messages that say so.
std::string row_seal_unbound(const std::vector<std::string>& row);
std::string row_seal_without_checked(const std::vector<std::string>& row);

}  // namespace gpm
