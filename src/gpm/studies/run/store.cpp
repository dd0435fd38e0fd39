#include "gpm/studies/run/store.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/kernel/device_pass.hpp"
#include "gpm/studies/define/registry.hpp"  // row_provenance_columns

namespace gpm {

namespace fs = std::filesystem;

void add_cache_options(Args& a) {
  a.flag("verify", "recompute the selected units in memory and compare them with --out\n"
                   "  (numbers to 1e-9 relative); write nothing; exit 4 on a difference")
      .flag("recheck", "as --verify, then write: the recomputed units replace the file's and,\n"
                       "  if all agreed, rows of older code are re-stamped as current")
      .flag("census", "compute nothing: list the units of the selected levels that --out\n"
                      "  lacks; exit 4 if any")
      .flag("replace", "discard what in --out does not match this run (other parameters or\n"
                       "  columns, malformed, unsealed or duplicate rows) instead of refusing");
}

CacheMode cache_mode(const Args& a) {
  std::vector<std::string> given;
  for (const char* f : {"verify", "recheck", "census", "replace"})
    if (a.has(f)) given.push_back(std::string("--") + f);
  if (given.size() > 1) throw InputError(given[0] + " and " + given[1] + " exclude each other");
  return a.has("verify")    ? CacheMode::verify
         : a.has("recheck") ? CacheMode::recheck
         : a.has("census")  ? CacheMode::census
         : a.has("replace") ? CacheMode::replace
                            : CacheMode::run;
}

std::size_t recheck_count(const std::string& record) {
  std::size_t n = 0;
  const auto plus = record.rfind("(+");
  if (plus != std::string::npos) n = std::strtoul(record.c_str() + plus + 2, nullptr, 10);
  for (auto at = record.find("recheck "); at != std::string::npos; at = record.find("recheck ", at + 1)) ++n;
  return n;
}

std::string checked_cell(const std::string& last, std::size_t earlier) {
  return last + (earlier ? " (+" + std::to_string(earlier) + " earlier)" : "");
}

std::string escaped(const std::string& s) {
  if (s.size() > 200) return escaped(s.substr(0, 200)) + " [... " + std::to_string(s.size()) + " characters]";
  std::string out;
  for (unsigned char c : s) {
    if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (c == '\n') out += "\\n";
    else if (c < 0x20 || c >= 0x7f) {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02X", c);
      out += b;
    } else out += static_cast<char>(c);
  }
  return out;
}

bool is_storage_column(const std::string& n) { return n == "storage" || n == "nnz"; }

bool is_path_parameter(const std::string& k) { return k == "solver"; }

bool is_path_column(const std::string& n) {
  static const std::set<std::string> path = {"cg_iterations",      "rel_residual", "cg_mean_iterations",
                                             "max_rel_residual",   "propagator",   "subspace"};
  return path.count(n) > 0;
}

bool is_volatile_column(const std::string& n) {
  auto ends = [&](const std::string& s) {
    return n.size() >= s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0;
  };
  const auto& prov = row_provenance_columns();
  return ends("_s") || n == "seconds" || n == "s_per_step" || n.find("rss") != std::string::npos ||
         std::find(prov.begin(), prov.end(), n) != prov.end();
}

std::string today() {
  char d[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(d, sizeof d, "%Y-%m-%d", std::gmtime(&now));
  return d;
}

namespace {

// Relative difference of two cells, or −1 if they differ as texts (not both numbers).
// The difference of two cells on the scale of kStoreRelTol (-1: not comparable numbers).
// Residual columns (name contains "residual": a solver's final ‖b − Sx‖/‖b‖, ~1e-11) are
// rounding-level quantities whose relative change across CPUs or memory alignments is ~1e-6
// (seen between two builds on one Zen 5: 6.753016866e-11 and 6.753015450e-11), and after
// tens of CG iterations on another vector width much more: Table 4.7's piecewise quintic
// θ = 1 at 2^-5 (about 80 iterations per step) ends at 9.27e-11 on an AVX-512 Zen 5 and at
// 9.68e-11 on an AVX2 EPYC (4.2 %), every error of those rows the same to 1e-13.  So they agree
// within max(kStoreResidualAbsTol, kStoreResidualRelTol·max(|a|, |b|)), scaled onto kStoreRelTol.
// A non-finite number (inf, nan, 1e999, …) never agrees, not even with itself: no study
// writes one into a store file on purpose (a blow-up is written as NA, a text), so one there
// is a failure to be seen, not a value to be carried.
double cell_difference(const std::string& a, const std::string& b, bool residual) {
  char *ea = nullptr, *eb = nullptr;
  const double x = std::strtod(a.c_str(), &ea), y = std::strtod(b.c_str(), &eb);
  const bool numbers = !a.empty() && !b.empty() && !*ea && !*eb;
  if (numbers && (!std::isfinite(x) || !std::isfinite(y))) return -1;
  if (a == b) return 0;
  if (!numbers) return -1;
  if (residual)
    return std::fabs(x - y) /
           std::max(kStoreResidualAbsTol, kStoreResidualRelTol * std::max(std::fabs(x), std::fabs(y))) *
           kStoreRelTol;
  const double scale = std::max(std::fabs(x), std::fabs(y));
  return scale > 0 ? std::fabs(x - y) / scale : 0;
}

// The exclusive lock at `lock` (created if absent), on a descriptor above the standard
// streams (should stderr be closed, a message written to fd 2 must not land in the lock
// file): its descriptor, or -1 if another process holds it.  InputError if it cannot be opened.
int take_lock(const std::string& lock) {
  int fd = ::open(lock.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError("cannot open lock file " + lock + ": " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return -1;
  }
  if (fd <= 2) {
    const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
    ::close(fd);
    if (moved < 0) throw InputError("cannot hold the lock " + lock);
    fd = moved;
  }
  return fd;
}

}  // namespace

StoreFileLock::StoreFileLock(const std::string& file) : fd_(take_lock(file + ".lock")) {
  if (fd_ < 0)
    throw InputError(file + " is being written by another process (its lock " + file +
                     ".lock is held); nothing written");
}

StoreFileLock::~StoreFileLock() {
  if (fd_ >= 0) ::close(fd_);
}

UnitCache::UnitCache(std::string path, std::vector<std::pair<std::string, std::string>> params,
                       std::vector<std::string> columns, int key_columns, CacheMode mode,
                       bool writer, bool quick_run)
    : path_(std::move(path)),
      key_columns_(key_columns),
      mode_(mode),
      code_(code_fingerprint()),
      made_on_(machine_summary() + (using_device() ? ", device " + device_name() : "")),
      writer_(writer),
      quick_run_(quick_run) {
  if (path_.empty()) throw InputError("--out PATH is required (see --help)");
  for (auto& [k, v] : params)
    if (k == "program") program_ = v;
  std::error_code ec;
  const auto st = fs::symlink_status(path_, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw InputError("--out " + path_ + " exists and is not a regular file");
  if (mode_ == CacheMode::recheck && !fs::exists(st))
    throw InputError("--recheck: " + path_ + " does not exist: nothing to re-check");
  if (mode_ == CacheMode::verify && !fs::exists(st))
    throw InputError("--verify: " + path_ + " does not exist: nothing to verify");
  if (mode_ != CacheMode::verify && mode_ != CacheMode::census && writer_) {
    // The writer's lock: a second process on the same file is refused, not raced.
    const std::string lock = path_ + ".lock";
    if (fs::path(path_).has_parent_path()) fs::create_directories(fs::path(path_).parent_path());
    lock_fd_ = take_lock(lock);
    if (lock_fd_ < 0)
      throw InputError("another process is writing " + path_ + " (its lock " + lock +
                       " is held); wait for it or choose another --out");
  }
  for (auto& [k, v] : params) table_.set(k, v);
  params_ = params;
  table_.source = path_;  // for messages naming a malformed cell
  table_.columns = columns;
  for (auto& c : row_provenance_columns()) table_.columns.push_back(c);
  try {
    load(params);
  } catch (...) {
    // A refused file leaves no lock behind (no destructor runs for a throwing constructor).
    if (lock_fd_ >= 0) ::close(lock_fd_);
    throw;
  }
}

UnitCache::~UnitCache() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the flock
}

void UnitCache::refuse_file(const std::string& problem, std::size_t rows, bool replace) {
  if (!replace)
    throw InputError(path_ + ": " + problem + "; nothing written (--replace discards its " +
                     std::to_string(rows) + " rows; or restore the file from git)");
  std::fprintf(stderr, "[store] %s: %s: its %zu rows are discarded (%s)\n", path_.c_str(),
               problem.c_str(), rows, reason_.c_str());
}

void UnitCache::load(const std::vector<std::pair<std::string, std::string>>& params) {
  if (!fs::exists(path_)) return;
  const TsvTable old = TsvTable::load(path_, false);  // InputError: unreadable, CRLF, BOM
  disk_ = disk_state();
  // Only the study that owns a store file writes it: another program's file is refused even
  // with --replace, which would discard its rows.
  if (!old.columns.empty() && old.columns.back() == "seal" && old.get("program").value_or("?") != program_)
    throw InputError("--out " + path_ + " is a sealed result-store file of " +
                     escaped(old.get("program").value_or("?")) + ": only that study writes it (give another path)");
  // A header that names a key twice contradicts itself (a stray line pasted in): which line
  // holds is not guessed, the file is refused (only --replace discards it).
  for (std::size_t i = 0; i < old.meta.size(); ++i)
    for (std::size_t j = i + 1; j < old.meta.size(); ++j)
      if (old.meta[i].first == old.meta[j].first && old.meta[i].second != old.meta[j].second)
        return refuse_file("its header names '" + escaped(old.meta[i].first) + "' twice ('" +
                               escaped(old.meta[i].second) + "', then '" + escaped(old.meta[j].second) +
                               "')",
                           old.rows.size(), mode_ == CacheMode::replace);
  // A sealed file in a result store's folder (…/results/paper/) is its reading's and
  // realization's: --replace recomputes its own units, it never turns one reading's file into
  // another's (Table 4.6's file by a run of Table 4.5, seed 2's by seed 3's, the identified
  // reading's by the printed one's), and it is never a quick-profile cache, whatever its
  // header says.
  const bool sealed = !old.columns.empty() && old.columns.back() == "seal";
  const bool in_store = in_result_store_folder(path_);
  if (sealed && in_store && mode_ == CacheMode::replace)
    for (auto& [k, v] : params) {
      static const std::set<std::string> identity = {"table", "profile", "seed", "h_rule", "volumes",
                                                     "steps", "dt_nominal", "jitter", "function"};
      const auto have = old.get(k);
      if (identity.count(k) && have && *have != v)
        throw InputError("--out " + path_ + " holds another reading or realization (its '" + k + "' is '" +
                         escaped(*have) + "', this run's '" + escaped(v) + "'): --replace replaces a store "
                         "file's own units only (give another path)");
    }
  // A file of the quick profile, found by a quick run, is a cache of minutes: replaced, not
  // defended.  A paper run never discards rows without --replace.
  const bool quick_cache = !(sealed && in_store) && old.get("profile") == "quick" &&
                           (quick_run_ || table_.get("profile") == "quick");
  const bool replace = (mode_ == CacheMode::replace || quick_cache) &&
                       mode_ != CacheMode::verify && mode_ != CacheMode::census;
  reason_ = mode_ == CacheMode::replace ? "--replace" : "a quick-profile cache";
  // --verify by another path (issue 58, item 3): a path parameter (how the numbers were
  // solved for, not which numbers: is_path_parameter) may differ from the file's; the rows
  // are then compared at the path's tolerance, the path's own columns aside.
  // A path parameter the file names and the run does not (a plain run onto a preconditioned
  // run's file) differs as much as one both name.
  for (auto& [k, v] : old.meta)
    if (is_path_parameter(k) && !table_.get(k)) {
      if (mode_ == CacheMode::verify) other_path_ = true;
      else return refuse_file("parameter '" + k + "' differs (file: '" + escaped(v) + "'; now: absent)",
                              old.rows.size(), replace);
    }
  for (auto& [k, v] : params) {
    const auto have = old.get(k);
    if (mode_ == CacheMode::verify && is_path_parameter(k)) {
      if (!have || *have != v) other_path_ = true;
      continue;
    }
    if (!have || *have != v)
      return refuse_file("parameter '" + k + "' differs (file: " +
                             (have ? "'" + escaped(*have) + "'" : std::string("absent")) +
                             "; now: '" + escaped(v) + "')",
                         old.rows.size(), replace);
  }
  if (old.columns != table_.columns) {
    std::vector<std::string> unsealed(table_.columns.begin(), table_.columns.end() - 1);
    if (old.columns == unsealed)
      return refuse_file("its rows carry no seal: every store file has been sealed since 2026-12-02, "
                         "so the seal column was removed (restore the file from git)", old.rows.size(), replace);
    std::size_t c = 0;
    while (c < old.columns.size() && c < table_.columns.size() && old.columns[c] == table_.columns[c]) ++c;
    return refuse_file("its columns differ from this program's (column " + std::to_string(c + 1) +
                           ": file '" + (c < old.columns.size() ? escaped(old.columns[c]) : "-") +
                           "', now '" + (c < table_.columns.size() ? table_.columns[c] : "-") + "')",
                       old.rows.size(), replace);
  }
  // Each row whole, sealed and not a copy of another; the first bad one is named.
  const int cseal = table_.column("seal");
  std::set<std::vector<std::string>> seen;
  std::size_t bad = 0;
  std::string first;
  for (std::size_t i = 0; i < old.rows.size(); ++i) {
    const auto& row = old.rows[i];
    std::string why;
    if (row.size() != old.columns.size())
      why = std::to_string(row.size()) + " cells for " + std::to_string(old.columns.size()) + " columns";
    else if (row[cseal] != row_seal(row, path_))
      why = row[cseal] == row_seal_unbound(row) || row[cseal] == row_seal_without_checked(row)
                ? "sealed before the seal bound rows to their file (2026-12-05): seal the file anew once "
                  "with `gpm store-seal FILE`"
                : "its seal does not match its cells and this file's name (edited after it was written, "
                  "or pasted from another file?)";
    else {
      std::vector<std::string> content;
      for (std::size_t c = 0; c < row.size(); ++c)
        if (!is_volatile_column(table_.columns[c])) content.push_back(row[c]);
      if (!seen.insert(content).second) why = "a duplicate of an earlier row";
    }
    if (why.empty()) {
      table_.rows.push_back(row);
      continue;
    }
    if (bad++ == 0)
      first = "line " + std::to_string(old.row_lines[i]) + " (" + key_text(key_of(row)) + "): " + why;
  }
  if (bad) {
    const std::string problem = std::to_string(bad) + " bad row" + (bad > 1 ? "s" : "") + ", first " + first;
    if (!replace)
      throw InputError(path_ + ": " + problem + "; nothing written (--replace drops " +
                       (bad > 1 ? "them" : "it") + " and recomputes " + (bad > 1 ? "their units" : "its unit") +
                       " when run; or restore the file from git)");
    std::fprintf(stderr, "[store] %s: %s: dropped (%s); their units are recomputed when run\n",
                 path_.c_str(), problem.c_str(), reason_.c_str());
  }
  // The header is sealed too (io/seal.hpp): an edited line (a parameter no run compares, the
  // command, the revision) is refused like an edited row, after the rows so that a file copied
  // under another name is named by its rows.  A sealed file outside a result store written
  // before header seals (2026-12-06) is read without one.
  if (sealed) {
    const std::string problem = header_seal_problem(old.meta, path_);
    const bool absent = !old.get("header_seal");
    if (!problem.empty() && (!absent || in_store)) {
      table_.rows.clear();
      return refuse_file(problem + (absent ? " (seal it once with `gpm store-seal " + path_ + "`)" : ""),
                         old.rows.size(), replace);
    }
  }
  // One unit's rows come from one run (a unit is computed, replaced and re-stamped whole):
  // rows of one unit from two runs are two copies of it, as a merge of two versions of the
  // file leaves them.  Which to keep is not guessed.
  const int cmade = table_.column("made_on"), crun = table_.column("code");
  std::map<std::vector<std::string>, std::pair<std::string, std::string>> run_of;
  std::set<std::vector<std::string>> mixed;
  std::string mix;
  for (auto& r : table_.rows) {
    const auto key = key_of(r);
    const std::pair<std::string, std::string> run{r[crun], r[cmade]};
    const auto [it, fresh] = run_of.emplace(key, run);
    if (fresh || it->second == run || !mixed.insert(key).second || !mix.empty()) continue;
    mix = "unit " + key_text(key) + " holds rows of two runs (code " + it->second.first + ", " +
          it->second.second + "; code " + run.first + ", " + run.second +
          "): two copies of one unit, as a merge leaves them";
  }
  if (!mixed.empty()) {
    if (!replace)
      throw InputError(path_ + ": " + mix + "; nothing written (keep one copy, or --replace drops "
                       "them and recomputes the unit when run)");
    std::fprintf(stderr, "[store] %s: %s: %zu such units dropped (%s)\n", path_.c_str(), mix.c_str(),
                 mixed.size(), reason_.c_str());
    std::erase_if(table_.rows, [&](const auto& x) { return mixed.count(key_of(x)) > 0; });
  }
  const int ccode = table_.column("code");
  for (auto& r : table_.rows) reused_ += r[ccode] == code_;
  const std::size_t other = table_.rows.size() - reused_;
  if (other && running())
    std::fprintf(stderr, "[store] %s: %zu rows come from other code (code fingerprint now %s): not "
                         "reused without --recheck\n", path_.c_str(), other, code_.c_str());
  if (!running()) reused_ = 0;  // verify, recheck, census reuse nothing
}

// A row of older code carried over by a re-check: current code, the last check's record with
// the count of earlier ones, a new seal (its old one was verified when the file was read).
void UnitCache::restamp(std::vector<std::string>& r, const std::string& tail) const {
  const int ccode = table_.column("code"), cchecked = table_.column("checked");
  r[cchecked] = checked_cell("recheck " + today() + " of code " + r[ccode] + tail, recheck_count(r[cchecked]));
  r[ccode] = code_;
  r.back() = row_seal(r, path_);
}

std::vector<std::string> UnitCache::key_of(const std::vector<std::string>& row) const {
  return {row.begin(), row.begin() + std::min<std::size_t>(key_columns_, row.size())};
}

std::string UnitCache::key_text(const std::vector<std::string>& key) const {
  std::string s;
  for (std::size_t c = 0; c < key.size(); ++c)
    s += (c ? ", " : "") + table_.columns[c] + " " + escaped(key[c]);
  return s;
}

bool UnitCache::has(const std::vector<std::string>& key, std::size_t expected_rows) const {
  if (mode_ == CacheMode::verify || mode_ == CacheMode::recheck) return false;
  const int ccode = table_.column("code");
  std::size_t n = 0, current = 0;
  for (auto& r : table_.rows)
    if (key_of(r) == key) ++n, current += r[ccode] == code_;
  const bool whole = n > 0 && (expected_rows == 0 || n == expected_rows);
  if (mode_ == CacheMode::census) {
    if (!whole && std::find(missing_.begin(), missing_.end(), key) == missing_.end())
      missing_.push_back(key);
    return true;
  }
  return whole && current == n;
}

void UnitCache::add(std::vector<std::string> row) {
  const std::size_t own = table_.columns.size() - row_provenance_columns().size();
  if (row.size() != own)
    throw std::logic_error("UnitCache::add: a row of " + std::to_string(row.size()) +
                           " cells for " + std::to_string(own) + " columns (" + path_ + ")");
  row.insert(row.end(), {code_, made_on_, "computed", ""});
  row.back() = row_seal(row, path_);
  if (!running()) {
    fresh_.push_back(std::move(row));
    return;
  }
  const auto key = key_of(row);
  if (started_.insert(key).second)
    std::erase_if(table_.rows, [&](const auto& r) { return key_of(r) == key; });
  table_.add_row(std::move(row));
  ++added_;
}

UnitCache::DiskState UnitCache::disk_state() const {
  struct stat st;
  if (::stat(path_.c_str(), &st) != 0) return {};
  return {static_cast<long long>(st.st_dev), static_cast<long long>(st.st_ino),
          static_cast<long long>(st.st_size), static_cast<long long>(st.st_mtim.tv_sec),
          static_cast<long long>(st.st_mtim.tv_nsec)};
}

// The lock this run took is the one at `<file>.lock` still: a lock file removed (or replaced)
// meanwhile lets a second writer in, so it is taken again at its path, and if another process
// holds it now, this run does not write.
bool UnitCache::hold_lock() {
  const std::string lock = path_ + ".lock";
  struct stat held, now;
  if (::fstat(lock_fd_, &held) == 0 && ::stat(lock.c_str(), &now) == 0 && held.st_dev == now.st_dev &&
      held.st_ino == now.st_ino)
    return false;
  int fd = -1;
  try {
    fd = take_lock(lock);
  } catch (const InputError& e) {
    rescue(std::string("its lock was removed or replaced while this run held it, and ") + e.what());
  }
  if (fd < 0)
    rescue("its lock " + lock + " was removed or replaced while this run held it, and another "
           "process holds the new one");
  ::close(lock_fd_);
  lock_fd_ = fd;
  std::fprintf(stderr, "[store] %s: its lock was removed or replaced while this run held it; "
                       "taken again, the file merged with what is on disk\n", path_.c_str());
  return true;
}

// This run's rows saved beside the file (a new path, never the store file), then InputError.
void UnitCache::rescue(const std::string& problem) {
  const std::string kept = path_ + ".rescued-" + std::to_string(::getpid()) + ".tsv";
  add_provenance(table_);
  table_.save(kept);
  throw InputError(path_ + ": " + problem + ": not written; this run's rows are in " + kept);
}

// Another writer changed the file since this run read or wrote it (a lock file removed, a
// hand edit): its rows are merged, not overwritten.  Per unit: this run's rows where it
// computed the unit, else the file's, else (a unit the file no longer holds) the ones read.
void UnitCache::merge_disk() {
  TsvTable disk;
  try {
    disk = TsvTable::load(path_, false);
  } catch (const InputError& e) {
    rescue(std::string("it changed on disk meanwhile and cannot be read (") + e.what() + ")");
  }
  for (auto& [k, v] : params_)
    if (disk.get(k) != v) rescue("it changed on disk meanwhile, its parameter '" + k + "' now differs");
  if (const std::string problem = header_seal_problem(disk.meta, path_); disk.get("header_seal") && !problem.empty())
    rescue("it changed on disk meanwhile, and " + problem);
  if (disk.columns != table_.columns) rescue("it changed on disk meanwhile, its columns now differ");
  for (std::size_t i = 0; i < disk.rows.size(); ++i)
    if (disk.rows[i].size() != disk.columns.size() || disk.rows[i].back() != row_seal(disk.rows[i], path_))
      rescue("it changed on disk meanwhile, line " + std::to_string(disk.row_lines[i]) +
             " is not a whole sealed row");
  std::vector<std::vector<std::string>> merged;
  std::set<std::vector<std::string>> placed;
  std::size_t taken = 0;
  auto place = [&](const std::vector<std::string>& key) {
    if (!placed.insert(key).second) return;
    bool on_disk = false;
    for (auto& r : disk.rows) on_disk = on_disk || key_of(r) == key;
    const bool ours = started_.count(key) || !on_disk;
    for (auto& r : ours ? table_.rows : disk.rows)
      if (key_of(r) == key) merged.push_back(r), taken += !ours;
  };
  for (auto& r : table_.rows) place(key_of(r));
  for (auto& r : disk.rows) place(key_of(r));
  table_.rows = std::move(merged);
  std::fprintf(stderr, "[store] %s changed on disk while this run held it: merged (%zu rows of "
                       "units this run did not compute taken from the file)\n", path_.c_str(), taken);
}

void UnitCache::write_file() {
  const bool lost = lock_fd_ >= 0 && hold_lock();
  const DiskState now = disk_state();
  if ((lost || now != disk_) && now != DiskState{}) {  // (a file removed meanwhile: ours is written)
    if (!running()) rescue("it changed on disk while this run held it");
    merge_disk();
  }
  add_provenance(table_);
  table_.set("header_seal", header_seal(table_.meta, path_));  // last: it covers every line above
  table_.save(path_);
  disk_ = disk_state();
}

void UnitCache::save() {
  if (!running() || !writer_) return;
  write_file();
}

void UnitCache::finish() {
  if (running()) return;
  if (mode_ == CacheMode::census) {
    // The census is this mode's output (stdout); a failure is one line on stderr.
    std::printf("[store] census %s: %zu rows, %zu units of this run missing\n", path_.c_str(),
                table_.rows.size(), missing_.size());
    for (std::size_t i = 0; i < missing_.size(); ++i)  // every one: tables/store_census.sh prices them
      std::printf("[store]   missing: %s\n", key_text(missing_[i]).c_str());
    std::fflush(stdout);
    if (!missing_.empty())
      throw StoreMismatch(path_ + ": " + std::to_string(missing_.size()) + " units missing, first " +
                          key_text(missing_.front()));
    return;
  }
  const char* what = mode_ == CacheMode::verify ? "verify" : "recheck";
  if (fresh_.empty()) throw InputError(std::string("--") + what + ": no unit selected");
  // The recomputed units, in order, each against the file's rows of the same key.
  std::vector<std::vector<std::string>> units;
  for (auto& r : fresh_)
    if (std::find(units.begin(), units.end(), key_of(r)) == units.end()) units.push_back(key_of(r));
  double max_diff = 0;
  std::size_t compared = 0, missing = 0;
  std::vector<std::string> problems;
  std::set<std::string> old_codes;
  const int ccode = table_.column("code");
  const int cstorage = table_.column("storage");
  const int cpropagator = table_.column("propagator");
  double tol_used = kStoreRelTol;  // the widest tolerance a row was compared at
  bool by_other_path = false;
  for (auto& key : units) {
    std::vector<const std::vector<std::string>*> a, b;
    for (auto& r : fresh_)
      if (key_of(r) == key) a.push_back(&r);
    for (auto& r : table_.rows)
      if (key_of(r) == key) b.push_back(&r);
    if (b.empty()) {
      ++missing;
      if (mode_ == CacheMode::verify) problems.push_back(key_text(key) + ": not in the file");
      continue;
    }
    if (a.size() != b.size()) {
      problems.push_back(key_text(key) + ": " + std::to_string(b.size()) + " rows in the file, " +
                         std::to_string(a.size()) + " computed");
      continue;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
      old_codes.insert((*b[i])[ccode]);
      ++compared;
      // A unit recomputed by another storage of its Laplacian (matrix-free on a device
      // against an assembled row) is compared on its numbers, not on how the product ran.
      const bool other_storage = cstorage >= 0 && (*a[i])[cstorage] != (*b[i])[cstorage];
      // Another path (store.hpp): the run's solver differs from the file's, or this row's
      // propagator from the stored row's (a Krylov subspace for a stepped row).
      const bool other_propagator = cpropagator >= 0 && (*a[i])[cpropagator] != (*b[i])[cpropagator];
      const double tol = other_propagator ? kStorePropagatorPathRelTol
                         : other_path_    ? kStoreSolverPathRelTol
                                          : kStoreRelTol;
      tol_used = std::max(tol_used, tol);
      by_other_path = by_other_path || other_propagator || other_path_;
      for (std::size_t c = 0; c < table_.columns.size(); ++c) {
        if (is_volatile_column(table_.columns[c])) continue;
        if (other_storage && is_storage_column(table_.columns[c])) continue;
        if ((other_propagator || other_path_) && is_path_column(table_.columns[c])) continue;
        const double d = cell_difference((*a[i])[c], (*b[i])[c],
                                         table_.columns[c].find("residual") != std::string::npos);
        if (d >= 0) max_diff = std::max(max_diff, d);
        if (d < 0 || d > tol) {
          if (problems.size() < 5)
            problems.push_back(key_text(key) + ", row " + std::to_string(i + 1) + ": " +
                               table_.columns[c] + " " + escaped((*b[i])[c]) + " in the file, " +
                               escaped((*a[i])[c]) + " now");
          else
            problems.push_back("");
        }
      }
    }
  }
  char diff[32];
  std::snprintf(diff, sizeof diff, "%.3g", max_diff);
  std::string codes;
  for (auto& c : old_codes) codes += (codes.empty() ? "" : ",") + c;
  std::fprintf(stderr,
               "[store] %s %s: %zu units recomputed (%zu not in the file), %zu rows compared "
               "(file's code %s), max relative difference %s (tolerance %g%s)%s\n",
               what, path_.c_str(), units.size(), missing, compared, codes.empty() ? "-" : codes.c_str(),
               diff, tol_used, by_other_path ? ", another path" : "", problems.empty() ? ": agree" : "");
  std::string first;
  for (auto& p : problems)
    if (!p.empty()) {
      std::fprintf(stderr, "[store]   differs: %s\n", p.c_str());
      if (first.empty()) first = p;
    }
  const bool agree = problems.empty() && compared > 0;

  if (mode_ == CacheMode::recheck) {
    // Recomputed units replace the file's in place (new ones at the end); then, only if all
    // agreed, the rows of other code are carried over.
    std::vector<std::vector<std::string>> merged;
    std::set<std::vector<std::string>> placed;
    auto place = [&](const std::vector<std::string>& key) {
      if (!placed.insert(key).second) return;
      for (auto& r : fresh_)
        if (key_of(r) == key) merged.push_back(r);
    };
    for (auto& r : table_.rows) {
      const auto key = key_of(r);
      if (std::find(units.begin(), units.end(), key) != units.end())
        place(key);
      else
        merged.push_back(r);
    }
    for (auto& key : units) place(key);
    table_.rows = std::move(merged);
    // Only rows of a code whose own units were just recomputed and agreed are carried over:
    // agreement with rows that the current code made itself proves nothing about older rows.
    std::size_t restamped = 0;
    if (agree) {
      const std::string tail = ": " + std::to_string(units.size()) + " units recomputed, max rel diff " + diff;
      for (auto& r : table_.rows)
        if (r[ccode] != code_ && old_codes.count(r[ccode])) restamp(r, tail), ++restamped;
      if (restamped) {
        // The whole chain of re-checks lives in a log beside the file, not in every row.
        const fs::path log_path = fs::path(path_).parent_path() / "rechecks.log";
        std::ofstream log(log_path, std::ios::app);
        log << fs::path(path_).filename().string() << "\trecheck " << today() << " of code " << codes
            << tail << " -> " << code_ << "\t" << restamped << " rows\n";
        log.close();
        if (!log)
          throw InputError("cannot append to " + log_path.string() + ": the re-check of " + path_ +
                           " is not written (its record would be lost)");
      }
    }
    write_file();
    std::fprintf(stderr, "[store] recheck %s: %zu rows re-stamped as current\n", path_.c_str(),
                 restamped);
  }
  if (!agree)
    throw StoreMismatch(path_ + ": " +
                        (compared == 0 ? std::string("no stored unit to compare with") : first));
}

}  // namespace gpm
