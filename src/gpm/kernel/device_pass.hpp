// Where the fused passes run: the CPU (gpm::FusedKernel, always) or a device that a build
// installed (the CUDA path, src/cuda, configured with -DGPM_CUDA=ON).  The core never
// includes device code: a device build installs a factory at start-up, and a study selects
// the device with --device cuda (StudyRunner), which calls use_device(true).  Then
//   * fused_error_maxima (every truncation pass: imoto §5, Tables 4.1–4.3) evaluates its
//     weights and fields through the device pass,
//   * a matrix-free DiscreteLaplacian (the Poisson and heat solvers' products) is a device
//     pass with one weight (Δ only) and one field, its conjugate gradients on the host.
// The device sums the same pairs in another order: results agree with the CPU's to ~1e-13
// relative (tests/unit/test_device_pass.cpp runs the device arithmetic on the CPU through
// this very hook).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gpm/geometry/domain.hpp"
#include "gpm/kernel/kernel.hpp"

namespace gpm {

// The operators of one evaluation: column ((w·nf + f)·4 + c), c = Π, ∂x ∇, ∂y ∇, Δ, with nt
// values each in the order of the targets given (columns of operators a weight does not ask
// for hold zeros).
struct DeviceColumns {
  int nw = 0, nf = 0;
  std::size_t nt = 0;
  std::vector<double> data;
  double kernel_ms = 0;  // device time of the evaluation
  const double* column(int w, int f, int c) const {
    return data.data() + static_cast<std::size_t>((w * nf + f) * 4 + c) * nt;
  }
};

// One set of particles, volumes, h and weights on a device (uploaded once, reused).
class DevicePass {
 public:
  virtual ~DevicePass() = default;
  virtual DeviceColumns apply(const std::vector<int32_t>& targets,
                              const std::vector<std::vector<double>>& fields) const = 0;
};

using DevicePassFactory = std::unique_ptr<DevicePass> (*)(const Particles& p,
                                                          const std::vector<double>& V, double h,
                                                          const std::vector<KernelWeight>& weights);

// Called by a device build (or a test) once: `name` says what it is ("cuda").
void install_device(DevicePassFactory factory, const std::string& name);
bool device_installed();
std::string device_name();  // "" if none

// Whether the passes of this process run on the device (InputError if none is installed).
void use_device(bool on);
bool using_device();

// A pass on the installed device (InputError if none is installed).
std::unique_ptr<DevicePass> make_device_pass(const Particles& p, const std::vector<double>& V,
                                             double h, const std::vector<KernelWeight>& weights);

}  // namespace gpm
