// Self-describing TSV data files.
//
// Every data file starts with `# key = value` lines naming every parameter, the seed,
// the git revision, the profile and the wall time, then one header row of column names,
// then data rows.  Files are written to `<path>.tmp` and renamed, so a reader never
// sees half a file.  A study that runs level by level rewrites the file after each
// level (`TsvTable::save`), and on a rerun with the same parameters reads back the
// levels it already has (`TsvTable::load_matching`) instead of recomputing them.
#pragma once
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gpm {

struct TsvTable {
  std::vector<std::pair<std::string, std::string>> meta;  // ordered `# key = value`
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;

  void set(const std::string& key, const std::string& value);
  void set(const std::string& key, double value);
  std::optional<std::string> get(const std::string& key) const;
  void add_row(std::vector<std::string> row);
  int column(const std::string& name) const;  // -1 if absent

  // The `# key = value` lines, the header row and the rows, as they go to a file.
  void write(std::ostream& out) const;
  // Atomic write (tmp + rename); creates parent directories.
  void save(const std::string& path) const;
  // Throws InputError if the file is missing or malformed.
  static TsvTable load(const std::string& path);
  // The rows of an existing file whose `# key = value` lines agree with `params` on every
  // key of `params`: the cache of a previous run with the same parameters.  Empty if the
  // file is absent or any parameter differs.
  static std::vector<std::vector<std::string>> load_matching(
      const std::string& path, const std::vector<std::pair<std::string, std::string>>& params);
};

// Number formatting used in every data file: shortest round-trip representation.
std::string fmt(double v);
std::string fmt(long long v);
inline std::string fmt(int v) { return fmt(static_cast<long long>(v)); }
inline std::string fmt(unsigned long v) { return fmt(static_cast<long long>(v)); }
inline std::string fmt(unsigned long long v) { return fmt(static_cast<long long>(v)); }

// Provenance every data file carries: git revision, build, host, date, threads.
void add_provenance(TsvTable& t);

}  // namespace gpm
