// The plain baseline of the fused kernel, the benchmark's "before" (bench_kernel's `plain`
// variant): per target a loop over the 3×3 cells of size h, particles as array of structs
// {x, y, V, v}, `if (r < h)`, one weight, one field, Π + ∇ + Δ.  Same definitions and output
// as the kernel (a unit test checks it against a brute-force reference).  No study uses it;
// it has its own header so that kernel.hpp, which every study includes, declares only the
// kernel.
#pragma once
#include <cstdint>
#include <vector>

#include "gpm/weights/weights.hpp"

namespace gpm {

struct BaselineResult {
  std::vector<double> interp, grad_x, grad_y, lap;  // indexed like the targets
};
BaselineResult plain_baseline(const std::vector<double>& x, const std::vector<double>& y,
                              const std::vector<double>& V, const std::vector<double>& v,
                              const WeightFunction& w, double h,
                              const std::vector<int32_t>& targets, int threads = 0);

}  // namespace gpm
