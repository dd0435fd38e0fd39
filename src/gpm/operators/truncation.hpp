// One truncation-error measurement: build the distribution, the volumes and the
// neighbour structure, evaluate an operator at every particle in Ω with the fused
// kernel, and return the relative ℓ∞ error (imoto §5, thesis §4.1):
//   interp: max|v − Π_h v| / max|v|,   grad: max|∇v − ∇_h v| / max|∇v|,
//   lap:    max|Δv − Δ_h v| / max|Δv|,
// maxima over the particles in Ω; |·| of a gradient is the Euclidean length of the vector
// (imoto §1 defines |x| as the Euclidean norm on R^d; the thesis' [ℓ∞(Ω)]² of §4.1.2 is the
// maximum over particles of that length).
#pragma once
#include <cstdint>
#include <string>

#include "gpm/geometry/influence_radius.hpp"

namespace gpm {

struct Particles;

enum class Operator { interp, grad, lap };
enum class Volumes { uniform, voronoi };

Operator parse_operator(const std::string& s);  // InputError listing valid names
Volumes parse_volumes(const std::string& s);
std::string operator_name(Operator op);
std::string volumes_name(Volumes v);


struct TruncationSetting {
  Operator op = Operator::interp;
  std::string weight = "quadratic_spike";
  Volumes volumes = Volumes::uniform;
  std::string function = "sin2pi";
  double dx = 0, h = 0;
  uint64_t seed = 1;
  double jitter = 0.25;  // |η| bound in units of Δx (jittered_grid's amplitude); 0 = plain grid
};

struct TruncationResult {
  std::size_t n = 0, n_in_omega = 0;
  double pairs = 0;        // neighbour pairs with r < h summed over targets
  double rel_error = 0;
  double worst_x = 0, worst_y = 0;  // the particle of Ω where the error is largest
  double seconds = 0;      // wall time of the whole measurement
  bool h_exceeds_H = false;
  // Below the largest spacing, some targets see no particle but themselves: their operator
  // values are no approximation at all, and rel_error says nothing about the method.
  double largest_spacing = 0;    // max over targets in Ω of the distance to the nearest other particle
  std::size_t isolated_targets = 0;  // targets in Ω with no other particle within h
};

TruncationResult truncation_error(const TruncationSetting& s);

// Largest h a measurement accepts: the side of Ω_H.  Beyond it every particle is a neighbour
// of every other (O(N²) pairs) and the kernel says nothing about a local operator.
double max_influence_radius();

// Peak memory of truncation_error per particle of the grid, in bytes: particles, volumes,
// cell list, sampled fields and kernel workspace (Voronoi volumes add the triangulation).
// Measured at Δx = 2^-10 (peak RSS / N) and rounded up; see truncation.cpp.
double truncation_bytes_per_particle(Volumes v);

// For the jittered grid p (amplitude `jitter` in units of dx): the largest distance from a
// particle in Ω to its nearest other particle, and how many particles in Ω have no other
// particle closer than h.
struct TargetSpacing {
  double largest = 0;
  std::size_t isolated = 0;
};
TargetSpacing target_spacing(const Particles& p, double dx, double jitter, double h);

}  // namespace gpm
