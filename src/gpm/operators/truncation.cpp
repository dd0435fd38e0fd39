#include "gpm/operators/truncation.hpp"

#include <chrono>
#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/operators/norms.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

Operator parse_operator(const std::string& s) {
  if (s == "interp") return Operator::interp;
  if (s == "grad") return Operator::grad;
  if (s == "lap") return Operator::lap;
  throw InputError("unknown operator '" + s + "'; valid: interp, grad, lap");
}

Volumes parse_volumes(const std::string& s) {
  if (s == "uniform") return Volumes::uniform;
  if (s == "voronoi") return Volumes::voronoi;
  throw InputError("unknown volume choice '" + s + "'; valid: uniform, voronoi");
}

std::string operator_name(Operator op) {
  return op == Operator::interp ? "interp" : op == Operator::grad ? "grad" : "lap";
}

std::string volumes_name(Volumes v) { return v == Volumes::uniform ? "uniform" : "voronoi"; }

double max_influence_radius() { return Domain{}.side(); }

double truncation_bytes_per_particle(Volumes v) {
  // Peak RSS / N of `gpm trunc --dx 2^-10 --m 3` (1.5e6 particles, one weight, one field):
  // 98 bytes with uniform volumes, 193 with Voronoi volumes; half as much again for the
  // heavier weights and fields of other settings.
  return v == Volumes::uniform ? 150 : 300;
}

TargetSpacing target_spacing(const Particles& p, double dx, double jitter, double h) {
  // Every particle has a grid neighbour node at distance dx; both moved by less than
  // jitter·dx per component, so that particle lies within dx·√((1+2j)² + (2j)²).
  const double reach = dx * std::sqrt((1 + 2 * jitter) * (1 + 2 * jitter) + 4 * jitter * jitter) *
                       (1 + 1e-12);
  const CellList cl(p.x, p.y, reach);
  TargetSpacing out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.in_omega[i]) continue;
    double nearest2 = reach * reach;
    cl.for_each_neighbour(p.x[i], p.y[i], reach, [&](int32_t slot, double, double, double r2) {
      if (cl.index()[slot] != static_cast<int32_t>(i)) nearest2 = std::min(nearest2, r2);
    });
    const double nearest = std::sqrt(nearest2);
    out.largest = std::max(out.largest, nearest);
    out.isolated += nearest >= h;
  }
  return out;
}

TruncationResult truncation_error(const TruncationSetting& s) {
  const auto t0 = std::chrono::steady_clock::now();
  require_positive(s.h, "h");
  const Domain dom;
  const TestFunction& f = test_function(s.function);
  const WeightFunction& w = weight(s.weight);

  // Particles and volumes: |Ω_H|/N (imoto §5, thesis (A.10)) or Voronoi cell areas.
  const Particles p = jittered_grid(s.dx, s.seed, s.jitter);
  std::vector<double> V;
  if (s.volumes == Volumes::uniform)
    V = uniform_volumes(p, dom);
  else
    V = voronoi_cells(p, dom).area;

  const auto e = fused_errors(p, V, s.h, {ErrorRequest{w.name, s.op}}, {f.name});
  TruncationResult out;
  out.n = p.size();
  out.n_in_omega = p.count_in_omega();
  out.pairs = e.pairs;
  out.rel_error = e.errors.at(0).rel_error;
  out.worst_x = p.x[static_cast<std::size_t>(e.errors.at(0).worst)];
  out.worst_y = p.y[static_cast<std::size_t>(e.errors.at(0).worst)];
  out.h_exceeds_H = s.h >= dom.H;
  const TargetSpacing sp = target_spacing(p, s.dx, s.jitter, s.h);
  out.largest_spacing = sp.largest;
  out.isolated_targets = sp.isolated;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace gpm
