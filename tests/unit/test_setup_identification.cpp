// The set-up rule on a fixture store (paper/04-setup-rule.md): eight readings of Table 4.6
// whose θ = 0 rates are the published ones times a factor per reading, so each distance is
// |ln factor|; the rule picks h, volumes and time step one at a time, and the distance bands
// over the stored seed files say whether each decision is firm, suggested or not assessed.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <string>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/judge/setup_identification.hpp"
#include "../temp_dir.hpp"

using namespace gpm;

namespace {

const std::map<std::string, double> kPublished = {
    {"quartic_polynomial", -281}, {"piecewise_cubic_polynomial", -314}, {"piecewise_quintic_polynomial", -416}};

// A Table 4.6 file with θ = 0 rows at 2^-8 (h = 1) and 2^-9 (h = 1/2) whose rates are the
// published ones times `factor`: rate = log2(e8/e9).
void write_reading(const std::filesystem::path& path, double factor) {
  std::ofstream f(path);
  f << "weight\ttheta\tlevel\th\trel_error\n";
  for (auto& [w, p] : kPublished) {
    f << w << "\t0\t8\t1\t1\n";
    f << w << "\t0\t9\t0.5\t" << std::exp2(-p * factor) << "\n";
  }
}

// The published file: Table 4.6's rates with their levels (the fingerprint rows θ = 0).
TsvTable published() {
  TsvTable t;
  t.set("rate_levels", "8,9");
  t.columns = {"weight", "theta", "numerical"};
  for (auto& [w, p] : kPublished) t.add_row({w, "0", fmt(p)});
  return t;
}

// The store file of a reading's seed N (its registry name), or of the reading itself.
std::string file_of(const RegisteredStudy& s, const std::string& slice) {
  for (const StoreFile& f : s.store_files)
    if (f.slice == slice) return f.name + ".tsv";
  return s.store_file_of(slice).name + ".tsv";
}

}  // namespace

TEST_CASE("set-up identification: details one at a time, with their uncertainty", "[unit][setup]") {
  TempDir tmp("gpm_setup_");
  // The registry's Table 4.6 entry, with seed files for h15_exact as well (the registry may
  // not hold them yet): the rule reads whatever seed files its study names.
  RegisteredStudy study = setup_fingerprint_study(study_registry());
  for (int n = 2; n <= 5; ++n)
    study.store_files.push_back({.name = "fixture_h15_exact_seed" + fmt(n), .slice = "h15_exact_seed" + fmt(n)});
  // h10 readings far off (factor 2), h15 close; cell and exact closest together.
  const std::map<std::string, double> factor = {
      {"h10", 2.0}, {"h10_exact", 2.05}, {"h10_cell", 1.98}, {"h10_cell_exact", 2.02},
      {"h15", 1.0225}, {"h15_exact", 1.0115}, {"h15_cell", 1.015}, {"h15_cell_exact", 1.004}};
  for (auto& [r, f] : factor) write_reading(tmp.dir / file_of(study, r), f);

  SECTION("one realization each: identified, the uncertainty not assessed") {
    const SetupIdentification id = identify_setup(StoreSnapshot(tmp.dir.string()), study, published());
    INFO(id.table.get("incomplete").value_or("") << " " << id.decisions);
    REQUIRE(id.identified);
    CHECK(id.identified->name() == "h15_cell_exact");
    CHECK(id.table.get("robust_volumes").value().rfind("not assessed: 1 realizations of h15_cell_exact", 0) == 0);
    CHECK(id.table.number(7, id.table.require_column("distance")) == Approx(std::log(1.004)));
  }
  // Seeds 2-5 of the two readings the volume decision compares (h15_cell_exact against
  // h15_exact): seed files under the registry's names.
  auto seeds = [&](const std::string& r, std::vector<double> f) {
    for (std::size_t i = 0; i < f.size(); ++i) write_reading(tmp.dir / file_of(study, r + "_seed" + fmt(i + 2)), f[i]);
  };
  SECTION("bands a factor of two apart: firm") {
    seeds("h15_cell_exact", {1.0035, 1.0040, 1.0038, 1.0042});
    seeds("h15_exact", {1.011, 1.012, 1.0125, 1.013});
    const SetupIdentification id = identify_setup(StoreSnapshot(tmp.dir.string()), study, published());
    REQUIRE(id.identified);
    CHECK(id.identified->name() == "h15_cell_exact");
    CHECK(id.table.get("robust_volumes").value().rfind("firm: h15_cell_exact's distances", 0) == 0);
    CHECK(id.table.text(7, "seeds") == "5");
    // The time-step decision compares h15_cell, which has one realization.
    CHECK(id.table.get("robust_dt_rule").value().rfind("not assessed", 0) == 0);
  }
  SECTION("bands closer than a factor of two: suggested, the decision unchanged") {
    seeds("h15_cell_exact", {1.0035, 1.0040, 1.0038, 1.0042});
    seeds("h15_exact", {1.011, 1.006, 1.0125, 1.013});
    const SetupIdentification id = identify_setup(StoreSnapshot(tmp.dir.string()), study, published());
    REQUIRE(id.identified);
    CHECK(id.identified->name() == "h15_cell_exact");
    CHECK(id.table.get("robust_volumes").value().rfind("suggested: ", 0) == 0);
  }
  SECTION("one read of the store: a snapshot judges the bytes it read first") {
    const StoreSnapshot store(tmp.dir.string());
    const SetupIdentification first = identify_setup(store, study, published());
    const std::size_t read = store.files_read();
    CHECK(read == factor.size());  // the eight readings' files, each read once
    // The files change on disk after the first judgement: the same snapshot judges again
    // without reading them (same distances, no further read); a new snapshot sees the change.
    for (auto& [r, f] : factor) write_reading(tmp.dir / file_of(study, r), 1.5 * f);
    const SetupIdentification again = identify_setup(store, study, published());
    CHECK(store.files_read() == read);
    CHECK(again.table.rows == first.table.rows);
    const SetupIdentification fresh = identify_setup(StoreSnapshot(tmp.dir.string()), study, published());
    CHECK(fresh.table.rows != first.table.rows);
  }
  SECTION("a reading without rows: nothing identified") {
    std::filesystem::remove(tmp.dir / file_of(study, "h15_exact"));
    const SetupIdentification id = identify_setup(StoreSnapshot(tmp.dir.string()), study, published());
    CHECK(!id.identified);
    CHECK(id.incomplete == std::vector<std::string>{"h15_exact"});
  }
}
