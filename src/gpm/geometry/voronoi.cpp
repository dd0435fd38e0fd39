#include "gpm/geometry/voronoi.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/spatial_sort.h>
#include <omp.h>

#include <algorithm>
#include <boost/property_map/property_map.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "gpm/error.hpp"

namespace gpm {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Fb = CGAL::Triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;
using Point = K::Point_2;
using Vertex_handle = Delaunay::Vertex_handle;

// Readable property map index -> Point_2 over the particle arrays, so that spatial_sort
// can order a vector of indices without copying the points.
struct ParticlePointMap {
  using key_type = std::size_t;
  using value_type = Point;
  using reference = Point;
  using category = boost::readable_property_map_tag;
  const double* x;
  const double* y;
  friend Point get(const ParticlePointMap& m, std::size_t i) { return Point(m.x[i], m.y[i]); }
};

struct Pt {
  double x, y;
};

// One Sutherland–Hodgman step: keeps the part of the polygon `in` with
// coordinate[axis] >= c (upper = false) or <= c (upper = true).
// The crossing point of an edge is computed from its endpoints in lexicographic order,
// so the two cells sharing that edge get bit-identical clipped vertices.
void clip_half_plane(const std::vector<Pt>& in, std::vector<Pt>& out, int axis, double c,
                     bool upper) {
  out.clear();
  const std::size_t n = in.size();
  if (n == 0) return;
  auto coord = [axis](const Pt& p) { return axis == 0 ? p.x : p.y; };
  auto inside = [&](const Pt& p) { return upper ? coord(p) <= c : coord(p) >= c; };
  auto cross = [&](Pt a, Pt b) {
    if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
    if (axis == 0) {
      const double t = (c - a.x) / (b.x - a.x);
      double yy = a.y + t * (b.y - a.y);
      yy = std::clamp(yy, std::min(a.y, b.y), std::max(a.y, b.y));
      return Pt{c, yy};
    }
    const double t = (c - a.y) / (b.y - a.y);
    double xx = a.x + t * (b.x - a.x);
    xx = std::clamp(xx, std::min(a.x, b.x), std::max(a.x, b.x));
    return Pt{xx, c};
  };
  Pt s = in[n - 1];
  bool s_in = inside(s);
  for (std::size_t k = 0; k < n; ++k) {
    const Pt e = in[k];
    const bool e_in = inside(e);
    if (e_in) {
      if (!s_in) out.push_back(cross(s, e));
      out.push_back(e);
    } else if (s_in) {
      out.push_back(cross(s, e));
    }
    s = e;
    s_in = e_in;
  }
}

// Per-thread scratch buffers: grown on first use, then reused (no allocation per cell).
struct Scratch {
  std::vector<Pt> a, b;
  Scratch() {
    a.reserve(64);
    b.reserve(64);
  }
};

// The Voronoi cell of the real vertex v clipped to [lo, hi]², counter-clockwise, with
// consecutive near-coincident vertices merged.  The result is left in s.a.
void clipped_cell(const Delaunay& dt, Vertex_handle v, double lo, double hi, double tol,
                  Scratch& s) {
  s.a.clear();
  auto fc = dt.incident_faces(v), done = fc;
  do {
    if (dt.is_infinite(fc)) {
      // Impossible: every particle lies strictly inside the sentinels' hull.  Leave an
      // empty cell, which the caller reports (no exception inside the OpenMP region).
      s.a.clear();
      return;
    }
    const Point c = CGAL::circumcenter(fc->vertex(0)->point(), fc->vertex(1)->point(),
                                       fc->vertex(2)->point());
    s.a.push_back(Pt{c.x(), c.y()});
  } while (++fc != done);
  clip_half_plane(s.a, s.b, 0, lo, false);
  clip_half_plane(s.b, s.a, 0, hi, true);
  clip_half_plane(s.a, s.b, 1, lo, false);
  clip_half_plane(s.b, s.a, 1, hi, true);
  // Merge consecutive near-duplicates (cyclically).
  auto& q = s.a;
  std::size_t m = 0;
  for (std::size_t k = 0; k < q.size(); ++k) {
    if (m > 0 && std::abs(q[k].x - q[m - 1].x) <= tol && std::abs(q[k].y - q[m - 1].y) <= tol)
      continue;
    q[m++] = q[k];
  }
  while (m > 1 && std::abs(q[m - 1].x - q[0].x) <= tol && std::abs(q[m - 1].y - q[0].y) <= tol)
    --m;
  q.resize(m);
}

std::string point_text(double x, double y) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << x << ", " << y << ")";
  return s.str();
}

}  // namespace

double polygon_area(const double* xs, const double* ys, std::size_t n, double ox, double oy) {
  if (n < 3) return 0.0;
  double twice = 0;
  double ux = xs[n - 1] - ox, uy = ys[n - 1] - oy;
  for (std::size_t k = 0; k < n; ++k) {
    const double vx = xs[k] - ox, vy = ys[k] - oy;
    twice += ux * vy - vx * uy;
    ux = vx;
    uy = vy;
  }
  return 0.5 * twice;
}

VoronoiCells voronoi_cells(const Particles& p, const Domain& dom, bool keep_polygons) {
  const std::size_t n = p.size();
  if (n == 0) throw InputError("voronoi: no particles");
  if (p.y.size() != n) throw InputError("voronoi: particle arrays x and y differ in length");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i]) || !dom.in_omega_H(p.x[i], p.y[i])) {
      std::ostringstream s;
      s << "voronoi: particle " << i << " at " << point_text(p.x[i], p.y[i])
        << " is not inside the open square Omega_H = (" << dom.lo() << ", " << dom.hi()
        << ")^2";
      throw InputError(s.str());
    }
  }
  const double lo = dom.lo(), hi = dom.hi(), side = dom.side();
  const double tol = 1e-14 * side;

  // Vertex handles by particle index; filled during insertion.
  std::vector<Vertex_handle> vh(n);
  VoronoiCells out;
  {
    Delaunay dt;
    // Sentinels: 8 points on a circle of radius R = 100·side about the centre of Ω_H.
    // (a) They cannot change any cell inside Ω_H: for y ∈ Ω_H every particle (all lie in
    //     Ω_H) is within diam(Ω_H) = √2·side of y, while every sentinel is at least
    //     R − side/√2 ≈ 99.3·side away, so the nearest site of y is always a particle
    //     and σ_i ∩ Ω_H is the same with or without them.
    // (b) They make every particle's cell bounded: the particles lie strictly inside the
    //     sentinel octagon (inradius R·cos(π/8) ≈ 92·side > side/√2), so no particle is
    //     on the convex hull and no infinite face is incident to a particle's vertex.
    // Inserted first, so that every particle insertion is an interior one.
    const double cx = 0.5 * (lo + hi), cy = cx, R = 100.0 * side;
    for (int k = 0; k < 8; ++k) {
      const double t = k * std::numbers::pi / 4;
      auto v = dt.insert(Point(cx + R * std::cos(t), cy + R * std::sin(t)));
      v->info() = n + k;
    }
    {
      std::vector<std::size_t> order(n);
      for (std::size_t i = 0; i < n; ++i) order[i] = i;
      const ParticlePointMap pmap{p.x.data(), p.y.data()};
      CGAL::spatial_sort(order.begin(), order.end(),
                         CGAL::Spatial_sort_traits_adapter_2<K, ParticlePointMap>(pmap));
      Delaunay::Face_handle hint;
      for (std::size_t i : order) {
        const auto before = dt.number_of_vertices();
        Vertex_handle v = dt.insert(Point(p.x[i], p.y[i]), hint);
        if (dt.number_of_vertices() == before) {
          const std::size_t j = v->info();
          std::ostringstream s;
          s << "voronoi: particles " << std::min(i, j) << " and " << std::max(i, j)
            << " coincide at " << point_text(p.x[i], p.y[i]);
          throw InputError(s.str());
        }
        v->info() = i;
        vh[i] = v;
        hint = v->face();
      }
    }  // `order` freed here

    out.area.resize(n);
    out.cover.resize(n);
    if (keep_polygons) out.offset.assign(n + 1, 0);

    // Pass 1: area, covering distance and (for the CSR layout) vertex count per cell.
    bool bad = false;
    std::size_t bad_i = 0;
#pragma omp parallel
    {
      Scratch s;
#pragma omp for schedule(dynamic, 2048)
      for (std::size_t i = 0; i < n; ++i) {
        clipped_cell(dt, vh[i], lo, hi, tol, s);
        const auto& q = s.a;
        double a = 0, r2 = 0;
        if (q.size() >= 3) {
          double ux = q.back().x - p.x[i], uy = q.back().y - p.y[i];
          for (const Pt& e : q) {
            const double vx = e.x - p.x[i], vy = e.y - p.y[i];
            a += ux * vy - vx * uy;
            r2 = std::max(r2, vx * vx + vy * vy);
            ux = vx;
            uy = vy;
          }
          a *= 0.5;
        }
        out.area[i] = a;
        out.cover[i] = std::sqrt(r2);
        if (keep_polygons) out.offset[i + 1] = q.size();
        if (!(a > 0) || !std::isfinite(a) || !std::isfinite(r2)) {
#pragma omp critical(gpm_voronoi_bad)
          if (!bad || i < bad_i) bad = true, bad_i = i;
        }
      }
    }
    if (bad) {
      std::ostringstream s;
      s << "voronoi: the cell of particle " << bad_i << " at "
        << point_text(p.x[bad_i], p.y[bad_i]) << " came out empty or non-finite (area "
        << out.area[bad_i] << ")";
      throw NumericalError(s.str());
    }

    // Pass 2 (only for the polygons): the same cells again, written into CSR arrays sized
    // from pass 1.  Recomputing is cheaper in memory than keeping per-thread copies.
    if (keep_polygons) {
      for (std::size_t i = 0; i < n; ++i) out.offset[i + 1] += out.offset[i];
      out.px.resize(out.offset[n]);
      out.py.resize(out.offset[n]);
#pragma omp parallel
      {
        Scratch s;
#pragma omp for schedule(dynamic, 2048)
        for (std::size_t i = 0; i < n; ++i) {
          clipped_cell(dt, vh[i], lo, hi, tol, s);
          std::size_t k = out.offset[i];
          for (const Pt& e : s.a) out.px[k] = e.x, out.py[k] = e.y, ++k;
        }
      }
    }
  }  // triangulation freed here
  std::vector<Vertex_handle>().swap(vh);

  // Reductions in index order: deterministic for any thread count.
  double sum = 0, comp = 0;  // Neumaier summation
  for (std::size_t i = 0; i < n; ++i) {
    const double a = out.area[i], t = sum + a;
    comp += std::abs(sum) >= std::abs(a) ? (sum - t) + a : (a - t) + sum;
    sum = t;
    if (out.cover[i] > out.covering_radius) out.covering_radius = out.cover[i], out.worst = i;
  }
  out.area_sum = sum + comp;
  return out;
}

}  // namespace gpm
