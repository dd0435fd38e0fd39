// The open set-up questions of the documents and what the committed result store says about
// each (`gpm decisions`; the report's decisions chapter): one row per question (columns
// question, evidence, decision), every number read from a store file or computed by the
// library, none typed.  A question whose runs are not yet in the store says so.
//
// The questions, in the order of the rows:
//   Table 4.7's time step (dt = T/K or dt = dt0): per pair of levels 7/8 and 8/9, the θ = 1
//     and θ = 1/2 two-level rates of both readings (finite_series, join_rates at those levels)
//     and the reading closer to the published rates (mean |reproduced − published|), the same
//     set-up with V_i = dx² where stored, and the steps K of dt = T/K per level;
//   Table 4.4 (per reading of h): error / |τ_predicted| per particle set (plain grid,
//     jittered grids), the volume mismatch of (A.10), and per weight the 2⁻⁸/2⁻⁹ rates of
//     seed1, plain, seed1_cell and plain_cell against the published one;
//   Imoto Table 1, Lap1/Lap2 at m = 5: per level 2⁻⁹…2⁻¹² the plain-grid error beside the
//     prediction |(1 + δ)(1 − ε) − 1| (ε the Laplacian's smoothing error, δ the volume mismatch
//     |Ω_H|/(N dx²) − 1 of the stored N), the errors of seeds 1-3, and the 2⁻¹¹/2⁻¹² rates;
//   Imoto Table 1, Lap1/Lap2 at m = 5: where the maximum sits (imoto_m5_where.tsv), and how
//     closely those runs reproduce the stored errors;
//   per table of the score (gpm store-rates --score) with two or more readings: how many
//     published rates each reading reproduces, and the one the board counts;
//   Ω_H, the square or the rounded H-neighbourhood, and jittered particles mirrored or
//     dropped: node counts and the expected particles that leave at 2⁻⁵, 2⁻⁷, 2⁻⁸, 2⁻⁹;
//   w^bell and the gradient error norm: decided by the documents' definitions (fixed text).
// Every rate is two_level_rate's (norms.hpp).  The Table 4.4 weights come in the order they
// first occur in the diagnostic file.
#pragma once
#include <optional>
#include <string>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/snapshot.hpp"

namespace gpm {

// The rows for the store `store`, published values from `published_dir`; `score` adds the
// readings' rows (none when absent).  InputError for a store file that cannot be read or
// lacks a column a question needs.
TsvTable decisions(const StoreSnapshot& store, const PublishedTables& published, const std::string& diagnostics,
                   const std::optional<TsvTable>& score);

}  // namespace gpm
