// What every convergence study shares: the per-level cache of a data file and the
// relative errors of many (weight, operator, test function) combinations from ONE fused
// kernel pass per level.
//
// A study program reads like the documents' "numerical results" paragraph:
//
//   LevelCache cache(out, params, columns, /*key columns*/ 2);   // store.hpp
//   for (int k : levels) for (double m : orders) {
//     if (cache.has({fmt(k), fmt(m)})) continue;            // done in an earlier run
//     ... build particles, volumes, h ...
//     auto e = fused_errors(p, V, h, requests, functions);  // one pass, all weights
//     cache.add(rows...); cache.save();                     // after every level
//   }
#pragma once
#include <string>
#include <vector>

#include "gpm/domain.hpp"
#include "gpm/truncation.hpp"
#include "gpm/store.hpp"
#include "gpm/tsv.hpp"

namespace gpm {

// One requested operator of one weight.
struct ErrorRequest {
  std::string weight;  // registry name
  Operator op;
};

struct ErrorResult {
  std::string weight, function;
  Operator op;
  double rel_error = 0;
  int32_t worst = -1;  // the particle where |error| is largest (the first such, in target order)
};

struct FusedErrors {
  std::vector<ErrorResult> errors;  // requests × functions, in request order
  double pairs = 0;                 // pairs with r < h summed over the targets (self included)
  double kernel_seconds = 0;        // wall time of the fused pass alone
};

// Relative ℓ∞ errors over the particles in Ω (see truncation.hpp for the definitions) of
// every request for every test function, from one fused kernel pass.  Weights requested
// for several operators are evaluated once.  Throws NumericalError naming the particle on
// a non-finite result.
FusedErrors fused_errors(const Particles& p, const std::vector<double>& V, double h,
                         const std::vector<ErrorRequest>& requests,
                         const std::vector<std::string>& functions, bool count_pairs = true);

// |Ω_H|/N for every particle (imoto §5, thesis (A.10)).
std::vector<double> uniform_volumes(const Particles& p, const Domain& dom = Domain{});

// Δx² for every particle: the area of one cell of the grid G_Δx the particles come from.
// Not a choice of the documents: a diagnostic beside (A.10).  With H = 0.1 the side 1.2/Δx of
// Ω_H is not a whole number of cells (153.6 at Δx = 2^-7), so N·Δx² ≠ |Ω_H| and every (A.10)
// volume is off by volume_mismatch(); the discrete Laplacian is scaled by the same factor.
std::vector<double> cell_volumes(const Particles& p, double dx);
// |Ω_H|/(N·Δx²) − 1: +0.79% at Δx = 2^-7, +0.13% at 2^-8, −0.20% at 2^-9 (N = 153², 307², 615²).
double volume_mismatch(const Particles& p, double dx, const Domain& dom = Domain{});

// The volume choices of the PDE studies, by name: "lattice" = (A.10), "cell" = Δx².
std::vector<double> pde_volumes(const std::string& choice, const Particles& p, double dx,
                                const Domain& dom = Domain{});
// What a data file's header says of a choice (InputError naming an unknown one).
std::string pde_volumes_description(const std::string& choice);

}  // namespace gpm
