// The device hook (gpm/kernel/device_pass.hpp) end to end, on the CPU: a DevicePass that runs
// the CUDA path's own per-target arithmetic (src/cuda/kernel_cuda_body.hpp: what each GPU
// thread computes) is installed as "the device", and the studies' code paths — a fused
// truncation pass (fused_errors), a matrix-free Laplacian in a heat run — give the same
// results with it as with the CPU kernel, to rounding (the sums run in another order).
// What this cannot check is the CUDA plumbing itself (uploads, launches, the GPU's
// rounding): that needs a GPU (bench/run_paper_on_device.sh).
#include <catch2/catch.hpp>
#include <cmath>

#include "cuda/kernel_cuda_body.hpp"
#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/kernel/device_pass.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/thesis_tables.hpp"

using namespace gpm;

namespace {

// The device arithmetic compiled for the CPU, one "thread" per target, cells of h/4.
class EmulatedDevice final : public DevicePass {
 public:
  EmulatedDevice(const Particles& p, const std::vector<double>& V, double h,
                 const std::vector<KernelWeight>& weights)
      : cl_(p.x, p.y, h / 4), Vs_(cl_.gather(V)), g_(cuda::grid_view(cl_, Vs_.data(), h)) {
    for (auto& k : weights) we_.push_back(cuda::weight_entry(k.weight, k.ops));
  }
  DeviceColumns apply(const std::vector<int32_t>& targets,
                      const std::vector<std::vector<double>>& fields) const override {
    DeviceColumns c;
    c.nw = static_cast<int>(we_.size()), c.nf = static_cast<int>(fields.size());
    c.nt = targets.size();
    // The device's own layout of the fields (one buffer, a stride), so a wrong stride shows
    // here on the CPU too.
    const cuda::SortedFields sorted = cuda::sorted_fields(cl_, fields);
    std::vector<const double*> v(fields.size());
    cuda::field_pointers(sorted.data.data(), sorted.stride, c.nf, v.data());
    const std::size_t ncol = static_cast<std::size_t>(c.nw * c.nf * 4);
    c.data.assign(ncol * c.nt, 0.0);
    std::vector<double> o(ncol);
    for (std::size_t t = 0; t < c.nt; ++t) {
      cuda::fused_target_sums(g_, we_.data(), c.nw, v.data(), c.nf, cl_.slot()[targets[t]],
                              o.data());
      for (std::size_t k = 0; k < ncol; ++k) c.data[k * c.nt + t] = o[k];
    }
    return c;
  }

 private:
  CellList cl_;
  std::vector<double> Vs_;
  cuda::GridView g_;
  std::vector<cuda::WeightEntry> we_;
};

std::unique_ptr<DevicePass> make_emulated(const Particles& p, const std::vector<double>& V,
                                          double h, const std::vector<KernelWeight>& w) {
  return std::make_unique<EmulatedDevice>(p, V, h, w);
}

// Installs the emulated device for one test and removes it after.
struct WithEmulatedDevice {
  WithEmulatedDevice() { install_device(&make_emulated, "emulated"); }
  ~WithEmulatedDevice() { install_device(nullptr, ""); }
};

}  // namespace

TEST_CASE("device hook: without a device, --device cuda is refused", "[device]") {
  install_device(nullptr, "");
  CHECK_FALSE(device_installed());
  CHECK_THROWS_WITH(use_device(true), Catch::Contains("-DGPM_CUDA=ON"));
  CHECK_FALSE(using_device());
}

TEST_CASE("device hook: the studies' truncation passes on the emulated device", "[device]") {
  WithEmulatedDevice dev;
  const Particles p = jittered_grid(std::ldexp(1.0, -6), 1);
  std::vector<double> V(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    V[i] = std::ldexp(1.0, -12) * (0.9 + 0.2 * std::fabs(std::cos(3.0 * static_cast<double>(i))));
  std::vector<std::string> cases;
  for (auto& c : thesis_cases()) cases.push_back(c.function);
  struct Mix {
    std::vector<ErrorRequest> req;
    std::vector<std::string> fns;
  };
  std::vector<Mix> mixes = {{imoto_study().requests(), {imoto_study().function}}};
  for (auto& t : thesis_table_specs()) mixes.push_back({t.requests, cases});
  for (const Mix& m : mixes) {
    use_device(false);
    const FusedErrors cpu = fused_errors(p, V, 0.09, m.req, m.fns);
    use_device(true);
    const FusedErrors gpu = fused_errors(p, V, 0.09, m.req, m.fns);
    use_device(false);
    REQUIRE(cpu.errors.size() == gpu.errors.size());
    CHECK(cpu.pairs == gpu.pairs);
    for (std::size_t i = 0; i < cpu.errors.size(); ++i) {
      INFO(cpu.errors[i].weight << " " << operator_name(cpu.errors[i].op) << " "
                                << cpu.errors[i].function);
      // Errors are differences of nearly equal numbers: compare them on the scale of the
      // operator's values (relative error 1e-12 of the exact maximum).
      CHECK(std::fabs(cpu.errors[i].rel_error - gpu.errors[i].rel_error) < 1e-11);
    }
  }
}

TEST_CASE("device hook: a heat run with the matrix-free Laplacian on the emulated device", "[device]") {
  WithEmulatedDevice dev;
  const Particles p = jittered_grid(std::ldexp(1.0, -5), 1);
  const std::vector<double> V(p.size(), Domain{}.area_H() / static_cast<double>(p.size()));
  const double h = pde_h(HRule::h10, std::ldexp(1.0, -5));
  HeatSetting s;
  s.theta = 1;
  s.dt_nominal = 0.5 * h * h;
  use_device(false);
  const DiscreteLaplacian cpu(p, V, weight("quartic_polynomial"), h, LaplacianStorage::matrix_free);
  use_device(true);
  const DiscreteLaplacian gpu(p, V, weight("quartic_polynomial"), h, LaplacianStorage::matrix_free);
  use_device(false);
  Eigen::VectorXd x(static_cast<Eigen::Index>(cpu.n_unknowns())), yc, yg;
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = std::sin(0.01 * static_cast<double>(k));
  cpu.apply(x, yc);
  gpu.apply(x, yg);
  CHECK((yc - yg).lpNorm<Eigen::Infinity>() / yc.lpNorm<Eigen::Infinity>() < 1e-12);
  const HeatResult a = solve_heat(p, cpu, s), b = solve_heat(p, gpu, s);
  CHECK(a.K == b.K);
  CHECK(std::fabs(a.rel_error - b.rel_error) < 1e-10 * a.rel_error);
}
