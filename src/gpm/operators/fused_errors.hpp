// The relative errors of many (weight, operator, test function) combinations from ONE
// fused kernel pass per level: what every convergence study computes per level.
//
// A study program reads like the documents' "numerical results" paragraph:
//
//   UnitCache cache(out, params, columns, /*key columns*/ 2);   // store.hpp
//   for (int k : levels) for (double m : orders) {
//     if (cache.has({fmt(k), fmt(m)})) continue;            // done in an earlier run
//     ... build particles, volumes, h ...
//     auto e = fused_errors(p, V, h, requests, functions);  // one pass, all weights
//     cache.add(rows...); cache.save();                     // after every level
//   }
#pragma once
#include <string>
#include <vector>

#include "gpm/geometry/domain.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/operators/truncation.hpp"

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

// The kernel weights of a pass: one per distinct registry name, with the union of the
// operators requested for it (so a weight asked for Π and ∇ is evaluated once).
std::vector<KernelWeight> kernel_weights(const std::vector<ErrorRequest>& requests);

// A contiguous share of the targets (the particles in Ω, in index order): part `part` of
// `parts` nearly equal ranges.  {0, 1} is all of them.
struct TargetShare {
  int part = 0, parts = 1;
};

// What the relative errors are made of, over a share of the targets: per request × function
// (in request order, functions inner) the largest |error|, the first target in target order
// where it occurs, and the largest |exact value|; the pairs within h of the share's targets.
struct ErrorMaxima {
  std::vector<double> error, exact;
  std::vector<int32_t> worst;
  double pairs = 0;           // an integer count: sums of shares are exact
  double kernel_seconds = 0;  // this share's kernel calls
  // Adds the share that follows this one in target order.  The result is exactly that of
  // one pass over both: maxima do not depend on the order, the worst particle stays the
  // first in target order (a later share wins only with a strictly larger error).
  void merge_following(const ErrorMaxima& later);
};

// One fused kernel pass over a share of the targets.  Throws NumericalError naming the
// particle on a non-finite result.
ErrorMaxima fused_error_maxima(const Particles& p, const std::vector<double>& V, double h,
                               const std::vector<ErrorRequest>& requests,
                               const std::vector<std::string>& functions, bool count_pairs = true,
                               TargetShare share = {});

// The relative errors from the maxima of all targets (InputError if an exact value vanishes
// on Ω).
FusedErrors relative_errors(const ErrorMaxima& m, const std::vector<ErrorRequest>& requests,
                            const std::vector<std::string>& functions);

// Relative ℓ∞ errors over the particles in Ω (see truncation.hpp for the definitions) of
// every request for every test function, from one fused kernel pass over all targets.
// Weights requested for several operators are evaluated once.
FusedErrors fused_errors(const Particles& p, const std::vector<double>& V, double h,
                         const std::vector<ErrorRequest>& requests,
                         const std::vector<std::string>& functions, bool count_pairs = true);

}  // namespace gpm
