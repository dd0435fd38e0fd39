// Cell list: the particles sorted by square cells, row-major, as structure of arrays.
//
// Cell (cx, cy) covers [x0 + cx·c, x0 + (cx+1)·c) × [y0 + cy·c, y0 + (cy+1)·c); cell
// number cy·nx + cx; the particles of cell k occupy the sorted slots [start[k], start[k+1]).
// Within a cell the particles keep their original order (a stable counting sort), so the
// sorted order — and every neighbour sum taken in it — is a pure function of the input.
//
// A query for the disc |x − p| < h visits, for each row of cells that can meet the disc,
// only the columns that overlap the disc's chord in that row.  Because cells are sorted
// row-major, those cells are ONE contiguous range of sorted slots per row: the kernel
// runs one branch-free loop per range (see kernel.hpp).  Choose the cell size about h/4:
// candidates ≈ 1.3 × the particles in the disc (3×3 cells of size h: 2.9×).
//
// The sorted coordinate arrays carry kPad extra slots at the end (copies of the last
// point), so a vector loop may read up to kPad slots past the end of a range; it must
// mask those lanes (they are no neighbours), but all its arithmetic on them stays finite.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gpm {

class CellList {
 public:
  static constexpr int kPad = 16;  // padding slots after the last particle

  CellList() = default;
  // The grid's origin is the lower-left corner of the points' bounding box.
  // Throws InputError if cell_size is not finite and positive, x and y differ in length,
  // a coordinate is not finite, or the grid would exceed 2^28 cells.
  CellList(const std::vector<double>& x, const std::vector<double>& y, double cell_size);
  // Same with a given origin (x0, y0) ≤ every point (e.g. the corner of Ω_H).
  CellList(const std::vector<double>& x, const std::vector<double>& y, double cell_size,
           double x0, double y0);

  std::size_t size() const { return index_.size(); }
  double cell_size() const { return c_; }
  double x0() const { return x0_; }
  double y0() const { return y0_; }
  int64_t nx() const { return nx_; }
  int64_t ny() const { return ny_; }
  int64_t cell_count() const { return nx_ * ny_; }

  // Sorted coordinates: slot k holds the point index()[k]; size() + kPad entries (the
  // padding repeats the last point).
  const double* xs() const { return xs_.data(); }
  const double* ys() const { return ys_.data(); }
  const std::vector<int32_t>& index() const { return index_; }  // slot → original index
  const std::vector<int32_t>& slot() const { return slot_; }    // original index → slot
  const std::vector<int32_t>& start() const { return start_; }  // cell_count() + 1 offsets

  // Column / row of the cell holding a coordinate, clamped to the grid.
  int64_t column(double x) const { return clamp_index((x - x0_) * inv_c_, nx_); }
  int64_t row(double y) const { return clamp_index((y - y0_) * inv_c_, ny_); }

  // A per-point payload in sorted order, followed by kPad copies of `pad`.
  std::vector<double> gather(const std::vector<double>& payload, double pad = 0) const;
  // Values in sorted order back to original order.
  std::vector<double> scatter(const std::vector<double>& sorted) const;

  // Calls f(begin, end) for each row of cells that can hold points with |x − p| < h:
  // [begin, end) are the sorted slots of the cells overlapping the disc's chord in that
  // row (rows bottom to top; an empty range is skipped).  Every point within h of p is
  // in exactly one range; the ranges may also hold points farther away (candidates).
  template <class F>
  void for_each_range(double px, double py, double h, F&& f) const;
  // Calls f(slot, dx, dy, r2) for every point with r2 = dx² + dy² < h², dx = x_k − px.
  template <class F>
  void for_each_neighbour(double px, double py, double h, F&& f) const;
  // Original indices of the points with |x_i − p| < h, ascending.
  std::vector<int32_t> neighbours(double px, double py, double h) const;
  // Number of candidate slots a query visits (the sum of its range lengths).
  int64_t candidates(double px, double py, double h) const;

 private:
  void build(const std::vector<double>& x, const std::vector<double>& y, double cell_size,
             double x0, double y0);
  static int64_t clamp_index(double t, int64_t n) {
    if (!(t >= 0)) return 0;  // also NaN
    if (t >= static_cast<double>(n - 1)) return n - 1;
    return static_cast<int64_t>(t);
  }

  double c_ = 1, inv_c_ = 1, x0_ = 0, y0_ = 0, margin_ = 0;
  int64_t nx_ = 0, ny_ = 0;
  std::vector<double> xs_, ys_;
  std::vector<int32_t> index_, slot_, start_;
};

// Squared distance, computed the same way by the cell list, the operators and the
// brute-force checks.
inline double dist2(double dx, double dy) { return dx * dx + dy * dy; }

template <class F>
void CellList::for_each_range(double px, double py, double h, F&& f) const {
  if (index_.empty() || !(h > 0)) return;
  // The grid's extent; a disc entirely outside it meets no point.
  const double xe = x0_ + nx_ * c_, ye = y0_ + ny_ * c_;
  const double hm = h + margin_;
  if (px + hm < x0_ || px - hm > xe || py + hm < y0_ || py - hm > ye) return;
  const int64_t r0 = row(py - hm), r1 = row(py + hm);
  for (int64_t cy = r0; cy <= r1; ++cy) {
    // Distance from py to the band of row cy (0 inside it); shrink by the margin so that a
    // point assigned to this row by rounding is never missed.
    const double ylo = y0_ + cy * c_, yhi = ylo + c_;
    double dy = std::max(ylo - py, py - yhi);
    dy = std::max(0.0, dy - margin_);
    if (dy >= h) continue;
    const double half = std::sqrt(h * h - dy * dy) + margin_;
    const int64_t c0 = column(px - half), c1 = column(px + half);
    const int64_t base = cy * nx_;
    const int32_t b = start_[base + c0], e = start_[base + c1 + 1];
    if (b < e) f(b, e);
  }
}

template <class F>
void CellList::for_each_neighbour(double px, double py, double h, F&& f) const {
  const double h2 = h * h;
  for_each_range(px, py, h, [&](int32_t b, int32_t e) {
    for (int32_t k = b; k < e; ++k) {
      const double dx = xs_[k] - px, dy = ys_[k] - py;
      const double r2 = dist2(dx, dy);
      if (r2 < h2) f(k, dx, dy, r2);
    }
  });
}

}  // namespace gpm
