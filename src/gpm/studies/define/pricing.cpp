#include "gpm/studies/define/pricing.hpp"

#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/io/args.hpp"  // parse_number: the calibration file's cells
#include "gpm/solvers/heat_cost.hpp"
#include "gpm/solvers/laplacian_storage.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/thesis_tables.hpp"

namespace gpm {

namespace {
constexpr double kMiB = 1024.0 * 1024.0;
constexpr double kMaxAssembledBytes = 8e9;  // the programs' default --max-gb 8
double dx_of(int k) { return std::ldexp(1.0, -k); }
}  // namespace


// The thesis' truncation tables: levels, readings and h from thesis_table_specs() (the
// programs' own definitions); each pass is timed with its table's own mix (spec.mix()).

const std::vector<FusedMix>& fused_mixes() {
  static const std::vector<FusedMix> m = [] {
    std::vector<FusedMix> v;
    v.push_back({"imoto9", imoto_study().requests(), {imoto_study().function}});
    // The thesis tables' mixes are their programs' own requests (thesis_table_specs()).
    std::vector<std::string> cases;
    for (auto& c : thesis_cases()) cases.push_back(c.function);
    for (auto& t : thesis_table_specs()) v.push_back({t.mix(), t.requests, cases});
    return v;
  }();
  return m;
}

const FusedMix& fused_mix(const std::string& name) {
  for (auto& m : fused_mixes())
    if (m.name == name) return m;
  throw InputError("unknown weight mix '" + name + "'");
}

void Calibration::write(TsvTable& t) const {
  t.set("calibration_source", source);
  t.set("calibration_seconds", seconds);
  t.set("calibration_cpu_seconds", cpu_seconds);
  t.set("calibration_load_before", load_before);
  t.set("calibration_load_after", load_after);
  t.set("cal.base_mib", base_mib);
  for (auto& [k, v] : fused) {
    t.set("cal.fused." + k + ".per_target_s", v.per_target_s);
    t.set("cal.fused." + k + ".per_pair_s", v.per_pair_s);
  }
  t.set("cal.voronoi_s_per_particle", voronoi_s_per_particle);
  t.set("cal.setup_s_per_nnz", setup_s_per_nnz);
  t.set("cal.spmv_s_per_nnz", spmv_s_per_nnz);
  t.set("cal.spmv_full_s_per_nnz", spmv_full_s_per_nnz);
  t.set("cal.matrix_free.per_target_s", matrix_free.per_target_s);
  t.set("cal.matrix_free.per_pair_s", matrix_free.per_pair_s);
  for (auto& [k, v] : poisson_its) t.set("cal.poisson_its." + k, v);
  for (auto& [k, v] : heat_its) t.set("cal.heat_its." + k, v);
  for (auto& [k, v] : block_ratio) t.set("cal.block_ratio." + fmt(k), v);
}

Calibration Calibration::read(const TsvTable& t) {
  Calibration c;
  auto num = [&](const std::string& key) {
    auto v = t.get(key);
    if (!v) throw InputError("calibration: header key '" + key + "' missing");
    return parse_number(*v, key);
  };
  c.source = "read from an earlier calibration (" + t.get("calibration_source").value_or("?") + ")";
  c.seconds = num("calibration_seconds");
  c.cpu_seconds = num("calibration_cpu_seconds");
  c.load_before = num("calibration_load_before");
  c.load_after = num("calibration_load_after");
  c.base_mib = num("cal.base_mib");
  for (auto& m : fused_mixes())
    c.fused[m.name] = {num("cal.fused." + m.name + ".per_target_s"),
                       num("cal.fused." + m.name + ".per_pair_s")};
  c.voronoi_s_per_particle = num("cal.voronoi_s_per_particle");
  c.setup_s_per_nnz = num("cal.setup_s_per_nnz");
  c.spmv_s_per_nnz = num("cal.spmv_s_per_nnz");
  c.spmv_full_s_per_nnz = num("cal.spmv_full_s_per_nnz");
  c.matrix_free = {num("cal.matrix_free.per_target_s"), num("cal.matrix_free.per_pair_s")};
  for (auto& [k, v] : t.meta) {
    if (k.rfind("cal.poisson_its.", 0) == 0) c.poisson_its[k.substr(16)] = parse_number(v, k);
    if (k.rfind("cal.heat_its.", 0) == 0) c.heat_its[k.substr(13)] = parse_number(v, k);
    if (k.rfind("cal.block_ratio.", 0) == 0) c.block_ratio[std::stoi(k.substr(16))] = parse_number(v, k);
  }
  if (c.block_ratio.empty()) throw InputError("calibration: no block-product ratios in the header");
  if (c.poisson_its.empty() || c.heat_its.empty())
    throw InputError("calibration: no CG iteration counts in the header");
  return c;
}

// --- Pricing units: the formulas every registered study uses ------------------------------

PlanUnit UnitPricer::base(const std::string& study, const std::string& variant, int k, double h) const {
  const Domain dom;
  PlanUnit u;
  u.study = study, u.variant = variant, u.level = k, u.dx = dx_of(k), u.h = h;
  u.N = grid_particle_count(u.dx, dom);
  u.targets = omega_target_estimate(u.dx);
  u.pairs = h > 0 ? predicted_pairs(u.dx, h, dom) : 0;
  return u;
}

// Memory of a fused pass: particles (x, y, flag) 17 B, volumes 8 B, the kernel's sorted
// copies (x, y, V, index) 28 B and cell heads ~4 B, per field the values and exact
// values/derivatives (original and sorted order) ~48 B, per result column 8 B per target.
void UnitPricer::add_fused(const std::string& study, const std::string& variant, int k, double h,
                           const std::string& mix_name) {
  PlanUnit u = base(study, variant, k, h);
  const FusedMix& m = fused_mix(mix_name);
  u.method = "fused";
  u.time_s = u.time_before_s = c_.fused.at(mix_name).seconds(u.targets, u.pairs);
  const double nf = static_cast<double>(m.functions.size());
  u.mem_mib = c_.base_mib + (u.N * (57 + 48 * nf) + u.targets * 8.0 * m.columns()) / kMiB;
  u.basis = "a*N_omega + b*pairs, mix " + mix_name;
  out_.push_back(u);
}

void UnitPricer::add_voronoi(const std::string& study, const std::string& variant, int k) {
  PlanUnit u = base(study, variant, k, 0);
  u.method = "voronoi";
  u.time_s = u.time_before_s = c_.voronoi_s_per_particle * u.N;
  u.mem_mib = c_.base_mib + 190.0 * u.N / kMiB;
  u.basis = "s/particle * N";
  out_.push_back(u);
}

bool UnitPricer::priced(const std::string& study, const std::string& variant, int k) const {
  return std::any_of(out_.begin(), out_.end(),
                     [&](const PlanUnit& u) { return u.study == study && u.variant == variant && u.level == k; });
}

// The Laplacian: assembled (kAssembledBytesPerNonzero) unless over the programs' memory
// budget, then matrix-free.  `pairs` is the non-zero count (self included = diagonal).
bool UnitPricer::is_assembled(const PlanUnit& u) const {
  return kAssembledBytesPerNonzero *
             estimated_laplacian_nnz(static_cast<std::size_t>(u.N), static_cast<std::size_t>(u.targets), u.h,
                                     Domain{}) <=
         kMaxAssembledBytes;
}

double UnitPricer::product_s(const PlanUnit& u, bool assembled) const {
  return assembled ? u.pairs * c_.spmv_s_per_nnz : c_.matrix_free.seconds(u.targets, u.pairs);
}

// Before the symmetric half: the full matrix where 12 B per non-zero fit the budget.
double UnitPricer::product_before_s(const PlanUnit& u) const {
  const bool full = 12.0 * estimated_laplacian_nnz(static_cast<std::size_t>(u.N),
                                                   static_cast<std::size_t>(u.targets), u.h,
                                                   Domain{}) <= kMaxAssembledBytes;
  return full ? u.pairs * c_.spmv_full_s_per_nnz : c_.matrix_free.seconds(u.targets, u.pairs);
}

// Memory: particles and volumes 25 B, ~8 vectors over the particles (data, solution,
// right-hand side) 64 B, CG's 6 vectors over Ω 48 B, the assembled storage per non-zero
// and its diagonal, volumes and row pointers (or the kernel's sorted copies ~40 B per particle).
double UnitPricer::pde_mib(const PlanUnit& u, bool assembled) const {
  return c_.base_mib + (u.N * (25 + 64) + u.targets * 48 +
                        (assembled ? kAssembledBytesPerNonzero * u.pairs + 36 * u.targets : 40 * u.N)) / kMiB;
}

double UnitPricer::laplacian_setup_s(const PlanUnit& u, bool assembled) const {
  return assembled ? u.pairs * c_.setup_s_per_nnz : 2 * product_s(u, false);
}

double UnitPricer::heat_steps(const std::string& table, double h) const {
  const HeatTable& hp = heat_table(table);
  return std::ceil(kHeatT / (hp.c * std::pow(h, hp.p)) - 1e-9);
}

double UnitPricer::heat_cg_its(const std::string& table, HRule rule,
                               const std::string& weight, double theta, double h) const {
  if (theta == 0) return 0;
  const HeatTable& hp = heat_table(table);
  const double h5 = pde_h(rule, dx_of(5));
  const double r5 = hp.c * std::pow(h5, hp.p) / (h5 * h5);
  const double dt0 = hp.c * std::pow(h, hp.p);
  return c_.heat_its.at(table + "/" + h_rule_name(rule) + "/" + weight + "/" + fmt(theta)) * std::sqrt((dt0 / (h * h)) / r5);
}

double UnitPricer::heat_krylov_dim(const PlanUnit& u) const { return heat_krylov_products(u.dx, u.h); }

double UnitPricer::heat_krylov_mib(const PlanUnit& u) const {
  return 2.5 * heat_krylov_dim(u) * u.targets * 8.0 / kMiB;
}

double UnitPricer::heat_krylov_s(const PlanUnit& u, bool assembled) const {
  const double m = heat_krylov_dim(u);
  return m * product_s(u, assembled) +
         2 * u.targets * m * m * c_.spmv_s_per_nnz * 8 / kAssembledBytesPerNonzero;
}

bool UnitPricer::heat_krylov_chosen(const PlanUnit& u, const std::string& table, double theta) const {
  const HeatTable& hp = heat_table(table);
  const double dt0 = hp.c * std::pow(u.h, hp.p);
  return heat_stepped_products(u.dx, u.h, dt0, kHeatT, theta) > heat_krylov_products(u.dx, u.h);
}

}  // namespace gpm
