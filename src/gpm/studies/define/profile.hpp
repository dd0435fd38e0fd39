// The two run profiles.  `quick` reproduces every figure in minutes on this machine
// (SEP's [R]); `paper` runs the documents' exact resolutions (SEP's [CR], hours).
// The levels of each study per profile are in the study catalog (catalog.hpp).
#pragma once
#include <string>

#include "gpm/geometry/influence_radius.hpp"
#include "gpm/solvers/laplacian_storage.hpp"
#include <vector>

namespace gpm {

enum class Profile { quick, paper };

// Throws InputError "unknown profile 'x'; valid: quick, paper".
Profile parse_profile(const std::string& name);
std::string profile_name(Profile p);

// Levels k (Δx = 2^-k) of a study for the given profile.
inline const std::vector<int>& pick(Profile p, const std::vector<int>& quick,
                                    const std::vector<int>& paper) {
  return p == Profile::quick ? quick : paper;
}

class Args;
// The levels of a run: the profile's list, or the comma-separated --levels option when given
// (each an integer in [lo, hi]; InputError "--levels: 5.5 is not an integer in [3, 13]").
std::vector<int> levels_option(const Args& a, Profile p, const std::vector<int>& quick,
                               const std::vector<int>& paper, int lo, int hi);

// Peak resident memory of this process so far, in MiB (VmHWM).
double peak_rss_mib();

// The machine's memory in bytes (MemTotal of /proc/meminfo; 0 where unknown).
double machine_memory_bytes();

// Particles of a jittered grid of spacing dx on Ω_H, (⌊side/dx⌋ + 1)², as a double (at
// dx = 1e-300 it overflows every integer type).
double grid_particle_estimate(double dx);  // (cost_model.hpp: grid_particle_count, exact)

// Refuses, before anything is allocated, a grid spacing whose jittered grid on Ω_H would
// need more memory than the machine has: N ≈ (side/dx + 1)² particles times
// `bytes_per_particle` (what the caller's data structures hold per particle).  The
// InputError names `option`, dx, N and both memory sizes.  Also refuses dx ≥ 0.5 (no node
// inside Ω) so that no caller builds a grid it cannot use.
void require_grid_fits_memory(double dx, double bytes_per_particle, const std::string& option);

// Memory per particle of a Poisson or heat problem with influence radius h at spacing dx:
// matrix-free, peak RSS / N was 264 bytes at dx = 2^-8 (400 with margin); an assembled
// Laplacian adds kAssembledBytesPerNonzero per non-zero of the Ω × all matrix, about π(h/dx)²
// per unknown, |Ω|/|Ω_H| of the particles; `automatic` assembles only within max_bytes.
double pde_bytes_per_particle(double h, double dx, LaplacianStorage storage, double max_bytes);
// Before a PDE study runs: every level's grid and Laplacian, under each h rule, within the
// machine's memory (InputError naming the level, as --levels gave it).
void require_pde_levels_fit_memory(const std::vector<int>& levels, const std::vector<HRule>& h_rules,
                                   LaplacianStorage storage, double max_bytes);

}  // namespace gpm
