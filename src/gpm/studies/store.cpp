#include "gpm/studies/store.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/kernel/device_pass.hpp"

namespace gpm {

namespace fs = std::filesystem;

void add_cache_options(Args& a) {
  a.flag("verify", "recompute the selected units in memory and compare them with --out\n"
                   "  (numbers to 1e-9 relative); write nothing; exit 4 on a difference")
      .flag("recheck", "as --verify, then write: the recomputed units replace the file's and,\n"
                       "  if all agreed, rows of older code are re-stamped as current");
}

CacheMode cache_mode(const Args& a) {
  if (a.has("verify") && a.has("recheck"))
    throw InputError("--verify and --recheck exclude each other");
  return a.has("verify") ? CacheMode::verify : a.has("recheck") ? CacheMode::recheck
                                                                : CacheMode::run;
}

const std::vector<std::string>& row_provenance_columns() {
  static const std::vector<std::string> c = {"code", "made_on", "checked"};
  return c;
}

bool is_volatile_column(const std::string& n) {
  auto ends = [&](const std::string& s) {
    return n.size() >= s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0;
  };
  const auto& prov = row_provenance_columns();
  return ends("_s") || n == "seconds" || n == "s_per_step" || n.find("rss") != std::string::npos ||
         std::find(prov.begin(), prov.end(), n) != prov.end();
}

namespace {

std::string today() {
  char d[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(d, sizeof d, "%Y-%m-%d", std::gmtime(&now));
  return d;
}

// Relative difference of two cells, or −1 if they differ as texts (not both numbers).
// The difference of two cells on the scale of kStoreRelTol (-1: not comparable numbers).
// Residual columns (name contains "residual": a solver's final ‖b − Sx‖/‖b‖, ~1e-11) are
// rounding-level quantities whose relative change across CPUs or memory alignments is ~1e-6
// (seen between two builds on one Zen 5: 6.753016866e-11 and 6.753015450e-11); they are
// compared absolutely, scaled so that kStoreResidualAbsTol maps onto kStoreRelTol.
double cell_difference(const std::string& a, const std::string& b, bool residual) {
  if (a == b) return 0;
  char *ea = nullptr, *eb = nullptr;
  const double x = std::strtod(a.c_str(), &ea), y = std::strtod(b.c_str(), &eb);
  if (a.empty() || b.empty() || *ea || *eb) return -1;
  if (std::isnan(x) || std::isnan(y)) return -1;
  if (residual) return std::fabs(x - y) / kStoreResidualAbsTol * kStoreRelTol;
  const double scale = std::max(std::fabs(x), std::fabs(y));
  return scale > 0 ? std::fabs(x - y) / scale : 0;
}

}  // namespace

LevelCache::LevelCache(std::string path, std::vector<std::pair<std::string, std::string>> params,
                       std::vector<std::string> columns, int key_columns, CacheMode mode,
                       bool writer)
    : path_(std::move(path)),
      key_columns_(key_columns),
      mode_(mode),
      code_(code_fingerprint()),
      made_on_(machine_summary() + (using_device() ? ", device " + device_name() : "")),
      writer_(writer) {
  if (path_.empty()) throw InputError("--out PATH is required (see --help)");
  std::error_code ec;
  const auto st = fs::symlink_status(path_, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw InputError("--out " + path_ + " exists and is not a regular file");
  if (mode_ != CacheMode::verify && writer_) {
    // The writer's lock: a second process on the same file is refused, not raced.
    const std::string lock = path_ + ".lock";
    if (fs::path(path_).has_parent_path()) fs::create_directories(fs::path(path_).parent_path());
    lock_fd_ = ::open(lock.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (lock_fd_ < 0) throw InputError("cannot open lock file " + lock + ": " + std::strerror(errno));
    if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(lock_fd_);
      lock_fd_ = -1;
      throw InputError("another process is writing " + path_ + " (its lock " + lock +
                       " is held); wait for it or choose another --out");
    }
  }
  for (auto& [k, v] : params) table_.set(k, v);
  table_.source = path_;  // for messages naming a malformed cell
  table_.columns = columns;
  for (auto& c : row_provenance_columns()) table_.columns.push_back(c);
  load(params, columns);
}

LevelCache::~LevelCache() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the flock
}

void LevelCache::load(const std::vector<std::pair<std::string, std::string>>& params,
                      const std::vector<std::string>& own_columns) {
  if (!fs::exists(path_)) return;
  const TsvTable old = TsvTable::load(path_);  // InputError names the file if unreadable
  for (auto& [k, v] : params) {
    const auto have = old.get(k);
    if (!have || *have != v) {
      std::fprintf(stderr,
                   "[store] %s: parameter '%s' differs (file: %s; now: %s): its %zu rows are "
                   "not reused%s\n",
                   path_.c_str(), k.c_str(), have ? have->c_str() : "absent", v.c_str(),
                   old.rows.size(), mode_ == CacheMode::verify ? "" : " and will be replaced");
      return;
    }
  }
  params_match_ = true;
  // Rows from before the store had provenance columns: kept, but as "unrecorded" code,
  // which only a re-check can carry over.
  const bool legacy = old.columns == own_columns;
  if (!legacy && old.columns != table_.columns) {
    std::fprintf(stderr, "[store] %s: columns differ from this program's: its %zu rows are "
                         "not reused\n", path_.c_str(), old.rows.size());
    params_match_ = false;
    return;
  }
  // For rows of a file without provenance columns, what its header says of the run.
  const std::string legacy_made_on =
      "CPU unrecorded (host " + old.get("host").value_or("?") + "), " +
      old.get("omp_threads").value_or("?") + " threads, " +
      old.get("written_utc").value_or("?").substr(0, 10);
  std::size_t malformed = 0, first_bad = 0;
  for (std::size_t i = 0; i < old.rows.size(); ++i) {
    auto row = old.rows[i];
    if (row.size() != old.columns.size()) {
      if (malformed++ == 0) first_bad = i + 1;
      continue;
    }
    if (legacy) row.insert(row.end(), {"unrecorded", legacy_made_on, "-"});
    table_.rows.push_back(std::move(row));
  }
  if (malformed)
    std::fprintf(stderr, "[store] %s: %zu malformed rows dropped (first: data row %zu has the "
                         "wrong number of cells); their units are recomputed\n",
                 path_.c_str(), malformed, first_bad);
  const int ccode = table_.column("code");
  for (auto& r : table_.rows) reused_ += r[ccode] == code_;
  const std::size_t other = table_.rows.size() - reused_;
  if (other)
    std::fprintf(stderr, "[store] %s: %zu rows come from other code (fingerprint now %s): not "
                         "reused without --recheck\n", path_.c_str(), other, code_.c_str());
}

std::vector<std::string> LevelCache::key_of(const std::vector<std::string>& row) const {
  return {row.begin(), row.begin() + std::min<std::size_t>(key_columns_, row.size())};
}

std::string LevelCache::key_text(const std::vector<std::string>& key) const {
  std::string s;
  for (std::size_t c = 0; c < key.size(); ++c)
    s += (c ? ", " : "") + table_.columns[c] + " " + key[c];
  return s;
}

bool LevelCache::has(const std::vector<std::string>& key, std::size_t expected_rows) const {
  if (mode_ != CacheMode::run) return false;
  const int ccode = table_.column("code");
  std::size_t n = 0;
  for (auto& r : table_.rows) {
    if (key_of(r) != key) continue;
    if (r[ccode] != code_) return false;
    ++n;
  }
  return n > 0 && (expected_rows == 0 || n == expected_rows);
}

void LevelCache::add(std::vector<std::string> row) {
  const std::size_t own = table_.columns.size() - row_provenance_columns().size();
  if (row.size() != own)
    throw std::logic_error("LevelCache::add: a row of " + std::to_string(row.size()) +
                           " cells for " + std::to_string(own) + " columns (" + path_ + ")");
  row.insert(row.end(), {code_, made_on_, "computed"});
  if (mode_ != CacheMode::run) {
    fresh_.push_back(std::move(row));
    return;
  }
  const auto key = key_of(row);
  if (started_.insert(key).second)
    std::erase_if(table_.rows, [&](const auto& r) { return key_of(r) == key; });
  table_.add_row(std::move(row));
}

void LevelCache::save() {
  if (mode_ != CacheMode::run || !writer_) return;
  add_provenance(table_);
  table_.save(path_);
}

void LevelCache::finish() {
  if (mode_ == CacheMode::run) return;
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
      for (std::size_t c = 0; c < table_.columns.size(); ++c) {
        if (is_volatile_column(table_.columns[c])) continue;
        const double d = cell_difference((*a[i])[c], (*b[i])[c],
                                         table_.columns[c].find("residual") != std::string::npos);
        if (d >= 0) max_diff = std::max(max_diff, d);
        if (d < 0 || d > kStoreRelTol) {
          if (problems.size() < 5)
            problems.push_back(key_text(key) + ", row " + std::to_string(i + 1) + ": " +
                               table_.columns[c] + " " + (*b[i])[c] + " in the file, " +
                               (*a[i])[c] + " now");
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
               "(file's code %s), max relative difference %s (tolerance %g)%s\n",
               what, path_.c_str(), units.size(), missing, compared, codes.empty() ? "-" : codes.c_str(),
               diff, kStoreRelTol, problems.empty() ? ": agree" : "");
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
      const int cchecked = table_.column("checked");
      for (auto& r : table_.rows)
        if (r[ccode] != code_ && old_codes.count(r[ccode])) {
          // The chain of checks stays readable: an older record is kept before the new one.
          const std::string before = r[cchecked] == "computed" || r[cchecked] == "-"
                                         ? std::string()
                                         : r[cchecked] + "; ";
          r[cchecked] = before + "recheck " + today() + " of code " + r[ccode] + ": " +
                        std::to_string(units.size()) + " units recomputed, max rel diff " + diff;
          r[ccode] = code_;
          ++restamped;
        }
    }
    add_provenance(table_);
    table_.save(path_);
    std::fprintf(stderr, "[store] recheck %s: %zu rows re-stamped as current\n", path_.c_str(),
                 restamped);
  }
  if (!agree)
    throw StoreMismatch(path_ + ": " +
                        (compared == 0 ? std::string("no stored unit to compare with") : first));
}

}  // namespace gpm
