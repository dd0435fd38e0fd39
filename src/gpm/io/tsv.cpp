#include "gpm/io/tsv.hpp"

#include <omp.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/command_line.hpp"
#include "gpm/io/provenance.hpp"

namespace gpm {

void TsvTable::set(const std::string& key, const std::string& value) {
  for (auto& kv : meta)
    if (kv.first == key) {
      kv.second = value;
      return;
    }
  meta.emplace_back(key, value);
}

void TsvTable::set(const std::string& key, double value) { set(key, fmt(value)); }

std::optional<std::string> TsvTable::get(const std::string& key) const {
  for (auto& kv : meta)
    if (kv.first == key) return kv.second;
  return std::nullopt;
}

void TsvTable::add_row(std::vector<std::string> row) { rows.push_back(std::move(row)); }

TsvRow::TsvRow(std::vector<std::string> columns)
    : columns_(std::move(columns)), cells_(columns_.size()), set_(columns_.size(), false) {}

std::string& TsvRow::operator[](const std::string& name) {
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c] == name) {
      set_[c] = true;
      return cells_[c];
    }
  throw std::logic_error("row: '" + name + "' is not a column");
}

std::vector<std::string> TsvRow::cells() const {
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (!set_[c]) throw std::logic_error("row: column '" + columns_[c] + "' left unset");
  return cells_;
}

int TsvTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return static_cast<int>(c);
  return -1;
}

int TsvTable::require_column(const std::string& name) const {
  const int c = column(name);
  if (c < 0)
    throw InputError((source.empty() ? std::string("table") : source) + " has no column '" +
                     name + "'");
  return c;
}

void TsvTable::write(std::ostream& out) const {
  for (auto& [k, v] : meta) out << "# " << k << " = " << v << '\n';
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "\t" : "") << columns[c];
  out << '\n';
  for (auto& r : rows) {
    for (std::size_t c = 0; c < r.size(); ++c) out << (c ? "\t" : "") << r[c];
    out << '\n';
  }
}

namespace {

namespace fs = std::filesystem;

// "FILE line L (data row R), column 'NAME'" for messages about one cell.
std::string cell_where(const TsvTable& t, std::size_t row, int col) {
  std::string s = t.source.empty() ? std::string("table") : t.source;
  if (row < t.row_lines.size()) s += " line " + std::to_string(t.row_lines[row]);
  s += " (data row " + std::to_string(row + 1) + ")";
  s += ", column ";
  s += col >= 0 && static_cast<std::size_t>(col) < t.columns.size()
           ? "'" + t.columns[col] + "'"
           : std::to_string(col + 1);
  return s;
}

// The temp file of one save: `NAME.gpm-tmp.PID.HEX` (16 random hex digits), a name no user
// gives a file by accident, so that the cleanup below can only ever touch its own kind.
constexpr const char* kTempMarker = ".gpm-tmp.";

std::string temp_name(const fs::path& p) {
  static thread_local std::mt19937_64 draw{std::random_device{}() ^
                                           (static_cast<uint64_t>(::getpid()) << 32)};
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(draw()));
  return p.string() + kTempMarker + std::to_string(::getpid()) + "." + hex;
}

// Leftovers of save() in processes that died between writing and renaming: names of exactly
// temp_name's form beside the output whose PID no longer runs.  A live writer's temp file
// is left alone (a reused pid only delays a removal); `x.tsv.tmp.12`, `x.tsv.gpm-tmp.12` or
// anything else a user named so is never removed.
void remove_stale_temps(const fs::path& p) {
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  const std::string prefix = p.filename().string() + kTempMarker;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string n = it->path().filename().string();
    if (n.size() <= prefix.size() || n.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = n.substr(prefix.size());  // PID.HEX
    const auto dot = rest.find('.');
    if (dot == std::string::npos || dot == 0 || dot > 9 || rest.size() != dot + 17) continue;
    const std::string pid_text = rest.substr(0, dot), hex = rest.substr(dot + 1);
    if (pid_text.find_first_not_of("0123456789") != std::string::npos ||
        hex.find_first_not_of("0123456789abcdef") != std::string::npos)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
    const bool dead = ::kill(pid, 0) != 0 && errno == ESRCH;
    if (!dead) continue;
    std::error_code e2;
    if (fs::is_regular_file(fs::symlink_status(it->path(), e2))) fs::remove(it->path(), e2);
  }
}

}  // namespace

const std::string& TsvTable::text(std::size_t row, int col) const {
  if (row >= rows.size() || col < 0)
    throw std::logic_error("TsvTable: no cell (" + std::to_string(row) + ", " +
                           std::to_string(col) + ")");
  const auto& r = rows[row];
  if (static_cast<std::size_t>(col) >= r.size())
    throw InputError(cell_where(*this, row, col) + ": the row has only " +
                     std::to_string(r.size()) + " cells");
  return r[col];
}

double TsvTable::number(std::size_t row, int col) const {
  const std::string& c = text(row, col);
  double v = 0;
  if (read_decimal(c, v)) return v;
  if (c == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (c == "inf" || c == "-inf") return c[0] == '-' ? -HUGE_VAL : HUGE_VAL;
  throw InputError(cell_where(*this, row, col) + ": '" + c + "' is not a number");
}

long long TsvTable::integer(std::size_t row, int col) const {
  const std::string& c = text(row, col);
  try {
    return parse_integer(c, "integer");
  } catch (const InputError&) {  // parse_integer's message names no file: say it here
    throw InputError(cell_where(*this, row, col) + ": '" + c + "' is not an integer");
  }
}

namespace {
std::string octal(unsigned mode) {
  char b[16];
  std::snprintf(b, sizeof b, "%04o", mode);
  return b;
}
}  // namespace

std::optional<std::string> sealed_file_program(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(fs::status(path, ec))) return std::nullopt;
  std::ifstream in(path);
  std::string line, program;
  // The header is a few dozen lines; a file whose first 10,000 lines are all comments is
  // not a store file.
  for (int n = 0; n < 10000 && std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // a store file with CRLF still is one
    if (line.rfind("# program = ", 0) == 0 && program.empty()) program = line.substr(12);
    if (line.rfind("#", 0) == 0 || line.empty()) continue;
    const auto tab = line.rfind('\t');
    if (tab == std::string::npos || line.substr(tab + 1) != "seal") return std::nullopt;
    return program.empty() ? std::string("?") : program;
  }
  return std::nullopt;
}

void check_output_path(const std::string& option, const std::string& path, const std::string& owner,
                       bool writes) {
  if (path.empty()) return;
  for (unsigned char c : path)
    if (c < 0x20 || c == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "\\x%02X", c);
      std::string shown;
      for (unsigned char d : path.substr(0, 200)) shown += d < 0x20 || d == 0x7f ? '?' : static_cast<char>(d);
      throw InputError(option + " '" + shown + (path.size() > 200 ? "...'" : "'") +
                       ": the path holds a control character (" + code +
                       "); paths with control characters are refused");
    }
  const std::string what = option + " " + path;
  std::error_code ec;
  const auto st = fs::symlink_status(path, ec);
  if (fs::exists(st)) {
    // rename() would replace a link by a file (its target untouched) and fails on a
    // directory; a device would first be read as a cache by some programs.
    if (fs::is_symlink(st))
      throw InputError(what + " is a symbolic link: outputs replace only regular files "
                              "(give the file it points to, or a new path)");
    if (fs::is_directory(st)) throw InputError(what + " is a directory, not a file");
    if (!fs::is_regular_file(st))
      throw InputError(what + " is not a regular file (a device, pipe or socket): outputs "
                              "replace only regular files");
    // A store file's rows are sealed results of hours: only the study that wrote it may
    // replace it (through its store, which reuses, verifies and merges them).
    if (const auto program = sealed_file_program(path); program && *program != owner)
      throw InputError(what + " is a sealed result-store file of " + *program +
                       ": only that study writes it (give another path)");
    // A file made read-only, or another user's, was protected on purpose: a rename would
    // replace it with this process's mode and owner (root may keep them: save_atomically).
    struct stat s;
    if (writes && ::stat(path.c_str(), &s) == 0) {
      if ((s.st_mode & 0222) == 0)
        throw InputError(what + " is read-only (mode " + octal(s.st_mode & 07777) +
                         "): not replaced (make it writable, or give another path)");
      if (::geteuid() != 0 && s.st_uid != ::geteuid())
        throw InputError(what + " belongs to another user (uid " + std::to_string(s.st_uid) +
                         "): not replaced (give another path)");
    }
  }
  if (!writes) return;
  // The nearest existing ancestor must be a directory this process can create files in.
  fs::path dir = fs::path(path).parent_path();
  while (!dir.empty() && !fs::exists(fs::status(dir, ec))) dir = dir.parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(fs::status(dir, ec)))
    throw InputError(what + ": " + dir.string() + " is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(what + ": cannot create files in " + dir.string() + " (" +
                     std::strerror(errno) + ")");
}

namespace {
// The atomic write behind every output: `body` into temp_name(NAME), then rename over NAME.
// `owner`: the program a sealed store file at NAME must belong to ("" for none).
void save_atomically(const std::string& path, const std::string& owner,
                     const std::function<void(std::ostream&)>& body) {
  check_output_path("output", path, owner);
  const fs::path p(path);
  if (p.has_parent_path()) fs::create_directories(p.parent_path());
  remove_stale_temps(p);
  const std::string tmp = temp_name(p);
  try {
    // Our own name, but whatever stands there (a link planted to redirect the write) goes.
    std::error_code gone;
    fs::remove(tmp, gone);
    std::ofstream out(tmp, std::ios::trunc);
    if (!out) throw std::runtime_error("cannot create " + tmp + ": " + std::strerror(errno));
    // A file replaced keeps its mode and (root writing) its owner.
    struct stat old;
    if (::stat(path.c_str(), &old) == 0) {
      if (::chmod(tmp.c_str(), old.st_mode & 07777) != 0 ||
          (::geteuid() == 0 && (old.st_uid != 0 || old.st_gid != 0) &&
           ::chown(tmp.c_str(), old.st_uid, old.st_gid) != 0))
        throw std::runtime_error("cannot give " + tmp + " the mode and owner of " + path + ": " +
                                 std::strerror(errno));
    }
    body(out);
    out.close();  // flushes: a full disk shows here
    if (!out) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    std::error_code ec;
    fs::rename(tmp, p, ec);
    if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
}
}  // namespace

void TsvTable::save(const std::string& path) const {
  // A sealed table may replace the sealed file of its own program (the store's save).
  const bool sealed = !columns.empty() && columns.back() == "seal";
  save_atomically(path, sealed ? get("program").value_or("?") : std::string(),
                  [this](std::ostream& out) { write(out); });
}

void save_text(const std::string& path, const std::string& text) {
  save_atomically(path, "", [&text](std::ostream& out) { out << text; });
}

TsvTable TsvTable::load(const std::string& path, bool whole_rows) {
  // A device (/dev/zero) would be read without end; a pipe has an end and may stay.
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_fifo(st))
    throw InputError("data file " + path + " is not a regular file");
  std::ifstream in(path);
  if (!in) throw InputError("cannot read data file " + path);
  TsvTable t;
  t.source = path;
  std::size_t line_no = 0;
  std::string line;
  bool have_header = false;
  auto split = [](const std::string& s) {  // "a\t" is two cells, the second empty
    std::vector<std::string> out;
    std::size_t from = 0;
    for (std::size_t tab; (tab = s.find('\t', from)) != std::string::npos; from = tab + 1)
      out.push_back(s.substr(from, tab - from));
    out.push_back(s.substr(from));
    return out;
  };
  while (std::getline(in, line)) {
    ++line_no;
    // Data files are LF-only UTF-8 without a byte-order mark (.gitattributes keeps the store
    // so): a \r or a BOM would become an invisible part of a cell or key.
    if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
      throw InputError("data file " + path + " starts with a UTF-8 byte-order mark; save it without one");
    if (!line.empty() && line.back() == '\r')
      throw InputError("data file " + path + " line " + std::to_string(line_no) +
                       " ends in CRLF (\\r\\n); data files use LF line endings only");
    if (line.empty()) continue;
    if (line.rfind("# ", 0) == 0) {
      const auto eq = line.find(" = ");
      if (eq != std::string::npos) t.meta.emplace_back(line.substr(2, eq - 2), line.substr(eq + 3));
      continue;
    }
    if (!have_header) {
      t.columns = split(line);
      have_header = true;
    } else {
      t.rows.push_back(split(line));
      t.row_lines.push_back(line_no);
    }
  }
  if (!have_header) throw InputError("data file " + path + " has no column header");
  if (whole_rows) t.require_whole_rows();
  return t;
}

void TsvTable::require_whole_rows() const {
  // A row cut short (or run long) would shift or drop values: refused, not read.
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].size() != columns.size())
      throw InputError("data file " + source +
                       (i < row_lines.size() ? " line " + std::to_string(row_lines[i]) : " data row " + std::to_string(i + 1)) + ": " +
                       std::to_string(rows[i].size()) + " cells for " + std::to_string(columns.size()) +
                       " columns");
}

std::vector<std::vector<std::string>> TsvTable::load_matching(
    const std::string& path, const std::vector<std::pair<std::string, std::string>>& params) {
  if (!std::filesystem::exists(path)) return {};
  TsvTable t;
  try {
    t = load(path);
  } catch (const InputError&) {
    return {};
  }
  for (auto& [k, v] : params) {
    auto have = t.get(k);
    if (!have || *have != v) return {};
  }
  return t.rows;
}

std::string fmt(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string fmt(long long v) { return std::to_string(v); }

namespace {
std::string g_command_line;
}

void set_command_line(int argc, char** argv) {
  std::string out;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    const bool plain = !a.empty() && a.find_first_not_of(
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=,:+^%@") ==
        std::string::npos;
    if (i) out += ' ';
    const bool control = std::any_of(a.begin(), a.end(), [](char c) {
      return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
    });
    if (plain) {
      out += a;
    } else if (control) {
      // bash's $'...': a newline in an argument must not end the `# command` header line.
      out += "$'";
      for (char c : a) {
        const auto u = static_cast<unsigned char>(c);
        char code[8];
        std::snprintf(code, sizeof code, "\\x%02X", u);
        out += u < 0x20 || u == 0x7f ? std::string(code)
               : c == '\'' || c == '\\' ? std::string("\\") + c
                                          : std::string(1, c);
      }
      out += '\'';
    } else {
      out += '\'';
      for (char c : a) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
      out += '\'';
    }
  }
  g_command_line = out;
}

const std::string& command_line() { return g_command_line; }

void add_provenance(TsvTable& t) {
  if (!g_command_line.empty()) t.set("command", g_command_line);
  t.set("git_revision", git_revision());
  char host[256] = {0};
  ::gethostname(host, sizeof host - 1);
  t.set("host", host);
  std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  t.set("written_utc", date);
  t.set("omp_threads", fmt(static_cast<long long>(omp_get_max_threads())));
}

void require_distinct_paths(const std::vector<std::pair<std::string, std::string>>& paths) {
  std::map<std::string, std::string> seen;
  for (auto& [opt, p] : paths) {
    if (p.empty()) continue;
    const std::string norm = fs::weakly_canonical(fs::absolute(p)).string();
    auto [it, fresh] = seen.emplace(norm, opt);
    if (!fresh)
      throw InputError(opt + " " + p + " is the same file as " + it->second +
                       ": each output needs its own path");
  }
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

TsvTable rows_where(const TsvTable& data, const std::vector<std::pair<std::string, std::string>>& where) {
  std::vector<int> cols;
  for (auto& [column, value] : where) cols.push_back(data.require_column(column));
  TsvTable slice = data;
  slice.rows.clear(), slice.row_lines.clear();
  for (std::size_t i = 0; i < data.rows.size(); ++i) {
    bool keep = true;
    for (std::size_t w = 0; w < where.size(); ++w) keep = keep && data.rows[i][cols[w]] == where[w].second;
    if (!keep) continue;
    slice.rows.push_back(data.rows[i]);
    if (i < data.row_lines.size()) slice.row_lines.push_back(data.row_lines[i]);
  }
  return slice;
}

}  // namespace gpm
