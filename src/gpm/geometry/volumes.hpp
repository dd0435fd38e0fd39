// The particle volumes V_i the studies use: the documents' uniform |Ω_H|/N and, as a
// diagnostic, the grid cell Δx².
#pragma once
#include <string>
#include <vector>

#include "gpm/geometry/domain.hpp"

namespace gpm {

// |Ω_H|/N for every particle (imoto §5, thesis (A.10)).
std::vector<double> uniform_volumes(const Particles& p, const Domain& dom = Domain{});

// Δx² for every particle: the area of one cell of the grid G_Δx the particles come from.
// Not a choice of the documents: a diagnostic beside (A.10).  With H = 0.1 the side 1.2/Δx of
// Ω_H is not a whole number of cells (153.6 at Δx = 2^-7), so N·Δx² ≠ |Ω_H| and every (A.10)
// volume is off by volume_mismatch(); the discrete Laplacian is scaled by the same factor.
std::vector<double> cell_volumes(const Particles& p, double dx);
// |Ω_H|/(N·Δx²) − 1: +0.79% at Δx = 2^-7, +0.13% at 2^-8, −0.20% at 2^-9 (N = 153², 307², 615²).
double volume_mismatch(const Particles& p, double dx, const Domain& dom = Domain{});
// The same from the particle count alone (a data file's N column).
double volume_mismatch(double n_particles, double dx, const Domain& dom = Domain{});

// The volume choices of the PDE studies: lattice = (A.10)'s |Ω_H|/N, cell = Δx².  Their
// names are what options, data files and the set-up readings say.
enum class PdeVolumes { lattice, cell };
std::string pde_volumes_name(PdeVolumes v);
// InputError "--volumes: 'x' is not lattice (…) or cell (…)".
PdeVolumes parse_pde_volumes(const std::string& s);
std::vector<double> pde_volumes(PdeVolumes choice, const Particles& p, double dx,
                                const Domain& dom = Domain{});
// What a data file's header says of a choice.
std::string pde_volumes_description(PdeVolumes choice);

}  // namespace gpm
