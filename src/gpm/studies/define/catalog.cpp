#include "gpm/studies/define/catalog.hpp"

#include <algorithm>

#include "gpm/error.hpp"
#include "gpm/io/tsv.hpp"

namespace gpm {

namespace {
std::string span(const std::vector<int>& k) {
  if (k.empty()) return "none";
  const auto [lo, hi] = std::minmax_element(k.begin(), k.end());
  return *lo == *hi ? fmt(static_cast<long long>(*lo))
                    : fmt(static_cast<long long>(*lo)) + "-" + fmt(static_cast<long long>(*hi));
}
}  // namespace

std::string ProfileLevels::help() const {
  return "quick (levels " + span(quick) + ") or paper (levels " + span(paper) + ")";
}

const ImotoStudy& imoto_study() {
  // The document runs 2^-5 … 2^-12.  The quick profile stops at 2^-10 (about a minute here,
  // 8.5e9 pairs): level 11 would add 6.8e10 pairs for m = 5 alone.  Pairs grow per level by
  // 4× (m = 1), 2^(10/3) ≈ 10× (m = 3) and 2^3.6 ≈ 12× (m = 5).
  static const ImotoStudy s = {
      {{5, 6, 7, 8, 9, 10}, {5, 6, 7, 8, 9, 10, 11, 12}},
      {1, 3, 5},
      "sin2pi",
      {{"Pi1", Operator::interp, "interpolant"},
       {"Pi2", Operator::interp, "interpolant"},
       {"Pi3", Operator::interp, "interpolant"},
       {"Grad1", Operator::grad, "gradient"},
       {"Grad2", Operator::grad, "gradient"},
       {"Grad3", Operator::grad, "gradient"},
       {"Lap1", Operator::lap, "laplacian"},
       {"Lap2", Operator::lap, "laplacian"},
       {"Lap3", Operator::lap, "laplacian"}},
      {1, 2, 3},
      {"level", "m", "operator", "weight", "dx", "h", "N", "N_in_omega", "pairs", "rel_error",
       "smoothing_part", "time_s", "kernel_s"}};
  return s;
}

std::vector<ErrorRequest> ImotoStudy::requests() const {
  std::vector<ErrorRequest> r;
  for (auto& w : weights) r.push_back({w.weight, w.op});
  return r;
}

const std::vector<std::string>& pde_weights() {
  static const std::vector<std::string> w = {"quartic_polynomial", "piecewise_cubic_polynomial",
                                             "piecewise_quintic_polynomial"};
  return w;
}

const PoissonTable& poisson_table() {
  static const PoissonTable t = {
      {{5, 6, 7}, {5, 6, 7, 8, 9}},
      "8,9",
      {"h_rule", "weight", "level", "dx", "h", "N", "N_omega", "nnz", "storage", "rel_error",
       "cg_iterations", "rel_residual", "assembly_s", "solve_s", "seconds"}};
  return t;
}

const PoissonDiagnostic& poisson_diagnostic() {
  static const PoissonDiagnostic d = {
      {{5, 6, 7}, {7, 8, 9}},
      // Three realizations of the studies' jitter (1/4 dx) and the plain grid with the volumes of
      // (A.10); then seed 1 and the plain grid with V_i = dx^2.
      {{"seed1", 1, 0.25, PdeVolumes::lattice},
       {"seed2", 2, 0.25, PdeVolumes::lattice},
       {"seed3", 3, 0.25, PdeVolumes::lattice},
       {"plain", 1, 0.0, PdeVolumes::lattice},
       {"seed1_cell", 1, 0.25, PdeVolumes::cell},
       {"plain_cell", 1, 0.0, PdeVolumes::cell}},
      {"h_rule", "weight", "level", "variant", "dx", "h", "h_over_H", "N_omega", "rel_error", "max_x", "max_y",
       "max_distance_over_h", "rel_error_inner", "volume_mismatch", "eps_smoothing", "tau_predicted", "tau_fit",
       "tau_max", "cg_iterations", "seconds"}};
  return d;
}

std::vector<std::string> PoissonDiagnostic::variant_names() const {
  std::vector<std::string> names;
  for (const ParticleSet& v : variants) names.push_back(v.name);
  return names;
}

const ParticleSet& PoissonDiagnostic::variant(const std::string& name) const {
  for (const ParticleSet& v : variants)
    if (v.name == name) return v;
  std::string known;
  for (const ParticleSet& v : variants) known += (known.empty() ? "" : ", ") + v.name;
  throw InputError("--variants: unknown particle set '" + name + "' (" + known + ")");
}

const VoronoiStudy& voronoi_study() {
  // Level 12 (2.4e7 particles) needs about 4 GB and a few minutes per distribution.
  static const VoronoiStudy s = {
      {{5, 6, 7, 8, 9}, {5, 6, 7, 8, 9, 10, 11, 12}},
      {1, 2, 3},
      {"level", "dx", "seed", "distribution", "N", "N_in_omega", "area_sum", "area_rel_err", "r_c",
       "r_c_over_dx", "r_c_omega_over_dx", "r_c_grid_pred", "imoto_bound", "imoto_holds",
       "thesis_range_holds", "worst_x", "worst_y", "min_area_over_dx2", "max_area_over_dx2",
       "time_s", "peak_rss_mb"}};
  return s;
}

std::string VoronoiStudy::seeds_option() const {
  std::vector<std::string> s;
  for (int k : seeds) s.push_back(fmt(k));
  return join(s, ",");
}

}  // namespace gpm
