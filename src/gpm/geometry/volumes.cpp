#include "gpm/geometry/volumes.hpp"

#include "gpm/error.hpp"

namespace gpm {

std::vector<double> uniform_volumes(const Particles& p, const Domain& dom) {
  return std::vector<double>(p.size(), dom.area_H() / static_cast<double>(p.size()));
}

std::vector<double> cell_volumes(const Particles& p, double dx) {
  return std::vector<double>(p.size(), dx * dx);
}

double volume_mismatch(const Particles& p, double dx, const Domain& dom) {
  return volume_mismatch(static_cast<double>(p.size()), dx, dom);
}

double volume_mismatch(double n_particles, double dx, const Domain& dom) {
  return dom.area_H() / (n_particles * dx * dx) - 1;
}

std::string pde_volumes_name(PdeVolumes v) { return v == PdeVolumes::lattice ? "lattice" : "cell"; }

PdeVolumes parse_pde_volumes(const std::string& s) {
  for (PdeVolumes v : {PdeVolumes::lattice, PdeVolumes::cell})
    if (pde_volumes_name(v) == s) return v;
  throw InputError("--volumes: '" + s + "' is not lattice (|Omega_H|/N, thesis (A.10)) or cell (dx^2)");
}

std::string pde_volumes_description(PdeVolumes choice) {
  if (choice == PdeVolumes::lattice) return "uniform |Omega_H|/N";  // the text older files carry
  return "cell dx^2 (diagnostic; sum over Omega_H is N dx^2, not |Omega_H|)";
}

std::vector<double> pde_volumes(PdeVolumes choice, const Particles& p, double dx, const Domain& dom) {
  return choice == PdeVolumes::cell ? cell_volumes(p, dx) : uniform_volumes(p, dom);
}

}  // namespace gpm
