#include "gpm/solvers/laplacian_storage.hpp"

#include <numbers>

#include "gpm/error.hpp"

namespace gpm {

LaplacianStorage parse_laplacian_storage(const std::string& s) {
  if (s == "auto" || s == "automatic") return LaplacianStorage::automatic;
  if (s == "assembled") return LaplacianStorage::assembled;
  if (s == "matrix_free" || s == "matrix-free") return LaplacianStorage::matrix_free;
  if (s == "full") return LaplacianStorage::full;
  throw InputError("unknown storage '" + s + "'; valid: auto, assembled, matrix_free, full");
}

std::string laplacian_storage_name(LaplacianStorage s) {
  switch (s) {
    case LaplacianStorage::automatic: return "auto";
    case LaplacianStorage::assembled: return "assembled";
    case LaplacianStorage::matrix_free: return "matrix_free";
    case LaplacianStorage::full: return "full";
  }
  return "?";
}

double estimated_laplacian_nnz(std::size_t n, std::size_t n_omega, double h, const Domain& dom) {
  return static_cast<double>(n_omega) *
         (1.0 + std::numbers::pi * h * h * static_cast<double>(n) / dom.area_H());
}

}  // namespace gpm
