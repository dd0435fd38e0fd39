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
#include "gpm/studies/judge/rates.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/judge/verdicts.hpp"  // seed_files

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

}  // namespace

TrendFinding judge_trend(const std::vector<double>& rates, double theory, bool finest_beyond,
                         double tolerance) {
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

namespace {

// A series' finite errors by level: level → (h, error).
using Series = std::map<int, std::pair<double, double>>;

std::map<std::pair<std::string, std::string>, Series> series_of(const TsvTable& t) {
  std::map<std::pair<std::string, std::string>, Series> out;
  const int cw = t.require_column("weight"), ct = t.require_column("theta"), cl = t.require_column("level"),
            ch = t.require_column("h"), ce = t.require_column("rel_error");
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const double e = t.number(i, ce);
    if (!std::isfinite(e) || e <= 0) continue;
    out[{t.text(i, cw), t.text(i, ct)}][static_cast<int>(t.integer(i, cl))] = {t.number(i, ch), e};
  }
  return out;
}

double rate_between(const Series& s, int lo, int hi) {
  const auto a = s.find(lo), b = s.find(hi);
  if (a == s.end() || b == s.end()) return std::numeric_limits<double>::quiet_NaN();
  return std::log(a->second.second / b->second.second) / std::log(a->second.first / b->second.first);
}

TsvTable published_or_refuse(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError("rate levels: no published file " + path);
  return TsvTable::load(path, false);
}

const TsvTable& stored_or_refuse(const StoreSnapshot& store, const std::string& name) {
  if (!store.has(name)) throw InputError("rate levels: the store has no " + store.path(name));
  return store.table(name, false);
}

}  // namespace

RateLevels rate_levels(const StoreSnapshot& store, const std::string& published) {
  RateLevels out;
  out.rates.columns = {"table", "reading", "weight", "theta", "level_lo", "level_hi", "pair", "rate", "band_lo",
                       "band_hi", "seeds", "published", "theoretical", "where"};
  out.findings.columns = {"table", "reading", "weight", "theta", "pairs", "finest_pair", "finest_rate",
                          "theoretical", "published", "finding", "why"};
  const StudyRegistry& reg = study_registry();
  for (const HeatTable& hp : heat_tables()) {
    const RegisteredStudy& study = reg.study(heat_study_name(hp));
    const TsvTable pub = published_or_refuse(published_file(published, study.published->table));
    const std::string doc_levels = pub.get("rate_levels").value_or(hp.rate_levels);
    const int doc_hi = std::stoi(doc_levels.substr(doc_levels.find(',') + 1));
    for (const std::string reading : {"h10", "h15_cell_exact"}) {
      const auto seed1 = series_of(stored_or_refuse(store, study.store_file_of(reading).name + ".tsv"));
      std::vector<std::map<std::pair<std::string, std::string>, Series>> others;
      for (const StoreFile* f : seed_files(study, reading))
        if (store.has(f->name + ".tsv")) others.push_back(series_of(store.table(f->name + ".tsv", false)));
      for (std::size_t p = 0; p < pub.rows.size(); ++p) {
        const std::string w = pub.text(p, "weight"), th = pub.text(p, "theta");
        const double published_rate = pub.number(p, pub.require_column("numerical"));
        // The theory's rate, or none where the document gives a word ("unstable": Table 4.6's
        // explicit series, whose growth is the set-up fingerprint, not a rate).
        const std::string theory_text = pub.text(p, "theoretical");
        char* end = nullptr;
        const double parsed = std::strtod(theory_text.c_str(), &end);
        const double theory = !theory_text.empty() && !*end ? parsed : std::numeric_limits<double>::quiet_NaN();
        const auto it = seed1.find({w, th});
        if (it == seed1.end()) continue;
        const Series& s = it->second;
        std::vector<int> levels;
        for (auto& [k, v] : s) levels.push_back(k);
        std::vector<double> rates;
        for (std::size_t i = 0; i + 1 < levels.size(); ++i) {
          const int lo = levels[i], hi = levels[i + 1];
          const double r = rate_between(s, lo, hi);
          rates.push_back(r);
          // The band: seed 1 and every other realization that holds both levels.
          double blo = r, bhi = r;
          int seeds = 1;
          for (auto& o : others) {
            const auto oi = o.find({w, th});
            if (oi == o.end()) continue;
            const double ro = rate_between(oi->second, lo, hi);
            if (!std::isfinite(ro)) continue;
            blo = std::min(blo, ro), bhi = std::max(bhi, ro), ++seeds;
          }
          const std::string pair = fmt(lo) + "," + fmt(hi);
          const bool document = pair == doc_levels;
          TsvRow row = out.rates.named_row();
          row["table"] = hp.table, row["reading"] = reading, row["weight"] = w, row["theta"] = th;
          row["level_lo"] = fmt(lo), row["level_hi"] = fmt(hi), row["pair"] = "2^-" + fmt(lo) + "/2^-" + fmt(hi);
          row["rate"] = cell(r), row["band_lo"] = seeds > 1 ? cell(blo) : "NA";
          row["band_hi"] = seeds > 1 ? cell(bhi) : "NA", row["seeds"] = fmt(seeds);
          row["published"] = document ? cell(published_rate) : "NA", row["theoretical"] = std::isfinite(theory) ? cell(theory) : theory_text;
          row["where"] = document ? "document" : hi > doc_hi ? "beyond" : "coarser";
          out.rates.add_row(row);
        }
        const bool beyond = !levels.empty() && levels.back() > doc_hi;
        const TrendFinding f = std::isfinite(theory) ? judge_trend(rates, theory, beyond, kRateTolerance)
                                                     : TrendFinding{Trend::not_decided, "no theoretical rate ('" + theory_text + "')"};
        TsvRow row = out.findings.named_row();
        row["table"] = hp.table, row["reading"] = reading, row["weight"] = w, row["theta"] = th;
        row["pairs"] = fmt(rates.size());
        row["finest_pair"] = levels.size() < 2 ? "NA" : fmt(levels[levels.size() - 2]) + "," + fmt(levels.back());
        row["finest_rate"] = rates.empty() ? "NA" : cell(rates.back());
        row["theoretical"] = std::isfinite(theory) ? cell(theory) : theory_text;
        row["published"] = cell(published_rate), row["finding"] = trend_name(f.trend), row["why"] = f.why;
        out.findings.add_row(row);
      }
    }
  }
  return out;
}

}  // namespace gpm
