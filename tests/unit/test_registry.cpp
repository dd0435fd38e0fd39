// The study registry (src/gpm/studies/define/registry.hpp): every study the catalog runs is priced
// by one registry entry, the plan's studies are the entries' data files, and a data file is
// read back by the entry that writes it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/plan/study_plan.hpp"
#include "gpm/studies/define/thesis_tables.hpp"

using namespace gpm;

namespace {
// A calibration with every key the plan reads (made-up rates: the test checks coverage and
// bookkeeping, not speed).
Calibration made_up_calibration() {
  Calibration c;
  c.base_mib = 10, c.voronoi_s_per_particle = 1e-6, c.setup_s_per_nnz = 1e-8;
  c.spmv_s_per_nnz = 1e-9, c.spmv_full_s_per_nnz = 2e-9;
  c.matrix_free = {1e-7, 1e-8};
  c.fused["imoto9"] = {1e-7, 1e-8};
  for (auto& t : thesis_table_specs()) c.fused[t.mix()] = {1e-7, 1e-8};
  for (const char* rule : {"h10", "h15"})
    for (auto& w : pde_weights()) {
      c.poisson_its[std::string(rule) + "/" + w] = 50;
      for (auto& hp : heat_tables())
        for (double th : hp.thetas)
          if (th > 0) c.heat_its[hp.table + "/" + rule + "/" + w + "/" + fmt(th)] = 3;
    }
  c.block_ratio = {{3, 0.6}, {6, 0.4}, {12, 0.25}};
  return c;
}
}  // namespace

TEST_CASE("registry: every catalog study is priced, every registered file has units", "[unit][registry]") {
  std::set<std::string> files;
  for (auto& s : study_registry())
    for (auto& f : s.files) files.insert(f.name);
  for (auto& e : study_registry()) {
    INFO("study " << e.name);
    CHECK(files.count(e.name) == 1);  // a study's first file carries its name
  }
  const auto planned = planned_studies();
  CHECK(std::set<std::string>(planned.begin(), planned.end()) == files);
  CHECK(planned.size() == files.size());  // each file once
  const Calibration c = made_up_calibration();
  for (Profile p : {Profile::quick, Profile::paper}) {
    std::set<std::string> priced;
    for (auto& u : plan_units(p, c)) {
      priced.insert(u.study);
      CHECK(u.time_s >= 0);
    }
    CHECK(priced == files);
  }
  CHECK_THROWS_AS(registered_study_of_file("thesis_table4_9"), InputError);
}

TEST_CASE("registry: a heat data file read back per unit", "[unit][registry]") {
  TsvTable d;
  d.columns = {"weight", "theta", "level", "propagator", "subspace", "seconds", "steps_done", "cg_mean_iterations"};
  d.add_row({"quartic_polynomial", "1", "6", "stepped", "0", "2.5", "10", "3"});
  d.add_row({"quartic_polynomial", "0", "6", "stepped", "0", "0.5", "10", "0"});
  d.add_row({"quartic_polynomial", "0.5", "6", "krylov", "90", "0.2", "10", "0"});
  const PlannedPairs planned = {{{"quartic_polynomial/theta=1", 6}, 1000.0},
                                {{"quartic_polynomial/theta=0", 6}, 1000.0},
                                {{"quartic_polynomial/theta=0.5", 6}, 1000.0}};
  const auto r = recorded_units("thesis_table4_6_h15", d, planned);
  REQUIRE(r.size() == 3);
  // θ = 1: (CG its + 1) products per step; θ = 0: one; propagated: its share of the subspace's
  // m products (the table's three θ share one subspace).
  CHECK(r.at({"quartic_polynomial/theta=1", 6}).pair_interactions == Approx(1000.0 * 10 * 4));
  CHECK(r.at({"quartic_polynomial/theta=0", 6}).pair_interactions == Approx(1000.0 * 10 * 1));
  CHECK(r.at({"quartic_polynomial/theta=0.5", 6}).pair_interactions == Approx(1000.0 * 90 / 3));
  CHECK(r.at({"quartic_polynomial/theta=1", 6}).seconds == 2.5);
}

// The per-reading figures find a reading's store file through the registry: each heat
// reading stored has one file, named by the reading's suffix (thesis_heat writes the same
// names), Table 4.4 keeps both h rules of one volume choice per file and has no time step,
// and an unknown reading or a study without readings is refused.
TEST_CASE("registry: a set-up reading's store file", "[unit][registry]") {
  const StudyRegistry& r = study_registry();
  int heat_files = 0;
  for (const HeatTable& hp : heat_tables()) {
    const RegisteredStudy& s = r.study("thesis_table" + std::string(1, hp.table[0]) + "_" + hp.table.substr(2));
    for (const StoreFile& f : s.store_files) {
      if (f.readings.empty()) {  // another jitter realization of a reading: named after it
        CHECK(f.name.find("_seed") != std::string::npos);
        CHECK(f.slice.find("_seed") != std::string::npos);
        continue;
      }
      REQUIRE(f.readings.size() == 1);
      const PdeReading reading = PdeReading::named(f.readings.front());
      CHECK(f.name == s.name + reading.file_suffix());
      CHECK(s.store_file_of(reading.name()).name == f.name);
      ++heat_files;
    }
  }
  CHECK(heat_files == 4 + 8 + 8);
  const RegisteredStudy& poisson = r.study("thesis_table4_4");
  CHECK(poisson.store_file_of("h10").name == "thesis_table4_4");
  CHECK(poisson.store_file_of("h15_exact").name == "thesis_table4_4");
  CHECK(poisson.store_file_of("h15_cell_exact").name == "thesis_table4_4_cellvol");
  CHECK_THROWS_AS(poisson.store_file_of("h20"), InputError);
  CHECK_THROWS_AS(r.study("thesis_table4_5").store_file_of("h15_exact"), InputError);  // not stored
  CHECK_THROWS_AS(r.study("thesis_table4_1").store_file_of("h10"), InputError);        // no readings
}

TEST_CASE("registry: a study without its units or their price is refused", "[unit][registry]") {
  StudyRegistry r;
  RegisteredStudy s;
  s.name = s.program = "unpriced";
  s.units = [](const UnitScope& scope) {
    std::vector<StudyUnit> out;
    for (int k : scope.levels) out.push_back({k, 0, {fmt(k)}, "level"});
    return out;
  };
  CHECK_THROWS_AS(r.add(s), InputError);  // units, no price
  s.price = [](UnitPricer&, const StudyUnit&) {};
  s.units = nullptr;
  CHECK_THROWS_AS(r.add(s), InputError);  // price, no units
  s.units = [](const UnitScope&) { return std::vector<StudyUnit>{}; };
  r.add(s);
  CHECK(r.studies().size() == 1);
}

TEST_CASE("registry: the heat tables' units, every one run, and the plan's price of them", "[unit][registry]") {
  const RegisteredStudy& s = study_registry().study("thesis_table4_5");
  const HeatTable& t = heat_table("4.5");
  // The paper profile runs every series under both h rules at every level: each h rule is a
  // reading the set-up rule weighs, so none is trimmed.
  const auto units = s.units({true, t.paper, false});
  for (auto& u : units) CHECK(u.trimmed.empty());
  CHECK(units.size() == t.paper.size() * 2 * pde_weights().size() * t.thetas.size());
  std::set<std::string> parts;
  for (auto& u : units)
    if (u.level == t.paper.back()) parts.insert(u.part);
  CHECK(parts == std::set<std::string>{"h10", "h15"});
  // The plan: a set-up per (level, h rule, weight), then one unit per series.
  const Calibration c = made_up_calibration();  // the pricer keeps a reference
  UnitPricer p(Profile::paper, c);
  for (auto& u : units) s.price(p, u);
  std::size_t setups = 0;
  for (auto& u : p.units()) setups += u.variant.rfind("setup/", 0) == 0;
  CHECK(setups == t.paper.size() * 2 * pde_weights().size());
  CHECK(p.units().size() == setups + units.size());
  // A series run in the Krylov subspace holds it: its peak is its set-up's plus 2.5 vectors of
  // the unknowns per dimension (basis grown by half, and the ℓ∞ map), a stepped one's is not.
  std::map<std::string, const PlanUnit*> setup_of;
  for (auto& u : p.units())
    if (u.variant.rfind("setup/", 0) == 0) setup_of[u.study + "|" + fmt(u.level) + "|" + u.variant.substr(6)] = &u;
  std::size_t propagated = 0;
  for (auto& u : p.units()) {
    if (u.variant.rfind("setup/", 0) == 0) continue;
    const PlanUnit& a = *setup_of.at(u.study + "|" + fmt(u.level) + "|" + u.variant.substr(0, u.variant.find('/')));
    INFO(u.study << " " << u.variant << " at 2^-" << u.level);
    if (u.basis.find("Krylov") == std::string::npos) {
      CHECK(u.mem_mib == a.mem_mib);
      continue;
    }
    ++propagated;
    CHECK(u.mem_mib == Approx(a.mem_mib + p.heat_krylov_mib(u)));
    CHECK(p.heat_krylov_mib(u) == Approx(2.5 * p.heat_krylov_dim(u) * u.targets * 8 / (1024.0 * 1024.0)));
  }
  CHECK(propagated > 0);
}

TEST_CASE("registry: a trimmed unit is priced and marked in the plan, never run", "[unit][registry]") {
  // Tables 4.1-4.3 trim the uniform volumes (beyond the document) above
  // paper_uniform_max_level in the paper profile.
  const ThesisTableSpec& t = thesis_table_spec("thesis_table4_1");
  const RegisteredStudy& s = study_registry().study(t.program);
  std::size_t over = 0;
  for (auto& u : s.units({true, t.paper_levels, false})) {
    const bool uniform_above = u.key[1] == volumes_name(Volumes::uniform) && u.level > t.paper_uniform_max_level;
    INFO(u.variant << " at 2^-" << u.level);
    CHECK(u.trimmed.empty() == !uniform_above);
    over += uniform_above;
  }
  REQUIRE(over > 0);
  // With --levels nothing is trimmed.
  for (auto& u : s.units({true, t.paper_levels, true})) CHECK(u.trimmed.empty());
  // The plan prices them with their reason; the quick profile trims nothing.
  const Calibration c = made_up_calibration();
  std::size_t marked = 0;
  for (auto& u : plan_units(Profile::paper, c))
    if (u.study == t.program && !u.trimmed.empty()) {
      CHECK(u.level > t.paper_uniform_max_level);
      CHECK(u.trimmed.find("uniform volumes") != std::string::npos);
      ++marked;
    }
  CHECK(marked == over);
  for (auto& u : plan_units(Profile::quick, c)) CHECK(u.trimmed.empty());
}

TEST_CASE("plan: one study priced at levels past its profile (plan --study --levels)", "[unit][registry]") {
  const Calibration c = made_up_calibration();
  const auto units = plan_units(Profile::paper, c, study_registry(), {.study = "thesis_table4_6", .levels = {10, 11}});
  REQUIRE(!units.empty());
  std::set<std::string> parts;
  for (auto& u : units) {
    CHECK(u.study.rfind("thesis_table4_6", 0) == 0);  // its parts (h rules) only
    CHECK((u.level == 10 || u.level == 11));
    CHECK(u.time_s > 0);
    parts.insert(u.study);
  }
  CHECK(parts.size() == 2);  // both h rules run at levels given, as --levels runs them
  // The finer level costs more: four times the particles, smaller steps.
  double t10 = 0, t11 = 0;
  for (auto& u : units) (u.level == 10 ? t10 : t11) += u.time_s;
  CHECK(t11 > 4 * t10);
  CHECK_THROWS_AS(plan_units(Profile::paper, c, study_registry(), {.study = "thesis_table9", .levels = {}}), InputError);
}
