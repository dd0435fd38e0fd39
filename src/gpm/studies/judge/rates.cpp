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

TsvTable load_published(const std::string& path, const std::string& who) {
  if (!std::filesystem::exists(path)) throw InputError(who + ": no published file " + path);
  return TsvTable::load(path, false);
}

bool cell_number(const std::string& s, double& value) {
  std::size_t i = !s.empty() && s[0] == '-' ? 1 : 0;
  const std::size_t mantissa = i;
  while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
  if (i == mantissa) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t digits = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    if (i == digits) return false;
  }
  if (i != s.size()) return false;
  value = std::strtod(s.c_str(), nullptr);
  return std::isfinite(value);
}

double cell_number_or(const std::string& s, double otherwise) {
  double v;
  return cell_number(s, v) ? v : otherwise;
}

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
std::vector<int> fixed_levels(const RateJoin& join, const TsvTable& pub, TsvTable& out) {
  std::vector<int> fixed;
  if (join.levels.empty()) return fixed;
  std::string lv = join.levels;
  if (lv == "published") lv = documents_levels_text(pub);
  std::stringstream ss(lv);
  for (std::string item; std::getline(ss, item, ',');)
    fixed.push_back(static_cast<int>(parse_integer(item, "--levels", 0, 63)));
  if (fixed.size() != 2 || !(fixed[0] < fixed[1]))
    throw InputError("--levels: '" + lv + "' is not two increasing levels");
  out.set("rate_levels", lv);
  return fixed;
}

// The levels past the transition (issue 59 item 5): the finest run of consecutive stored
// levels over which every two-level rate lies within the tolerance of the finest pair's.  A
// least-squares line through a curved series measures its curvature, not a rate; through
// this tail it measures the rate the series settles to.  Returns its first level.
template <class Series>
int transition_tail_start(const Series& s, double tolerance) {
  std::vector<int> lv;
  std::vector<double> rate;  // rate[i]: levels lv[i], lv[i+1]
  for (auto& [level, pt] : s) lv.push_back(level);
  for (std::size_t i = 0; i + 1 < lv.size(); ++i) {
    const auto& a = s.at(lv[i]);
    const auto& b = s.at(lv[i + 1]);
    rate.push_back(two_level_rate(a.x, a.y, b.x, b.y));
  }
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

std::map<std::string, int> join_rates(const TsvTable& data, const TsvTable& pub,
                                      const RateJoin& join, TsvTable& out) {
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

  // Per key: (level, x, y) sorted by level; where each came from, for a duplicate's message.
  struct Point {
    double x, y;
    std::size_t row;
  };
  std::map<std::string, std::map<int, Point>> series;
  for (std::size_t i = 0; i < data.rows.size(); ++i) {
    const std::string key = key_of(data, i, dk);
    const long long level = data.integer(i, cl);
    const auto [it, fresh] = series[key].emplace(
        static_cast<int>(level), Point{data.number(i, cx), data.number(i, cy), i});
    if (!fresh)
      throw InputError(data.source + ": key '" + key + "' has two rows at level " +
                       std::to_string(level) + " (data rows " + std::to_string(it->second.row + 1) +
                       " and " + std::to_string(i + 1) + ")");
  }

  out.columns.insert(out.columns.end(), join.keys.begin(), join.keys.end());
  for (const char* c : {"published", "theoretical", "reproduced", "difference", "lsq_slope",
                        "lsq_half95", "lsq_points", "lsq_from", "levels", "h_ratio", "rate_before",
                        "rate_after", "status", "reason"})
    out.columns.push_back(c);
  const std::vector<int> fixed = fixed_levels(join, pub, out);
  std::map<std::string, int> counts;
  for (std::size_t i = 0; i < pub.rows.size(); ++i) {
    const std::string key = key_of(pub, i, pk);
    const double published = pub.number(i, cv);
    std::string rep = "NA", diff = "NA", lsq = "NA", half = "NA", points = "0", from = "NA", levels = "",
                ratio = "NA", before = "NA", after = "NA", status = "not-computed", why = "";
    auto it = series.find(key);
    const bool have = it != series.end() &&
                      (fixed.empty() ? it->second.size() >= 2
                                     : it->second.count(fixed[0]) && it->second.count(fixed[1]));
    if (have) {
      auto last = fixed.empty() ? std::prev(it->second.end()) : it->second.find(fixed[1]);
      auto prev = fixed.empty() ? std::prev(last) : it->second.find(fixed[0]);
      const double rate = two_level_rate(prev->second.x, prev->second.y, last->second.x,
                                         last->second.y);
      // The least-squares slope over the levels past the transition only (three at least).
      const int tail = transition_tail_start(it->second, join.tolerance);
      std::vector<double> xs, ys;
      for (auto& [lv, pt] : it->second)
        if (lv >= tail) xs.push_back(pt.x), ys.push_back(pt.y);
      rep = fmt(rate);
      from = std::to_string(tail);
      points = fmt(static_cast<long long>(xs.size()));
      if (xs.size() >= 3) {
        const RateFit fit = least_squares_fit(xs, ys);
        lsq = fmt(fit.slope), half = fmt(fit.half95), points = fmt(static_cast<long long>(fit.points));
      }
      levels = std::to_string(prev->first) + "," + std::to_string(last->first);
      // The pair's ratio of h, and our rate one level coarser and one finer: how far it moves
      // around the pair (the verdicts' "pre-asymptotic") and what a rate difference is as an
      // error ratio per level (their "near miss").
      ratio = fmt(prev->second.x / last->second.x);
      if (prev != it->second.begin()) {
        const auto b = std::prev(prev);
        if (b->first == prev->first - 1)
          before = fmt(two_level_rate(b->second.x, b->second.y, prev->second.x, prev->second.y));
      }
      if (const auto a = std::next(last); a != it->second.end() && a->first == last->first + 1)
        after = fmt(two_level_rate(last->second.x, last->second.y, a->second.x, a->second.y));
      // NaN fails every comparison: tested first, or it would fall through to a reason.
      if (!std::isfinite(rate) || !std::isfinite(published)) {
        status = "undefined";
      } else {
        diff = fmt(rate - published);
        if (!doc_levels.empty() && levels != doc_levels) {
          status = "other-levels";
          why = "rate from levels " + levels + "; the document's are " + doc_levels;
        } else {
          status = std::fabs(rate - published) <= join.tolerance ? "agrees" : "differs";
        }
      }
    }
    ++counts[status];
    std::vector<std::string> row;
    for (int c : pk) row.push_back(pub.text(i, c));
    for (auto& s : {fmt(published), ct >= 0 ? pub.text(i, ct) : std::string("NA"), rep, diff, lsq,
                    half, points, from, levels, ratio, before, after, status, why})
      row.push_back(s);
    out.add_row(row);
  }
  for (auto& [s, n] : counts) out.set("count_" + s, fmt(n));
  return counts;
}


}  // namespace gpm
