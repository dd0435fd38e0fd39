#include "gpm/kernel/device_pass.hpp"

#include "gpm/error.hpp"

namespace gpm {

namespace {
DevicePassFactory g_factory = nullptr;
std::string g_name;
bool g_use = false;
}  // namespace

void install_device(DevicePassFactory factory, const std::string& name) {
  g_factory = factory;
  g_name = factory ? name : "";
  if (!factory) g_use = false;
}

bool device_installed() { return g_factory != nullptr; }
std::string device_name() { return g_name; }

void use_device(bool on) {
  if (on && !g_factory)
    throw InputError("--device cuda: this build has no device path (configure a build with "
                     "-DGPM_CUDA=ON, see README)");
  g_use = on;
}

bool using_device() { return g_use; }

std::unique_ptr<DevicePass> make_device_pass(const Particles& p, const std::vector<double>& V,
                                             double h, const std::vector<KernelWeight>& weights) {
  if (!g_factory) throw InputError("no device path is installed in this build");
  return g_factory(p, V, h, weights);
}

}  // namespace gpm
