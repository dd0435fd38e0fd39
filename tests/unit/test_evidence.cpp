// The judges' typed evidence (judge/evidence.hpp): a table's series by key, only finite and
// positive errors kept; a rate between two stored levels, NaN where one is missing; the error
// constant e/h^p.
#include <catch2/catch.hpp>

#include <cmath>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/judge/evidence.hpp"

using namespace gpm;

TEST_CASE("evidence: series by key, rates between stored levels, error constants", "[unit][judge]") {
  TsvTable t;
  t.columns = {"weight", "theta", "level", "h", "rel_error"};
  t.rows = {{"a", "0.5", "5", "0.2", "0.04"},  {"a", "0.5", "6", "0.1", "0.01"},
            {"a", "0.5", "7", "0.05", "NA"},   {"a", "1", "5", "0.2", "0"},
            {"b", "0.5", "5", "0.2", "0.08"}};
  const EvidenceSeriesMap m = read_series(t, {"weight", "theta"});
  REQUIRE(m.size() == 2);  // (a, 1) holds no positive error: no series
  const EvidenceSeries& s = m.at({"a", "0.5"});
  REQUIRE(s.size() == 2);  // level 7's NA left out
  CHECK(series_rate(s, 5, 6) == Approx(2.0));
  CHECK(std::isnan(series_rate(s, 6, 7)));
  CHECK(error_constant(s.at(6), 2) == Approx(1.0));
  t.columns[3] = "radius";
  CHECK_THROWS(read_series(t, {"weight", "theta"}));  // no h column: refused, not guessed
}

TEST_CASE("evidence: a store file's realization and set-up come from its arguments, not its name",
          "[unit][judge]") {
  RegisteredStudy s;
  s.store_files = {{.name = "t", .slice = "all"},
                   {.name = "t_seed2", .slice = "seed2", .args = {"--seed", "2"}},
                   {.name = "t_cell", .slice = "cell", .args = {"--volumes", "cell"}},
                   // A name that says seed 9, arguments that say seed 3 of the cell set-up.
                   {.name = "t_cell_seed9", .slice = "cell_seed9", .args = {"--volumes", "cell", "--seed", "3"}},
                   {.name = "t_cell_tau", .slice = "cell_tau", .args = {"--volumes", "cell", "--solver", "tau", "--seed", "1"}},
                   {.name = "t_cell_tau_seed2", .slice = "x", .args = {"--volumes", "cell", "--solver", "tau", "--seed", "2"}}};
  const auto& f = s.store_files;
  CHECK(file_seed(f[0]) == 1);
  CHECK(file_seed(f[3]) == 3);
  CHECK(file_solver(f[4]) == "tau");
  CHECK(setup_args(f[5]) == std::vector<std::string>{"--volumes", "cell"});
  auto names = [](const std::vector<const StoreFile*>& v) {
    std::vector<std::string> n;
    for (auto* p : v) n.push_back(p->name);
    return n;
  };
  CHECK(names(realizations_of(s, f[0])) == std::vector<std::string>{"t_seed2"});
  CHECK(names(realizations_of(s, f[2])) == std::vector<std::string>{"t_cell_seed9"});
  CHECK(names(realizations_of(s, f[4])) == std::vector<std::string>{"t_cell_tau_seed2"});
  CHECK(seed_one_of(s, f[3]) == &f[2]);
  CHECK(seed_one_of(s, f[5]) == &f[4]);
  CHECK(seed_one_of(s, f[1]) == &f[0]);
  // Every registered store file's arguments are option-value pairs, as the reading assumes.
  for (const RegisteredStudy& r : study_registry())
    for (const StoreFile& g : r.store_files) {
      INFO(g.name);
      CHECK(g.args.size() % 2 == 0);
      CHECK(seed_one_of(r, g) != nullptr);
    }
}
