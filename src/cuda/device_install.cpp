// The CUDA path as the core's device (gpm/kernel/device_pass.hpp): a DevicePass that runs
// CudaFusedPass, installed when the program starts.  cmake/cuda.cmake links this library
// whole into every study program of a -DGPM_CUDA=ON build, so the installation runs there
// and nowhere else; --device cuda then selects it (the default stays the CPU).
#include "cuda/kernel_cuda.hpp"
#include "gpm/kernel/device_pass.hpp"

namespace gpm::cuda {
namespace {

class CudaDevicePass final : public DevicePass {
 public:
  CudaDevicePass(const Particles& p, const std::vector<double>& V, double h,
                 const std::vector<KernelWeight>& weights)
      : pass_(p, V, h, as_pairs(weights)) {}
  DeviceColumns apply(const std::vector<int32_t>& targets,
                      const std::vector<std::vector<double>>& fields) const override {
    CudaPassResult r = pass_.apply(targets, fields);
    DeviceColumns c;
    c.nw = r.nw, c.nf = r.nf, c.nt = r.nt, c.kernel_ms = r.kernel_ms;
    c.data = std::move(r.data);  // the same layout: column ((w·nf + f)·4 + c)
    return c;
  }

 private:
  static std::vector<std::pair<WeightFunction, unsigned>> as_pairs(
      const std::vector<KernelWeight>& weights) {
    std::vector<std::pair<WeightFunction, unsigned>> v;
    for (auto& k : weights) v.emplace_back(k.weight, k.ops);
    return v;
  }
  CudaFusedPass pass_;
};

std::unique_ptr<DevicePass> make_cuda_pass(const Particles& p, const std::vector<double>& V,
                                           double h, const std::vector<KernelWeight>& weights) {
  return std::make_unique<CudaDevicePass>(p, V, h, weights);
}

// Installed at start-up (static initialization of this translation unit).
const bool installed = (install_device(&make_cuda_pass, "cuda"), true);

}  // namespace
}  // namespace gpm::cuda
