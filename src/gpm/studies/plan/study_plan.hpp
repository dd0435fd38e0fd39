// The plan of a profile: every unit of work of every modelled study (a fused pass, a
// Voronoi decomposition, a Poisson solve, a heat run), with its predicted pairs, time and
// peak memory, before anything runs; and, after a run, the time each study recorded for
// the same unit, so that prediction and measurement can be compared.
//
// Modelled studies: the entries of the study registry (registry.hpp), each pricing its own
// units with the formulas of UnitPricer (studies/define/pricing.hpp; each entry's price in
// registry_books.cpp; the data file's base name is the study's):
//   imoto_fig5_table1           one fused pass (nine weights, one field) per (level, m)
//   thesis_table4_1, 4_2, 4_3   one fused pass per (h reading, volumes, level), plus the
//                               Voronoi volumes once per level
//   thesis_table4_4             per (h rule, weight, level): Laplacian set-up + CG solve
//   thesis_table4_5/6/7[_h15]   per (weight, θ, level): K steps of operator products
//   core_voronoi                per (level, distribution, seed): one Voronoi decomposition
// Not modelled (their cost is small or not neighbour sums): imoto_regularity (covering
// radius and LPs), koba_sato_*, the figure programs.
//
// The levels, h rules, weight mixes and time-step rules come from the catalog's definitions
// (catalog.hpp, thesis_tables.hpp, heat_tables.hpp), which the study programs read too;
// h from the same library functions (imoto_h, thesis_h, pde_h).  A level or unit in a data
// file that the plan lacks is reported by the comparison (plan_vs_actual), so a drift
// between the two shows up in the report.
//
// Times come from a calibration run on the spot (calibrate(): a few seconds), on small
// levels of the studies' own code paths:
//   * fused pass: t = a·N_Ω + b·pairs per weight mix, fitted from two passes at Δx = 2^-7
//     (h = 3Δx and 30Δx), each the best of three;
//   * Voronoi: seconds per particle at Δx = 2^-8;
//   * Laplacian (piecewise cubic polynomial, printed h): seconds per non-zero of one
//     assembled product (Δx = 2^-6, best of five) and per pair of one matrix-free product
//     (Δx = 2^-7, best of three, over the predicted pairs); set-up seconds per non-zero
//     = a Poisson unit's time at 2^-6 less its (iterations + 2) products;
//   * CG iterations at Δx = 2^-5 per (h rule, weight) for Poisson, per (table, h rule,
//     weight, θ) per heat step (mean over the first ≤ 40 steps), carried to finer levels by
//     the condition number:
//     Poisson ∝ 1/h (κ(Δ_h) ∝ h⁻²), heat ∝ √(Δt₀/h²) (κ(I − θκΔtΔ_h) ≈ θκΔt·λ_max ∝ Δt/h²).
// The machine is shared: the calibration records its CPU time and the load average, so a
// calibration made under load (wall ≫ CPU/threads) can be recognised.
// Memory: a per-particle byte count of each phase's arrays (see plan_units), plus the
// calibration run's own resident size as the base; Voronoi 190 B per particle (core_voronoi's
// measured peak, voronoi.hpp).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/pricing.hpp"
#include "gpm/studies/define/profile.hpp"

namespace gpm {
// Runs the calibration (a few seconds on 2 cores); progress lines on stderr.
Calibration calibrate();


class StudyRegistry;
// Every unit of the profile of every study of `registry` (default: the package's), priced.
std::vector<PlanUnit> plan_units(Profile profile, const Calibration& c);
std::vector<PlanUnit> plan_units(Profile profile, const Calibration& c, const StudyRegistry& registry);
// Which units a plan prices besides a profile's: one study (empty: every study) at the levels
// given (empty: the profile's), every part of it at them as its program's --levels runs them
// (the levels past the documents a run is about to add: plan --study NAME --levels 10,11).
struct PlanScope {
  std::string study;
  std::vector<int> levels;
};
std::vector<PlanUnit> plan_units(Profile profile, const Calibration& c, const StudyRegistry& registry,
                                 const PlanScope& scope);


// The heat tables' whole reading matrix (2 h rules × 2 volumes × 2 time-step rules, every θ
// of each table, the profile's levels without trims) priced three ways, per table:
//   alone       every series streams the Laplacian by itself (before the block product);
//   per_reading one run per reading, its θ advancing together (thesis_heat with one reading);
//   batched     one run per table, every series of a (level, h rule, weight) in one block
//               stream (thesis_heat with lists; matrix-free units gain nothing: no block pass).
// Laplacian set-ups included (per reading, or per h rule when batched).
//   propagated  batched, every series by the default propagator (auto): a series whose
//               stepped products exceed the subspace's dimension joins the one Krylov
//               subspace of its (level, h rule, weight, volumes), the others step as batched.
struct HeatMatrixCost {
  std::string table;
  int series = 0;
  double alone_s = 0, per_reading_s = 0, batched_s = 0, propagated_s = 0;
};
std::vector<HeatMatrixCost> heat_matrix_costs(Profile profile, const Calibration& c);

// The names of the modelled studies, in plan order.
std::vector<std::string> planned_studies();

std::map<std::pair<std::string, int>, RecordedUnit> recorded_units(
    const std::string& study, const TsvTable& data,
    const std::map<std::pair<std::string, int>, double>& planned_pairs);
// Largest peak resident size the data file records (MiB); NaN where it records none.
double recorded_peak_mib(const std::string& study, const TsvTable& data);

}  // namespace gpm
