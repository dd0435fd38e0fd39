#include "gpm/studies/judge/evidence.hpp"

#include <cmath>
#include <limits>

#include "gpm/operators/norms.hpp"  // two_level_rate
#include "gpm/studies/judge/rates.hpp"  // cell_number

namespace gpm {

EvidenceSeriesMap read_series(const TsvTable& t, const std::vector<std::string>& keys, const std::string& error) {
  std::vector<int> ck;
  for (auto& k : keys) ck.push_back(t.require_column(k));
  const int cl = t.require_column("level"), ch = t.require_column("h"), ce = t.require_column(error);
  EvidenceSeriesMap out;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    double e = 0;  // NA (a blown-up series), nan, inf, 0 or below: no point
    if (!cell_number(t.text(i, ce), e) || !std::isfinite(e) || e <= 0) continue;
    std::vector<std::string> key;
    for (int c : ck) key.push_back(t.text(i, c));
    out[key][static_cast<int>(t.integer(i, cl))] = {t.number(i, ch), e};
  }
  return out;
}

double series_rate(const EvidenceSeries& s, int lo, int hi) {
  const auto a = s.find(lo), b = s.find(hi);
  if (a == s.end() || b == s.end()) return std::numeric_limits<double>::quiet_NaN();
  return two_level_rate(a->second.h, a->second.error, b->second.h, b->second.error);
}

double error_constant(const EvidencePoint& pt, double p) { return pt.error / std::pow(pt.h, p); }

}  // namespace gpm
