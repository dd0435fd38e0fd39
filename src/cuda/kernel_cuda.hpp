// The optional CUDA path (issue 7, item 5): the truncation-error kernel for one weight and
// one field, and the matrix-free Laplacian of the Poisson/heat solvers, on an NVIDIA GPU.
// Built only with -DGPM_CUDA=ON (cmake/cuda.cmake); nothing else in the project needs it.
//
// Same definitions as gpm::FusedKernel (gpm/kernel/kernel.hpp) and gpm::DiscreteLaplacian
// (gpm/solvers/laplacian_matrix.hpp); the per-target arithmetic is kernel_cuda_body.hpp, which the
// unit tests also run on the CPU.  Layout: the particles sorted by a uniform grid of cells
// of size h/cells_per_h on the host (gpm::CellList), uploaded once with the cell offsets;
// one GPU thread per target, targets processed in cell order (neighbouring threads read
// neighbouring particles), results returned to the host in the caller's order.
//
// One object = one set of device buffers on device 0: calls on the same object must not
// overlap (apply() is const for the caller but reuses those buffers); the calls block until
// the results are on the host.
//
// Errors: no usable device → InputError("no CUDA device: ..."); a failed allocation, copy
// or launch → NumericalError naming the CUDA call, the error and (for memory) the bytes
// asked for and free.  This header needs no CUDA headers: plain C++ callers include it.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gpm/geometry/domain.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm::cuda {

// What cudaGetDeviceCount and the first device report; never throws.  count = 0 with
// `error` set when there is no device or no driver.
struct DeviceInfo {
  int count = 0;
  std::string error;  // the CUDA error text when count = 0
  std::string name;   // device 0
  int cc_major = 0, cc_minor = 0;
  double memory_gib = 0;
  int runtime_version = 0, driver_version = 0;
};
DeviceInfo device_info();

// The device's fp64 peak as measured: FLOP/s of a kernel of independent DFMA chains (an FMA
// counted as 2), all multiprocessors busy.  InputError without a device.
double fp64_peak_flops();

// Results of one apply: indexed like the targets; columns of operators not requested are
// empty.  kernel_ms: device time of the kernel alone (cudaEvent), transfers excluded.
struct CudaResult {
  std::vector<double> interp, grad_x, grad_y, lap;
  double kernel_ms = 0;
};

class CudaKernel {
 public:
  // ops: bits of gpm::KernelOp (1 Π, 2 ∇, 4 Δ).  InputError for h ≤ 0, sizes that differ,
  // cells_per_h < 1, a weight unbounded at 0 asked for Π, or no CUDA device.
  CudaKernel(const Particles& p, const std::vector<double>& V, const WeightFunction& w,
             double h, unsigned ops = 7u, int cells_per_h = 1);
  ~CudaKernel();
  CudaKernel(CudaKernel&&) noexcept;
  CudaKernel& operator=(CudaKernel&&) noexcept;

  std::size_t n_particles() const;
  double h() const;
  unsigned ops() const;
  int cells_per_h() const;

  // The requested operators of field v (one value per particle, original order) at the
  // targets (particle indices).  InputError for a bad target or field size.
  CudaResult apply(const std::vector<int32_t>& targets, const std::vector<double>& v) const;

 private:
  friend class CudaLaplacian;
  friend class CudaFusedPass;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// y = M_ΩΩ x (gpm/solvers/laplacian_matrix.hpp): Δ_h of the field equal to x in Ω and 0 outside,
// at the particles of Ω (unknowns numbered in increasing particle index, as in
// DiscreteLaplacian).  The field lives on the device; each apply moves x and y only.
class CudaLaplacian {
 public:
  CudaLaplacian(const Particles& p, const std::vector<double>& V, const WeightFunction& w,
                double h, int cells_per_h = 1);
  ~CudaLaplacian();
  CudaLaplacian(CudaLaplacian&&) noexcept;
  CudaLaplacian& operator=(CudaLaplacian&&) noexcept;

  std::size_t n_unknowns() const;
  const std::vector<int32_t>& omega() const;  // unknown → particle
  // InputError if x.size() differs from n_unknowns(); y is resized.
  void apply(const std::vector<double>& x, std::vector<double>& y) const;
  double last_kernel_ms() const;  // device time of the last apply's kernel

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A study's whole fused truncation pass on the device: several weights (each with its own
// operators, bits 1 Π, 2 ∇, 4 Δ) and several fields in one pass over the pairs, the arithmetic
// of fused_target_sums (kernel_cuda_body.hpp; tests/unit/test_cuda_body.cpp checks it on the
// CPU against gpm::FusedKernel for imoto's and the thesis tables' mixes).  At most
// kMaxWeights = 9 weights and kMaxFieldsDevice = 4 fields (the studies use 9 and 3).
struct CudaPassResult {
  int nw = 0, nf = 0;
  std::size_t nt = 0;           // targets, in the caller's order
  std::vector<double> data;     // column ((w·nf + f)·4 + c), c = Π, ∂x ∇, ∂y ∇, Δ: nt values each
  double kernel_ms = 0;         // device time of the kernel alone
  const double* column(int w, int f, int c) const {
    return data.data() + (static_cast<std::size_t>((w * nf + f) * 4 + c)) * nt;
  }
};

class CudaFusedPass {
 public:
  // InputError for h ≤ 0, sizes that differ, no weight or more than kMaxWeights, a weight
  // unbounded at 0 asked for Π, or no CUDA device.
  CudaFusedPass(const Particles& p, const std::vector<double>& V, double h,
                const std::vector<std::pair<WeightFunction, unsigned>>& weights,
                int cells_per_h = 4);
  ~CudaFusedPass();
  CudaFusedPass(CudaFusedPass&&) noexcept;
  CudaFusedPass& operator=(CudaFusedPass&&) noexcept;

  // Every weight's operators of every field (one value per particle, original order) at the
  // targets (particle indices).  InputError for a bad target, field size or field count.
  CudaPassResult apply(const std::vector<int32_t>& targets,
                       const std::vector<std::vector<double>>& fields) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gpm::cuda
