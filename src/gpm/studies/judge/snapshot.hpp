// One read of the result store for a judging pass (gpm store-rates): a file is read from disk
// the first time a judgement asks for it and kept, so the rates, the checked reasons, the
// set-up identification, the decisions and the rate-against-level view of one pass all judge
// the same bytes, each file read once (files_read() counts the reads; a test holds it to the
// number of files asked for).  Nothing here writes to the store.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"

namespace gpm {

class StoreSnapshot {
 public:
  // The store folder `dir` (not read until a file is asked for).
  explicit StoreSnapshot(std::string dir) : dir_(std::move(dir)) {}
  const std::string& dir() const { return dir_; }
  // The path of a store file, for messages and provenance.
  std::string path(const std::string& name) const { return dir_ + "/" + name; }
  // Whether the store holds a file of that name (decided at the first ask, then kept).
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
  mutable std::map<std::string, TsvTable> tables_;
  mutable std::map<std::string, bool> present_;
};

}  // namespace gpm
