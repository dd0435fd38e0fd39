// gpm fingerprint, store-seal, store-add-columns, store-rates, rate-levels, checked-reasons,
// verdicts, decisions: the committed result store, its provenance and the verdicts read from it.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "gpm/error.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/io/text_format.hpp"
#include "gpm/studies/judge/checked_reasons.hpp"
#include "gpm/studies/judge/decisions.hpp"
#include "gpm/studies/judge/page_verdicts.hpp"
#include "gpm/studies/judge/error_constants.hpp"
#include "gpm/studies/judge/mode_constants.hpp"
#include "gpm/studies/judge/rate_levels.hpp"
#include "gpm/studies/judge/rates.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/judge/setup_identification.hpp"
#include "gpm/studies/run/store.hpp"
#include "gpm/studies/judge/open_causes.hpp"
#include "gpm/studies/judge/verdicts.hpp"

namespace gpm::cli {

namespace {

// The folders a store subcommand reads (--store, --published, --data): each must exist.
void require_directories(const std::vector<std::pair<std::string, std::string>>& options) {
  for (auto& [option, path] : options)
    if (!std::filesystem::is_directory(path)) throw InputError("--" + option + " " + path + " is not a directory");
}

using Lines = std::vector<std::pair<std::string, std::string>>;

// The header every output of the store's verdicts starts with: the program, the git revision
// and the date, then the lines given; `store_rows`: the table's rows are the store's, so also
// the store's profile and seed (store_provenance).
TsvTable verdicts_header(const std::string& program, const std::string& store, bool store_rows, const Lines& lines) {
  TsvTable h;
  h.set("program", program);
  for (auto& [k, v] : store_provenance(store))
    if (store_rows || k == "git_revision" || k == "written_utc") h.set(k, v);
  for (auto& [k, v] : lines) h.set(k, v);
  return h;
}

// `t` with `header`'s lines ahead of its own (a TsvTable writes its meta in order).
TsvTable headed(TsvTable t, const TsvTable& header) {
  t.meta.insert(t.meta.begin(), header.meta.begin(), header.meta.end());
  return t;
}

}  // namespace

// The fingerprint of the code that decides each named program's numbers, as the result
// store's rows carry it (provenance.hpp): a stored row is current when they agree.
int cmd_fingerprint(int argc, char** argv) {
  if (argc >= 3 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h")) {
    std::cout << "usage: gpm fingerprint PROGRAM...\n"
                 "The code fingerprint of each program: the `code` column of a result-store row\n"
                 "it computed with the code of this build (results/paper/README.md).\n";
    return 0;
  }
  if (argc < 3) throw InputError("gpm fingerprint: name at least one program (see --help)");
  const auto known = fingerprinted_programs();
  for (int i = 2; i < argc; ++i)
    if (std::find(known.begin(), known.end(), argv[i]) == known.end())
      throw InputError("gpm fingerprint: '" + std::string(argv[i]) + "' is not a program of this build; valid: " +
                       join(known, ", "));
  TsvTable t;
  t.set("git_revision", git_revision());
  t.columns = {"program", "code"};  // two columns written on the next line: kept by position
  for (int i = 2; i < argc; ++i) t.add_row({argv[i], code_fingerprint(argv[i])});
  print(t);
  return 0;
}

// gpm store-seal: the steps that gave the result store's rows their seal (store.hpp), each
// done once per file.  A file written before seals (provenance columns code, made_on, checked)
// gets the seal column; each row's `checked` chain of re-checks is cut to its last record with
// the count of earlier ones, the chain itself going to rechecks.log beside the file.  A file
// sealed before the seal covered `checked` (2026-12-03) has every row verified under that
// seal and is sealed anew; a row that fails refuses the file.  Sealing vouches for nothing but
// the rows as they are now: their history is git's.
namespace {
void seal_unsealed(TsvTable& t, const std::string& path) {
  t.columns.push_back("seal");
  const int cchecked = t.require_column("checked");
  std::map<std::string, std::size_t> chains;  // each distinct chain once, with its row count
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    auto& row = t.rows[r];
    if (row.size() + 1 != t.columns.size())
      throw InputError(path + " line " + std::to_string(t.row_lines[r]) + ": " +
                       std::to_string(row.size()) + " cells for " + std::to_string(t.columns.size() - 1) +
                       " columns; mend or recompute it before sealing");
    std::string& chain = row[cchecked];
    const auto last = chain.rfind("; ");
    if (last != std::string::npos) {
      ++chains[chain];
      chain = checked_cell(chain.substr(last + 2), recheck_count(chain) - 1);
    }
    row.push_back("");
    row.back() = row_seal(row, path);
  }
  const auto log_path = std::filesystem::path(path).parent_path() / "rechecks.log";
  std::ofstream log(log_path, std::ios::app);
  for (auto& [chain, n] : chains)
    log << std::filesystem::path(path).filename().string() << "\t" << n << " rows\t" << chain << "\n";
  log.close();
  if (!log) throw InputError("cannot append to " + log_path.string() + "; " + path + " not sealed");
}

// Returns the number of rows sealed anew (0: every row carries the current seal already).  A
// row is verified under the one earlier rule the file's rows all share (without `checked`,
// or without the file's name) before it is sealed anew; a file whose rows mix rules, or a row
// under none, is refused whole.
std::size_t seal_anew(TsvTable& t, const std::string& path) {
  std::size_t current = 0, unbound = 0, unchecked = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    auto& row = t.rows[r];
    const bool whole = row.size() == t.columns.size();
    if (whole && row.back() == row_seal(row, path)) ++current;
    else if (whole && row.back() == row_seal_unbound(row)) ++unbound;
    else if (whole && row.back() == row_seal_without_checked(row)) ++unchecked;
    else
      throw InputError(path + " line " + std::to_string(t.row_lines[r]) +
                       ": its seal matches its cells under no rule (this file's name, the seal before it, "
                       "the seal before `checked`); nothing written");
  }
  if (current != t.rows.size() && (current != 0 || (unbound != 0 && unchecked != 0)))
    throw InputError(path + ": its rows carry seals of different rules (" + std::to_string(current) + " current, " +
                     std::to_string(unbound) + " without the file's name, " + std::to_string(unchecked) +
                     " without `checked`); nothing written");
  for (auto& row : t.rows) row.back() = row_seal(row, path);
  return t.rows.size() - current;
}
// Whether git's committed version of `path` (HEAD, where the file is tracked) has sealed rows
// and a sealed header: then a copy without the seal column or the header_seal line had it
// removed, and sealing it anew would bless whatever was edited meanwhile.  Both false where
// git or the file's history is absent.
struct Committed {
  bool sealed_rows = false, sealed_header = false;
};
Committed git_committed(const std::string& path) {
  const std::filesystem::path p = std::filesystem::absolute(path);
  const std::string cmd = "git -C '" + p.parent_path().string() + "' show 'HEAD:./" + p.filename().string() +
                          "' 2>/dev/null";
  Committed c;
  if (p.string().find('\'') != std::string::npos) return c;  // not quotable here: no check
  FILE* f = ::popen(cmd.c_str(), "r");
  if (!f) return c;
  char buf[65536];
  while (std::fgets(buf, sizeof buf, f)) {
    std::string line(buf);
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    if (line.rfind("# header_seal = ", 0) == 0) c.sealed_header = true;
    if (line.empty() || line[0] == '#') continue;
    c.sealed_rows = line.size() >= 5 && line.compare(line.size() - 5, 5, "\tseal") == 0;
    break;
  }
  while (std::fgets(buf, sizeof buf, f)) {}
  ::pclose(f);
  return c;
}

// One line per sealing in rechecks.log: the file, its rows, when and by whom.
void log_sealing(const std::string& path, std::size_t rows, const std::string& what) {
  const char* user = std::getenv("USER");
  char host[256] = "?";
  ::gethostname(host, sizeof host - 1);
  const auto log_path = std::filesystem::path(path).parent_path() / "rechecks.log";
  std::ofstream log(log_path, std::ios::app);
  log << std::filesystem::path(path).filename().string() << "\t" << rows << " rows\t" << what << " "
      << today() << " by " << (user ? user : "?") << "@" << host << " (gpm store-seal)\n";
  log.close();
  if (!log) throw InputError("cannot append to " + log_path.string() + "; " + path + " not sealed");
}
}  // namespace

int cmd_store_seal(int argc, char** argv) {
  if (argc >= 3 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h")) {
    std::cout << "usage: gpm store-seal FILE...\n"
                 "Seals result-store files: one written before seals gets the seal column (its\n"
                 "re-check chains shortened to their last record); one sealed under an earlier\n"
                 "rule (before the seal bound a row to its file's name, 2026-12-05, or covered\n"
                 "`checked`, 2026-12-03) is verified row by row under that rule and sealed anew;\n"
                 "a header without its seal (before 2026-12-06) gets one.  An edited header, or a\n"
                 "seal removed from git's committed version, is refused.\n";
    return 0;
  }
  if (argc < 3) throw InputError("gpm store-seal: name at least one file (see --help)");
  for (int i = 2; i < argc; ++i) {
    const std::string path = argv[i];
    TsvTable t = TsvTable::load(path);
    const std::vector<std::string> before = {"code", "made_on", "checked"};
    const bool sealed = !t.columns.empty() && t.columns.back() == "seal";
    if (!sealed && (t.columns.size() < 3 || !std::equal(before.begin(), before.end(), t.columns.end() - 3)))
      throw InputError(path + ": not a store file (its last columns are neither code, made_on, "
                       "checked nor ... seal)");
    const Committed committed = git_committed(path);
    if (!sealed && committed.sealed_rows)
      throw InputError(path + ": git's committed version is sealed, this copy has no seal column: a "
                       "removed seal is not sealed again (restore the file from git); nothing written");
    // The header's seal (2026-12-06): added where it is absent, never renewed over an edit.
    const bool has_header_seal = t.get("header_seal").has_value();
    if (const std::string problem = header_seal_problem(t.meta, path); has_header_seal && !problem.empty())
      throw InputError(path + ": " + problem + ": an edited header is not sealed again (restore the file "
                       "from git); nothing written");
    if (!has_header_seal && committed.sealed_header)
      throw InputError(path + ": git's committed version has a header_seal line, this copy none: a removed "
                       "seal is not sealed again (restore the file from git); nothing written");
    std::string what = "sealed";
    if (!sealed) {
      seal_unsealed(t, path);
    } else if (seal_anew(t, path) != 0) {
      what = "sealed anew (the seal now binds the file's name)";
    } else if (!has_header_seal) {
      what = "header sealed (rows sealed already)";
    } else {
      std::cout << path << ": every row and the header sealed already (" << t.rows.size() << " rows)\n";
      continue;
    }
    t.set("header_seal", header_seal(t.meta, path));
    log_sealing(path, t.rows.size(), what);
    t.save(path);
    std::cout << "sealed " << path << " (" << t.rows.size() << " rows)\n";
  }
  return 0;
}

// gpm store-add-columns: a column added to a study's data file after rows were stored (the
// heat tables' `propagator` and `subspace`, which every row made before them has as
// `stepped`, 0).  Every row's seal is verified first (a file with a bad row is refused whole),
// the cells inserted after the named column, each row re-sealed, and the step logged in
// rechecks.log beside the file.  It vouches for what the value means for the old rows, nothing
// else: their numbers are untouched.
int cmd_store_add_columns(int argc, char** argv) {
  Args a("gpm store-add-columns",
         "Adds columns with one value to every row of result-store files written before they\n"
         "existed: seals verified, cells inserted after --after, rows re-sealed, logged.");
  a.opt("after", "", "the column the new ones follow (required)")
      .opt("add", "", "NAME=VALUE[,NAME=VALUE…]: the new columns and their value (required)")
      .opt("files", "", "comma list of store files (required)");
  a.parse(argc, argv, 2);
  for (const char* o : {"after", "add", "files"})
    if (a.str(o).empty()) throw InputError("gpm store-add-columns: --" + std::string(o) + " is required");
  std::vector<std::pair<std::string, std::string>> add;
  for (auto& item : a.list("add")) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--add: '" + item + "' is not NAME=VALUE");
    // A tab or a newline in a cell would cut every row of the file in the wrong place.
    for (unsigned char c : item)
      if (c < 0x20 || c == 0x7f)
        throw InputError("--add: '" + escaped(item) + "' holds a control character; nothing written");
    add.push_back({item.substr(0, eq), item.substr(eq + 1)});
  }
  // Every file locked and checked before any is written: one bad file leaves all as they were.
  std::vector<std::unique_ptr<StoreFileLock>> locks;
  std::vector<std::pair<std::string, TsvTable>> done;
  for (auto& path : a.list("files")) {
    locks.push_back(std::make_unique<StoreFileLock>(path));
    TsvTable t = TsvTable::load(path);
    const int after = t.column(a.str("after"));
    if (after < 0) throw InputError(path + ": no column '" + a.str("after") + "'; nothing written");
    if (t.column("seal") != static_cast<int>(t.columns.size()) - 1)
      throw InputError(path + ": not a sealed store file (its last column is not 'seal'); nothing written");
    for (auto& [name, value] : add)
      if (t.column(name) >= 0) throw InputError(path + ": has a column '" + name + "' already; nothing written");
    for (std::size_t r = 0; r < t.rows.size(); ++r)
      if (t.rows[r].size() != t.columns.size() || t.rows[r].back() != row_seal(t.rows[r], path))
        throw InputError(path + " line " + std::to_string(t.row_lines[r]) +
                         ": its seal does not match its cells and this file's name; nothing written");
    if (const std::string problem = header_seal_problem(t.meta, path); !problem.empty())
      throw InputError(path + ": " + problem + "; nothing written");
    std::vector<std::string> names, values;
    for (auto& [name, value] : add) names.push_back(name), values.push_back(value);
    t.columns.insert(t.columns.begin() + after + 1, names.begin(), names.end());
    for (auto& row : t.rows) {
      row.insert(row.begin() + after + 1, values.begin(), values.end());
      row.back() = row_seal(row, path);
    }
    t.set("header_seal", header_seal(t.meta, path));
    done.emplace_back(path, std::move(t));
  }
  for (auto& [path, t] : done) {
    t.save(path);
    std::ofstream log(std::filesystem::path(path).parent_path() / "rechecks.log", std::ios::app);
    log << std::filesystem::path(path).filename().string() << "\t" << t.rows.size() << " rows\t"
        << "columns added " << today() << " after " << a.str("after") << ": " << a.str("add") << "\n";
    if (!log) throw InputError(path + ": cannot append to rechecks.log");
    std::cout << "added " << a.str("add") << " to " << path << " (" << t.rows.size() << " rows)\n";
  }
  return 0;
}

// The rate-against-level view as written: the rates per pair of levels and (second) the
// finding per series, each with the header lines that say how they were computed.
std::pair<TsvTable, TsvTable> rate_levels_tables(const StoreSnapshot& store, const PublishedTables& published) {
  const RateLevels r = rate_levels(store, published);
  const Lines lines = {{"tolerance", fmt(kRateTolerance)},
                       {"rate", "log(e1/e2)/log(h1/h2) of rel_error (4.2) between consecutive stored levels"},
                       {"band", "min and max of the rate over seed 1 and the stored realizations <file>_seedN holding both levels"},
                       {"where", "document: the documents' pair; beyond: finer than their finest level; coarser"}};
  TsvTable rates = verdicts_header("gpm rate-levels", store.dir(), false, lines);
  rates.columns = r.rates.columns, rates.rows = r.rates.rows;
  TsvTable findings = verdicts_header("gpm rate-levels --findings", store.dir(), false,
                                      {{"rule", "approaches: the last two rates within the tolerance of the theory's, or the "
                                                "distance falling over the last three pairs with the last within 0.3; stays "
                                                "away: the finest pair beyond the documents, more than 0.3 off and no nearer "
                                                "than the pair before; otherwise not decided"}});
  findings.columns = r.findings.columns, findings.rows = r.findings.rows;
  return {std::move(rates), std::move(findings)};
}

// The open set-up questions as written (decisions.hpp), `score` the boards' counts.
TsvTable decisions_table(const StoreSnapshot& store, const PublishedTables& published, const std::string& diagnostics,
                         const std::optional<TsvTable>& score) {
  TsvTable table = decisions(store, published, diagnostics, score);
  table.meta = verdicts_header("gpm decisions", store.dir(), false, {{"store", store.dir()}}).meta;
  return table;
}

// gpm rate-levels: the heat tables' and Table 4.4's rates at every consecutive pair of stored
// levels, with their seed bands, beside the published and the theory's rates, and a finding
// per series (rate_levels.hpp): whether the rates approach the theory's as the thesis
// conjectured.
// (gpm store-rates --rate-levels writes the same in its judging pass.)
int cmd_rate_levels(int argc, char** argv) {
  Args a("gpm rate-levels",
         "The two-level rates at every consecutive pair of stored levels of the heat tables (printed\n"
         "and identified reading) and of Table 4.4 (both h rules, V_i = dx^2), with seed bands, beside\n"
         "the published and the theory's rates; and per series whether the rates approach the\n"
         "theory's (src/gpm/studies/judge/rate_levels.hpp).");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published", "the published values (thesis_table4_N_long.tsv)")
      .output("out", "", "the rates per pair of levels (required)")
      .output("findings", "", "one finding per table, reading, weight and theta (optional)");
  a.parse(argc, argv, 2);
  const std::string out_path = a.required("out");
  require_directories({{"store", a.str("store")}, {"published", a.str("published")}});
  auto [rates, findings] = rate_levels_tables(StoreSnapshot(a.str("store"), StoreChecks::store), a.str("published"));
  rates.save(out_path);
  if (!a.str("findings").empty()) findings.save(a.str("findings"));
  return 0;
}

// The store file each per-reading figure draws on each board (identified: the reading the
// set-up rule identified, or the printed one where it decided none; printed: the study's
// printed slice), from the registry: figures/store_reading.sh reads it by column name.
TsvTable figure_files_table(const StudyRegistry& registry, const std::optional<PdeReading>& identified) {
  TsvTable t;
  t.columns = {"study", "figure", "board", "reading", "store_file"};
  for (const RegisteredStudy& s : registry.studies())
    for (const StudyFigure& f : s.figures) {
      if (!f.per_reading || !s.published) continue;
      const std::string printed = s.published->printed_slice;
      for (const auto& [board, reading] :
           {std::pair<std::string, std::string>{"identified", identified ? identified->name() : printed},
            std::pair<std::string, std::string>{"printed", printed}})
        t.add_row({s.name, f.name, board, reading, s.store_file_of(reading).name + ".tsv"});
    }
  return t;
}

// gpm store-rates: the documents' rates judged against the committed result store (verdicts.hpp),
// the report's paper-scale tables.  Every input is read and every output path checked before
// anything is written; each output is written to a temporary file and renamed (TsvTable::save).
int cmd_store_rates(int argc, char** argv) {
  Args a("gpm store-rates",
         "The documents' rates from the committed result store, with their verdicts and the two\n"
         "scoreboards (src/gpm/studies/judge/verdicts.hpp defines every verdict); no study is run.");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published", "the published values (imoto_table1.tsv, thesis_table4_N_long.tsv)")
      .flag("no-reasons", "judge without any checked reason (every differing rate unexplained)")
      .output("out", "", "the rates with their verdicts and boards (required)")
      .output("reasons", "", "the checked reasons computed here, one row per checked rate (gpm checked-reasons --out)")
      .output("reasons-by-mechanism", "", "the same reasons, one row per mechanism")
      .output("summary", "", "where the stored rows come from, file by file")
      .output("score", "", "the verdict counts per table and slice, and each board's totals")
      .output("ident", "", "setup_identification's table: the set-up fingerprint evidence of Chapter 4's reading")
      .output("causes", "", "the open rates of the identified board grouped by what the store says of them "
                            "(src/gpm/studies/judge/open_causes.hpp)")
      .output("figure-files", "", "the store file each per-reading figure draws, identified and printed "
                                  "(figures/store_reading.sh)")
      .output("decisions", "", "the documents' open set-up questions with the store's evidence, the boards' "
                               "reading among them (gpm decisions; src/gpm/studies/judge/decisions.hpp)")
      .opt("diagnostics", "results/diagnostics", "targeted diagnostic runs that are not studies, for --decisions "
                                                 "(imoto_m5_where.tsv)")
      .output("rate-levels", "", "the heat rates at every pair of stored levels (gpm rate-levels)")
      .output("findings", "", "per heat series, whether its rates approach the theory's (gpm rate-levels --findings)")
      .output("constants", "", "the error constant e/h^p of every heat and Poisson series per level and realization, "
                               "beside its a-priori model (src/gpm/studies/judge/error_constants.hpp)")
      .output("constant-findings", "", "per series, the error constants' finding (approaches, stays away, not decided)");
  a.parse(argc, argv, 2);
  const std::string out = a.required("out"), pub = a.str("published");
  require_directories({{"store", a.str("store")}, {"published", pub}});
  // One read of the store: every judgement below reads its files from this snapshot.
  const StoreSnapshot store(a.str("store"), StoreChecks::store);  // the store's door (snapshot.hpp)
  const PublishedTables published(pub);  // and one read of each published file
  // The checked reasons, computed from the same store in this pass (one read of the store
  // judges every rate; the reasons' files are outputs).
  const bool computed = !a.has("no-reasons");
  if (!computed && (!a.str("reasons").empty() || !a.str("reasons-by-mechanism").empty()))
    throw InputError("--reasons and --reasons-by-mechanism write the reasons computed here: not with --no-reasons");
  const TsvTable reasons = computed ? checked_reasons(store, published, kRateTolerance) : TsvTable{};
  const CheckedReasons checked = a.has("no-reasons") ? CheckedReasons{} : passed_reasons(reasons);

  // The reading of Chapter 4 that Table 4.6's theta = 0 rates identify (paper/04-setup-rule.md).
  const RegisteredStudy& fp = setup_fingerprint_study(study_registry());
  SetupIdentification ident = identify_setup(store, fp, published.file(fp.published->file));
  const std::vector<JudgedRate> judged = judge_rates(store_rates(store, published, kRateTolerance),
                                                     store_unstable_series(store, published), checked,
                                                     kRateTolerance, ident.identified);
  auto with_header = [&](TsvTable t, const std::string& program, const Lines& lines) {
    return headed(std::move(t), verdicts_header(program, store.dir(), /*store_rows=*/true, lines));
  };
  // Every table is made before the first is written: a store file that cannot be read leaves
  // no output half done.
  std::vector<std::pair<std::string, TsvTable>> outputs;
  outputs.emplace_back(
      out, with_header(rates_table(judged), "gpm store-rates",
                       {{"store", store.dir()},
                        {"checked_reasons", computed ? "computed from the store in this pass (checked_reasons.hpp)"
                                                     : "none (no reason accepted)"},
                        {"note", "rates at the documents' levels from the committed paper-profile rows; status from "
                                 "rate_table (tolerance " + fmt(kRateTolerance) + "); verdict as listed in "
                                 "src/gpm/studies/judge/verdicts.hpp"}}));
  if (!a.str("summary").empty())
    outputs.emplace_back(
        a.str("summary"),
        with_header(store_summary(store), "gpm store-rates (summary)",
                    {{"store", store.dir()},
                     {"current", "rows whose code column is the fingerprint of this build's program (gpm fingerprint)"}}));
  const TsvTable score = score_table(judged, published);
  if (!a.str("score").empty())
    outputs.emplace_back(
        a.str("score"),
        with_header(score, "gpm store-rates (score)",
                    {{"boards", "printed: every set-up detail as the text prints it; identified: the readings of "
                                "paper/04-setup-rule.md (fingerprint: a published rate that identified the reading)"}}));
  const std::pair<std::string, std::string> reasons_note = {
      "note", "rules and thresholds in src/gpm/studies/judge/checked_reasons.hpp; published values from " + pub};
  if (!a.str("reasons").empty())
    outputs.emplace_back(a.str("reasons"),
                         headed(reasons, verdicts_header("gpm store-rates (checked reasons)", store.dir(), false,
                                                         {{"store", store.dir()},
                                                          {"tolerance", fmt(kRateTolerance) + " (rates)"},
                                                          reasons_note})));
  if (!a.str("reasons-by-mechanism").empty())
    outputs.emplace_back(a.str("reasons-by-mechanism"),
                         headed(reasons_by_mechanism(reasons),
                                verdicts_header("gpm store-rates (checked reasons by mechanism)", store.dir(), false,
                                                {{"sources", a.str("reasons")}, reasons_note})));
  if (!a.str("causes").empty())
    outputs.emplace_back(
        a.str("causes"),
        with_header(open_causes(judged, kRateTolerance), "gpm store-rates (open causes)",
                    {{"open", "identified board: differs, unexplained; both unstable, rate differs"},
                     {"causes", "another reading gives it (a stored reading other than the identified one within the "
                                "tolerance of the published rate); robust gap (at least " +
                                    std::to_string(kSeedBandDecides) +
                                    " realizations, all on one side); blow-up rate (sign only); one realization"}}));
  if (!a.str("figure-files").empty())
    outputs.emplace_back(a.str("figure-files"),
                         with_header(figure_files_table(study_registry(), ident.identified),
                                     "gpm store-rates (figure files)",
                                     {{"identified", ident.identified ? ident.identified->name() : "NA (the printed reading drawn)"}}));
  if (!a.str("ident").empty()) {
    ident.table.set("program", "gpm store-rates (setup_identification)");
    add_provenance(ident.table);
    outputs.emplace_back(a.str("ident"), ident.table);
  }
  if (!a.str("decisions").empty())
    outputs.emplace_back(a.str("decisions"), decisions_table(store, published, a.str("diagnostics"), score));
  if (!a.str("rate-levels").empty() || !a.str("findings").empty()) {
    auto [rates, findings] = rate_levels_tables(store, published);
    if (!a.str("rate-levels").empty()) outputs.emplace_back(a.str("rate-levels"), std::move(rates));
    if (!a.str("findings").empty()) outputs.emplace_back(a.str("findings"), std::move(findings));
  }
  if (!a.str("constants").empty() || !a.str("constant-findings").empty()) {
    ErrorConstants ec = error_constants(store, published, a.str("diagnostics"));
    const Lines lines = {{"constant", "rel_error / h^p, p the theory's rate"},
                         {"model", "the one-mode prediction / h^p (Table 4.4: R eps/((1-eps)), R = max|u - phi| = " +
                                       fmt(poisson_boundary_factor()) + "; heat: thesis_heat_mode_model)"},
                         {"limit", "the model's constant as h -> 0"},
                         {"R", format_text("%.6f", poisson_boundary_factor())},
                         {"projected_excess", "thesis_mode_excess's (1-Q)/eps - 1 (heat) or its Poisson form, seed 1, from " +
                                                  a.str("diagnostics") + " (NA where not measured)"},
                         {"rule", "q = |e/predicted - 1|; approaches: q <= " + fmt(kConstantReach) +
                                      " and not growing; stays away: q > " + fmt(kConstantReach) +
                                      " and q >= 0.9 q_before; else not decided (rule dated 2026-12-05, "
                                      "results/predictions/error_constants_2e-11.md)"}};
    if (!a.str("constants").empty())
      outputs.emplace_back(a.str("constants"), headed(std::move(ec.constants),
                                                      verdicts_header("gpm store-rates (error constants)", store.dir(), false, lines)));
    if (!a.str("constant-findings").empty())
      outputs.emplace_back(a.str("constant-findings"),
                           headed(std::move(ec.findings),
                                  verdicts_header("gpm store-rates (error-constant findings)", store.dir(), false, lines)));
  }
  for (auto& [path, table] : outputs) table.save(path);
  return 0;
}

// gpm checked-reasons: the reasons for differing paper-scale rates, each with the diagnostic
// that checks it against the committed store (checked_reasons.hpp); gpm store-rates computes the
// same in its judging pass.  Both tables are made before either is written (temporary file and
// rename each): a store file that cannot be read leaves no output half done.
int cmd_checked_reasons(int argc, char** argv) {
  Args a("gpm checked-reasons",
         "Reasons for paper-scale rates that differ from the published ones, each with the\n"
         "diagnostic that checks it against the committed result store (pass or fail, and whether\n"
         "a run restores the published rate); src/gpm/studies/judge/checked_reasons.hpp states each rule.");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published", "the published values (thesis_table4_N_long.tsv)")
      .output("out", "", "one row per checked rate: table, slice, key, reason, evidence, check, restores (required)")
      .output("by-mechanism", "", "the same reasons, one row per mechanism with the rows it covers");
  a.parse(argc, argv, 2);
  const std::string out = a.required("out"), store = a.str("store"), pub = a.str("published");
  require_directories({{"store", store}, {"published", pub}});
  TsvTable checked = checked_reasons(StoreSnapshot(store, StoreChecks::store), pub, kRateTolerance);
  // The header: what the report prints under the table.
  const std::pair<std::string, std::string> note = {
      "note", "rules and thresholds in src/gpm/studies/judge/checked_reasons.hpp; published values from " + pub};
  std::vector<std::pair<std::string, TsvTable>> outputs;
  outputs.emplace_back(out, headed(checked, verdicts_header("gpm checked-reasons", store, false,
                                                            {{"store", store}, {"tolerance", fmt(kRateTolerance) + " (rates)"}, note})));
  if (!a.str("by-mechanism").empty())
    outputs.emplace_back(a.str("by-mechanism"), headed(reasons_by_mechanism(checked),
                                                       verdicts_header("gpm checked-reasons (by mechanism)", store, false,
                                                                       {{"sources", out}, note})));
  for (auto& [path, table] : outputs) table.save(path);
  return 0;
}

// gpm verdicts: page one of the report, a verdict per item of the documents with the number
// that decides it (page_verdicts.hpp).  Every input is read before the output is written
// (temporary file and rename).
int cmd_verdicts(int argc, char** argv) {
  Args a("gpm verdicts",
         "Page one of the report: one verdict per figure and table of the documents (the items\n"
         "file), each with the number that decides it, from the store's score and this run's data\n"
         "files; src/gpm/studies/judge/page_verdicts.hpp states each rule and how rows are merged.");
  a.opt("items", "tables/items.tsv", "the documents' items and the rule of each (document, item, shows, rule, section)")
      .opt("score", "", "the store's verdict counts (gpm store-rates --score; required)")
      .opt("data", "", "the folder of this run's data files (koba_sato_cor71.tsv, core_voronoi.tsv, ...; required)")
      .output("out", "", "page one's table: document, item, shows, verdict, evidence, section (required)");
  a.parse(argc, argv, 2);
  const std::string out = a.required("out"), score = a.required("score"), data = a.required("data"),
                    items = a.str("items");
  require_directories({{"data", data}});
  TsvTable page = page_verdicts(TsvTable::load(items), TsvTable::load(score), page_data_dir(data));
  page.meta = verdicts_header("gpm verdicts", "", false,
                              {{"items", items}, {"score", score + " (paper scale, the result store)"}, {"data", data}})
                  .meta;
  page.save(out);
  return 0;
}

// gpm decisions: the documents' open set-up questions, each with the evidence the committed
// store gives (decisions.hpp).  The table is made before it is written (temporary file and
// rename): a store file that cannot be read leaves no output.
int cmd_decisions(int argc, char** argv) {
  Args a("gpm decisions",
         "The documents' open set-up questions (time step, volumes, smoothing, Omega_H, ...), each\n"
         "with the evidence the committed result store gives; src/gpm/studies/judge/decisions.hpp lists them.");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published", "the published values (thesis_table4_N_long.tsv, imoto_table1.tsv)")
      .opt("diagnostics", "results/diagnostics", "targeted diagnostic runs that are not studies (imoto_m5_where.tsv)")
      .opt("score", "", "the store's verdict counts (gpm store-rates --score): adds which reading each table ran")
      .output("out", "", "one row per question: question, evidence, decision (required)");
  a.parse(argc, argv, 2);
  const std::string out = a.required("out"), store = a.str("store"), pub = a.str("published");
  require_directories({{"store", store}, {"published", pub}});
  std::optional<TsvTable> score;
  if (!a.str("score").empty()) score = TsvTable::load(a.str("score"));
  decisions_table(StoreSnapshot(store, StoreChecks::store), pub, a.str("diagnostics"), score).save(out);
  return 0;
}

}  // namespace gpm::cli
