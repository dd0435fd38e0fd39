// The judging pass's one read of the store (judge/snapshot.hpp): a file is read at its first
// ask and kept, absent files are answered without a read, and a row cut short is refused where
// whole rows are asked for, as TsvTable::load refuses it.
#include <catch2/catch.hpp>

#include <fstream>

#include "gpm/error.hpp"
#include "gpm/studies/judge/snapshot.hpp"
#include "../temp_dir.hpp"

using namespace gpm;

TEST_CASE("store snapshot: each file read once, at its first ask", "[unit][store]") {
  TempDir tmp("gpm_snapshot_");
  std::ofstream(tmp.dir / "b.tsv") << "# program = x\nlevel\trel_error\n5\t0.1\n";
  std::ofstream(tmp.dir / "a.tsv") << "level\trel_error\n5\n";  // a row cut short
  std::ofstream(tmp.dir / ".hidden.tsv") << "level\n";
  std::ofstream(tmp.dir / "notes.txt") << "not a data file\n";
  const StoreSnapshot store(tmp.dir.string());
  CHECK(store.files_read() == 0);
  CHECK(store.data_files() == std::vector<std::string>{"a.tsv", "b.tsv"});
  CHECK_FALSE(store.has("c.tsv"));
  CHECK_THROWS_AS(store.table("c.tsv"), InputError);

  const TsvTable& b = store.table("b.tsv");
  CHECK(b.get("program") == "x");
  CHECK(&store.table("b.tsv") == &b);
  CHECK(store.files_read() == 1);

  // Read as it is for the store's own checks; refused, with its line, where rows must be whole.
  CHECK(store.table("a.tsv", false).rows.size() == 1);
  CHECK_THROWS_WITH(store.table("a.tsv"), Catch::Contains("a.tsv line 2: 1 cells for 2 columns"));
  CHECK_THROWS_WITH(TsvTable::load(store.path("a.tsv")), Catch::Contains("a.tsv line 2: 1 cells for 2 columns"));
  CHECK(store.files_read() == 2);
}

TEST_CASE("published tables: each file read once for a judging pass", "[unit][store]") {
  TempDir tmp("gpm_published_");
  std::ofstream(tmp.dir / "t_long.tsv") << "# rate_levels = 8,9\nweight\tnumerical\nquartic\t2\n";
  const PublishedTables pub(tmp.dir.string());
  CHECK(pub.files_read() == 0);
  const TsvTable& t = pub.file("t_long.tsv");
  CHECK(t.get("rate_levels") == "8,9");
  CHECK(&pub.file("t_long.tsv") == &t);
  CHECK(pub.files_read() == 1);
  CHECK_THROWS_WITH(pub.file("u_long.tsv"), Catch::Contains("no published file") && Catch::Contains("u_long.tsv"));
  CHECK(pub.files_read() == 1);
}
