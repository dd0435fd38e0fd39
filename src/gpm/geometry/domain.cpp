#include "gpm/geometry/domain.hpp"

#include <cmath>
#include <sstream>

#include "gpm/error.hpp"

namespace gpm {

std::size_t Particles::count_in_omega() const {
  std::size_t n = 0;
  for (auto f : in_omega) n += f;
  return n;
}

void Particles::push(double px, double py, int32_t i, int32_t j) {
  x.push_back(px);
  y.push_back(py);
  gi.push_back(i);
  gj.push_back(j);
  in_omega.push_back(Domain::in_omega(px, py) ? 1 : 0);
}

namespace {
uint64_t splitmix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
}  // namespace

double jitter(uint64_t seed, int64_t i, int64_t j, int c, double amplitude) {
  // Three chained rounds so that nearby (i, j) give unrelated streams.
  uint64_t h = splitmix64(seed);
  h = splitmix64(h ^ static_cast<uint64_t>(i));
  h = splitmix64(h ^ (static_cast<uint64_t>(j) * 2 + static_cast<uint64_t>(c)));
  // 53 random bits -> u in the open interval (0, 1).
  const double u = (static_cast<double>(h >> 11) + 0.5) * 0x1.0p-53;
  return (2.0 * u - 1.0) * amplitude;  // open interval (−amplitude, amplitude)
}

int64_t grid_first(double dx, const Domain& dom) {
  // smallest i with i·dx > lo
  int64_t i = static_cast<int64_t>(std::floor(dom.lo() / dx));
  while (i * dx <= dom.lo()) ++i;
  return i;
}

int64_t grid_last(double dx, const Domain& dom) {
  int64_t i = static_cast<int64_t>(std::ceil(dom.hi() / dx));
  while (i * dx >= dom.hi()) --i;
  return i;
}

Particles jittered_grid(double dx, uint64_t seed, double amplitude, const Domain& dom) {
  require_positive(dx, "dx");
  if (dx >= 0.5) {
    std::ostringstream s;
    s << "dx = " << dx << " is too coarse: no grid node would lie inside Omega=(0,1)^2";
    throw InputError(s.str());
  }
  if (!(amplitude >= 0 && amplitude < 0.5)) {
    std::ostringstream s;
    s << "jitter amplitude must lie in [0, 0.5), got " << amplitude;
    throw InputError(s.str());
  }
  const int64_t a = grid_first(dx, dom), b = grid_last(dx, dom);
  const int64_t n1 = b - a + 1;
  Particles p;
  p.x.reserve(n1 * n1);
  p.y.reserve(n1 * n1);
  p.gi.reserve(n1 * n1);
  p.gj.reserve(n1 * n1);
  p.in_omega.reserve(n1 * n1);
  auto fold = [&](double v, double node) {
    if (v <= dom.lo()) v = 2 * dom.lo() - v;
    if (v >= dom.hi()) v = 2 * dom.hi() - v;
    // On the edge exactly (probability ~2^-53): fall back to the node itself.
    if (!(v > dom.lo() && v < dom.hi())) v = node;
    return v;
  };
  for (int64_t j = a; j <= b; ++j)
    for (int64_t i = a; i <= b; ++i) {
      const double nx = i * dx, ny = j * dx;
      const double px = fold(nx + jitter(seed, i, j, 0, amplitude) * dx, nx);
      const double py = fold(ny + jitter(seed, i, j, 1, amplitude) * dx, ny);
      p.push(px, py, static_cast<int32_t>(i), static_cast<int32_t>(j));
    }
  return p;
}

}  // namespace gpm
