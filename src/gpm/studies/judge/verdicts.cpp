#include "gpm/studies/judge/verdicts.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

#include "gpm/error.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/studies/judge/rates.hpp"

namespace gpm {

namespace {

// Every verdict with its printed name, score column, the group a one-line summary counts
// it in (reproduced, explained by a measurement, not explained, used to identify the set-up,
// undecided, missing) and whether it leaves the rate open (a miss no diagnostic accounts for:
// tests/paper/known_unexplained.tsv lists each): the one place they are spelled.
struct VerdictSpelling {
  Verdict verdict;
  std::string name, column, group;
  bool open = false;
};
const std::vector<VerdictSpelling>& spellings() {
  static const std::vector<VerdictSpelling> s = {
      {Verdict::agrees, "agrees", "agrees", "reproduced"},
      {Verdict::non_convergence, "non-convergence reproduced", "non_convergence", "reproduced"},
      {Verdict::sign_only, "both unstable, rate differs", "sign_only", "not_explained", true},
      {Verdict::in_seed_band, "inside seed band", "in_seed_band", "reproduced"},
      {Verdict::checked_reason, "differs, checked reason", "checked_reason", "explained"},
      {Verdict::explained_ours, "our rate explained, the published one not", "explained_ours", "explained"},
      {Verdict::near_miss, "near miss", "near_miss", "not_explained", true},
      {Verdict::pre_asymptotic, "pre-asymptotic, not comparable at the tolerance", "pre_asymptotic", "undecided", true},
      {Verdict::unexplained, "differs, unexplained", "unexplained", "not_explained", true},
      {Verdict::not_computed, "not computed", "not_computed", "missing"},
      {Verdict::undefined, "undefined", "undefined", "undecided"},
      {Verdict::setup_fingerprint, "fingerprint", "fingerprint", "used_for_setup"},
      {Verdict::indeterminate, "consistent with the spread of realizations", "consistent_spread", "consistent"},
      {Verdict::not_counted, "not counted", "", ""},
  };
  return s;
}

const VerdictSpelling& spelling(Verdict v) {
  for (auto& s : spellings())
    if (s.verdict == v) return s;
  throw std::logic_error("verdict without a spelling");
}

// The tables of the documents with a published rate, each with the slice of the reading its
// text prints (the printed board), in registry order (the order the score totals them).
std::vector<std::pair<std::string, std::string>> printed_slices(const StudyRegistry& registry) {
  std::vector<std::pair<std::string, std::string>> p;
  for (auto& s : registry)
    if (s.published) p.emplace_back(s.published->table, s.published->printed_slice);
  return p;
}

// The slice of each table on the identified board: a table whose slice follows the set-up
// reading (Chapter 4's PDE tables) takes the identified one; the rest as printed.
std::map<std::string, std::string> identified_slices(const std::optional<PdeReading>& identified,
                                                     const StudyRegistry& registry) {
  const auto printed = printed_slices(registry);
  std::map<std::string, std::string> s(printed.begin(), printed.end());
  if (identified)
    for (auto& st : registry)
      if (st.published && st.published->identified_slice)
        s[st.published->table] = st.published->identified_slice(*identified);
  return s;
}

// printf into a string: the bands and reasons print their numbers as the report shows them.
std::string format(const char* f, auto... args) {
  char b[512];
  std::snprintf(b, sizeof b, f, args...);
  return b;
}

// The cell (row, col) of a file read with short rows allowed; empty where there is none.
const std::string& cell_or_empty(const TsvTable& t, std::size_t row, int col) {
  static const std::string none;
  return col >= 0 && static_cast<std::size_t>(col) < t.rows[row].size() ? t.rows[row][col] : none;
}

// The seed band of a rate: the reproduced rates of its seed-1 slice and of the same slice of
// the other seeds (the same band: realizations_of).
struct SeedBand {
  int seeds = 0;
  double lo = 0, hi = 0;
};
// A rate's band: the same rate of its slice at seed 1 and of that slice's other realizations
// (StoreRate::band, from the files' arguments).
RateKey band_key(const StoreRate& r) { return {r.table, r.band, r.key}; }
std::map<RateKey, SeedBand> seed_bands(const std::vector<StoreRate>& rates) {
  std::map<RateKey, SeedBand> bands;
  for (const StoreRate& r : rates) {
    const double rate = r.reproduced;
    if ((r.setup != kDocumentSetup && r.setup != kJitterSetup) || !std::isfinite(rate)) continue;
    SeedBand& b = bands[band_key(r)];
    b.lo = b.seeds == 0 ? rate : std::min(b.lo, rate);
    b.hi = b.seeds == 0 ? rate : std::max(b.hi, rate);
    ++b.seeds;
  }
  return bands;
}

// A differing rate without a checked reason, by its size and by what our own series shows
// (issue 59 item 5): a near miss where the per-level error ratios, h_ratio^|difference|, are
// within kNearMiss; else pre-asymptotic where our rate moves by more than the tolerance to the
// documents' pair from the pair one level coarser or one finer and passes the published rate
// there (within the tolerance): a shift of the transition by part of a level would give the
// published rate, so the pair is not comparable at the tolerance; else a gross difference,
// unexplained.  Each reason states the tolerance at this pair as an error ratio.
std::pair<Verdict, std::string> miss_of(const StoreRate& r, double tolerance) {
  const double ours = r.reproduced, published = r.published;
  if (!std::isfinite(ours) || !std::isfinite(published) || !(r.h_ratio > 1))
    return {Verdict::unexplained, ""};
  const double tol_ratio = std::pow(r.h_ratio, tolerance) - 1;
  const double gap = std::pow(r.h_ratio, std::fabs(ours - published)) - 1;
  const std::string said = format("per-level error ratios %.1f %% apart (tolerance %.1f %% at this pair, near "
                                  "miss %.0f %%)",
                                  100 * gap, 100 * tol_ratio, 100 * kNearMiss);
  if (gap <= kNearMiss) return {Verdict::near_miss, said};
  double move = 0, lo = ours, hi = ours;
  for (double n : {r.rate_before, r.rate_after})
    if (std::isfinite(n)) move = std::max(move, std::fabs(n - ours)), lo = std::min(lo, n), hi = std::max(hi, n);
  if (move > tolerance && published >= lo - tolerance && published <= hi + tolerance)
    return {Verdict::pre_asymptotic,
            format("%s; our rate moves by %.2f per level around the pair (%s, %.2f, %s), more than the "
                   "tolerance %.2f, and passes the published one within a level",
                   said.c_str(), move, std::isfinite(r.rate_before) ? format("%.2f", r.rate_before).c_str() : "-",
                   ours, std::isfinite(r.rate_after) ? format("%.2f", r.rate_after).c_str() : "-", tolerance)};
  return {Verdict::unexplained, said};
}

// The verdict of a document rate (the list in verdicts.hpp), with its reason; `band`: its seed
// band where it has two realizations or more.
std::pair<Verdict, std::string> verdict_of(const StoreRate& r, const SeedBand* band,
                                           const UnstableSeries& unstable, const CheckedReasons& checked,
                                           double tolerance) {
  const RateKey place{r.table, r.slice, r.key};
  const auto blown = unstable.find(place);
  const bool differs = r.status.rfind("differs", 0) == 0;
  if (r.status == "agrees") {
    // One realization agreeing decides nothing when the realizations spread wider than the
    // tolerance: seed 1 could as well have missed (the same rule as for a differing rate, and
    // for a non-convergence too: Imoto's m = 1 rows are judged by the same band).
    if (band && band->hi - band->lo > tolerance)
      return {Verdict::indeterminate,
              format("seed 1 agrees, but the band of %d seeds is %.2f wide, wider than the tolerance %.2f: "
                     "the realizations cannot decide",
                     band->seeds, band->hi - band->lo, tolerance)};
    if (r.theoretical == "NA") return {Verdict::non_convergence, ""};
    return {Verdict::agrees, ""};
  }
  // Both runs unstable but the rates further apart than the tolerance: the blow-up is
  // reproduced, its rate is not (the rate of a blow-up measures the growth per level, which
  // the set-up decides: Table 4.6's h10 reading grows by -37 where the document prints -281).
  // Only the sign agrees, so it is not counted as reproduced.
  if (differs && r.theoretical == "unstable" && blown != unstable.end() &&
      std::isfinite(r.reproduced) && r.reproduced < 0 && std::isfinite(r.published) && r.published < 0)
    return {Verdict::sign_only, "both unstable (" + blown->second + "), rate < 0 on both sides: sign only"};
  if (differs) {
    // Inside the band of the jitter realizations: a verdict only with enough of them and a
    // band no wider than the tolerance; otherwise the seeds cannot decide (more seeds only
    // widen a band already too wide).
    if (band && std::isfinite(r.published) && r.published >= band->lo && r.published <= band->hi) {
      const double width = band->hi - band->lo;
      if (band->seeds >= kSeedBandDecides && width <= tolerance) return {Verdict::in_seed_band, ""};
      return {Verdict::indeterminate,
              width > tolerance
                  ? format("band of %d seeds %.2f wide, wider than the tolerance %.2f: the realizations cannot decide",
                           band->seeds, width, tolerance)
                  : format("published inside the band of %d seeds; %d are needed to decide", band->seeds,
                           kSeedBandDecides)};
    }
    // A checked reason whose check includes a run that restores the published rate; one that
    // explains only our rate leaves the published one unexplained, and says so.
    if (const auto c = checked.find(place); c != checked.end())
      return {c->second.restores ? Verdict::checked_reason : Verdict::explained_ours, c->second.text};
    return miss_of(r, tolerance);
  }
  if (r.status == "not-computed" && blown != unstable.end())
    return {Verdict::undefined, "no finite rate: " + blown->second};
  if (r.status == "not-computed") return {Verdict::not_computed, ""};
  // A rate from other levels than those of the document (a reading the catalog trims before
  // the finest level of the document): shown, but not computed at the levels of the document.
  if (r.status == "other-levels")
    return {Verdict::not_computed, "rate from levels " + r.levels +
                                       " only (the catalog trims this reading before the finest level of the document)"};
  if (r.status == "undefined") return {Verdict::undefined, ""};
  throw std::logic_error("rate status '" + r.status + "' has no verdict");
}

}  // namespace

const std::string& verdict_name(Verdict v) { return spelling(v).name; }
bool verdict_open(Verdict v) { return spelling(v).open; }
const std::string& verdict_column(Verdict v) { return spelling(v).column; }
const std::vector<std::string>& score_groups() {
  static const std::vector<std::string> g = [] {
    std::vector<std::string> out;
    for (auto& sp : spellings())
      if (!sp.group.empty() && std::find(out.begin(), out.end(), sp.group) == out.end()) out.push_back(sp.group);
    return out;
  }();
  return g;
}

const std::vector<Verdict>& scored_verdicts() {
  static const std::vector<Verdict> v = [] {
    std::vector<Verdict> s;
    for (auto& sp : spellings())
      if (sp.verdict != Verdict::not_counted) s.push_back(sp.verdict);
    return s;
  }();
  return v;
}

std::string slice_setup(const std::string& table, const StoreFile& file, const TsvTable& rows) {
  const int cv = rows.column("volumes");
  bool uniform = cv >= 0 && !rows.rows.empty();
  for (std::size_t i = 0; uniform && i < rows.rows.size(); ++i) uniform = rows.text(i, cv) == "uniform";
  if (uniform) return "beyond the document (uniform volumes)";
  if (file_seed(file) != 1) return kJitterSetup;
  if (file_arg(file, "--jitter") == "0") return "plain grid (no jitter)";
  if (table == "imoto_table1" && file_arg(file, "--volumes") == "cell") return "delta-free volumes (V_i = dx^2)";
  return kDocumentSetup;
}

namespace {
// A joined row's least-squares slope as the store's rate table shows it.
std::string lsq_text(const JoinedRate& r) {
  if (!r.fitted || !std::isfinite(r.lsq_slope)) return "";
  const double points = static_cast<double>(r.lsq_points), from = r.lsq_from;
  char buf[80];
  if (std::isfinite(r.lsq_half95))
    std::snprintf(buf, sizeof buf, "%.2f \u00b1 %.2f (levels %.0f-%.0f)", r.lsq_slope, r.lsq_half95, from,
                  from + points - 1);
  else
    std::snprintf(buf, sizeof buf, "%.2f (%.0f levels)", r.lsq_slope, points);
  return buf;
}
}  // namespace

std::vector<StoreRate> store_rates_of(const std::string& table, const SliceIdentity& id,
                                      const JoinedRates& joined, const std::vector<std::string>& keys,
                                      bool claims_theoretical, const std::string& split_by) {
  const std::string& slice = id.slice;
  const std::string& setup = id.setup;
  std::vector<StoreRate> out;
  for (const JoinedRate& j : joined.rows) {
    StoreRate r;
    r.table = table, r.slice = slice, r.setup = setup, r.seed = id.seed, r.band = id.band;
    for (auto& k : keys) r.key += (r.key.empty() ? "" : " ") + joined.key(j, k);
    auto led = [&](const std::string& x) { return joined.key(j, split_by) + (x == "all" ? "" : "_" + x); };
    if (!split_by.empty()) r.slice = led(slice), r.band = led(id.band);
    r.published = j.published;
    r.reproduced = j.computed ? j.reproduced : NAN;
    r.levels = j.computed ? std::to_string(j.level_lo) + "," + std::to_string(j.level_hi) : "";
    r.lsq = lsq_text(j);
    r.h_ratio = j.h_ratio, r.rate_before = j.rate_before, r.rate_after = j.rate_after;
    r.status = setup == kDocumentSetup ? j.status : "no published value for this set-up";
    // Only a printed NA means "no convergence claimed" (rate_table writes NA where the
    // published file has no theoretical column).
    r.theoretical = claims_theoretical ? j.theoretical : "";
    out.push_back(r);
  }
  return out;
}

TsvTable finite_series(const TsvTable& heat) {
  const int cw = heat.require_column("weight"), ct = heat.require_column("theta");
  const int cb = heat.require_column("blew_up");
  std::set<std::pair<std::string, std::string>> blown;
  for (std::size_t i = 0; i < heat.rows.size(); ++i)
    if (heat.text(i, cb) == "yes") blown.emplace(heat.text(i, cw), heat.text(i, ct));
  TsvTable finite = heat;
  finite.rows.clear(), finite.row_lines.clear();
  for (std::size_t i = 0; i < heat.rows.size(); ++i)
    if (!blown.count({heat.text(i, cw), heat.text(i, ct)})) {
      finite.rows.push_back(heat.rows[i]);
      finite.row_lines.push_back(heat.row_lines.empty() ? 0 : heat.row_lines[i]);
    }
  return finite;
}

void add_unstable_series(const std::string& table, const std::string& slice, const TsvTable& heat,
                         const std::string& rate_levels, UnstableSeries& out) {
  const auto comma = rate_levels.find(',');
  if (comma == std::string::npos) return;
  const std::string l1 = rate_levels.substr(0, comma), l2 = rate_levels.substr(comma + 1);
  // Per series: how many of its rows at the rate levels are unstable, and their evidence.
  std::map<std::string, std::pair<int, std::string>> series;
  for (std::size_t i = 0; i < heat.rows.size(); ++i) {
    const std::string& level = heat.text(i, "level");
    if (level != l1 && level != l2) continue;
    const bool blew_up = heat.text(i, "blew_up") == "yes";
    // rel_error is NA in a run that blew up: 0 there (the judges' one number reader).
    const double error = cell_number_or(heat.text(i, "rel_error"), 0);
    if (!blew_up && !(error > 1)) continue;
    auto& [n, evidence] = series[heat.text(i, "weight") + " " + heat.text(i, "theta")];
    ++n;
    evidence += (evidence.empty() ? "" : "; ") + ("2^-" + level + ": ") +
                (blew_up ? "blew up at step " + heat.text(i, "blowup_step") + " of " + heat.text(i, "K")
                         : format("error %.3g after %lld steps", error,
                                  static_cast<long long>(cell_number_or(heat.text(i, "K"), 0))));
  }
  for (auto& [key, s] : series)
    if (s.first == 2) out[{table, slice, key}] = "unstable at both rate levels (" + s.second + ")";
}

CheckedReasons passed_reasons(const TsvTable& checked) {
  CheckedReasons out;
  for (std::size_t i = 0; i < checked.rows.size(); ++i) {
    if (checked.text(i, "check") != "pass") continue;
    out[{checked.text(i, "table"), checked.text(i, "slice"), checked.text(i, "key")}] = {
        checked.text(i, "reason") + ": " + checked.text(i, "evidence"), checked.text(i, "restores") == "yes"};
  }
  return out;
}

// Whether a rate is one of the set-up rule's fingerprint rates (its study's
// PublishedRates::setup_fingerprint: the key column's value in the rate's key).
bool is_setup_fingerprint(const StoreRate& r, const StudyRegistry& registry) {
  for (auto& s : registry) {
    if (!s.published || s.published->table != r.table || s.published->setup_fingerprint.first.empty()) continue;
    const auto& [column, value] = s.published->setup_fingerprint;
    const std::vector<std::string> key = s.published->rate_key();
    std::istringstream cells(r.key);  // the key's cells, space-separated, in key order
    std::string cell;
    for (std::size_t k = 0; k < key.size() && cells >> cell; ++k)
      if (key[k] == column) return cell == value;
  }
  return false;
}

std::vector<JudgedRate> judge_rates(const std::vector<StoreRate>& rates, const UnstableSeries& unstable,
                                    const CheckedReasons& checked, double tolerance,
                                    const std::optional<PdeReading>& identified, const StudyRegistry& registry) {
  const std::map<RateKey, SeedBand> bands = seed_bands(rates);
  const auto printed_list = printed_slices(registry);
  const std::map<std::string, std::string> printed(printed_list.begin(), printed_list.end());
  const std::map<std::string, std::string> ident = identified_slices(identified, registry);
  auto on_board = [](const std::map<std::string, std::string>& board, const StoreRate& r) {
    const auto it = board.find(r.table);
    return r.setup == kDocumentSetup && it != board.end() && it->second == r.slice;
  };
  std::vector<JudgedRate> out;
  for (const StoreRate& r : rates) {
    JudgedRate j;
    j.rate = r;
    const auto b = bands.find(band_key(r));
    const SeedBand* band = b != bands.end() && b->second.seeds >= 2 ? &b->second : nullptr;
    if (band) {
      j.seed_band = format("%.2f to %.2f (%d seeds)", band->lo, band->hi, band->seeds);
      j.band_seeds = band->seeds, j.band_lo = band->lo, j.band_hi = band->hi;
    }
    if (r.setup == kDocumentSetup)
      std::tie(j.verdict, j.reason) = verdict_of(r, band, unstable, checked, tolerance);
    j.printed = on_board(printed, r);
    j.identified = on_board(ident, r);
    // The fingerprint rates identified the reading: on that board they are evidence, not results.
    const bool fingerprint = j.identified && identified && is_setup_fingerprint(r, registry);
    j.verdict_identified = fingerprint ? Verdict::setup_fingerprint : j.verdict;
    out.push_back(j);
  }
  return out;
}

TsvTable rates_table(const std::vector<JudgedRate>& rates) {
  TsvTable t;
  t.columns = {"table",  "slice",     "setup",   "key",     "published",  "reproduced",         "levels", "lsq", "status",
               "seed_band", "verdict", "reason", "printed", "identified", "verdict_identified", "counted",
               "open", "open_identified"};
  for (const JudgedRate& j : rates) {
    TsvRow row = t.named_row();
    row["table"] = j.rate.table, row["slice"] = j.rate.slice, row["setup"] = j.rate.setup;
    row["key"] = j.rate.key, row["published"] = fmt(j.rate.published), row["reproduced"] = number_cell(j.rate.reproduced);
    row["levels"] = j.rate.levels, row["lsq"] = j.rate.lsq, row["status"] = j.rate.status, row["seed_band"] = j.seed_band;
    row["verdict"] = verdict_name(j.verdict), row["reason"] = j.reason;
    row["printed"] = j.printed ? "yes" : "no", row["identified"] = j.identified ? "yes" : "no";
    row["verdict_identified"] = verdict_name(j.verdict_identified);
    row["counted"] = j.identified ? "yes" : "no";
    row["open"] = verdict_open(j.verdict) ? "yes" : "no";
    row["open_identified"] = verdict_open(j.verdict_identified) ? "yes" : "no";
    t.add_row(row);
  }
  return t;
}

std::string stored_file(const std::string& study, const std::string& slice, const StudyRegistry& registry) {
  const RegisteredStudy& s = registry.study(study);
  if (slice.empty() && !s.store_files.empty()) return s.store_files.front().name + ".tsv";
  for (const StoreFile& f : s.store_files)
    if (f.slice == slice) return f.name + ".tsv";
  throw InputError("study '" + study + "' keeps no slice '" + slice + "' in the store");
}

std::optional<std::string> reading_file(const RegisteredStudy& study, const std::string& reading) {
  if (const StoreFile* f = study.find_store_file_of(reading)) return f->name + ".tsv";
  return std::nullopt;
}

const TsvTable& published_table(const PublishedTables& published, const std::string& table,
                                const StudyRegistry& registry) {
  for (auto& s : registry)
    if (s.published && s.published->table == table) return published.file(s.published->file);
  throw InputError("no registered study has the published table '" + table + "'");
}

namespace {

// One row of the score: a slice's counts, or a board's totals.
struct Tally {
  std::string table, slice, setup;
  bool printed = false, identified = false;
  int rows = 0;
  std::map<Verdict, int> counts;
  int differences = 0;  // rates with a number on both sides, and the sum of |reproduced - published|
  double sum_difference = 0;
};

// Per (table, slice, setup), in the order of the rates: the identified slice counts its own
// verdicts (fingerprint rows), the others their verdicts.
std::vector<Tally> slice_tallies(const std::vector<JudgedRate>& rates) {
  std::vector<Tally> slices;
  for (const JudgedRate& j : rates) {
    const StoreRate& r = j.rate;
    auto s = std::find_if(slices.begin(), slices.end(), [&](const Tally& x) {
      return x.table == r.table && x.slice == r.slice && x.setup == r.setup;
    });
    if (s == slices.end()) {
      s = slices.insert(slices.end(), Tally{});
      s->table = r.table, s->slice = r.slice, s->setup = r.setup;
    }
    ++s->rows;
    ++s->counts[j.identified ? j.verdict_identified : j.verdict];
    s->printed = s->printed || j.printed;
    s->identified = s->identified || j.identified;
    if (std::isfinite(r.reproduced) && std::isfinite(r.published)) {
      s->sum_difference += std::fabs(r.reproduced - r.published);
      ++s->differences;
    }
  }
  return slices;
}

// The totals of the printed board (identified = false) or the identified one.  A table the
// board has no stored rows of counts its published rates not computed: as many as the printed
// board counts (Table 4.4's file lists each weight once per reading of h), else the rows of
// its published file.
Tally board_tally(const std::vector<JudgedRate>& rates, bool identified, const PublishedTables& published,
                  const StudyRegistry& registry) {
  Tally total;
  total.table = "total", total.slice = identified ? "as identified" : "as printed", total.setup = kDocumentSetup;
  total.printed = !identified, total.identified = identified;
  std::set<std::string> tables;
  std::map<std::string, int> printed_rows;
  for (const JudgedRate& j : rates) {
    if (j.printed) ++printed_rows[j.rate.table];
    if (identified ? !j.identified : !j.printed) continue;
    tables.insert(j.rate.table);
    ++total.counts[identified ? j.verdict_identified : j.verdict];
  }
  for (auto& [table, slice] : printed_slices(registry))
    if (!tables.count(table))
      total.counts[Verdict::not_computed] +=
          printed_rows.count(table) ? printed_rows[table]
                                    : static_cast<int>(published_table(published, table, registry).rows.size());
  for (Verdict v : scored_verdicts()) total.rows += total.counts[v];
  return total;
}

void add_score_row(TsvTable& t, Tally& tally) {
  TsvRow row = t.named_row();
  row["table"] = tally.table, row["slice"] = tally.slice, row["setup"] = tally.setup;
  row["printed"] = tally.printed ? "yes" : "no", row["identified"] = tally.identified ? "yes" : "no";
  row["counted"] = tally.identified ? "yes" : "no";
  row["rates"] = fmt(tally.rows);
  std::map<std::string, int> groups;
  for (Verdict v : scored_verdicts()) {
    row[verdict_column(v)] = fmt(tally.counts[v]);
    groups[spelling(v).group] += tally.counts[v];
  }
  for (auto& g : score_groups()) row[g] = fmt(groups[g]);
  row["mean_abs_diff"] = tally.differences ? format("%.3g", tally.sum_difference / tally.differences) : "NA";
  t.add_row(row);
}

}  // namespace

TsvTable score_table(const std::vector<JudgedRate>& rates, const PublishedTables& published,
                     const StudyRegistry& registry) {
  TsvTable t;
  t.columns = {"table", "slice", "setup", "printed", "identified", "counted", "rates"};
  for (Verdict v : scored_verdicts()) t.columns.push_back(verdict_column(v));
  for (auto& g : score_groups()) t.columns.push_back(g);
  t.columns.push_back("mean_abs_diff");
  for (Tally& s : slice_tallies(rates)) add_score_row(t, s);
  for (bool identified : {false, true}) {
    Tally total = board_tally(rates, identified, published, registry);
    add_score_row(t, total);
  }
  return t;
}

std::vector<IdentifiedSlice> stored_slices(const RegisteredStudy& s, const StoreSnapshot& store) {
  std::vector<IdentifiedSlice> out;
  const PublishedRates* p = s.published ? &*s.published : nullptr;
  for (const StoreFile& f : s.store_files) {
    if (!store.has(f.name + ".tsv")) continue;
    const TsvTable& data = store.table(f.name + ".tsv");
    // The band's name: the slice the seed-1 file of the same set-up gives for the same rows.
    const StoreFile* one = seed_one_of(s, f);
    std::vector<StoreSlice> slices, bands;
    if (p && p->cut) {
      slices = p->cut(f, data);
      if (one) bands = p->cut(*one, data);
    } else {
      slices = {{f.slice, data}};
      if (one) bands = {{one->slice, {}}};
    }
    for (std::size_t k = 0; k < slices.size(); ++k) {
      IdentifiedSlice is;
      is.id.slice = slices[k].slice;
      is.id.setup = slice_setup(p ? p->table : s.name, f, slices[k].data);
      is.id.seed = file_seed(f);
      is.id.band = k < bands.size() ? bands[k].slice : slices[k].slice;
      is.data = std::move(slices[k].data);
      out.push_back(std::move(is));
    }
  }
  return out;
}

std::vector<StoreRate> store_rates(const StoreSnapshot& store, const PublishedTables& published,
                                   double tolerance, const StudyRegistry& registry) {
  // Per slice, named "table.slice": its rows (the slices in the order of their names).
  std::map<std::string, std::vector<StoreRate>> slices;
  for (auto& s : registry) {
    if (!s.published) continue;
    const PublishedRates& p = *s.published;
    const TsvTable& pub = published.file(p.file);
    for (IdentifiedSlice& slice : stored_slices(s, store)) {
      RateJoin join;
      join.keys = p.key, join.levels = "published", join.tolerance = tolerance;
      const JoinedRates joined = join_rates(p.finite_series ? finite_series(slice.data) : slice.data, pub, join);
      // A slice's name stays unique: a second one would replace the first, as a file would.
      slices[p.table + "." + slice.id.slice + ".tsv"] =
          store_rates_of(p.table, slice.id, joined, p.rate_key(), pub.column("theoretical") >= 0, p.split_by);
    }
  }
  std::vector<StoreRate> out;
  for (auto& [name, rows] : slices) out.insert(out.end(), rows.begin(), rows.end());
  return out;
}

UnstableSeries store_unstable_series(const StoreSnapshot& store, const PublishedTables& published,
                                     const StudyRegistry& registry) {
  UnstableSeries out;
  // The studies whose rates come from the series that never blew up (the heat tables).
  for (auto& s : registry) {
    if (!s.published || !s.published->finite_series) continue;
    std::optional<std::string> levels;
    for (IdentifiedSlice& slice : stored_slices(s, store)) {
      if (!levels) levels = documents_levels_text(published.file(s.published->file));
      add_unstable_series(s.published->table, slice.id.slice, slice.data, *levels, out);
    }
  }
  return out;
}

TsvTable store_summary(const StoreSnapshot& store) {
  const std::vector<std::string> files = store.data_files();
  const std::vector<std::string> programs = fingerprinted_programs();
  TsvTable t;
  t.columns = {"file", "program", "rows", "levels", "current_computed", "current_by_recheck", "other_code", "made_on"};
  for (const std::string& name : files) {
    const TsvTable& data = store.table(name, false);
    const int code_col = data.column("code");
    if (code_col < 0) continue;  // a derived file (cost, rates input) or a script's: no code column
    const std::string program = data.get("program").value_or("");
    const bool known = std::find(programs.begin(), programs.end(), program) != programs.end();
    const std::string code = known ? code_fingerprint(program) : "";
    const int level_col = data.column("level"), made_col = data.column("made_on"), recheck_col = data.column("checked");
    std::set<std::string> levels, made_on;
    int fresh = 0, carried = 0, other = 0;
    for (std::size_t i = 0; i < data.rows.size(); ++i) {
      levels.insert(cell_or_empty(data, i, level_col));
      made_on.insert(cell_or_empty(data, i, made_col));
      if (cell_or_empty(data, i, code_col) != code) ++other;
      else if (cell_or_empty(data, i, recheck_col).find("recheck") != std::string::npos) ++carried;
      else ++fresh;
    }
    std::vector<std::string> level_list;
    for (int k = 1; k <= 20; ++k)
      if (levels.count(fmt(k))) level_list.push_back(fmt(k));
    TsvRow row = t.named_row();
    row["file"] = name, row["program"] = program, row["rows"] = fmt(data.rows.size());
    row["levels"] = join(level_list, ",");
    row["current_computed"] = fmt(fresh), row["current_by_recheck"] = fmt(carried), row["other_code"] = fmt(other);
    row["made_on"] = join(std::vector<std::string>(made_on.begin(), made_on.end()), "; ");
    t.add_row(row);
  }
  return t;
}

std::vector<std::pair<std::string, std::string>> store_provenance(const std::string& store) {
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {{"profile", "paper (the committed store " + store + ")"},
          {"seed", "1"},
          {"git_revision", git_revision()},
          {"written_utc", date}};
}

}  // namespace gpm
