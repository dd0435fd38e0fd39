#include "gpm/geometry/connectivity.hpp"

#include <deque>

#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"

namespace gpm {

ConnectivityResult h_connectivity(const Particles& p, double h) {
  require_positive(h, "influence radius h");
  ConnectivityResult r;
  const std::size_t n = p.size();
  r.hops.assign(n, -1);
  std::deque<int32_t> queue;
  for (std::size_t i = 0; i < n; ++i)
    if (!p.in_omega[i]) {
      r.hops[i] = 0;
      queue.push_back(static_cast<int32_t>(i));
    }
  r.n_sources = queue.size();
  if (n > 0) {
    const CellList cl(p.x, p.y, h);
    const auto& index = cl.index();
    while (!queue.empty()) {
      const int32_t i = queue.front();
      queue.pop_front();
      // The edge condition is the strict |x_i − x_j| < h of Definition 1.8.
      cl.for_each_neighbour(p.x[i], p.y[i], h, [&](int64_t slot, double, double, double) {
        const int32_t j = index[static_cast<std::size_t>(slot)];
        if (r.hops[j] < 0) {
          r.hops[j] = r.hops[i] + 1;
          queue.push_back(j);
        }
      });
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (p.in_omega[i] && r.hops[i] < 0) r.unconnected.push_back(static_cast<int32_t>(i));
  r.connected = r.unconnected.empty();
  return r;
}

std::vector<std::pair<int32_t, int32_t>> neighbour_edges(const Particles& p, double h) {
  require_positive(h, "influence radius h");
  std::vector<std::pair<int32_t, int32_t>> e;
  if (p.size() == 0) return e;
  const CellList cl(p.x, p.y, h);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int32_t j : cl.neighbours(p.x[i], p.y[i], h))
      if (static_cast<std::size_t>(j) > i) e.emplace_back(static_cast<int32_t>(i), j);
  return e;
}

}  // namespace gpm
