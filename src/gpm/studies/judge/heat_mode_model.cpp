#include "gpm/studies/judge/heat_mode_model.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/studies/judge/evidence.hpp"  // point_rate
#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

namespace {

const double kWaveNumber = M_PI * std::sqrt(2.0);           // |k| of sin πx sin πy
const double kMu = kHeatKappa * kWaveNumber * kWaveNumber;  // decay rate of ũ: 2κπ² = π²

}  // namespace

double mode_error(double theta, double mu_h, double dt, long long K) {
  const double z = mu_h * dt, g = (1 - (1 - theta) * z) / (1 + theta * z);
  double worst = 0, gk = 1;
  for (long long k = 0; k <= K; ++k, gk *= g) worst = std::max(worst, std::fabs(gk - std::exp(-kMu * k * dt)));
  return worst;
}

std::vector<ModeRow> mode_model(const TsvTable& d) {
  const auto vol = d.get("volumes");
  if (!vol) throw InputError(d.source + ": no '# volumes = ' line; is it a thesis_heat data file?");
  const bool cell = vol->rfind("cell", 0) == 0;  // V_i = Δx²: no mismatch
  const Domain dom;
  std::vector<ModeRow> out;
  for (std::size_t i = 0; i < d.rows.size(); ++i) {
    if (d.text(i, "blew_up") == "yes") continue;
    ModeRow r;
    r.weight = d.text(i, "weight");
    r.theta = d.text(i, "theta");
    r.level = static_cast<int>(d.integer(i, d.require_column("level")));
    r.h = d.number(i, d.require_column("h"));
    r.dt = d.number(i, d.require_column("dt"));
    r.K = d.integer(i, d.require_column("K"));
    r.measured = d.number(i, d.require_column("rel_error"));
    const double dx = d.number(i, d.require_column("dx"));
    const double n = d.number(i, d.require_column("N"));
    // δ = |Ω_H|/(N Δx²) − 1 from the row's N.
    r.mismatch = cell ? 0.0 : volume_mismatch(n, dx, dom);
    r.eps = laplacian_smoothing_error(weight(r.weight), kWaveNumber * r.h);
    const double theta = d.number(i, d.require_column("theta"));
    r.predicted = mode_error(theta, kMu * (1 + r.mismatch) * (1 - r.eps), r.dt, r.K);
    r.no_mismatch = mode_error(theta, kMu * (1 - r.eps), r.dt, r.K);
    out.push_back(r);
  }
  return out;
}

std::vector<ModeRate> mode_rates(const HeatTable& t, const std::vector<ModeRow>& rows,
                                 const std::vector<ModeRow>& cell_rows) {
  int lc = 0, lf = 0;  // the catalog's "coarse,fine"
  if (std::sscanf(t.rate_levels.c_str(), "%d,%d", &lc, &lf) != 2)
    throw std::logic_error("table " + t.table + ": rate levels '" + t.rate_levels + "'");
  // (key, level) -> row: the rates come out in the order of the keys.
  auto index = [](const std::vector<ModeRow>& v) {
    std::map<std::pair<std::string, int>, const ModeRow*> m;
    for (auto& r : v) m[{r.weight + " " + r.theta, r.level}] = &r;
    return m;
  };
  const auto m = index(rows), mc = index(cell_rows);
  std::vector<ModeRate> out;
  for (auto& [key, c] : m) {
    if (key.second != lc || !m.count({key.first, lf})) continue;
    const ModeRow& f = *m.at({key.first, lf});
    ModeRate r;
    r.key = key.first;
    r.reproduced = point_rate(*c, f, &ModeRow::measured);
    r.predicted = point_rate(*c, f, &ModeRow::predicted);
    r.no_mismatch = point_rate(*c, f, &ModeRow::no_mismatch);
    // The V_i = Δx² run's rate against the data's own h: the same particles' radii.
    if (mc.count({key.first, lc}) && mc.count({key.first, lf}))
      r.cell = point_rate(EvidencePoint{c->h, mc.at({key.first, lc})->measured},
                          EvidencePoint{f.h, mc.at({key.first, lf})->measured});
    r.ratio_coarse = c->measured / c->predicted;
    r.ratio_fine = f.measured / f.predicted;
    r.mismatch_coarse = c->mismatch;
    r.mismatch_fine = f.mismatch;
    out.push_back(r);
  }
  return out;
}

}  // namespace gpm
