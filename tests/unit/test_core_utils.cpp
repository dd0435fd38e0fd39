// Norms and rates, TSV round trip and cache matching, argument parsing.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/norms.hpp"
#include "gpm/studies/define/profile.hpp"

using namespace gpm;

TEST_CASE("two-level and least-squares rates recover a power law", "[norms]") {
  std::vector<double> h, e;
  for (int k = 0; k < 5; ++k) {
    h.push_back(0.1 / (1 << k));
    e.push_back(3.0 * std::pow(h.back(), 2.5));
  }
  CHECK(two_level_rate(h[3], e[3], h[4], e[4]) == Approx(2.5).epsilon(1e-12));
  CHECK(least_squares_rate(h, e) == Approx(2.5).epsilon(1e-12));
  CHECK(std::isnan(two_level_rate(0.1, 0.0, 0.05, 1.0)));
}

TEST_CASE("the least-squares rate's 95 % interval is Student's t times the slope's standard error", "[norms]") {
  // log e = 2 log h + r with residuals (d, -2d, d) at log h = 0, 1, 2: orthogonal to the
  // centred abscissa, so the slope stays 2; SSR = 6 d^2, Sxx = 2, one degree of freedom.
  const double d = 0.1;
  const std::vector<double> r = {d, -2 * d, d};
  std::vector<double> h, e;
  for (int k = 0; k < 3; ++k) h.push_back(std::exp(k)), e.push_back(std::exp(2.0 * k + r[k]));
  const RateFit fit = least_squares_fit(h, e);
  CHECK(fit.points == 3);
  CHECK(fit.slope == Approx(2.0).epsilon(1e-12));
  CHECK(fit.half95 == Approx(12.706204736174705 * std::sqrt(6 * d * d / 2)).epsilon(1e-9));
  // An exact power law has no scatter; two points have no interval; a zero error is skipped.
  CHECK(least_squares_fit({0.1, 0.05, 0.025}, {1e-2, 2.5e-3, 6.25e-4}).half95 == Approx(0).margin(1e-12));
  CHECK(std::isnan(least_squares_fit({0.1, 0.05}, {1e-2, 2.5e-3}).half95));
  CHECK(least_squares_fit({0.1, 0.05, 0.025}, {1e-2, 0.0, 6.25e-4}).points == 2);
}

TEST_CASE("discrete max norms respect the mask and refuse non-finite values", "[norms]") {
  std::vector<double> a = {1, -5, 2}, b = {1, 1, 1};
  std::vector<uint8_t> m = {1, 0, 1};
  CHECK(max_abs(a) == 5);
  CHECK(max_abs(a, m) == 2);
  CHECK(max_abs_diff(a, b, m) == 1);
  a[2] = std::nan("");
  CHECK_THROWS_AS(max_abs(a, m), NumericalError);
}

TEST_CASE("TSV files round-trip and the cache matches only equal parameters", "[tsv]") {
  const std::string path = (std::filesystem::temp_directory_path() / "gpm_tsv_test.tsv").string();
  TsvTable t;
  t.set("dx", 0.5);
  t.set("weight", "Pi1");
  t.columns = {"level", "err"};
  t.add_row({"5", fmt(1.25e-3)});
  t.save(path);
  auto u = TsvTable::load(path);
  CHECK(u.get("dx").value() == "0.5");
  CHECK(u.rows.size() == 1);
  CHECK(std::stod(u.rows[0][1]) == 1.25e-3);
  CHECK(TsvTable::load_matching(path, {{"weight", "Pi1"}}).size() == 1);
  CHECK(TsvTable::load_matching(path, {{"weight", "Pi2"}}).empty());
  CHECK(TsvTable::load_matching(path + ".absent", {{"weight", "Pi1"}}).empty());
  std::filesystem::remove(path);
}

TEST_CASE("numbers are parsed strictly; 2^-k is accepted", "[args]") {
  CHECK(parse_number("2^-9", "dx") == std::ldexp(1.0, -9));
  CHECK(parse_number("0.03", "h") == 0.03);
  CHECK_THROWS_AS(parse_number("0.03x", "h"), InputError);
  CHECK_THROWS_AS(parse_number("", "h"), InputError);
  CHECK_THROWS_AS(parse_number("inf", "h"), InputError);
  CHECK_THROWS_AS(parse_profile("fast"), InputError);
  CHECK(parse_profile("paper") == Profile::paper);
}

TEST_CASE("Args rejects unknown options and missing values", "[args]") {
  Args a("prog", "test");
  a.opt("h", "0.1", "radius");
  const char* argv1[] = {"prog", "--bogus", "1"};
  CHECK_THROWS_AS(a.parse(3, const_cast<char**>(argv1)), InputError);
  const char* argv2[] = {"prog", "--h"};
  CHECK_THROWS_AS(a.parse(2, const_cast<char**>(argv2)), InputError);
  const char* argv3[] = {"prog", "--h=-2"};
  a.parse(2, const_cast<char**>(argv3));
  CHECK_THROWS_AS(a.positive("h"), InputError);
}

TEST_CASE("TsvRow: cells by column name, unknown and unset names refused", "[unit][tsv]") {
  TsvTable t;
  t.columns = {"level", "h", "rel_error"};
  TsvRow r = t.named_row();
  r["rel_error"] = "0.5", r["level"] = "7";
  CHECK_THROWS_AS(r.cells(), std::logic_error);  // h left unset
  r["h"] = "0.1";
  t.add_row(r);
  CHECK(t.rows.back() == std::vector<std::string>{"7", "0.1", "0.5"});
  CHECK_THROWS_AS(r["H"], std::logic_error);  // not a column
}
