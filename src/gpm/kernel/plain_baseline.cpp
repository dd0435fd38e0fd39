// The plain baseline of the fused kernel: one weight, one field, the textbook loop over the
// cell list's neighbours (no blocks, no fusion).  The benchmark's "before"; a unit test
// checks it against the tests' brute-force reference.
#include "gpm/kernel/plain_baseline.hpp"

#include <omp.h>

#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/kernel/kernel_poly.hpp"  // PolyEval, build_eval, kD

namespace gpm {

namespace {
int thread_count(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }
}  // namespace

BaselineResult plain_baseline(const std::vector<double>& x, const std::vector<double>& y,
                              const std::vector<double>& V, const std::vector<double>& v,
                              const WeightFunction& w, double h,
                              const std::vector<int32_t>& targets, int threads) {
  require_positive(h, "influence radius h");
  if (V.size() != x.size() || v.size() != x.size())
    throw InputError("plain baseline: x, V and v differ in length");
  const PolyEval pi = build_eval(w, 0, "interpolant");
  const PolyEval g = build_eval(w, 2, "w/r^2");
  if (pi.m > 0) throw InputError("plain baseline: weight unbounded at r = 0");
  const CellList cl(x, y, h);  // cells of size h
  struct P {
    double x, y, V, v;
  };
  std::vector<P> aos(cl.size());
  for (std::size_t k = 0; k < cl.size(); ++k) {
    const int32_t i = cl.index()[k];
    aos[k] = {x[i], y[i], V[i], v[i]};
  }
  const std::size_t nt = targets.size();
  for (auto t : targets)
    if (t < 0 || static_cast<std::size_t>(t) >= x.size())
      throw InputError("plain baseline: target index out of range");
  BaselineResult r;
  r.interp.assign(nt, 0);
  r.grad_x.assign(nt, 0);
  r.grad_y.assign(nt, 0);
  r.lap.assign(nt, 0);
  const double h2 = h * h, h4 = h2 * h2;
  const int64_t nx = cl.nx(), ny = cl.ny();
#pragma omp parallel for schedule(dynamic, 64) num_threads(thread_count(threads))
  for (std::size_t t = 0; t < nt; ++t) {
    const int32_t j = targets[t];
    const double px = x[j], py = y[j], vj = v[j];
    const int64_t cx = cl.column(px), cy = cl.row(py);
    double s_pi = 0, s_gx = 0, s_gy = 0, s_lap = 0;
    for (int64_t ry = std::max<int64_t>(cy - 1, 0); ry <= std::min(cy + 1, ny - 1); ++ry)
      for (int64_t rx = std::max<int64_t>(cx - 1, 0); rx <= std::min(cx + 1, nx - 1); ++rx) {
        const int64_t c = ry * nx + rx;
        for (int32_t k = cl.start()[c]; k < cl.start()[c + 1]; ++k) {
          const P& p = aos[k];
          const double dx = p.x - px, dy = p.y - py;
          const double r2 = dist2(dx, dy);
          if (r2 < h2) {
            const double rr = std::sqrt(r2), q = rr / h;
            s_pi += p.V * p.v * eval_scalar(pi, q, 1.0);
            if (r2 > 0) {
              const double tt = p.V * (p.v - vj) * eval_scalar(g, q, h / rr);
              s_gx += tt * dx;
              s_gy += tt * dy;
              s_lap += tt;
            }
          }
        }
      }
    r.interp[t] = s_pi / h2;
    r.grad_x[t] = kD * s_gx / h4;
    r.grad_y[t] = kD * s_gy / h4;
    r.lap[t] = 2.0 * kD * s_lap / h4;
  }
  return r;
}

}  // namespace gpm
