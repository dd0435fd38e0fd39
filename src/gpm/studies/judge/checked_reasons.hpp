// Reasons for paper-scale rates that differ from the published ones, each CHECKED against the
// stored data (`gpm checked-reasons`): one row per published rate (table, slice, key), with the
// diagnostic's numbers (read from the store or computed from the library, none typed) and
// `check` = pass or fail.  gpm store-rates accepts a reason for a differing rate only when its
// row here passes (verdicts.hpp); otherwise the rate stays "differs, unexplained".  `restores`:
// the check includes a run that reproduces the published rate ("yes"), or the diagnostic
// explains our rate only ("no": the published one stays unexplained).
//
// Every rate is two_level_rate's (norms.hpp) and every "within" is |a − b| ≤ the rates'
// tolerance (kRateTolerance, rates.hpp), the one the verdicts judge with.
//
// Table 4.4 (thesis §4.2): the volume mismatch of (A.10).  thesis_poisson_diagnostic records,
// per reading of h, weight, level and particle set, the error and the operator's consistency
// on u predicted from the smoothing error and the volume mismatch alone,
//   tau_predicted = (V_i/dx^2)(1 - eps(kh)) - 1,
// and the same problem with V_i = dx^2 (variant seed1_cell).  The reason holds for a row when
//   (a) the rate predicted by |tau_predicted| at the rate levels is within the tolerance of the
//       reproduced rate (the mechanism accounts for the number), and
//   (b) the rate with V_i = dx^2 on the same particles is within the tolerance of the
//       published rate (removing the cause restores the documents' number).
//
// Tables 4.5–4.7 (thesis §4.3): the one-mode error (heat_mode_model.hpp) predicts each stored
// error from the exact solution's single Fourier mode: the θ-step's amplification at the
// discrete decay rate μ(1 + δ)(1 − ε), δ the volume mismatch of (A.10) (it changes sign
// between 2^-8 and 2^-9), ε the smoothing error.  The reason holds for a (weight, θ) when
//   (a) measured/predicted lies in [0.9, 1.1] at both rate levels and the predicted rate is
//       within the tolerance of the reproduced one (the model accounts for the number), and
//   (b) the rate measured with V_i = dx^2 (the table's _cellvol or _dtexact_cellvol file,
//       whichever ran the same Δt rule) is within the tolerance of the published rate
//       (removing the mismatch restores the documents' number).
//
// Table 4.3 (thesis §4.1.2), gradient of Case 2 (sin 2π(x+y)): the operator's own smoothing
// error ε_∇(|k|h), the relative error of the continuous gradient on the mode (smoothing.hpp).
// The reason holds for a weight when
//   (a) the stored error equals ε_∇ within 1 % at both rate levels (no particle part is left:
//       the reproduced rate is the operator's own), and
//   (b) the published rate lies more than the tolerance from the rate of ε_∇ over the same two
//       h — a rate the operator cannot give at these h, whatever the particles.
//
// Table 4.2, Case 1 (v = X^4 + Y^4): the interpolant's smoothing part is known in closed form
// (smoothing.hpp).  Where it is at most a fifth of the measured error at both rate levels, the
// measured two-level rate is the particle part's, not the smoothing order the document prints:
// the reason holds when, besides, the published rate is within the tolerance of the smoothing
// part's rate and the reproduced one is not.
//
// The Voronoi rows of Tables 4.2 and 4.3 come out per weight in byte order of its name, the
// heat rows in the order of their keys "weight theta", Table 4.4 in its published file's
// order.
#pragma once
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/heat_mode_model.hpp"
#include "gpm/studies/judge/snapshot.hpp"

namespace gpm {

// measured/predicted of the one-mode model that counts as accounting for a heat error.
inline constexpr double kModeRatioLow = 0.9, kModeRatioHigh = 1.1;
// |error/ε_∇ − 1| up to which a Table 4.3 error is the gradient's smoothing error alone.
inline constexpr double kGradientSmoothingShare = 0.01;
// The share smoothing part / error up to which a Table 4.2 error is the particle part's.
inline constexpr double kInterpolantSmoothingShare = 0.2;

// The checked reasons' columns: table, slice, key, reason, evidence, check, restores.  The
// reason's text up to its first ':' or ';' names the mechanism (reasons_by_mechanism).
const std::vector<std::string>& checked_reason_columns();

// --- Each mechanism, on tables in memory; each appends its rows to `out` (columns above) ---

// Table 4.4: per row (h_rule, weight) of `published` (its rate_levels), from `diagnostic`
// (thesis_poisson_diagnostic's rows: h_rule, weight, level, variant, rel_error, h,
// tau_predicted, volume_mismatch, eps_smoothing).  A row without both variants seed1 and
// seed1_cell at both levels fails ("diagnostic not yet at …").
void add_volume_mismatch_reasons(const TsvTable& published, const TsvTable& diagnostic, double tolerance,
                                 TsvTable& out);
// Table 4.3, slice READING_voronoi: the gradient rows of Case 2 of `data` (thesis_table4_3's
// rows) at `published`'s rate levels against ε_∇ at each row's h.
void add_gradient_smoothing_reasons(const TsvTable& published, const TsvTable& data, const std::string& reading,
                                    double tolerance, TsvTable& out);
// Table 4.2, slice READING_voronoi: the interpolant rows of Case 1 of `data` (thesis_table4_2's
// rows) at `published`'s rate levels against the closed-form smoothing part at each row's h.
void add_interpolant_smoothing_reasons(const TsvTable& published, const TsvTable& data,
                                       const std::string& reading, double tolerance, TsvTable& out);
// Tables 4.5-4.7: `table` ("thesis_table4_6") and `slice` (a heat reading's name, "h10") of the
// one-mode rates `rates` (mode_rates) against `published` (weight, theta, numerical); a
// published value that is not a plain decimal is skipped.
void add_heat_mode_reasons(const std::string& table, const std::string& slice, const TsvTable& published,
                           const std::vector<ModeRate>& rates, double tolerance, TsvTable& out);

// --- From the store -----------------------------------------------------------------------

// Every checked reason the store `store` gives (the published values in `published_dir`):
// Table 4.4 where the diagnostic has tau_predicted, Tables 4.3 and 4.2 in the printed then the
// scaled reading, then the heat tables 4.5-4.7 in the readings h10 and h10_exact (each with
// the V_i = dx^2 run of the same time-step rule, where stored).  Files not stored give no rows.
TsvTable checked_reasons(const StoreSnapshot& store, const PublishedTables& published, double tolerance);

// The reasons collapsed to one row per mechanism, in the order they first occur (columns
// mechanism, rows, checked, passed, restores): `rows` lists every "table slice" the mechanism
// was checked on, with how many rows passed (naming them where only some did); `restores`
// counts the rows whose check includes a run that restores the published rate.  InputError for
// a missing column of `checked`.
TsvTable reasons_by_mechanism(const TsvTable& checked);

}  // namespace gpm
