// The result store: a study's data file, unit by unit, where every row says which code
// computed it.
//
// A study writes one data file; rows whose first `key_columns` values agree form one
// finished unit of work (a level, or a level × order, …).  Every row ends with three
// provenance columns:
//   code     the fingerprint of the program that computed it (provenance.hpp),
//   made_on  CPU, threads and date,
//   checked  "computed" (by that code), or the record of the re-check that carried it
//            over from older code.
// A unit is reused only if all its rows are present, well formed and carry the current
// program's fingerprint.  Rows of other code are never shown as current without a check:
//   --verify   recompute the requested units in memory and compare them with the file
//              (numbers to a relative kStoreRelTol, everything else exactly; timing and
//              memory columns aside); write nothing; exit 4 on any difference.
//   --recheck  the same, then write: recomputed units replace the file's, and if every one
//              agreed, the rows of other code are re-stamped with the current fingerprint
//              and the check's record in `checked`.  A refactor that leaves the numbers as
//              they were is carried across by re-checking the cheap (coarse) units.
// Two processes never write one file: the writer holds an advisory lock on `<file>.lock`.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"

namespace gpm {

class Args;

enum class CacheMode { run, verify, recheck };

// Declares --verify and --recheck on a study's command line, and reads them back.
void add_cache_options(Args& a);
CacheMode cache_mode(const Args& a);

// Numbers of a re-computed unit agree with the stored ones when |a − b| ≤ tol·max(|a|, |b|).
// The runs are deterministic for any thread count (the pair sums run in a fixed order), so
// on one machine they agree bitwise; the tolerance admits another CPU's rounding.
constexpr double kStoreRelTol = 1e-9;
// Solver residual columns (name contains "residual") agree when |a − b| ≤ this, absolutely:
// they sit at the rounding level, where a relative comparison measures only rounding noise.
constexpr double kStoreResidualAbsTol = 1e-13;

// The provenance columns every store row ends with.
const std::vector<std::string>& row_provenance_columns();
// Columns that are measurements of the run, not of the numerics (compared never): names
// ending in "_s", "seconds", "s_per_step", anything with "rss", and the provenance columns.
bool is_volatile_column(const std::string& name);

class LevelCache {
 public:
  // `columns` are the study's own; the provenance columns are appended.  An existing file is
  // read if its `# key = value` header agrees with `params` on every key; otherwise its rows
  // are not reused (and, in run mode, are replaced at the first save).
  // `writer` false: a reader only (the ranks of an MPI run other than rank 0): no lock, and
  // save() writes nothing.
  LevelCache(std::string path, std::vector<std::pair<std::string, std::string>> params,
             std::vector<std::string> columns, int key_columns, CacheMode mode = CacheMode::run,
             bool writer = true);
  ~LevelCache();
  LevelCache(const LevelCache&) = delete;
  LevelCache& operator=(const LevelCache&) = delete;

  // Whether the unit `key` is finished under the current code: `expected_rows` rows (any
  // number ≥ 1 when 0), all carrying the current fingerprint.  Always false in verify and
  // recheck mode (the requested units are computed).
  bool has(const std::vector<std::string>& key, std::size_t expected_rows = 0) const;
  std::size_t reused() const { return reused_; }
  // One row of the study's own columns; the first row of a unit replaces what the file held
  // for that unit (a partial or outdated one).
  void add(std::vector<std::string> row);
  // Run mode: writes every row (atomic) with the params, provenance and any extra meta set
  // on table().  Verify and recheck mode: nothing (finish() decides).
  void save();
  // Verify/recheck: compares, reports on stderr, writes (recheck) and throws StoreMismatch on
  // a difference.  Run mode: nothing.  Call once, after the last unit.
  void finish();
  // Whether this run writes the data file (and so may write the outputs derived from it).
  bool writes() const { return mode_ == CacheMode::run && writer_; }

  TsvTable& table() { return table_; }
  const std::vector<std::vector<std::string>>& rows() const { return table_.rows; }

 private:
  std::vector<std::string> key_of(const std::vector<std::string>& row) const;
  std::string key_text(const std::vector<std::string>& key) const;
  void load(const std::vector<std::pair<std::string, std::string>>& params,
            const std::vector<std::string>& own_columns);

  std::string path_;
  TsvTable table_;
  int key_columns_;
  CacheMode mode_;
  std::string code_;  // the current program's fingerprint
  std::string made_on_;
  int lock_fd_ = -1;
  std::size_t reused_ = 0;
  std::set<std::vector<std::string>> started_;  // units added by this run
  std::vector<std::vector<std::string>> fresh_;  // verify/recheck: the recomputed rows
  bool params_match_ = false;
  bool writer_ = true;
};

}  // namespace gpm
