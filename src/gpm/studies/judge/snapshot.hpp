// One read of the result store for a judging pass (gpm store-rates): a file is read from disk
// the first time a judgement asks for it and kept, so the rates, the checked reasons, the
// set-up identification, the decisions and the rate-against-level view of one pass all judge
// the same bytes, each file read once (files_read() counts the reads; a test holds it to the
// number of files asked for).  Nothing here writes to the store.
//
// The store's door (StoreChecks::store, what gpm store-rates, rate-levels, checked-reasons
// and decisions open): a file the study registry names is read only if every row's seal
// matches its cells, its `# program` is its entry's program and its `# command` was run with
// its entry's arguments (the options that choose a reading or a realization: --table,
// --seed, --volumes, --h-rule, --dt-rule, --jitter; absent means the program's default), and
// a registered file that a judgement asks for and the store lacks is refused, not skipped.
// Each refusal is a StoreMismatch (exit 4) naming the file and, for a row, its data row.  What the door does not
// guard: a deliberate edit resealed by hand (the seal is a tripwire, not a signature; the
// recomputation catches it: tests/store/verify_store_full.sh), and header lines other than
// these two.  StoreChecks::none reads files as they are (the judges' unit tests' fixtures).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"

namespace gpm {

enum class StoreChecks { none, store };

// The documents' published rates (tables/published) for a judging pass: each file read once,
// on the first ask, as the store's are.  A judge called with a folder's name reads through a
// snapshot of its own (the conversion is implicit on purpose: the unit tests' fixtures).
class PublishedTables {
 public:
  PublishedTables(std::string dir) : dir_(std::move(dir)) {}  // NOLINT(google-explicit-constructor)
  PublishedTables(const char* dir) : dir_(dir) {}             // NOLINT(google-explicit-constructor)
  const std::string& dir() const { return dir_; }
  // The published file `name` (imoto_table1.tsv, thesis_table4_4_long.tsv); InputError
  // "no published file PATH" where it is absent.
  const TsvTable& file(const std::string& name) const;
  // How many files this snapshot has read from disk.
  std::size_t files_read() const { return tables_.size(); }

 private:
  std::string dir_;
  mutable std::map<std::string, TsvTable> tables_;
};

class StoreSnapshot {
 public:
  // The store folder `dir` (not read until a file is asked for).
  explicit StoreSnapshot(std::string dir, StoreChecks checks = StoreChecks::none)
      : dir_(std::move(dir)), checks_(checks) {}
  const std::string& dir() const { return dir_; }
  // The path of a store file, for messages and provenance.
  std::string path(const std::string& name) const { return dir_ + "/" + name; }
  // Whether the store holds a file of that name (decided at the first ask, then kept); at the
  // store's door a registered file it lacks is a StoreMismatch.
  bool has(const std::string& name) const;
  // The file's table, read on the first ask; whole_rows as TsvTable::load (a row whose cell
  // count differs from the header's is an InputError; without: read as it is, for the
  // store's own checks).  InputError for a file that is missing or malformed.
  const TsvTable& table(const std::string& name, bool whole_rows = true) const;
  // The names of the store's data files (*.tsv, no hidden file), sorted.
  std::vector<std::string> data_files() const;
  // How many files this snapshot has read from disk.
  std::size_t files_read() const { return tables_.size(); }

 private:
  std::string dir_;
  StoreChecks checks_ = StoreChecks::none;
  mutable std::map<std::string, TsvTable> tables_;
  mutable std::map<std::string, bool> present_;
};

}  // namespace gpm
