// Voronoi decomposition of Ω_H for a particle set (imoto eq. (5), thesis (1.5)):
//
//   σ_i = { y ∈ Ω_H : |y − x_i| < |y − x_j| for all j ≠ i },
//
// its cell areas |σ_i| (the Voronoi volumes of imoto §3, thesis Ṽ_i) and the covering
// radius  r_c = r_N = max_i sup_{y ∈ σ_i} |x_i − y|.
//
// Method: a CGAL Delaunay triangulation (exact predicates, double constructions) of the
// particles plus 8 far sentinel points; the Voronoi cell of a particle is the polygon of
// the circumcentres of its incident Delaunay faces in counter-clockwise order, clipped
// to the square Ω_H.  A clipped cell is convex, so the covering distance of a cell is
// the largest distance from x_i to a vertex of its clipped polygon.
//
// Cost: O(N log N) time (spatially sorted insertion is about linear in practice).
// Measured with core_voronoi (2-core VM): about 1.8 µs per particle, ~90% of it in the
// sequential triangulation, and a peak of about 185 bytes per particle for the whole
// program (particles included): 1.1 GiB at Δx = 2^-11, 4.4 GiB and ~45 s per particle
// set at Δx = 2^-12 (N = 2.4e7).  The per-cell loop runs on all OpenMP threads; each
// cell is computed independently, so the results are bit-identical for any thread count.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gpm/geometry/domain.hpp"

namespace gpm {

struct VoronoiCells {
  // Per particle (same order as the input):
  std::vector<double> area;   // |σ_i|
  std::vector<double> cover;  // max_{y ∈ σ_i} |x_i − y|
  // The clipped cells, only when keep_polygons: cell i has the counter-clockwise vertices
  // (px[k], py[k]) for k ∈ [offset[i], offset[i+1]); offset has N+1 entries.  Consecutive
  // vertices closer than 1e-14·side(Ω_H) are merged (a plain grid has 4 cocircular sites
  // per Voronoi vertex); `area` is the shoelace area of exactly these polygons.
  std::vector<uint64_t> offset;
  std::vector<double> px, py;
  double covering_radius = 0;  // r_c = max_i cover[i]
  std::size_t worst = 0;       // smallest i with cover[i] = r_c
  double area_sum = 0;         // Σ|σ_i| (compensated sum); equals |Ω_H| up to rounding
};

// Computes the Voronoi cells of Ω_H = dom's square for the particles p.
// Throws InputError if p is empty, if a particle is not finite or not inside the open
// square Ω_H (the message names the particle), or if two particles coincide (names both).
// Throws NumericalError if a cell comes out empty or non-finite (never expected).
VoronoiCells voronoi_cells(const Particles& p, const Domain& dom = Domain{},
                           bool keep_polygons = false);

// Signed shoelace area of the polygon (xs[k], ys[k]), k = 0..n−1: positive when
// counter-clockwise.  Coordinates are taken relative to (ox, oy) to limit cancellation.
double polygon_area(const double* xs, const double* ys, std::size_t n, double ox = 0,
                    double oy = 0);

}  // namespace gpm
