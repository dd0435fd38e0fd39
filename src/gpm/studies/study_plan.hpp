// The plan of a profile: every unit of work of every modelled study (a fused pass, a
// Voronoi decomposition, a Poisson solve, a heat run), with its predicted pairs, time and
// peak memory, before anything runs; and, after a run, the time each study recorded for
// the same unit, so that prediction and measurement can be compared.
//
// Modelled studies: the entries of the study registry (registry.hpp), each pricing its own
// units with the formulas of UnitPricer below (the data file's base name is the study's):
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
// (catalog.hpp, thesis_truncation.hpp, heat_tables.hpp), which the study programs read too;
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
#include "gpm/studies/cost_model.hpp"
#include "gpm/studies/profile.hpp"

namespace gpm {

struct Calibration {
  double base_mib = 0;                    // resident size of a study program before work
  std::map<std::string, PassCost> fused;  // per weight mix (imoto9, thesis4_1, …)
  double voronoi_s_per_particle = 0;
  double setup_s_per_nnz = 0;             // Laplacian assembly + solver set-up, per non-zero
  double spmv_s_per_nnz = 0;              // one assembled product (symmetric half), per non-zero
  double spmv_full_s_per_nnz = 0;         // the same with the full matrix (the plan's "before")
  PassCost matrix_free;                   // one matrix-free product, per target and per pair
  std::map<std::string, double> poisson_its;  // "h10/<weight>" → CG iterations at Δx = 2^-5
  std::map<std::string, double> heat_its;     // "4.5/h10/<weight>/<θ>" → mean per step, 2^-5
  // The block product's time per vector over the single product's, at s = 3, 6, 12 columns
  // (the assembled half at Δx = 2^-7, as spmv_s_per_nnz); 1 at s = 1.
  std::map<int, double> block_ratio;
  double seconds = 0;                     // wall time of the calibration
  double cpu_seconds = 0;                 // its process CPU time (all threads)
  double load_before = -1, load_after = -1;  // 1-minute load average (/proc/loadavg)
  std::string source = "calibrated on the spot";

  // As `# key = value` header lines of a TSV table, and back (InputError if incomplete).
  void write(TsvTable& t) const;
  static Calibration read(const TsvTable& t);
};

// Runs the calibration (a few seconds on 2 cores); progress lines on stderr.
Calibration calibrate();

struct PlanUnit {
  std::string study, variant;
  int level = 0;
  double dx = 0, h = 0, N = 0, targets = 0;
  double pairs = 0;     // neighbour pairs of one pass / non-zeros of the Laplacian
  double products = 0;  // operator applications (Poisson, heat), else 0
  std::string method;   // fused, voronoi, assembled, matrix_free
  double time_s = 0, mem_mib = 0;
  double time_before_s = 0;  // the same unit with the full-matrix product (before the half)
  bool recorded = true;  // the study's data file records this unit's time (else plan only)
  std::string basis;     // how the time was predicted
  std::string trimmed;   // why the profile skips this unit (a trim of the catalog); empty: it runs
};

class StudyRegistry;
// Every unit of the profile of every study of `registry` (default: the package's), priced.
std::vector<PlanUnit> plan_units(Profile profile, const Calibration& c);
std::vector<PlanUnit> plan_units(Profile profile, const Calibration& c, const StudyRegistry& registry);

// The cost formulas every study's plan prices its units with (one place; registry.cpp's
// entries call them): a unit's particles, targets and pairs at a level and h; a fused pass
// of a weight mix; a Voronoi decomposition; the Laplacian's storage, product and memory.
class UnitPricer {
 public:
  UnitPricer(Profile profile, const Calibration& c) : profile_(profile), c_(c) {}
  bool paper() const { return profile_ == Profile::paper; }
  const Calibration& cal() const { return c_; }
  std::vector<PlanUnit>& units() { return out_; }
  // A unit of `study` (its data file's name) with N, targets and pairs at level k and h.
  PlanUnit base(const std::string& study, const std::string& variant, int k, double h) const;
  // Appends one fused pass of the weight mix `mix_name` (fused_mixes()).
  void add_fused(const std::string& study, const std::string& variant, int k, double h,
                 const std::string& mix_name);
  // Appends one Voronoi decomposition of the level's particles.
  void add_voronoi(const std::string& study, const std::string& variant, int k);
  // Whether a unit of `study` and `variant` at level k is priced already (a set-up its
  // level's units share, priced with the first of them).
  bool priced(const std::string& study, const std::string& variant, int k) const;
  // The Laplacian of a unit (`pairs` = its non-zeros): assembled unless over the programs'
  // memory budget; one product (assembled or matrix-free); one product with the full matrix
  // where it fit (the storage before the symmetric half); the unit's peak memory.
  bool is_assembled(const PlanUnit& u) const;
  double product_s(const PlanUnit& u, bool assembled) const;
  double product_before_s(const PlanUnit& u) const;
  double pde_mib(const PlanUnit& u, bool assembled) const;
  // The Laplacian's set-up: assembly per non-zero, or (matrix-free) two products' worth.
  double laplacian_setup_s(const PlanUnit& u, bool assembled) const;
  // A heat series of Table `table` (heat_tables.hpp), h rule, weight and θ at h: its steps
  // K = ⌈T/Δt₀⌉ and its CG iterations per step, carried from the calibration's 2^-5 as
  // √(Δt₀/h²) (0 for θ = 0).
  double heat_steps(const std::string& table, double h) const;
  double heat_cg_its(const std::string& table, HRule rule, const std::string& weight,
                     double theta, double h) const;
  // The heat propagator's Krylov subspace (heat_krylov.hpp) for the unit's level and h: its
  // dimension m (heat_krylov_products), and its seconds: m products plus the full
  // re-orthogonalization, 2·N_Ω·m² basis entries streamed at the assembled product's bytes
  // per second (8 bytes each against kAssembledBytesPerNonzero per non-zero).
  double heat_krylov_dim(const PlanUnit& u) const;
  double heat_krylov_s(const PlanUnit& u, bool assembled) const;
  // Whether thesis_heat's default propagator (auto) sends a series of Table `table` and θ at
  // the unit's h to the subspace: run_heat's own rule (heat_stepped_products against
  // heat_krylov_products), so that the plan prices the choice the program makes; the
  // calibrated CG iterations only price the series that stay stepped.
  bool heat_krylov_chosen(const PlanUnit& u, const std::string& table, double theta) const;

 private:
  Profile profile_;
  const Calibration& c_;
  std::vector<PlanUnit> out_;
};

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

// What a study's data file records for one unit, keyed like PlanUnit (variant, level):
// its seconds and its pair interactions (the plan's pairs × max(1, products)): counted
// pairs of a fused pass; non-zeros × (CG iterations + 2) of a Poisson solve; for a heat run,
// which does not record its non-zeros, the steps done × products per step from its mean CG
// iterations, times the plan's non-zeros (`planned_pairs`); NaN for a Voronoi unit.
struct RecordedUnit {
  double seconds = 0, pair_interactions = 0;
};
using PlannedPairs = std::map<std::pair<std::string, int>, double>;
using RecordedUnits = std::map<std::pair<std::string, int>, RecordedUnit>;
std::map<std::pair<std::string, int>, RecordedUnit> recorded_units(
    const std::string& study, const TsvTable& data,
    const std::map<std::pair<std::string, int>, double>& planned_pairs);
// Largest peak resident size the data file records (MiB); NaN where it records none.
double recorded_peak_mib(const std::string& study, const TsvTable& data);

}  // namespace gpm
