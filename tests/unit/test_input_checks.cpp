// The input checks every program shares (issue 14): strict integers and decimals, output
// paths, the temp files of TsvTable::save, cells of a data file named by file, row and
// column, and the particle spacing behind gpm trunc's warning.  The programs' end-to-end
// behaviour is the bad-input table (tests/bad_input/cases.tsv).
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/truncation.hpp"
#include "../temp_dir.hpp"

using namespace gpm;
namespace fs = std::filesystem;

namespace {

// The message of the InputError that f throws ("" if none).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("integers: decimal only, overflow and range refused naming the value", "[args]") {
  CHECK(parse_integer("42", "--n") == 42);
  CHECK(parse_integer("-7", "--n") == -7);
  CHECK(parse_integer("9223372036854775807", "--n") == LLONG_MAX);
  // strtoll would clamp these to LLONG_MAX and report success.
  CHECK(input_error([] { parse_integer("9223372036854775808", "--n"); }) ==
        "--n: 9223372036854775808 is not an integer in [-9223372036854775808, "
        "9223372036854775807]");
  CHECK(input_error([] { parse_integer("18446744073709551616", "--seed", 0, 5); }) ==
        "--seed: 18446744073709551616 is not an integer in [0, 5]");
  for (const char* bad : {"0x10", "1e1", "5.5", " 5", "5 ", "", "-", "+", "1_000"})
    CHECK_FALSE(input_error([&] { parse_integer(bad, "--n"); }).empty());
  CHECK(parse_seed("0", "--seed") == 0);
  CHECK(parse_seed("9223372036854775807", "--seed") == 9223372036854775807ULL);
  CHECK(input_error([] { parse_seed("-1", "--seed"); }) ==
        "--seed: -1 is not an integer in [0, 9223372036854775807]");
  CHECK(parse_seeds("1,2,3", "--seeds") == std::vector<uint64_t>{1, 2, 3});
  CHECK(input_error([] { parse_seeds(",", "--seeds"); }) == "--seeds: no seed given");
}

TEST_CASE("decimals: no hex, no blanks; non-finite values named", "[args]") {
  double v = 0;
  CHECK(read_decimal("1.5e-3", v));
  CHECK(v == 1.5e-3);
  CHECK(read_decimal("1e400", v));  // a decimal, out of range: the caller sees inf
  CHECK(std::isinf(v));
  for (const char* bad : {"0x10", "0x1p-5", " 1", "1 ", "inf", "nan", "", "1,5"})
    CHECK_FALSE(read_decimal(bad, v));
  CHECK(input_error([] { parse_number("0x10", "--h"); }) ==
        "--h: cannot parse '0x10' as a decimal number");
  CHECK(input_error([] { parse_number("-inf", "--h"); }) == "--h must be finite, got '-inf'");
  CHECK(input_error([] { parse_number("2^5000", "--h"); }) == "--h must be finite, got '2^5000'");
}

TEST_CASE("flags refuse a value; options take --name=value; tolerances in (0, 1)", "[args]") {
  Args a("prog", "test");
  a.flag("polygons", "a flag").opt("tol", "0.5", "a tolerance");
  const char* argv1[] = {"prog", "--polygons=no"};
  CHECK(input_error([&] { a.parse(2, const_cast<char**>(argv1)); }) ==
        "--polygons is a flag and takes no value, got '--polygons=no' (omit it to leave it off)");
  CHECK_FALSE(a.has("polygons"));
  for (const char* t : {"--tol=0", "--tol=1", "--tol=2", "--tol=-0.1"}) {
    const char* argv[] = {"prog", t};
    a.parse(2, const_cast<char**>(argv));
    CHECK_FALSE(input_error([&] { a.tolerance("tol"); }).empty());
  }
  const char* argv2[] = {"prog", "--tol=1e-10", "--polygons"};
  a.parse(3, const_cast<char**>(argv2));
  CHECK(a.tolerance("tol") == 1e-10);
  CHECK(a.has("polygons"));
}

TEST_CASE("output paths: a regular file or nothing yet, checked at parse time", "[tsv][args]") {
  TempDir d("gpm_input_checks_");
  std::ofstream(d.file("file.tsv")) << "x\n";
  fs::create_directory(d.file("dir"));
  fs::create_symlink(d.file("file.tsv"), d.file("link.tsv"));
  CHECK_NOTHROW(check_output_path("--out", d.file("file.tsv")));
  CHECK_NOTHROW(check_output_path("--out", d.file("new/deeper/x.tsv")));  // directories are made
  CHECK_NOTHROW(check_output_path("--out", ""));
  CHECK(input_error([] { check_output_path("--out", "/dev/null"); }).find(
            "--out /dev/null is not a regular file") == 0);
  CHECK(input_error([&] { check_output_path("--out", d.file("dir")); }) ==
        "--out " + d.file("dir") + " is a directory, not a file");
  CHECK(input_error([&] { check_output_path("--out", d.file("link.tsv")); }).find(
            "is a symbolic link") != std::string::npos);
  CHECK(input_error([&] { check_output_path("--out", d.file("file.tsv/x.tsv")); }).find(
            "is not a directory") != std::string::npos);
  // Declared outputs are checked by parse(), before the program does anything else.
  Args a("prog", "test");
  a.output("out", "", "a file").output("log", "", "another");
  const std::string dir = d.file("dir"), same = d.file("file.tsv");
  const char* argv1[] = {"prog", "--out", dir.c_str()};
  CHECK_FALSE(input_error([&] { a.parse(3, const_cast<char**>(argv1)); }).empty());
  const char* argv2[] = {"prog", "--out", same.c_str(), "--log", same.c_str()};
  CHECK(input_error([&] { a.parse(5, const_cast<char**>(argv2)); }).find("is the same file as") !=
        std::string::npos);
  // save() refuses the same paths even when no parse() checked them.
  TsvTable t;
  t.columns = {"a"};
  CHECK_THROWS_AS(t.save(d.file("link.tsv")), InputError);
  CHECK(fs::is_symlink(d.file("link.tsv")));
}

TEST_CASE("save removes the temp files of dead writers and keeps a live one's", "[tsv]") {
  TempDir d("gpm_input_checks_");
  const std::string out = d.file("data.tsv");
  // pid_max is at most 2^22, so this pid belongs to no process; pid 1 always runs.  Only names
  // of save()'s own form (NAME.gpm-tmp.PID.16HEX) are ever removed: a user's files stay.
  const std::string dead = out + ".gpm-tmp.999999999.00112233aabbccdd";
  const std::string live = out + ".gpm-tmp.1.00112233aabbccdd";
  std::ofstream(dead) << "partial";
  std::ofstream(live) << "partial";
  for (const char* user : {".tmp.999999999", ".tmp.x1", ".gpm-tmp.999999999", ".gpm-tmp.999999999.short"})
    std::ofstream(out + user) << "not ours";
  TsvTable t;
  t.columns = {"a"};
  t.add_row({"1"});
  t.save(out);
  CHECK(fs::exists(out));
  CHECK_FALSE(fs::exists(dead));
  CHECK(fs::exists(live));
  for (const char* user : {".tmp.999999999", ".tmp.x1", ".gpm-tmp.999999999", ".gpm-tmp.999999999.short"})
    CHECK(fs::exists(out + user));
  for (auto& e : fs::directory_iterator(d.dir))  // this save's own temp file is gone
    CHECK(e.path().filename().string().find(".gpm-tmp." + std::to_string(::getpid()) + ".") == std::string::npos);
}

TEST_CASE("cells of a data file: errors name the file, line, data row and column", "[tsv]") {
  TempDir d("gpm_input_checks_");
  const std::string path = d.file("d.tsv");
  std::ofstream(path) << "# note = x\nlevel\terr\n5\t0.5\n\n6\tabc\n7.5\tnan\n8\n";
  CHECK(input_error([&] { TsvTable::load(path); }) == "data file " + path + " line 7: 1 cells for 2 columns");
  const TsvTable t = TsvTable::load(path, false);  // short rows read as they are
  CHECK(t.integer(0, 0) == 5);
  CHECK(t.number(0, 1) == 0.5);
  CHECK(std::isnan(t.number(2, 1)));  // fmt() writes NaN as "nan": a number of the format
  CHECK(input_error([&] { t.number(1, 1); }) ==
        path + " line 5 (data row 2), column 'err': 'abc' is not a number");
  CHECK(input_error([&] { t.integer(2, 0); }) ==
        path + " line 6 (data row 3), column 'level': '7.5' is not an integer");
  CHECK(input_error([&] { t.number(3, 1); }) ==
        path + " line 7 (data row 4), column 'err': the row has only 1 cells");
  CHECK(input_error([] { TsvTable::load("/dev/zero"); }) ==
        "data file /dev/zero is not a regular file");
}

TEST_CASE("target spacing: the largest distance to a nearest particle, and isolated targets",
          "[truncation]") {
  const double dx = 1.0 / 16;
  const Particles grid = jittered_grid(dx, 1, 0.0);
  const TargetSpacing at = target_spacing(grid, dx, 0.0, dx);  // nearest = dx: none within h
  CHECK(at.largest == Approx(dx).epsilon(1e-12));
  CHECK(at.isolated == grid.count_in_omega());
  CHECK(target_spacing(grid, dx, 0.0, 1.01 * dx).isolated == 0);
  // A jittered grid: the spacing lies between the grid's and the bound of the search.
  const Particles p = jittered_grid(dx, 7, 0.25);
  const TargetSpacing s = target_spacing(p, dx, 0.25, 2 * dx);
  CHECK(s.largest > 0.5 * dx);
  CHECK(s.largest < std::sqrt(1.5 * 1.5 + 0.5 * 0.5) * dx);
  CHECK(s.isolated == 0);
  CHECK(target_spacing(p, dx, 0.25, s.largest).isolated >= 1);
}
