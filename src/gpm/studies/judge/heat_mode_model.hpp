// The heat tables' errors (thesis §4.3, Tables 4.5–4.7) predicted from one Fourier mode,
// without solving anything: the program thesis_heat_mode_model sets them beside a data file's
// measured errors, and the checked reasons (checked_reasons.hpp) judge the heat tables' rates
// with them.
//
// The exact solution is one Fourier mode, ũ = e^{−μt} s(x, y), s = sin πx sin πy,
// μ = κ|k|² = 2κπ².  Before any particle effect, the discrete Laplacian maps s to
//   Δ_h s ≈ (V_i/Δx²)(1 − ε(|k|h)) Δs,
// ε the smoothing error of the weight (smoothing.hpp) and δ = V_i/Δx² − 1 the volume mismatch
// of (A.10) (volumes.hpp; δ = 0 for a data file run with V_i = Δx²).  So the semi-discrete
// problem decays at μ' = μ(1 + δ)(1 − ε), and the θ-method multiplies the mode by
//   g(z) = (1 − (1 − θ)z)/(1 + θz),  z = μ'Δt,
// per step.  The error (4.2) of this one mode, relative to max_k ‖ũ‖ = ‖s‖, is
//   predicted = max_{k=0..K} |g^k − e^{−μ kΔt}|,
// with K and Δt as the row ran them.  Three causes sit in that one number: the time step
// (g against e^{−z}), the smoothing ε (h) and the volume mismatch δ, whose sign changes between
// levels (+0.13 % at 2^-8, −0.20 % at 2^-9).  Where measured/predicted stays near 1 the data
// are this mode's error — particles, boundary and the explicit scheme's instability (θ = 0
// with Δt beyond its limit, not modelled) aside — and the model says which cause sets a rate.
// `no_mismatch` is the same prediction with δ = 0.
//
// No stored number depends on this model (it reads the store, it writes none of it), so it
// lives in the judging room, outside the code fingerprint (cmake/fingerprint.cmake).
#pragma once
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/heat_tables.hpp"

namespace gpm {

// The one-mode error (4.2) of K θ-steps of size dt at the discrete decay rate mu_h.
double mode_error(double theta, double mu_h, double dt, long long K);

// One row of a heat data file that did not blow up, with its prediction.
struct ModeRow {
  std::string weight, theta;
  int level = 0;
  double h = 0, dt = 0, mismatch = 0, eps = 0, measured = NAN, predicted = 0, no_mismatch = 0;
  long long K = 0;
};

// The rows of a thesis_heat data file that did not blow up, with their predictions; δ from
// each row's N unless the file's `volumes` line says V_i = Δx² (then 0).  InputError (naming
// heat.source) for a file without a `volumes` line or a row missing a column.
std::vector<ModeRow> mode_model(const TsvTable& heat);

// The rates of one (weight, θ) at a table's two rate levels, each log(e_coarse/e_fine)/
// log(h_coarse/h_fine) (two_level_rate, as the thesis takes its rates): measured, predicted,
// predicted without the mismatch and, where a run with V_i = Δx² has both levels, its
// measured rate (against the data's h); the ratios measured/predicted and the mismatch δ at
// both levels.
struct ModeRate {
  std::string key;  // "weight theta"
  double reproduced = 0, predicted = 0, no_mismatch = 0;
  std::optional<double> cell;
  double ratio_coarse = 0, ratio_fine = 0, mismatch_coarse = 0, mismatch_fine = 0;
};

// Per (weight, θ) of `rows` with both of the table's rate levels, in the order of their keys;
// `cell_rows`: the same table run with V_i = Δx² (may be empty).
std::vector<ModeRate> mode_rates(const HeatTable& table, const std::vector<ModeRow>& rows,
                                 const std::vector<ModeRow>& cell_rows);

}  // namespace gpm
