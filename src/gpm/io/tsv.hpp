// Self-describing TSV data files.
//
// Every data file starts with `# key = value` lines naming every parameter, the seed,
// the git revision, the profile and the wall time, then one header row of column names,
// then data rows.  Files are written to `<path>.gpm-tmp.<pid>.<16 random hex>` and renamed,
// so a reader never sees half a file; the temp file is removed on every error, and the
// leftovers of a killed run are removed by the next save of the same file (only names of
// exactly that form whose process is gone: never a user's `<path>.tmp.1` or the like).  A study that runs level by level rewrites the file after each
// level (`TsvTable::save`), and on a rerun with the same parameters reads back the
// levels it already has (`TsvTable::load_matching`) instead of recomputing them.
#pragma once
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gpm {

// A row filled by column name — row["h"] = fmt(h) — instead of by position, so that a row
// and its column list, often in different files, cannot drift apart: a name that is not a
// column throws at once, a column left unset throws when the cells are taken (both
// std::logic_error: a programming error, not bad input).
class TsvRow {
 public:
  explicit TsvRow(std::vector<std::string> columns);
  std::string& operator[](const std::string& name);
  // Every cell, in column order.
  std::vector<std::string> cells() const;
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::vector<std::string> columns_, cells_;
  std::vector<bool> set_;
};

struct TsvTable {
  std::vector<std::pair<std::string, std::string>> meta;  // ordered `# key = value`
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  // Set by load(): the file, and the line of each row in it (for messages naming a cell).
  std::string source;
  std::vector<std::size_t> row_lines;

  void set(const std::string& key, const std::string& value);
  void set(const std::string& key, double value);
  std::optional<std::string> get(const std::string& key) const;
  void add_row(std::vector<std::string> row);
  // An empty row of this table's columns, and that row once filled (its cells in order).
  TsvRow named_row() const { return TsvRow(columns); }
  void add_row(const TsvRow& row) { add_row(row.cells()); }
  int column(const std::string& name) const;  // -1 if absent
  // The column's index, or an InputError naming the file and the missing column.
  int require_column(const std::string& name) const;
  // The cell of `row` in the column named `name`: rows addressed by name, so a column
  // inserted before it changes nothing (InputError for a missing column or a short row).
  const std::string& text(std::size_t row, const std::string& name) const {
    return text(row, require_column(name));
  }
  // The cell (row, col); a row too short for it is an InputError naming file, line and column.
  const std::string& text(std::size_t row, int col) const;
  // The cell (row, col) as a number: a decimal, or nan / inf / -inf as fmt() writes them.
  // Anything else is an InputError naming the file, line, data row and
  // column, e.g. "data.tsv line 12 (data row 3), column 'rel_error': 'abc' is not a number".
  double number(std::size_t row, int col) const;
  // The same for a decimal integer.
  long long integer(std::size_t row, int col) const;

  // The `# key = value` lines, the header row and the rows, as they go to a file.
  void write(std::ostream& out) const;
  // Atomic write (tmp + rename); creates parent directories.  Refuses a path that
  // check_output_path refuses, and a sealed store file unless this table is sealed too and
  // names the same `# program` (the study that owns it); removes stale temp files of dead
  // processes (the header's note).
  void save(const std::string& path) const;
  // Throws InputError if the file is missing, not a regular file or malformed: CRLF line
  // endings, a byte-order mark, no header, or (whole_rows) a row whose cell count differs
  // from the header's.  whole_rows = false: such rows are read as they are (for the result
  // store, which names them and decides).
  static TsvTable load(const std::string& path, bool whole_rows = true);
  // The check load() makes with whole_rows, on a table it read without: an InputError naming
  // the file and line of the first row whose cell count differs from the header's.
  void require_whole_rows() const;
  // The rows of an existing file whose `# key = value` lines agree with `params` on every
  // key of `params`: the cache of a previous run with the same parameters.  Empty if the
  // file is absent or any parameter differs.
  static std::vector<std::vector<std::string>> load_matching(
      const std::string& path, const std::vector<std::pair<std::string, std::string>>& params);
};

// Throws InputError (naming `option` and `path`) unless `path` names a regular file or
// nothing yet, in a directory that exists or can be created and that this process may
// write (`writes` false: a read-only use, the directory need not be writable): a directory,
// a device (/dev/null, /dev/full), a pipe or a symbolic link is never replaced, and a path
// with a control character (a newline would break the `# command` header line) is refused.
// A sealed store file (sealed_file_program) is refused unless `owner` is the program that
// wrote it: only the study that owns a store file replaces it.  An empty path passes (the
// caller decides whether the output is required).
void check_output_path(const std::string& option, const std::string& path,
                       const std::string& owner = "", bool writes = true);

// The `# program` of a result-store file (its column header ends in `seal`), "?" for a sealed
// file that names none, nullopt for anything else (no file, another table, unreadable).
std::optional<std::string> sealed_file_program(const std::string& path);

// `text` written to `path` as TsvTable::save writes a table: atomically, parents created,
// the same paths refused (a sealed store file always).
void save_text(const std::string& path, const std::string& text);

// Throws InputError unless every named path is distinct from the others (after resolving
// "." and ".."), e.g. {{"--out", out}, {"--cost", cost}}; empty paths are ignored.
void require_distinct_paths(const std::vector<std::pair<std::string, std::string>>& paths);

// Number formatting used in every data file: shortest round-trip representation.
std::string fmt(double v);
std::string fmt(long long v);
// The items of v separated by sep: join({"a", "b"}, ",") = "a,b".
std::string join(const std::vector<std::string>& v, const std::string& sep);
inline std::string fmt(int v) { return fmt(static_cast<long long>(v)); }
inline std::string fmt(unsigned long v) { return fmt(static_cast<long long>(v)); }
inline std::string fmt(unsigned long long v) { return fmt(static_cast<long long>(v)); }

// Provenance every data file carries: git revision, build, host, date, threads.
void add_provenance(TsvTable& t);

// The rows of `data` whose cells equal every (column, value) of `where`: one slice of a study
// file (a reading of h and volume choice) before it is joined; InputError for an unknown
// column.
TsvTable rows_where(const TsvTable& data, const std::vector<std::pair<std::string, std::string>>& where);

}  // namespace gpm
