// The studies as the registry lists them (registry.hpp, the catalog of `gpm study`): one
// entry per study, levels a program can run, and the definitions the programs read.
#include <algorithm>
#include <set>

#include <catch2/catch.hpp>

#include "gpm/error.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/define/thesis_tables.hpp"

using namespace gpm;

TEST_CASE("Catalog: unique names, ascending levels, the quick profile inside the paper's",
          "[catalog]") {
  std::set<std::string> names;
  const auto& c = study_registry().studies();
  REQUIRE(c.size() == 10);  // core_voronoi, imoto, Tables 4.1–4.7, the Poisson diagnostic
  for (const auto& e : c) {
    INFO(e.name);
    CHECK(names.insert(e.name).second);
    CHECK(std::is_sorted(e.levels.quick.begin(), e.levels.quick.end()));
    CHECK(std::is_sorted(e.levels.paper.begin(), e.levels.paper.end()));
    CHECK(!e.levels.quick.empty());
    CHECK(e.levels.paper.back() >= e.levels.quick.back());
    // The Poisson diagnostic's paper profile is the thesis' rate levels only (7-9, where the
    // store's rows are); its quick profile ends where that begins.
    const bool rate_levels_only = e.name == "thesis_poisson_diagnostic";
    if (rate_levels_only) CHECK(e.levels.quick.back() == e.levels.paper.front());
    for (int k : e.levels.quick) {
      CHECK(k >= 3);
      if (!rate_levels_only)
        CHECK(std::find(e.levels.paper.begin(), e.levels.paper.end(), k) != e.levels.paper.end());
    }
  }
}

TEST_CASE("Catalog: the entries are the studies' own definitions", "[catalog]") {
  CHECK(study_registry().study("imoto_fig5_table1").levels.paper == imoto_study().levels.paper);
  CHECK(study_registry().study("thesis_table4_4").levels.quick == poisson_table().levels.quick);
  CHECK(study_registry().study("thesis_table4_6").fixed_args ==
        std::vector<std::string>{"--table", "4.6"});
  CHECK(study_registry().study("thesis_table4_6").levels.paper == heat_table("4.6").paper);
  CHECK(study_registry().study("thesis_table4_2").levels.paper ==
        thesis_table_spec("thesis_table4_2").paper_levels);
  CHECK(study_registry().study("thesis_poisson_diagnostic").columns == poisson_diagnostic().columns);
  CHECK(study_registry().study("thesis_poisson_diagnostic").levels.paper == poisson_diagnostic().levels.paper);
  CHECK(imoto_study().requests().size() == 9);
  CHECK(voronoi_study().seeds_option() == "1,2,3");
  CHECK(poisson_table().levels.help() == "quick (levels 5-7) or paper (levels 5-9)");
  CHECK_THROWS_WITH(study_registry().study("table4_8"),
                    Catch::Contains("unknown study 'table4_8'; valid: imoto_fig5_table1, thesis_table4_1"));
}
