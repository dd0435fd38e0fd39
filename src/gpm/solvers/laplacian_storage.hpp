// How the particle Laplacian is stored and what that costs in memory: the storage choice, the
// predicted non-zeros and the bytes per non-zero.  Kept apart from laplacian_matrix.hpp so
// that the memory rule's users (the pricer, the profiles' memory check, every program through
// the registry) are not built from the Laplacian itself: their code fingerprint then does not
// move with it (cmake/fingerprint.cmake).
#pragma once
#include <cstddef>
#include <string>

#include "gpm/geometry/domain.hpp"

namespace gpm {

// assembled: the symmetric half (laplacian_matrix.hpp); full: the whole Ω × all matrix in CSR,
// 12 B per non-zero, the storage before the half (kept for bench_laplacian and the plan's
// "before").
enum class LaplacianStorage { automatic, assembled, matrix_free, full };
LaplacianStorage parse_laplacian_storage(const std::string& s);  // InputError if unknown
std::string laplacian_storage_name(LaplacianStorage s);

// Non-zeros of the Ω × all matrix before assembly: N_Ω·(1 + πh²·N/|Ω_H|), the expected
// count of particles within h (the disc may be cut by the edge of Ω_H: an over-estimate).
double estimated_laplacian_nnz(std::size_t n, std::size_t n_omega, double h,
                               const Domain& dom = Domain{});
// Memory of the assembled storage for nnz non-zeros of the Ω × all matrix: 12 B per stored
// entry, 0.6 stored entries per non-zero (half of the Ω × Ω off-diagonal entries, all of the
// Ω × B ones; measured 0.48–0.57 for both readings of h at 2^-4…2^-9, test [laplacian]).
// The one rule of the memory budget, for the solvers, the plan and `gpm`.
constexpr double kAssembledBytesPerNonzero = 12 * 0.6;

}  // namespace gpm
