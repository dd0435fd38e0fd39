#include "gpm/studies/judge/rates.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <limits>
#include <sstream>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/operators/norms.hpp"

namespace gpm {

double theoretical_rate(const std::string& text) {
  return cell_number_or(text, std::numeric_limits<double>::quiet_NaN());
}

namespace {

// The key of row i: its cells in the key columns, joined by '|'.
std::string key_of(const TsvTable& t, std::size_t i, const std::vector<int>& cols) {
  std::string s;
  for (std::size_t k = 0; k < cols.size(); ++k) s += (k ? "|" : "") + t.text(i, cols[k]);
  return s;
}

// The two fixed levels of every rate, or none (the two finest of each series).
std::vector<int> fixed_levels(const RateJoin& join, const TsvTable& pub, std::string& text) {
  std::vector<int> fixed;
  if (join.levels.empty()) return fixed;
  std::string lv = join.levels;
  if (lv == "published") lv = documents_levels_text(pub);
  std::stringstream ss(lv);
  for (std::string item; std::getline(ss, item, ',');)
    fixed.push_back(static_cast<int>(parse_integer(item, "--levels", 0, 63)));
  if (fixed.size() != 2 || !(fixed[0] < fixed[1]))
    throw InputError("--levels: '" + lv + "' is not two increasing levels");
  text = lv;
  return fixed;
}

// The levels past the transition (issue 59 item 5): the finest run of consecutive stored
// levels over which every two-level rate lies within the tolerance of the finest pair's.  A
// least-squares line through a curved series measures its curvature, not a rate; through
// this tail it measures the rate the series settles to.  Returns its first level.
int transition_tail_start(const EvidenceSeries& s, double tolerance) {
  std::vector<int> lv;
  std::vector<double> rate;  // rate[i]: levels lv[i], lv[i+1]
  for (auto& [level, pt] : s) lv.push_back(level);
  for (std::size_t i = 0; i + 1 < lv.size(); ++i) rate.push_back(series_rate(s, lv[i], lv[i + 1]));
  if (rate.empty() || !std::isfinite(rate.back())) return lv.empty() ? 0 : lv.back();
  std::size_t first = rate.size() - 1;
  while (first > 0 && std::isfinite(rate[first - 1]) && std::fabs(rate[first - 1] - rate.back()) <= tolerance)
    --first;
  return lv[first];
}

}  // namespace

std::pair<int, int> documents_levels(const TsvTable& published) {
  const auto lv = published.get("rate_levels");
  if (!lv) throw InputError(published.source + ": no '# rate_levels = ' line");
  std::vector<int> k;
  std::stringstream ss(*lv);
  for (std::string item; std::getline(ss, item, ',');)
    k.push_back(static_cast<int>(parse_integer(item, published.source + " rate_levels", 0, 63)));
  if (k.size() != 2 || !(k[0] < k[1]))
    throw InputError(published.source + ": rate_levels '" + *lv + "' is not two increasing levels");
  return {k[0], k[1]};
}

std::string documents_levels_text(const TsvTable& published) {
  const auto [a, b] = documents_levels(published);
  return std::to_string(a) + "," + std::to_string(b);
}

const std::string& JoinedRates::key(const JoinedRate& r, const std::string& name) const {
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (keys[k] == name) return r.key[k];
  throw InputError("joined rates: no key column '" + name + "'");
}

JoinedRates join_rates(const TsvTable& data, const TsvTable& pub, const RateJoin& join) {
  std::vector<int> dk, pk;
  for (auto& k : join.keys) dk.push_back(data.require_column(k));
  for (auto& k : join.keys) pk.push_back(pub.require_column(k));
  const int cl = data.require_column(join.level);
  const int cx = data.require_column(join.x);
  const int cy = data.require_column(join.y);
  const int cv = pub.require_column(join.value);
  const int ct = pub.column("theoretical");

  // The document's two levels, where the published file names them.
  const std::string doc_levels = pub.get("rate_levels").value_or("");

  // Per key: level → (h, error), every stored row (a rate of an error ≤ 0 is undefined, not
  // left out); the data row of each level, for a duplicate's message.
  std::map<std::string, EvidenceSeries> series;
  std::map<std::string, std::map<int, std::size_t>> row_of;
  for (std::size_t i = 0; i < data.rows.size(); ++i) {
    const std::string key = key_of(data, i, dk);
    const int level = static_cast<int>(data.integer(i, cl));
    const auto [it, fresh] = row_of[key].emplace(level, i);
    if (!fresh)
      throw InputError(data.source + ": key '" + key + "' has two rows at level " +
                       std::to_string(level) + " (data rows " + std::to_string(it->second + 1) +
                       " and " + std::to_string(i + 1) + ")");
    series[key][level] = {data.number(i, cx), data.number(i, cy)};
  }

  JoinedRates out;
  out.keys = join.keys;
  const std::vector<int> fixed = fixed_levels(join, pub, out.fixed_levels);
  for (std::size_t i = 0; i < pub.rows.size(); ++i) {
    JoinedRate r;
    for (int c : pk) r.key.push_back(pub.text(i, c));
    r.published = pub.number(i, cv);
    if (ct >= 0) r.theoretical = pub.text(i, ct);
    auto it = series.find(key_of(pub, i, pk));
    const bool have = it != series.end() &&
                      (fixed.empty() ? it->second.size() >= 2
                                     : it->second.count(fixed[0]) && it->second.count(fixed[1]));
    if (have) {
      const EvidenceSeries& s = it->second;
      r.computed = true;
      r.level_hi = fixed.empty() ? std::prev(s.end())->first : fixed[1];
      r.level_lo = fixed.empty() ? std::prev(s.end(), 2)->first : fixed[0];
      r.reproduced = series_rate(s, r.level_lo, r.level_hi);
      // The least-squares slope over the levels past the transition only (three at least).
      r.lsq_from = transition_tail_start(s, join.tolerance);
      std::vector<double> xs, ys;
      for (auto& [lv, pt] : s)
        if (lv >= r.lsq_from) xs.push_back(pt.h), ys.push_back(pt.error);
      r.lsq_points = static_cast<long long>(xs.size());
      if (xs.size() >= 3) {
        const RateFit fit = least_squares_fit(xs, ys);
        r.fitted = true, r.lsq_slope = fit.slope, r.lsq_half95 = fit.half95;
        r.lsq_points = static_cast<long long>(fit.points);
      }
      // The pair's ratio of h, and our rate one level coarser and one finer: how far it moves
      // around the pair (the verdicts' "pre-asymptotic") and what a rate difference is as an
      // error ratio per level (their "near miss").
      r.h_ratio = s.at(r.level_lo).h / s.at(r.level_hi).h;
      r.rate_before = series_rate(s, r.level_lo - 1, r.level_lo);
      r.rate_after = series_rate(s, r.level_hi, r.level_hi + 1);
      // NaN fails every comparison: tested first, or it would fall through to a reason.
      const std::string levels = std::to_string(r.level_lo) + "," + std::to_string(r.level_hi);
      if (!std::isfinite(r.reproduced) || !std::isfinite(r.published)) {
        r.status = "undefined";
      } else {
        r.difference = r.reproduced - r.published;
        if (!doc_levels.empty() && levels != doc_levels) {
          r.status = "other-levels";
          r.reason = "rate from levels " + levels + "; the document's are " + doc_levels;
        } else {
          r.status = std::fabs(r.difference) <= join.tolerance ? "agrees" : "differs";
        }
      }
    }
    ++out.counts[r.status];
    out.rows.push_back(std::move(r));
  }
  return out;
}

void write_joined(const JoinedRates& joined, TsvTable& out) {
  out.columns.insert(out.columns.end(), joined.keys.begin(), joined.keys.end());
  for (const char* c : {"published", "theoretical", "reproduced", "difference", "lsq_slope",
                        "lsq_half95", "lsq_points", "lsq_from", "levels", "h_ratio", "rate_before",
                        "rate_after", "status", "reason"})
    out.columns.push_back(c);
  if (!joined.fixed_levels.empty()) out.set("rate_levels", joined.fixed_levels);
  for (const JoinedRate& r : joined.rows) {
    std::vector<std::string> row = r.key;
    const bool c = r.computed;
    for (auto& s : {fmt(r.published), r.theoretical, c ? fmt(r.reproduced) : "NA", number_cell(r.difference),
                    r.fitted ? fmt(r.lsq_slope) : "NA", r.fitted ? fmt(r.lsq_half95) : "NA",
                    fmt(r.lsq_points), c ? std::to_string(r.lsq_from) : "NA",
                    c ? std::to_string(r.level_lo) + "," + std::to_string(r.level_hi) : "",
                    c ? fmt(r.h_ratio) : "NA", number_cell(r.rate_before), number_cell(r.rate_after), r.status, r.reason})
      row.push_back(s);
    out.add_row(row);
  }
  for (auto& [s, n] : joined.counts) out.set("count_" + s, fmt(n));
}

}  // namespace gpm
