// One runner for every study program of the catalog.  It owns what the programs share, so
// that a study program is left with its method (a loop over levels):
//   * the common options: --out (required), --profile, --levels, --seed, --verify, --recheck;
//   * the data file: its parameters and columns, the per-unit cache and the result store's
//     fingerprints, lock and re-check (UnitCache, store.hpp);
//   * one line per finished unit, a progress line with an ETA, the wall time and peak memory
//     in the file's header, and the closing "wrote …" line;
//   * --parts K: a shared pass (below) split into K parts on one process, each part saved in
//     <out>.parts/ as it finishes, so that a unit longer than the time a machine is held
//     (the fused pass at 2^-12: hours) resumes from its last saved part.
// No inheritance: a program makes a StudyRunner, adds its own options to args(), and calls
// open() / claim() / add() / unit_done() / finish() around its loop.
//
// On a cluster (built with -DGPM_MPI=ON, started by mpirun): every rank runs the same loop,
// and a unit is done one of two ways.
//   * Dealt: claim(cost) gives the unit to one rank, the one with the least predicted work
//     so far (ties: the lowest rank; with equal costs this is round-robin in loop order).
//     Units whose arithmetic cannot be split without changing its result (a CG solve, a
//     heat run) are dealt.
//   * Shared: claim_shared() gives the unit to every rank; each computes its share() of the
//     targets and reduce() combines the shares in rank order, exactly (maxima: the fused
//     truncation passes), so that the largest unit (2^-12) no longer bounds the run.
// finish() gathers every row to rank 0, which adds them in loop order and alone writes the
// data file (holding its lock).  The file is then the one a single process writes, timing
// columns aside.  An MPI run writes at its end only (a job should be sized to its time
// limit: one table per job, see bench/slurm_paper.sh).
//
//   StudyRunner run(study_registry().study("thesis_table4_4"), "Discrete Poisson problem …");
//   run.args().opt("tol", "1e-10", "CG relative residual");
//   run.parse(argc, argv);
//   UnitCache& cache = run.open(params, 3);         // the entry's columns
//   for (const StudyUnit& unit : run.units()) {      // the entry's units: level, h, key
//     if (cache.has(unit.key) || !run.claim(cost)) continue;  // stored, or another rank's
//     …; run.add(row); run.unit_done(work, line);
//   }
//   run.finish();   // gathers to rank 0; verify/recheck: nothing more written
#pragma once
#include <chrono>
#include <deque>
#include <functional>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gpm/io/args.hpp"
#include "gpm/io/progress.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/studies/run/store.hpp"

namespace gpm {

struct RegisteredStudy;  // registry.hpp
struct StudyUnit;

class StudyRunner {
 public:
  // How a study names its particle sets; either way its finished units are cached in the
  // result store (--verify, --recheck).  `units`: one jitter realization (--seed) per run.
  // `units_without_seed`: the study names its particle sets itself (core_voronoi's --seeds,
  // imoto_regularity's): no --seed, no --parts.
  enum class Kind { units, units_without_seed };
  // `profile_help` is the --profile help (the catalog's ProfileLevels::help()).
  StudyRunner(std::string program, std::string summary, std::string profile_help,
              Kind kind = Kind::units);
  // A study of the registry (registry.hpp): its program, --profile help, kind (own_seeds),
  // levels per profile and columns are the entry's, so levels() and open(params, key) need
  // no more.  The entry must outlive the runner.
  StudyRunner(const RegisteredStudy& study, std::string summary);
  // MPI: a rank leaving by an exception skips MPI_Finalize at exit (its non-zero exit makes
  // mpirun stop the others, which would otherwise wait for its rows).
  ~StudyRunner();
  StudyRunner(const StudyRunner&) = delete;
  StudyRunner& operator=(const StudyRunner&) = delete;

  // The study's own options, declared before parse().
  Args& args() { return args_; }
  // Parses the command line and checks the common options (bad input: InputError).
  void parse(int argc, char** argv);

  const std::string& program() const { return program_; }
  const std::string& out() const { return out_; }
  Profile profile() const { return profile_; }
  uint64_t seed() const { return seed_; }
  CacheMode mode() const { return mode_; }
  // Whether --levels was given, and the levels a run uses: --levels, else the profile's.
  bool levels_given() const { return !args_.str("levels").empty(); }
  std::vector<int> levels(const std::vector<int>& quick, const std::vector<int>& paper,
                          int lo = 3, int hi = 13) const;
  // The registered study's levels (--levels, else its profile's).
  std::vector<int> levels() const;
  // The registered study's units of this run's scope (profile, levels), in its order
  // (RegisteredStudy::units), less those the profile trims, narrowed by --only.  A program
  // that claims work (claim, claim_group) without having asked for them does not select by
  // --only: the claim refuses a given --only (InputError) before any unit is computed.
  std::vector<StudyUnit> units() const;

  // The data file: rows are reused only where `params` agree with its header; `columns` are
  // the study's own (the store's provenance columns follow); a unit is keyed by the first
  // `key_columns` of a row.  Says how many rows it reuses.
  UnitCache& open(std::vector<std::pair<std::string, std::string>> params,
                   std::vector<std::string> columns, int key_columns);
  // The registered study's data file, with its columns.
  UnitCache& open(std::vector<std::pair<std::string, std::string>> params, int key_columns);
  UnitCache& cache() { return *caches_.at(0); }
  // Several data files from one run: variants of a set-up that share its costly part (the
  // heat readings of one Laplacian: volumes and time-step rules), each its own file with its
  // own parameters, the columns and unit keys common.  Rows go to a file by its index
  // (add(file, row)); every file is cached, verified and written as open()'s one.  The
  // files' paths replace --out (which names the pattern they were made from).
  struct DataFile {
    std::string path;
    std::vector<std::pair<std::string, std::string>> params;
    // Its own columns, for files that are parts of one study with different rows (the
    // Poisson failure probes and their h sweep); empty: open_files' common columns.
    std::vector<std::string> columns = {};
  };
  std::vector<UnitCache*> open_files(std::vector<DataFile> files, std::vector<std::string> columns,
                                      int key_columns);

  // Whether this process computes the next unit still to do.  Called, in loop order, for every
  // unit not in the cache (the same sequence on every rank, with the same costs); always
  // true on one process.  `cost`: the unit's predicted work, any additive measure.
  bool claim(double cost = 1);
  // The next n units together, to one rank (units that share a costly set-up: the θ of one
  // heat Laplacian); `cost` is their sum.  Always true on one process.
  bool claim_group(int n, double cost);
  // The next unit, for every rank: each computes its share() of the targets and calls
  // reduce() on its maxima; the unit's rows are kept from rank 0 (every rank may add them).
  // Always true.
  bool claim_shared();
  TargetShare share() const;  // of the unit being computed: {rank, ranks} if shared, else all
  // Every share of the current shared unit merged in rank order (the result of one pass over
  // all targets), on every rank.  One process: unchanged.
  void reduce(ErrorMaxima& m) const;
  // The pass of the shared unit being computed, over all its targets: `pass` computes one
  // share.  Several ranks: this rank's share, then reduce().  One process: the whole, or with
  // --parts K the K parts in target order, each loaded from <out>.parts/<unit>.<i>of<K>.tsv
  // when a part of the same program, code, parameters, seed and unit was saved there, else
  // computed and saved (atomically), then merged in order (merge_following: exactly the one
  // pass).  A unit's part files are removed once its rows are written (unit_done).
  ErrorMaxima shared_pass(const std::string& unit, const std::function<ErrorMaxima(TargetShare)>& pass);
  // One row of a unit this process computed (UnitCache::add on one process; kept for the
  // gathering in finish() on several).
  void add(std::vector<std::string> row) { add(0, std::move(row)); }
  void add(std::size_t file, std::vector<std::string> row);
  // A row of the study's own columns filled by name (TsvRow), and that row added.
  TsvRow row(std::size_t file = 0) const { return TsvRow(file_columns_.at(file)); }
  void add(const TsvRow& row) { add(0, row.cells()); }
  void add(std::size_t file, const TsvRow& row) { add(file, row.cells()); }
  int rank() const { return rank_; }
  int ranks() const { return size_; }

  // The work still to do (pairs, steps, …: any additive measure), for the ETA.
  void expect(double work, const char* unit);
  // After the rows of one unit were added: wall time and peak memory into the header, the
  // file written (atomically), `line` printed, the progress advanced by `work`.
  void unit_done(double work, const std::string& line);
  // After the last unit.  Verify/recheck mode: compares (throws StoreMismatch on a difference)
  // and returns false: nothing else is to be written.  Run mode: the closing line; true.
  bool finish();


  // Seconds since parse().
  double elapsed_s() const;

 private:
  std::string program_;
  const RegisteredStudy* study_ = nullptr;  // the registry's entry, where made from one
  Args args_;
  std::string out_;
  Profile profile_ = Profile::quick;
  Kind kind_;
  uint64_t seed_ = 1;
  CacheMode mode_ = CacheMode::run;
  std::vector<std::unique_ptr<UnitCache>> caches_;  // open() or open_files()
  std::vector<std::string> paths_;
  std::vector<std::vector<std::string>> file_columns_;  // each file's own columns (open_files)
  std::vector<std::size_t> saved_added_;  // rows each file had added when last written
  int parts_ = 1;                          // --parts
  mutable bool units_listed_ = false;      // units() was asked: --only is honoured
  std::string params_text_;                // the first data file's parameters, for part files
  std::vector<std::string> done_parts_;    // part files of the unit being computed
  std::unique_ptr<Progress> progress_;
  double done_ = 0;
  std::chrono::steady_clock::time_point start_;
  int rank_ = 0, size_ = 1;
  long next_unit_ = 0;        // claim() counter
  std::vector<double> load_;  // predicted work dealt to each rank so far
  struct Claimed {
    long unit;
    bool shared;
  };
  std::deque<Claimed> claimed_;  // units claimed here and not yet done, in claim order
  // Rows computed here while several ranks run: unit number, file index, row.
  struct MyRow {
    long unit;
    std::size_t file;
    std::vector<std::string> row;
  };
  std::vector<MyRow> mine_;
  void gather_rows();
  void stamp(TsvTable& t) const;
  void report(double work, const std::string& line);
};

// printf into a std::string: the one-line report of a finished unit.
std::string line_printf(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace gpm
