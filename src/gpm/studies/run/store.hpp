// The result store: a study's data file, unit by unit, where every row says which code
// computed it.
//
// A study writes one or more data files (its registry entry's store files: a reading, a seed);
// in each, rows whose first `key_columns` values agree form one finished unit of work (a
// level, or a level × order, …).  Every row ends with four provenance columns
// (row_provenance_columns(), registry.hpp):
//   code     the code fingerprint of the program that computed it (provenance.hpp),
//   made_on  CPU, threads and date,
//   checked  "computed" (by that code), or the record of the re-check that carried it
//            over from older code,
//   seal     a hash of the row's other cells (row_seal below): a tripwire for accidents.
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

#include "gpm/io/seal.hpp"
#include "gpm/io/tsv.hpp"

namespace gpm {

class Args;

// run: compute the units not yet stored; replace: the same, discarding file content that does
// not match (above); verify, recheck: below; census: compute nothing, report every unit of
// the run's loop that the file lacks (exit 4 if any).
enum class CacheMode { run, replace, verify, recheck, census };

// Declares --verify, --recheck, --census and --replace on a study's command line, and reads
// them back (two of them together: InputError).
void add_cache_options(Args& a);
CacheMode cache_mode(const Args& a);

// Numbers of a re-computed unit agree with the stored ones when |a − b| ≤ tol·max(|a|, |b|).
// The runs are deterministic for any thread count (the pair sums run in a fixed order), so
// on one machine they agree bitwise; the tolerance admits another CPU's rounding.
constexpr double kStoreRelTol = 1e-9;
// Solver residual columns (name contains "residual") agree when |a − b| ≤ this, absolutely:
// they sit at the rounding level, where a relative comparison measures only rounding noise.
// or, for a residual far above it, when they differ by less than kStoreResidualRelTol of it
// (a long CG on another CPU's vector width ends at another rounding: store.cpp).
constexpr double kStoreResidualAbsTol = 1e-13;
constexpr double kStoreResidualRelTol = 0.1;
// --verify by another path than the rows' own (issue 58, item 3: a cheaper, independent
// recomputation): the numbers agree when they differ by at most this, relatively.  Measured
// before it was set: preconditioned CG against plain CG (both to a relative residual of 1e-10)
// differ by at most 8.4e-8 in Table 4.4's error (36 rows, 2^-5..2^-10,
// results/bench/pcg_table4_4_*) and by 1.6e-10 in Table 4.7's implicit steps (38 rows,
// pcg_heat_4_7_*); Krylov against stepping by at most 1.6e-5 in rel_error_max (246 rows,
// heat_propagator_check.tsv).  A tenfold margin over the largest of its path: a changed digit
// of a stored error (1e-4 relative or more) is still a difference.
constexpr double kStoreSolverPathRelTol = 1e-6;
constexpr double kStorePropagatorPathRelTol = 1e-4;

// The writer's lock of a store file (`<file>.lock`, as a study's run takes it), for a tool that
// rewrites the file outside a study (gpm store-add-columns): InputError naming the file if
// another process holds it; released when the object goes.
class StoreFileLock {
 public:
  explicit StoreFileLock(const std::string& file);
  ~StoreFileLock();
  StoreFileLock(const StoreFileLock&) = delete;
  StoreFileLock& operator=(const StoreFileLock&) = delete;

 private:
  int fd_ = -1;
};

// Today's date (UTC, YYYY-MM-DD), as re-check records and logs write it.
std::string today();

// The seal of a row: row_seal (gpm/io/seal.hpp).
// The re-checks a row's `checked` cell (its re-check record; not a checked reason, which
// judges a rate: judge/checked_reasons.hpp) stands for: each "recheck …" record it holds (an
// older chain "a; b; c") plus the count it carries as "(+N earlier)"; 0 for "computed".
std::size_t recheck_count(const std::string& record);
// A `checked` cell: the last re-check's record and, if any, the count of earlier ones.
std::string checked_cell(const std::string& last, std::size_t earlier);
// A text with its invisible characters made visible (\r, \t, \xEF…), for messages.
std::string escaped(const std::string& s);
// Columns that are measurements of the run, not of the numerics (compared never): names
// ending in "_s", "seconds", "s_per_step", anything with "rss", and the provenance columns.
bool is_volatile_column(const std::string& name);
// Columns that say how a Laplacian product ran, not what it gave: `storage` (assembled,
// matrix_free, full) and `nnz` (exact when assembled, an estimate matrix-free).  --verify and
// --recheck compare them only between rows of the same storage, so a unit recomputed
// matrix-free (on a device, say) is judged on its numbers.
bool is_storage_column(const std::string& name);
// Header parameters that name how a unit's numbers were solved for, not which numbers they are
// (`solver`: plain or preconditioned CG, both to the file's tolerance).  --verify accepts a
// run whose path parameters differ from the file's and compares by another path (below).
bool is_path_parameter(const std::string& key);
// Columns that report how the path ran (iteration counts, residuals, the propagator and its
// subspace): compared only when the recomputation took the rows' own path.  A row recomputed
// by another propagator than its `propagator` cell names (a heat study's --verify --propagator)
// is compared at kStorePropagatorPathRelTol; a run whose path parameter differs from the
// file's at kStoreSolverPathRelTol.
bool is_path_column(const std::string& name);

// One data file of a study read and written unit by unit: a unit's rows are reused when the
// current code made them (or a re-check carried them), else computed and added; the modes
// verify, recheck and census recompute or only count them (was LevelCache: it caches units,
// not levels).
class UnitCache {
 public:
  // `columns` are the study's own; the provenance columns are appended.  An existing file is
  // read if its `# key = value` header agrees with `params` on every key and its rows are
  // whole, sealed and distinct; otherwise InputError, unless the mode is `replace` (or the
  // file is of the quick profile), where what differs is dropped and replaced.
  // `writer` false: a reader only (the ranks of an MPI run other than rank 0): no lock, and
  // save() writes nothing.
  // `quick_run`: this run is of the quick profile, so a file of the quick profile is its cache
  // (replaced where it differs), whether or not `params` name the profile.
  UnitCache(std::string path, std::vector<std::pair<std::string, std::string>> params,
             std::vector<std::string> columns, int key_columns, CacheMode mode = CacheMode::run,
             bool writer = true, bool quick_run = false);
  ~UnitCache();
  UnitCache(const UnitCache&) = delete;
  UnitCache& operator=(const UnitCache&) = delete;

  // Whether the unit `key` is finished under the current code: `expected_rows` rows (any
  // number ≥ 1 when 0), all carrying the current fingerprint.  Always false in verify and
  // recheck mode (the requested units are computed).  Census mode: always true (nothing is
  // computed), and a unit the file lacks (any code) is noted for finish().
  bool has(const std::vector<std::string>& key, std::size_t expected_rows = 0) const;
  std::size_t reused() const { return reused_; }
  // One row of the study's own columns; the first row of a unit replaces what the file held
  // for that unit (a partial or outdated one).
  void add(std::vector<std::string> row);
  // Run mode: writes every row (atomic) with the params, provenance and any extra meta set
  // on table().  Verify and recheck mode: nothing (finish() decides).
  void save();
  // Verify/recheck: compares, reports on stderr, writes (recheck) and throws StoreMismatch on
  // a difference.  Census: reports the missing units (StoreMismatch if any).  Run mode:
  // nothing.  Call once, after the last unit.
  void finish();
  // Whether this run writes the data file (and so may write the outputs derived from it).
  bool writes() const { return running() && writer_; }
  // Whether this run computes and writes units (run or replace).
  bool running() const { return mode_ == CacheMode::run || mode_ == CacheMode::replace; }
  // Rows this run added (run mode), for a truthful closing line.
  std::size_t added() const { return added_; }

  TsvTable& table() { return table_; }
  const std::vector<std::vector<std::string>>& rows() const { return table_.rows; }

 private:
  std::vector<std::string> key_of(const std::vector<std::string>& row) const;
  std::string key_text(const std::vector<std::string>& key) const;
  void load(const std::vector<std::pair<std::string, std::string>>& params);
  // A mismatch of the whole file: refused (InputError), or its rows dropped when replacing.
  void refuse_file(const std::string& problem, std::size_t rows, bool replace);
  // `tail`: what the re-check did (": N units recomputed, max rel diff D").
  void restamp(std::vector<std::string>& row, const std::string& tail) const;

  // What the file on disk was when this run last read or wrote it (all zero: no file).
  struct DiskState {
    long long dev = 0, ino = 0, size = 0, sec = 0, nsec = 0;
    bool operator==(const DiskState&) const = default;
  };
  DiskState disk_state() const;
  bool hold_lock();  // true if the lock had to be taken again
  void merge_disk();
  [[noreturn]] void rescue(const std::string& problem);
  void write_file();  // the lock checked, the disk merged, the table saved

  std::string path_;
  std::string program_;  // the study's (params' "program")
  std::vector<std::pair<std::string, std::string>> params_;
  DiskState disk_;
  std::string reason_ = "--replace";  // why rows may be discarded: --replace or a quick cache
  TsvTable table_;
  int key_columns_;
  CacheMode mode_;
  std::string code_;  // the current program's code fingerprint
  std::string made_on_;
  int lock_fd_ = -1;
  std::size_t reused_ = 0, added_ = 0;
  mutable std::vector<std::vector<std::string>> missing_;  // census: units the file lacks
  std::set<std::vector<std::string>> started_;  // units added by this run
  std::vector<std::vector<std::string>> fresh_;  // verify/recheck: the recomputed rows
  bool writer_ = true;
  bool quick_run_ = false;
  bool other_path_ = false;  // --verify through another solver (a path parameter differs)
};

}  // namespace gpm
