// The cost model's units and prices, as each study's registry entry uses them: the
// calibration's constants (measured by plan/study_plan.hpp's calibrate()), a priced unit of
// work, and the formulas that price one (UnitPricer).  The plan (plan/) sums them over a
// profile and compares them with what the runs recorded.
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/studies/define/cost_model.hpp"
#include "gpm/studies/define/profile.hpp"

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
  // The subspace's memory on top of the Laplacian's: its basis (a vector of the unknowns per
  // dimension, its capacity grown by half, old and new copies side by side while it grows) and
  // the ℓ∞ map S⁻¹QW formed beside it: up to 2.5 m vectors.
  double heat_krylov_mib(const PlanUnit& u) const;
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

// A fused-pass study's weight mix as the calibration times it and the pricer charges it:
// its requests and the functions it samples (imoto9, thesis4_1, …).
struct FusedMix {
  std::string name;
  std::vector<ErrorRequest> requests;
  std::vector<std::string> functions;
  int columns() const {  // result columns of the pass: Π 1, ∇ 2, Δ 1, per field
    int c = 0;
    for (auto& r : requests) c += r.op == Operator::grad ? 2 : 1;
    return c * static_cast<int>(functions.size());
  }
};
const std::vector<FusedMix>& fused_mixes();
const FusedMix& fused_mix(const std::string& name);  // InputError if unknown

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

}  // namespace gpm
