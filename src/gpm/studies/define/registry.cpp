#include "gpm/studies/define/registry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "gpm/error.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/io/args.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry_books.hpp"
#include "gpm/studies/define/thesis_tables.hpp"

namespace gpm {

namespace {

double dx_of(int k) { return std::ldexp(1.0, -k); }

// --- The studies ----------------------------------------------------------------------------

// An entry's identity: its catalog name (also its program's), item, make group, levels,
// columns and the coarse levels the paper profile re-checks.
RegisteredStudy identity(const std::string& name, const std::string& item, const std::string& group,
                         ProfileLevels levels, std::vector<std::string> columns, std::vector<int> recheck) {
  RegisteredStudy s;
  s.name = s.program = name;
  s.item = item, s.group = group, s.levels = std::move(levels), s.columns = std::move(columns);
  s.recheck_levels = std::move(recheck);
  return s;
}

// imoto §5: one fused pass per (level, m), nine weights.
RegisteredStudy imoto() {
  RegisteredStudy s = identity("imoto_fig5_table1", "imoto Figure 5, Table 1", "imoto", imoto_study().levels,
                               imoto_study().columns, {5, 6, 7});
  // A unit: one fused pass of the nine weights per (level, m), the particles shared by a
  // level's units.
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels)
      for (double m : imoto_study().orders) out.push_back({k, imoto_h(m, dx_of(k)), {fmt(k), fmt(m)}, "m=" + fmt(m)});
    return out;
  };
  imoto_books(s);
  return s;
}

// Thesis Tables 4.1–4.3: one fused pass per (h reading, volumes, level); Voronoi once per level.
RegisteredStudy thesis_truncation(const ThesisTableSpec& t) {
  std::vector<int> quick = t.quick_printed;
  for (int k : t.quick_scaled)
    if (std::find(quick.begin(), quick.end(), k) == quick.end()) quick.push_back(k);
  std::sort(quick.begin(), quick.end());
  RegisteredStudy s = identity(t.program, "thesis " + t.table, "truncation", {quick, t.paper_levels},
                               thesis_table_columns(), {5, 6, 7});
  // A unit: one fused pass per (level, h reading, volumes), keyed as the data file's rows.
  // Without --levels each reading runs at the profile's levels of its own (the quick profile
  // gives the printed and the scaled h different ones), and the paper profile trims the
  // uniform volumes above paper_uniform_max_level (rows beyond the document, no published
  // rate): those units are priced and marked, not run; with --levels every unit runs.
  s.units = [&t](const UnitScope& scope) {
    auto levels_of = [&](HReading r) -> const std::vector<int>& {
      if (scope.levels_given) return scope.levels;
      return scope.paper ? t.paper_levels : r == HReading::printed ? t.quick_printed : t.quick_scaled;
    };
    std::vector<int> all;
    for (HReading r : t.readings) all.insert(all.end(), levels_of(r).begin(), levels_of(r).end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    std::vector<StudyUnit> out;
    for (int k : all)
      for (HReading r : t.readings)
        for (Volumes v : {Volumes::voronoi, Volumes::uniform}) {
          const auto& lv = levels_of(r);
          if (std::find(lv.begin(), lv.end(), k) == lv.end()) continue;
          StudyUnit u{k, thesis_h(r, t.c, t.p, dx_of(k)), {h_reading_name(r), volumes_name(v), fmt(k)},
                      h_reading_name(r) + "/" + volumes_name(v)};
          if (scope.paper && !scope.levels_given && v == Volumes::uniform && k > t.paper_uniform_max_level)
            u.trimmed = "uniform volumes stop at 2^-" + fmt(t.paper_uniform_max_level) + " (beyond the document: no published rate)";
          out.push_back(std::move(u));
        }
    return out;
  };
  truncation_books(s, t);
  return s;
}

// Table 4.4: per (h rule, weight, level) the Laplacian's set-up and a CG solve, its
// iterations carried from 2^-5 as 1/h.
RegisteredStudy poisson() {
  RegisteredStudy s = identity("thesis_table4_4", "thesis Figure 4.8, Table 4.4", "poisson", poisson_table().levels,
                               poisson_table().columns, {5, 6});
  // A unit: one Laplacian and CG solve per (level, h rule, weight), the particles shared by
  // a level's units.
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels)
      for (HRule rule : pde_h_rules())
        for (auto& w : pde_weights())
          out.push_back({k, pde_h(rule, dx_of(k)), {h_rule_name(rule), w, fmt(k)}, h_rule_name(rule) + "/" + w});
    return out;
  };
  poisson_books(s);
  return s;
}

// Tables 4.5–4.7 under both h rules: K = ⌈T/Δt₀⌉ steps, one product per step (M·U^k, which
// also serves the CG's initial and true residuals) plus (θ > 0) the CG iterations; the
// Laplacian's set-up once per (level, weight), not in the per-row seconds.
RegisteredStudy heat(const HeatTable& hp) {
  const std::string name = heat_file(hp, HRule::h10);
  RegisteredStudy s = identity(name, "thesis Table " + hp.table, "heat", {hp.quick, hp.paper}, heat_columns(), {5});
  s.program = "thesis_heat", s.fixed_args = {"--table", hp.table};
  // A unit: one series (weight, θ) at a level under an h rule (StudyUnit::part: in a make run
  // each rule writes its own data file), keyed as the data file's rows.  The series of one
  // (level, h rule, weight) share a Laplacian, set up once for the first of them.  Both h
  // rules run at every level of the profile: each is a reading the set-up rule weighs.
  s.units = [&hp](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels)
      for (HRule rule : pde_h_rules())
        for (auto& w : pde_weights())
          for (double th : hp.thetas) {
            StudyUnit u{k, pde_h(rule, dx_of(k)), {w, fmt(th), fmt(k)}, w + "/theta=" + fmt(th)};
            u.part = h_rule_name(rule);
            out.push_back(std::move(u));
          }
    return out;
  };
  heat_books(s, hp);
  return s;
}

// thesis_poisson_diagnostic: per (level, particle set, h rule, weight) one Laplacian, its
// consistency on u and a CG solve (Table 4.4's problem; the reasons chapter reads it).  The
// store holds the rate levels on the particle sets the reasons use; its check recomputes
// 2^-7 for one weight.
RegisteredStudy poisson_diagnostic_study() {
  RegisteredStudy s = identity("thesis_poisson_diagnostic", "thesis Table 4.4: where the error sits", "diagnostic",
                               poisson_diagnostic().levels, poisson_diagnostic().columns, {7});
  s.own_seeds = true;  // its particle sets are its --variants
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels)
      for (const ParticleSet& var : poisson_diagnostic().variants)
        for (HRule rule : pde_h_rules())
          for (auto& w : pde_weights())
            out.push_back({k, pde_h(rule, dx_of(k)), {h_rule_name(rule), w, fmt(k), var.name},
                           h_rule_name(rule) + "/" + w + "/" + var.name});
    return out;
  };
  poisson_diagnostic_books(s);
  return s;
}

// core_voronoi: the plain grid once per level, the jittered grid per seed.
RegisteredStudy voronoi() {
  RegisteredStudy s = identity("core_voronoi", "covering radius (imoto §5, thesis Ch. 4)", "core", voronoi_study().levels,
                               voronoi_study().columns, {5});
  s.own_seeds = true;  // --seeds, a list of its own
  // A unit: a level, the plain grid and the jittered grid of every seed (--seeds; the plan
  // prices the default ones, as a make run uses them).
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels) out.push_back({k, 0, {fmt(k)}, "level"});
    return out;
  };
  voronoi_books(s);
  return s;
}

}  // namespace

std::string heat_file(const HeatTable& hp, HRule rule) {
  return heat_study_name(hp) + (rule == HRule::h15 ? "_h15" : "");
}

std::vector<std::string> PublishedRates::rate_key() const {
  std::vector<std::string> out;
  for (auto& k : key)
    if (k != split_by) out.push_back(k);
  return out;
}

const std::vector<std::string>& row_provenance_columns() {
  static const std::vector<std::string> c = {"code", "made_on", "checked", "seal"};
  return c;
}

std::vector<std::string> RegisteredStudy::header() const {
  std::vector<std::string> h = columns;
  for (auto& c : row_provenance_columns()) h.push_back(c);
  return h;
}

const StoreFile* RegisteredStudy::find_store_file_of(const std::string& reading) const {
  if (!published || !published->identified_slice) return nullptr;
  const std::string slice = published->identified_slice(PdeReading::named(reading));
  for (const StoreFile& f : store_files)
    if (std::find(f.readings.begin(), f.readings.end(), slice) != f.readings.end()) return &f;
  return nullptr;
}

const StoreFile& RegisteredStudy::store_file_of(const std::string& reading) const {
  if (!published || !published->identified_slice)
    throw InputError("study '" + name + "' keeps no set-up readings in the store");
  if (const StoreFile* f = find_store_file_of(reading)) return *f;
  throw InputError("study '" + name + "' stores no file of the reading '" + reading + "'");
}

std::vector<std::string> RegisteredStudy::command_args(const std::vector<std::string>& file_args) const {
  std::vector<std::string> a = fixed_args;
  a.insert(a.end(), file_args.begin(), file_args.end());
  return a;
}

void StudyRegistry::add(RegisteredStudy s) {
  if (!s.units || !s.price) throw InputError("study '" + s.name + "' lists no units or no price for them");
  for (auto& o : studies_) {
    if (o.name == s.name) throw InputError("study '" + s.name + "' is registered twice");
    for (auto& f : s.files)
      for (auto& g : o.files)
        if (f.name == g.name) throw InputError("data file '" + f.name + "' of study '" + s.name +
                                               "' is already written by '" + o.name + "'");
  }
  studies_.push_back(std::move(s));
}

const RegisteredStudy& StudyRegistry::study(const std::string& name) const {
  std::string valid;
  for (auto& s : studies_) {
    if (s.name == name) return s;
    valid += (valid.empty() ? "" : ", ") + s.name;
  }
  throw InputError("unknown study '" + name + "'; valid: " + valid);
}

const RegisteredStudy& StudyRegistry::study_of_file(const std::string& file) const {
  for (auto& s : studies_)
    for (auto& f : s.files)
      if (f.name == file) return s;
  throw InputError("no registered study writes the data file '" + file + "'");
}

TsvTable store_file_table(const StudyRegistry& registry) {
  TsvTable t;
  t.columns = {"study", "file", "program", "args", "census", "coarse", "slice"};
  for (auto& s : registry)
    for (auto& f : s.store_files) {
      TsvRow row = t.named_row();
      row["study"] = s.name, row["file"] = f.name, row["program"] = s.program;
      row["args"] = join(s.command_args(f.args), " "), row["census"] = join(f.census, " ");
      row["coarse"] = join(f.coarse, " "), row["slice"] = f.slice;
      t.add_row(row);
    }
  return t;
}

const StudyRegistry& study_registry() {
  static const StudyRegistry r = [] {
    StudyRegistry v;
    v.add(imoto());
    for (auto& t : thesis_table_specs()) v.add(thesis_truncation(t));
    v.add(poisson());
    for (auto& hp : heat_tables()) v.add(heat(hp));
    v.add(voronoi());
    v.add(poisson_diagnostic_study());
    return v;
  }();
  return r;
}

const RegisteredStudy& setup_fingerprint_study(const StudyRegistry& registry) {
  const RegisteredStudy* found = nullptr;
  for (auto& s : registry)
    if (s.published && !s.published->setup_fingerprint.first.empty()) {
      if (found) throw InputError("two studies carry the set-up fingerprint: " + found->name + ", " + s.name);
      found = &s;
    }
  if (!found) throw InputError("no registered study carries the set-up fingerprint");
  return *found;
}

const RegisteredStudy& registered_study_of_file(const std::string& file) {
  return study_registry().study_of_file(file);
}

}  // namespace gpm
