#include "gpm/studies/run/runner.hpp"

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <sstream>

#ifdef GPM_MPI
#include <mpi.h>
#endif

#include "gpm/error.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/kernel/device_pass.hpp"
#include "gpm/studies/define/registry.hpp"

namespace gpm {

#ifdef GPM_MPI
namespace {
// MPI is started once per process, by its first runner, and finished at exit, unless a rank
// failed: then MPI_Finalize would wait for the others, which wait for its rows; it exits
// non-zero instead, upon which mpirun stops the rest.
bool g_rank_failed = false;
void finalize_mpi() {
  int done = 0;
  MPI_Finalized(&done);
  if (!done && !g_rank_failed) MPI_Finalize();
}
}  // namespace
#endif

StudyRunner::StudyRunner(std::string program, std::string summary, std::string profile_help,
                         Kind kind)
    : program_(std::move(program)), args_(program_, std::move(summary)), kind_(kind) {
#ifdef GPM_MPI
  int started = 0;
  MPI_Initialized(&started);
  if (!started) {
    MPI_Init(nullptr, nullptr);
    std::atexit(finalize_mpi);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#endif
  args_.store_output("out", "", "data file (required)")
      .opt("profile", "quick", profile_help)
      .opt("levels", "", "comma-separated levels k (dx = 2^-k); default: the profile's")
      .opt("device", "cpu",
           "where the kernel passes run: cpu, or cuda (a build configured with -DGPM_CUDA=ON "
           "on a machine with an NVIDIA GPU; matrix-free Laplacians only, see --storage)");
  if (kind_ == Kind::units)
    args_.opt("seed", "1", "jitter seed (non-negative integer)")
        .opt("parts", "1", "split each fused truncation pass (Tables 4.1-4.3, Imoto Sec. 5) into this\n"
                           "  many parts, each saved in <out>.parts/ when done, so an interrupted\n"
                           "  unit resumes from its last part (one process; other studies: no effect)")
        .opt("only", "", "comma-separated key values (h15, or h10,quartic_polynomial): compute only\n"
                         "  the units whose key holds every one; the file's other rows are kept");
}

StudyRunner::~StudyRunner() {
#ifdef GPM_MPI
  if (std::uncaught_exceptions() > 0) {
    g_rank_failed = true;
    if (size_ > 1) std::fprintf(stderr, "[%s] rank %d of %d failed:\n", program_.c_str(), rank_, size_);
  }
#endif
}

void StudyRunner::parse(int argc, char** argv) {
  add_cache_options(args_);
  args_.parse(argc, argv);
  out_ = args_.required("out");
  profile_ = parse_profile(args_.str("profile"));
  const std::string device = args_.str("device");
  if (device != "cpu" && device != "cuda")
    throw InputError("unknown --device '" + device + "'; valid: cpu, cuda");
  use_device(device == "cuda");
  mode_ = cache_mode(args_);
  // parse() checked --out for its kind (and that no other program's store file is named);
  // a run that writes needs its folder writable too (--verify and --census write nothing).
  if (mode_ != CacheMode::verify && mode_ != CacheMode::census)
    check_output_path("--out", out_, program_, /*writes=*/true);
  if (kind_ == Kind::units) {
    seed_ = args_.seed();
    const std::string parts = args_.str("parts");
    char* end = nullptr;
    const long k = std::strtol(parts.c_str(), &end, 10);
    if (parts.empty() || *end != '\0' || k < 1 || k > 4096)
      throw InputError("--parts '" + parts + "' is not an integer from 1 to 4096");
    parts_ = static_cast<int>(k);
    if (parts_ > 1 && size_ > 1)
      throw InputError("--parts splits a pass on one process; " + std::to_string(size_) +
                       " ranks share it already");
  }
  if (size_ > 1 && mode_ != CacheMode::run && mode_ != CacheMode::replace)
    throw InputError("--verify, --recheck and --census run on one process, not on " +
                     std::to_string(size_) + " ranks");
  start_ = std::chrono::steady_clock::now();
}

StudyRunner::StudyRunner(const RegisteredStudy& study, std::string summary)
    : StudyRunner(study.program, std::move(summary), study.levels.help(),
                  study.own_seeds ? Kind::units_without_seed : Kind::units) {
  study_ = &study;
}

std::vector<int> StudyRunner::levels() const {
  if (!study_) throw std::logic_error("StudyRunner::levels(): not made from a registered study");
  return levels(study_->levels.quick, study_->levels.paper);
}

std::vector<StudyUnit> StudyRunner::units() const {
  if (!study_ || !study_->units) throw std::logic_error("StudyRunner::units(): the study lists no units");
  std::vector<StudyUnit> out;
  units_listed_ = true;
  // --only narrows the run, never the file: a long unit can go first (a 2^-11 h15 solve
  // before the hour-long h10 one) without a second data file.
  const std::vector<std::string> only = kind_ == Kind::units ? args_.list("only") : std::vector<std::string>{};
  const auto selected = [&](const StudyUnit& u) {
    return std::all_of(only.begin(), only.end(), [&](const std::string& v) {
      return std::find(u.key.begin(), u.key.end(), v) != u.key.end();
    });
  };
  bool any = false;
  for (StudyUnit& u : study_->units({profile_ == Profile::paper, levels(), levels_given()})) {
    if (!u.trimmed.empty()) continue;
    any = true;
    if (selected(u)) out.push_back(std::move(u));
  }
  if (any && out.empty()) throw InputError("--only '" + args_.str("only") + "' selects no unit of " + program_);
  return out;
}

UnitCache& StudyRunner::open(std::vector<std::pair<std::string, std::string>> params, int key_columns) {
  if (!study_) throw std::logic_error("StudyRunner::open(params, key): not made from a registered study");
  return open(std::move(params), study_->columns, key_columns);
}

std::vector<int> StudyRunner::levels(const std::vector<int>& quick,
                                     const std::vector<int>& paper, int lo, int hi) const {
  return levels_option(args_, profile_, quick, paper, lo, hi);
}

UnitCache& StudyRunner::open(std::vector<std::pair<std::string, std::string>> params,
                              std::vector<std::string> columns, int key_columns) {
  return *open_files({{out_, std::move(params)}}, std::move(columns), key_columns).front();
}

std::vector<UnitCache*> StudyRunner::open_files(std::vector<DataFile> files,
                                                 std::vector<std::string> columns,
                                                 int key_columns) {
  if (!caches_.empty()) throw std::logic_error("StudyRunner: data files opened twice");
  for (auto& [k, v] : files.front().params) params_text_ += k + "=" + v + ";";
  std::vector<UnitCache*> out;
  for (auto& f : files) {
    for (auto& p : paths_)
      if (p == f.path) throw InputError("one data file named twice in one run: " + f.path);
    // A file that refuses (InputError) leaves the earlier ones' locks to their destructors.
    file_columns_.push_back(f.columns.empty() ? columns : f.columns);
    caches_.push_back(std::make_unique<UnitCache>(f.path, std::move(f.params), file_columns_.back(),
                                                   key_columns, mode_, rank_ == 0, profile_ == Profile::quick));
    paths_.push_back(f.path);
    saved_added_.push_back(0);
    if (caches_.back()->reused() > 0 && rank_ == 0)
      std::fprintf(stderr, "[%s] reusing %zu stored rows of %s\n", program_.c_str(),
                   caches_.back()->reused(), f.path.c_str());
    out.push_back(caches_.back().get());
  }
  return out;
}

void StudyRunner::expect(double work, const char* unit) {
  progress_ = std::make_unique<Progress>(program_, work, unit, 0.0);
}

bool StudyRunner::claim(double cost) { return claim_group(1, cost); }

bool StudyRunner::claim_group(int n, double cost) {
  // A program that lists its units itself (thesis_heat: --weights, --thetas) would compute
  // every unit under a --only it never read; a verification by parts then recomputed whole
  // levels, once per part (found 2026-12-07).
  if (!units_listed_ && kind_ == Kind::units && !args_.str("only").empty())
    throw InputError("--only '" + args_.str("only") + "': " + program_ +
                     " does not select its units by key; use its own options (--help)");
  const long first = next_unit_;
  next_unit_ += n;
  if (load_.empty()) load_.assign(static_cast<std::size_t>(size_), 0.0);
  const auto least = std::min_element(load_.begin(), load_.end());
  *least += cost;
  if (least - load_.begin() != rank_) return false;
  for (long u = first; u < first + n; ++u) claimed_.push_back({u, false});
  return true;
}

bool StudyRunner::claim_shared() {
  claimed_.push_back({next_unit_++, size_ > 1});
  return true;
}

TargetShare StudyRunner::share() const {
  if (claimed_.empty() || !claimed_.front().shared) return {};
  return {rank_, size_};
}

void StudyRunner::reduce(ErrorMaxima& m) const {
  if (share().parts == 1) return;
#ifdef GPM_MPI
  // Every share as one array of doubles (maxima, exact maxima, worst particles, pairs; the
  // particle indices are exact in a double), gathered on every rank and merged in rank order.
  const std::size_t n = m.error.size(), len = 3 * n + 2;
  std::vector<double> mine(len), all(len * static_cast<std::size_t>(size_));
  for (std::size_t i = 0; i < n; ++i)
    mine[i] = m.error[i], mine[n + i] = m.exact[i], mine[2 * n + i] = m.worst[i];
  mine[3 * n] = m.pairs, mine[3 * n + 1] = m.kernel_seconds;
  MPI_Allgather(mine.data(), static_cast<int>(len), MPI_DOUBLE, all.data(),
                static_cast<int>(len), MPI_DOUBLE, MPI_COMM_WORLD);
  ErrorMaxima merged;
  for (int r = 0; r < size_; ++r) {
    const double* a = all.data() + len * static_cast<std::size_t>(r);
    ErrorMaxima part;
    part.error.assign(a, a + n);
    part.exact.assign(a + n, a + 2 * n);
    for (std::size_t i = 0; i < n; ++i) part.worst.push_back(static_cast<int32_t>(a[2 * n + i]));
    part.pairs = a[3 * n];
    part.kernel_seconds = a[3 * n + 1];
    if (r == 0) merged = std::move(part);
    else merged.merge_following(part);
  }
  merged.kernel_seconds = m.kernel_seconds;  // a timing: this rank's own share
  m = std::move(merged);
#else
  (void)m;  // one process: share() is always the whole
#endif
}

namespace {
// A part's maxima as text that reads back bit for bit (%a: hexadecimal floating point).
std::string hex(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%a", x);
  return b;
}
// A part file's seal: row_seal over its header values (but the seal's own) and its cells.
std::string part_seal(const TsvTable& t) {
  std::vector<std::string> cells;
  for (auto& [k, v] : t.meta)
    if (k != "seal") cells.push_back(k + "=" + v);
  for (auto& c : t.columns) cells.push_back(c);
  for (auto& r : t.rows) cells.insert(cells.end(), r.begin(), r.end());
  cells.push_back("");  // the seal's place (row_seal leaves the last cell out)
  return row_seal_unbound(cells);
}
double unhex(const std::string& s, const std::string& file) {
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0') throw InputError("part file " + file + ": '" + s + "' is not a number");
  return x;
}
}  // namespace

ErrorMaxima StudyRunner::shared_pass(const std::string& unit,
                                     const std::function<ErrorMaxima(TargetShare)>& pass) {
  if (size_ > 1 || parts_ == 1) {
    ErrorMaxima m = pass(share());
    reduce(m);
    return m;
  }
  // The part files: named by the unit (characters outside [A-Za-z0-9.-] become '_'); a part
  // is reused only if its header names this program, code, parameters, seed and unit.
  std::string name;
  for (char c : unit) name += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  const std::string dir = out_ + ".parts";
  const std::vector<std::pair<std::string, std::string>> id = {
      {"program", program_}, {"code", code_fingerprint(program_)}, {"params", params_text_},
      {"seed", std::to_string(seed_)}, {"unit", unit}, {"parts", std::to_string(parts_)}};
  ErrorMaxima all;
  for (int i = 0; i < parts_; ++i) {
    const std::string file = dir + "/" + name + "." + std::to_string(i) + "of" + std::to_string(parts_) + ".tsv";
    ErrorMaxima m;
    bool loaded = false;
    try {
      const TsvTable t = TsvTable::load(file);
      bool same = t.get("part").value_or("") == std::to_string(i);
      for (auto& [k, v] : id) same = same && t.get(k).value_or("") == v;
      // The part's seal (as a store row's, over its header and cells) says it is whole and
      // unedited; a part that fails it is named and computed again.
      if (same && t.get("seal").value_or("") != part_seal(t)) {
        std::fprintf(stderr, "[%s] %s: part file %s is not whole or was edited (its seal does not "
                             "match): computed again\n", program_.c_str(), unit.c_str(), file.c_str());
        same = false;
      }
      if (same) {
        for (auto& r : t.rows) {
          m.error.push_back(unhex(r[t.require_column("error")], file));
          m.exact.push_back(unhex(r[t.require_column("exact")], file));
          m.worst.push_back(static_cast<int32_t>(unhex(r[t.require_column("worst")], file)));
        }
        m.pairs = unhex(t.get("pairs").value_or(""), file);
        m.kernel_seconds = unhex(t.get("kernel_seconds").value_or(""), file);
        loaded = true;
      }
    } catch (const InputError&) {
      // no such file (or not a part file of this form): the part is computed
    }
    if (loaded) {
      std::fprintf(stderr, "[%s] %s: part %d of %d read from %s\n", program_.c_str(), unit.c_str(),
                   i + 1, parts_, file.c_str());
    } else {
      m = pass({i, parts_});
      TsvTable t;
      for (auto& [k, v] : id) t.set(k, v);
      t.set("part", std::to_string(i));
      t.set("pairs", hex(m.pairs));
      t.set("kernel_seconds", hex(m.kernel_seconds));
      t.columns = {"error", "exact", "worst"};
      for (std::size_t j = 0; j < m.error.size(); ++j)
        t.rows.push_back({hex(m.error[j]), hex(m.exact[j]), hex(static_cast<double>(m.worst[j]))});
      t.set("seal", part_seal(t));
      t.save(file);  // (creates the folder)
      std::fprintf(stderr, "[%s] %s: part %d of %d saved (%.1f s)\n", program_.c_str(), unit.c_str(),
                   i + 1, parts_, m.kernel_seconds);
    }
    done_parts_.push_back(file);
    if (i == 0) all = std::move(m);
    else all.merge_following(m);
  }
  return all;
}

// A program may claim several units before computing them (the θ of one Laplacian): their
// rows come in the order of the claims, each unit closed by unit_done().
void StudyRunner::add(std::size_t file, std::vector<std::string> row) {
  if (file >= caches_.size()) throw std::logic_error("StudyRunner::add: no data file " + std::to_string(file));
  if (size_ == 1) {
    caches_[file]->add(std::move(row));
    return;
  }
  if (claimed_.empty()) throw std::logic_error("StudyRunner::add: a row of no claimed unit");
  if (claimed_.front().shared && rank_ != 0) return;  // every rank has them: rank 0's are kept
  mine_.push_back({claimed_.front().unit, file, std::move(row)});
}

// The header's record of the run so far: wall time and peak memory.
void StudyRunner::stamp(TsvTable& t) const {
  t.set("wall_time_s", elapsed_s());
  t.set("peak_rss_mib", peak_rss_mib());
}

// One finished unit: its line, and the progress advanced by its work.
void StudyRunner::report(double work, const std::string& line) {
  if (size_ > 1)
    std::fprintf(stderr, "[%s rank %d] %s\n", program_.c_str(), rank_, line.c_str());
  else
    std::fprintf(stderr, "[%s] %s\n", program_.c_str(), line.c_str());
  done_ += work;
  if (progress_) progress_->update(done_);
}

void StudyRunner::unit_done(double work, const std::string& line) {
  if (size_ == 1)  // several ranks: rank 0 writes everything in finish()
    for (std::size_t f = 0; f < caches_.size(); ++f) {
      // Of several files, only those this unit added to (a file's wall time is the run's
      // up to its last unit).
      if (caches_.size() > 1 && caches_[f]->added() == saved_added_[f]) continue;
      stamp(caches_[f]->table());
      caches_[f]->save();
      saved_added_[f] = caches_[f]->added();
    }
  if (!claimed_.empty()) claimed_.pop_front();
  // The unit's rows are written: its saved parts are no longer needed.
  if (size_ == 1 && caches_.front()->writes())
    for (auto& f : done_parts_) std::remove(f.c_str());
  done_parts_.clear();
  report(work, line);
}

// Every rank's rows to rank 0, which adds them in the order of their units (the order one
// process computes them in) and writes the file.  Rows travel as text: the cells are the
// file's own, so rank 0 writes what the computing rank formatted.
void StudyRunner::gather_rows() {
#ifdef GPM_MPI
  std::string text;
  for (auto& [unit, file, row] : mine_) {
    text += std::to_string(unit) + "\t" + std::to_string(file);
    for (auto& cell : row) text += "\t" + cell;
    text += "\n";
  }
  int len = static_cast<int>(text.size());
  std::vector<int> lens(size_), offs(size_, 0);
  MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank_ == 0) {
    for (int r = 1; r < size_; ++r) offs[r] = offs[r - 1] + lens[r - 1];
    all.resize(static_cast<std::size_t>(offs[size_ - 1] + lens[size_ - 1]));
  }
  MPI_Gatherv(text.data(), len, MPI_CHAR, all.data(), lens.data(), offs.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  if (rank_ != 0) return;
  std::vector<MyRow> rows;
  std::istringstream in(all);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream ls(line);
    for (std::string c; std::getline(ls, c, '\t');) cells.push_back(c);
    const long unit = std::stol(cells.at(0));
    const std::size_t file = std::stoul(cells.at(1));
    cells.erase(cells.begin(), cells.begin() + 2);
    rows.push_back({unit, file, std::move(cells)});
  }
  // Within a unit the rows keep their order (stable sort): one rank made them all.
  std::stable_sort(rows.begin(), rows.end(),
                   [](const MyRow& a, const MyRow& b) { return a.unit < b.unit; });
  for (auto& r : rows) caches_.at(r.file)->add(std::move(r.row));
  for (auto& c : caches_) {
    stamp(c->table());
    c->table().set("mpi_ranks", std::to_string(size_));
    c->save();
  }
#endif
}

bool StudyRunner::finish() {
  if (progress_) progress_->finish();
  if (caches_.empty()) return true;
  if (size_ > 1) {
    gather_rows();
    if (rank_ != 0) return false;  // rank 0 alone writes (the file and what derives from it)
  }
  // Verify/recheck/census: every file is checked before the first difference is thrown.
  std::exception_ptr first;
  for (auto& c : caches_) try {
      c->finish();
    } catch (const StoreMismatch&) {
      if (!first) first = std::current_exception();
    }
  if (first) std::rethrow_exception(first);
  if (!caches_.front()->writes()) return false;
  for (std::size_t f = 0; f < caches_.size(); ++f) {
    const UnitCache& c = *caches_[f];
    if (c.rows().empty()) throw InputError("no level selected: nothing to write to " + paths_[f]);
    if (c.added() == 0)
      std::printf("%s: nothing to compute: %s holds every selected unit (%zu rows, %.1f s)\n",
                  program_.c_str(), paths_[f].c_str(), c.rows().size(), elapsed_s());
    else
      std::printf("%s: wrote %s (%zu rows: %zu new, %zu reused, %.1f s)\n", program_.c_str(),
                  paths_[f].c_str(), c.rows().size(), c.added(), c.reused(), elapsed_s());
  }
  return true;
}

double StudyRunner::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string line_printf(const char* format, ...) {
  char buf[1024];
  va_list ap;
  va_start(ap, format);
  std::vsnprintf(buf, sizeof buf, format, ap);
  va_end(ap);
  return buf;
}

}  // namespace gpm
