#include "gpm/studies/judge/rate_levels.hpp"

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "gpm/error.hpp"
#include "gpm/io/text_format.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/judge/evidence.hpp"
#include "gpm/studies/judge/rates.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/judge/verdicts.hpp"

namespace gpm {

std::string trend_name(Trend t) {
  switch (t) {
    case Trend::approaches: return "approaches";
    case Trend::stays_away: return "stays away";
    case Trend::not_decided: return "not decided";
  }
  return "?";
}

namespace {

// How far a rate moving toward the theory's may still be and count as approaching it.
constexpr double kApproachReach = 0.3;

// A number in a sentence (two decimals), and in a cell (every digit; NA when not a number).
std::string num(double v) { return std::isfinite(v) ? format_text("%.2f", v) : "NA"; }
std::string cell(double v) { return std::isfinite(v) ? fmt(v) : "NA"; }

// The rule on seed 1's rates alone.
TrendFinding seed1_trend(const std::vector<double>& rates, double theory, bool finest_beyond, double tolerance) {
  const std::size_t n = rates.size();
  if (n < 2) return {Trend::not_decided, "fewer than two pairs of levels"};
  std::vector<double> d;
  for (double r : rates) d.push_back(std::fabs(r - theory));
  if (!std::isfinite(d[n - 1]) || !std::isfinite(d[n - 2]))
    return {Trend::not_decided, "a rate of the finest pairs is not a number"};
  if (d[n - 1] <= tolerance && d[n - 2] <= tolerance)
    return {Trend::approaches, "the last two rates " + num(rates[n - 2]) + ", " + num(rates[n - 1]) +
                                   " within " + num(tolerance) + " of " + num(theory)};
  if (n >= 3 && d[n - 3] > d[n - 2] && d[n - 2] > d[n - 1] && d[n - 1] <= kApproachReach)
    return {Trend::approaches, "distance to " + num(theory) + " falling " + num(d[n - 3]) + ", " + num(d[n - 2]) +
                                   ", " + num(d[n - 1])};
  if (finest_beyond && d[n - 1] > kApproachReach && d[n - 1] >= d[n - 2] - tolerance)
    return {Trend::stays_away, "finest rate " + num(rates[n - 1]) + ", " + num(d[n - 1]) + " from " + num(theory) +
                                   " (the pair before: " + num(d[n - 2]) + ")"};
  if (!finest_beyond) return {Trend::not_decided, "no level beyond the documents' stored yet"};
  return {Trend::not_decided, "distance to " + num(theory) + " " + num(d[n - 2]) + " then " + num(d[n - 1]) +
                                  ": a level further would decide"};
}

}  // namespace

TrendFinding judge_trend(const std::vector<double>& rates, double theory, bool finest_beyond,
                         double tolerance, FinestBand band) {
  TrendFinding f = seed1_trend(rates, theory, finest_beyond, tolerance);
  if (!std::isfinite(band.lo) || !std::isfinite(band.hi) || f.trend == Trend::not_decided) return f;
  // Every realization must agree: the band's far end decides "approaches", its near end
  // (0 where the band holds the theory's rate) "stays away".
  const double dlo = std::fabs(band.lo - theory), dhi = std::fabs(band.hi - theory);
  const double far = std::max(dlo, dhi), near = band.lo <= theory && theory <= band.hi ? 0 : std::min(dlo, dhi);
  const std::string spread = "realizations " + num(band.lo) + " to " + num(band.hi) + " at the finest pair";
  if (f.trend == Trend::approaches && far > kApproachReach)
    return {Trend::not_decided, f.why + ", but the " + spread + " reach " + num(far) + " from " + num(theory)};
  if (f.trend == Trend::stays_away && near <= kApproachReach)
    return {Trend::not_decided, f.why + ", but the " + spread + " come within " + num(near) + " of " + num(theory)};
  f.why += " (" + spread + ")";
  return f;
}

namespace {

const TsvTable& stored_or_refuse(const StoreSnapshot& store, const std::string& name) {
  if (!store.has(name)) throw InputError("rate levels: the store has no " + store.path(name));
  return store.table(name, false);
}

// The series of a store file and of its stored jitter realizations (realizations_of).
struct Realizations {
  EvidenceSeriesMap seed1;
  std::vector<EvidenceSeriesMap> others;
};
Realizations realizations(const StoreSnapshot& store, const RegisteredStudy& study, const StoreFile& file,
                          const std::string& key1, const std::string& key2) {
  Realizations r{read_series(stored_or_refuse(store, file.name + ".tsv"), {key1, key2}), {}};
  for (const StoreFile* f : realizations_of(study, file))
    if (store.has(f->name + ".tsv")) r.others.push_back(read_series(store.table(f->name + ".tsv", false), {key1, key2}));
  return r;
}

// One series as the view names it, and what the documents say of it.
struct SeriesLabel {
  std::string table, reading, weight, theta;
  double published = std::numeric_limits<double>::quiet_NaN();
  std::string theory_text;  // the published file's `theoretical` cell: a rate, or a word
};

// The rows of one series (its rates at every consecutive pair of stored levels, with the band
// over the realizations holding both levels) and its finding.  `doc`: the documents' pair of
// levels (documents_levels).
void add_series(RateLevels& out, const SeriesLabel& label, const Realizations& reals,
                const std::vector<std::string>& key, const std::pair<int, int>& doc) {
  const auto it = reals.seed1.find(key);
  if (it == reals.seed1.end()) return;
  const EvidenceSeries& s = it->second;
  // The theory's rate, or none where the document gives a word ("unstable": Table 4.6's
  // explicit series, whose growth is the set-up fingerprint, not a rate).
  const double theory = theoretical_rate(label.theory_text);
  const std::string theory_cell = std::isfinite(theory) ? cell(theory) : label.theory_text;
  std::vector<int> levels;
  for (auto& [k, v] : s) levels.push_back(k);
  std::vector<double> rates;
  FinestBand band;
  for (std::size_t i = 0; i + 1 < levels.size(); ++i) {
    const int lo = levels[i], hi = levels[i + 1];
    const double r = series_rate(s, lo, hi);
    rates.push_back(r);
    double blo = r, bhi = r;
    int seeds = 1;
    for (auto& o : reals.others) {
      const auto oi = o.find(key);
      if (oi == o.end()) continue;
      const double ro = series_rate(oi->second, lo, hi);
      if (!std::isfinite(ro)) continue;
      blo = std::min(blo, ro), bhi = std::max(bhi, ro), ++seeds;
    }
    if (i + 2 == levels.size() && seeds > 1) band = {blo, bhi};
    const bool document = lo == doc.first && hi == doc.second;
    TsvRow row = out.rates.named_row();
    row["table"] = label.table, row["reading"] = label.reading, row["weight"] = label.weight, row["theta"] = label.theta;
    row["level_lo"] = fmt(lo), row["level_hi"] = fmt(hi), row["pair"] = "2^-" + fmt(lo) + "/2^-" + fmt(hi);
    row["rate"] = cell(r), row["band_lo"] = seeds > 1 ? cell(blo) : "NA";
    row["band_hi"] = seeds > 1 ? cell(bhi) : "NA", row["seeds"] = fmt(seeds);
    row["published"] = document ? cell(label.published) : "NA", row["theoretical"] = theory_cell;
    row["where"] = document ? "document" : hi > doc.second ? "beyond" : "coarser";
    out.rates.add_row(row);
  }
  const bool beyond = !levels.empty() && levels.back() > doc.second;
  const TrendFinding f = std::isfinite(theory)
                             ? judge_trend(rates, theory, beyond, kRateTolerance, band)
                             : TrendFinding{Trend::not_decided, "no theoretical rate ('" + label.theory_text + "')"};
  TsvRow row = out.findings.named_row();
  row["table"] = label.table, row["reading"] = label.reading, row["weight"] = label.weight, row["theta"] = label.theta;
  row["pairs"] = fmt(rates.size());
  row["finest_pair"] = levels.size() < 2 ? "NA" : fmt(levels[levels.size() - 2]) + "," + fmt(levels.back());
  row["finest_rate"] = rates.empty() ? "NA" : cell(rates.back());
  row["theoretical"] = theory_cell;
  row["published"] = cell(label.published), row["finding"] = trend_name(f.trend), row["why"] = f.why;
  out.findings.add_row(row);
}

// Tables 4.5–4.7 under the printed reading (h10) and the identified one (h15_cell_exact).
void heat_rate_levels(RateLevels& out, const StoreSnapshot& store, const PublishedTables& published) {
  const StudyRegistry& reg = study_registry();
  for (const HeatTable& hp : heat_tables()) {
    const RegisteredStudy& study = reg.study(heat_study_name(hp));
    const TsvTable& pub = published.file(study.published->file);
    const auto doc_levels = documents_levels(pub);
    for (const std::string reading : {"h10", "h15_cell_exact"}) {
      const Realizations reals = realizations(store, study, study.store_file_of(reading), "weight", "theta");
      for (std::size_t p = 0; p < pub.rows.size(); ++p) {
        const std::string w = pub.text(p, "weight"), th = pub.text(p, "theta");
        const SeriesLabel label{hp.table, reading, w, th, pub.number(p, pub.require_column("numerical")),
                                pub.text(p, "theoretical")};
        add_series(out, label, reals, {w, th}, doc_levels);
      }
    }
  }
}

// Table 4.4 (the Poisson problem, no θ) under both h rules with V_i = Δx², the volumes the
// set-up rule identifies: one file holds both rules (readings h10_cell and h15_cell).
void poisson_rate_levels(RateLevels& out, const StoreSnapshot& store, const PublishedTables& published) {
  const RegisteredStudy& study = study_registry().study("thesis_table4_4");
  const TsvTable& pub = published.file(study.published->file);
  const auto doc_levels = documents_levels(pub);
  const Realizations reals = realizations(store, study, study.store_file_of("h15_cell"), "h_rule", "weight");
  for (std::size_t p = 0; p < pub.rows.size(); ++p) {
    const std::string rule = pub.text(p, "h_rule"), w = pub.text(p, "weight");
    const SeriesLabel label{"4.4", rule + "_cell", w, "NA", pub.number(p, pub.require_column("numerical")),
                            pub.text(p, "theoretical")};
    add_series(out, label, reals, {rule, w}, doc_levels);
  }
}

}  // namespace

RateLevels rate_levels(const StoreSnapshot& store, const PublishedTables& published) {
  RateLevels out;
  out.rates.columns = {"table", "reading", "weight", "theta", "level_lo", "level_hi", "pair", "rate", "band_lo",
                       "band_hi", "seeds", "published", "theoretical", "where"};
  out.findings.columns = {"table", "reading", "weight", "theta", "pairs", "finest_pair", "finest_rate",
                          "theoretical", "published", "finding", "why"};
  poisson_rate_levels(out, store, published);
  heat_rate_levels(out, store, published);
  return out;
}

}  // namespace gpm
