#include "gpm/geometry/cells.hpp"

#include <limits>
#include <sstream>

#include "gpm/error.hpp"

namespace gpm {

CellList::CellList(const std::vector<double>& x, const std::vector<double>& y,
                   double cell_size) {
  double x0 = 0, y0 = 0;
  if (!x.empty()) {
    x0 = *std::min_element(x.begin(), x.end());
    y0 = *std::min_element(y.begin(), y.end());
  }
  build(x, y, cell_size, x0, y0);
}

CellList::CellList(const std::vector<double>& x, const std::vector<double>& y,
                   double cell_size, double x0, double y0) {
  build(x, y, cell_size, x0, y0);
}

void CellList::build(const std::vector<double>& x, const std::vector<double>& y,
                     double cell_size, double x0, double y0) {
  require_positive(cell_size, "cell size");
  require_finite(x0, "cell grid origin x0");
  require_finite(y0, "cell grid origin y0");
  if (x.size() != y.size()) throw InputError("cell list: x and y differ in length");
  if (x.size() >= static_cast<std::size_t>(std::numeric_limits<int32_t>::max() - kPad))
    throw InputError("cell list: too many points for 32-bit indices");
  const std::size_t n = x.size();
  double xmax = x0, ymax = y0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      std::ostringstream s;
      s << "cell list: point " << i << " has a non-finite coordinate";
      throw InputError(s.str());
    }
    if (x[i] < x0 || y[i] < y0) {
      std::ostringstream s;
      s << "cell list: point " << i << " lies below the grid origin (" << x0 << ", " << y0
        << ")";
      throw InputError(s.str());
    }
    xmax = std::max(xmax, x[i]);
    ymax = std::max(ymax, y[i]);
  }
  c_ = cell_size;
  inv_c_ = 1.0 / cell_size;
  x0_ = x0;
  y0_ = y0;
  const double cx = std::floor((xmax - x0) * inv_c_) + 1, cy = std::floor((ymax - y0) * inv_c_) + 1;
  if (cx * cy > static_cast<double>(1 << 28)) {
    std::ostringstream s;
    s << "cell list: cell size " << cell_size << " gives " << cx << " x " << cy
      << " cells (more than 2^28); choose a larger cell size";
    throw InputError(s.str());
  }
  nx_ = static_cast<int64_t>(cx);
  ny_ = static_cast<int64_t>(cy);
  // Rounding slack for the range queries: far below any spacing of interest, far above
  // the rounding error of (x − x0)·(1/c).
  margin_ = 1e-10 * std::max({c_, xmax - x0, ymax - y0, std::abs(x0), std::abs(y0)});

  // Stable counting sort by cell number.
  std::vector<int32_t> cell(n);
  start_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell[i] = static_cast<int32_t>(row(y[i]) * nx_ + column(x[i]));
    ++start_[cell[i] + 1];
  }
  for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
  std::vector<int32_t> fill(start_.begin(), start_.end() - 1);
  index_.resize(n);
  slot_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int32_t k = fill[cell[i]]++;
    index_[k] = static_cast<int32_t>(i);
    slot_[i] = k;
  }
  xs_ = gather(x, n ? x[index_[n - 1]] : 0.0);
  ys_ = gather(y, n ? y[index_[n - 1]] : 0.0);
}

std::vector<double> CellList::gather(const std::vector<double>& payload, double pad) const {
  if (payload.size() != index_.size())
    throw InputError("cell list: payload size differs from the number of points");
  std::vector<double> out(index_.size() + kPad, pad);
  for (std::size_t k = 0; k < index_.size(); ++k) out[k] = payload[index_[k]];
  return out;
}

std::vector<double> CellList::scatter(const std::vector<double>& sorted) const {
  if (sorted.size() < index_.size())
    throw InputError("cell list: sorted array shorter than the number of points");
  std::vector<double> out(index_.size());
  for (std::size_t k = 0; k < index_.size(); ++k) out[index_[k]] = sorted[k];
  return out;
}

std::vector<int32_t> CellList::neighbours(double px, double py, double h) const {
  std::vector<int32_t> out;
  for_each_neighbour(px, py, h,
                     [&](int32_t k, double, double, double) { out.push_back(index_[k]); });
  std::sort(out.begin(), out.end());
  return out;
}

int64_t CellList::candidates(double px, double py, double h) const {
  int64_t n = 0;
  for_each_range(px, py, h, [&](int32_t b, int32_t e) { n += e - b; });
  return n;
}

}  // namespace gpm
