// h-connectivity of a particle distribution (thesis Definition 1.8).
//
// X_{N,H} satisfies the h-connectivity if every particle in Ω can be joined to a particle
// on Γ ∪ Γ_H (the particles outside Ω, where the Dirichlet data are imposed) by a chain of
// particles whose consecutive members are closer than h.  Equivalently, in the graph G with
// the particles as vertices and an edge for every pair with |x_i − x_j| < h, every vertex in
// Ω has a path to a vertex outside Ω.  The discrete Poisson problem (thesis Ch. 2) needs it:
// an isolated group of particles in Ω sees no boundary value and its equations are singular.
//
// Method: one breadth-first search on G started from all particles outside Ω at once; the
// neighbours are found with a CellList of cell size h, so the cost is O(N · particles per
// disc).  The search visits each particle once; what it does not reach is the answer.
#pragma once
#include <cstdint>
#include <vector>

#include "gpm/geometry/domain.hpp"

namespace gpm {

struct ConnectivityResult {
  bool connected = false;              // h-connectivity holds
  std::vector<int32_t> unconnected;    // particles in Ω with no path to Γ ∪ Γ_H, ascending
  std::vector<int32_t> hops;           // per particle: edges to the nearest particle outside Ω
                                       // (0 outside Ω, −1 if unreachable)
  std::size_t n_sources = 0;           // particles outside Ω (the search's start set)
};

// Breadth-first search on G = (X_{N,H}, {|x_i − x_j| < h}) from the particles outside Ω.
// Throws InputError if h is not finite and positive.  With no particle outside Ω every
// particle in Ω is unconnected.
ConnectivityResult h_connectivity(const Particles& p, double h);

// The edges of G (i < j, |x_i − x_j| < h), for drawing the graph.
std::vector<std::pair<int32_t, int32_t>> neighbour_edges(const Particles& p, double h);

}  // namespace gpm
