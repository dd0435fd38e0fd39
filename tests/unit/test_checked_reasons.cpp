// The checked reasons for differing rates (src/gpm/studies/judge/checked_reasons.hpp) on small tables
// in memory: each mechanism's pass/fail rule and its `restores` (Table 4.4's volume mismatch,
// Table 4.3's gradient smoothing error, Table 4.2's interpolant smoothing part, the heat tables'
// one-mode model), the heat tables' choice of the V_i = dx^2 run with the same time-step rule,
// and the reasons collapsed per mechanism.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <utility>

#include "gpm/error.hpp"
#include "gpm/operators/norms.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/studies/judge/checked_reasons.hpp"
#include "gpm/studies/judge/rates.hpp"
#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

using Cells = std::initializer_list<std::pair<const char*, std::string>>;

// A row filled by column name.
void add(TsvTable& t, Cells cells) {
  TsvRow row = t.named_row();
  for (auto& [k, v] : cells) row[k] = v;
  t.add_row(row);
}

TsvTable table(std::vector<std::string> columns, const std::string& rate_levels = "") {
  TsvTable t;
  if (!rate_levels.empty()) t.set("rate_levels", rate_levels);
  t.columns = std::move(columns);
  return t;
}

TsvTable reasons() { return table(checked_reason_columns()); }

// The row of `out` with this key (there must be one).
std::size_t row_of(const TsvTable& out, const std::string& key) {
  for (std::size_t i = 0; i < out.rows.size(); ++i)
    if (out.text(i, "key") == key) return i;
  FAIL("no checked reason for key " << key);
  throw;
}

// A share as the evidence prints it (%.3f).
std::string format_share(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", s);
  return b;
}

// A rate of `r` between h and h/2: the second error is the first divided by 2^r.
std::string fine(double coarse, double r) { return fmt(coarse / std::pow(2.0, r)); }

}  // namespace

TEST_CASE("checked reasons: Table 4.4's volume mismatch", "[unit][checked_reasons]") {
  TsvTable pub = table({"h_rule", "weight", "numerical"}, "8,9");
  for (const char* w : {"accounts_restores", "accounts_only", "restores_only", "no_cell_run"})
    add(pub, {{"h_rule", "h10"}, {"weight", w}, {"numerical", "2.00"}});
  TsvTable diag = table({"h_rule", "weight", "level", "variant", "h", "rel_error", "tau_predicted",
                         "volume_mismatch", "eps_smoothing"});
  // Each weight: the error at rate r_err, |tau_predicted| at rate r_tau, the V_i = dx^2 run at
  // rate r_cell (none for no_cell_run); h halves from 2^-8 to 2^-9.
  auto weight_rows = [&](const char* w, double r_err, double r_tau, double r_cell) {
    add(diag, {{"h_rule", "h10"}, {"weight", w}, {"level", "8"}, {"variant", "seed1"}, {"h", "0.2"},
               {"rel_error", "0.04"}, {"tau_predicted", "-0.05"}, {"volume_mismatch", "0.0013"},
               {"eps_smoothing", "0.03"}});
    add(diag, {{"h_rule", "h10"}, {"weight", w}, {"level", "9"}, {"variant", "seed1"}, {"h", "0.1"},
               {"rel_error", fine(0.04, r_err)}, {"tau_predicted", fine(-0.05, r_tau)},
               {"volume_mismatch", "-0.002"}, {"eps_smoothing", "0.008"}});
    if (r_cell < 0) return;
    add(diag, {{"h_rule", "h10"}, {"weight", w}, {"level", "8"}, {"variant", "seed1_cell"}, {"h", "0.2"},
               {"rel_error", "0.03"}, {"tau_predicted", "-0.03"}, {"volume_mismatch", "0"}, {"eps_smoothing", "0.03"}});
    add(diag, {{"h_rule", "h10"}, {"weight", w}, {"level", "9"}, {"variant", "seed1_cell"}, {"h", "0.1"},
               {"rel_error", fine(0.03, r_cell)}, {"tau_predicted", "-0.008"}, {"volume_mismatch", "0"},
               {"eps_smoothing", "0.008"}});
  };
  weight_rows("accounts_restores", 3.0, 3.1, 2.1);  // |3.1 - 3.0| and |2.1 - 2.00| within 0.15
  weight_rows("accounts_only", 3.0, 3.1, 2.5);      // V_i = dx^2 does not give the published rate
  weight_rows("restores_only", 3.0, 2.0, 2.0);      // |tau| does not account for the rate
  weight_rows("no_cell_run", 3.0, 3.0, -1);
  TsvTable out = reasons();
  add_volume_mismatch_reasons(pub, diag, kRateTolerance, out);
  REQUIRE(out.rows.size() == 4);
  auto at = [&](const char* w, const char* column) { return out.text(row_of(out, w), column); };
  CHECK(at("accounts_restores", "check") == "pass");
  CHECK(at("accounts_restores", "restores") == "yes");
  CHECK(at("accounts_restores", "slice") == "h10");
  CHECK(at("accounts_restores", "reason").rfind(
            "volume mismatch of (A.10): V_i = |Omega_H|/N differs from dx^2 by +0.13% at 2^-8 and -0.20% at 2^-9", 0) == 0);
  CHECK(at("accounts_restores", "evidence") ==
        "consistency predicted from eps and the mismatch: -0.0500 at 2^-8, -0.0058 at 2^-9 (eps alone 0.0300, "
        "0.0080); error/|predicted| 0.80, 0.86; rate predicted 3.10, reproduced 3.00; with V_i = dx^2: rate 2.10 "
        "(published 2.00)");
  CHECK(at("accounts_only", "check") == "fail");
  CHECK(at("accounts_only", "restores") == "no");
  CHECK(at("restores_only", "check") == "fail");
  CHECK(at("restores_only", "restores") == "yes");
  CHECK(at("no_cell_run", "check") == "fail");
  CHECK(at("no_cell_run", "evidence") == "diagnostic not yet at 2^-8 and 2^-9");
  // The published file's order, whatever the diagnostic's.
  CHECK(out.text(0, "key") == "accounts_restores");
  CHECK(out.text(3, "key") == "no_cell_run");

  TsvTable no_levels = table({"h_rule", "weight", "numerical"});
  CHECK_THROWS_AS(add_volume_mismatch_reasons(no_levels, diag, kRateTolerance, out), InputError);
}

TEST_CASE("checked reasons: Table 4.3's gradient smoothing error", "[unit][checked_reasons]") {
  // quartic_polynomial's gradient error at 2^-10 and 2^-11 is eps_grad times `share` at each
  // level; the published rate lies `offset` from the rate of eps_grad.
  const double h10 = 0.05, h11 = 0.025;
  const WeightFunction& w = weight("quartic_polynomial");
  const double e10 = gradient_smoothing_error(w, kSin2piWaveNumber * h10);
  const double e11 = gradient_smoothing_error(w, kSin2piWaveNumber * h11);
  const double rate_eps = two_level_rate(h10, e10, h11, e11);
  auto check = [&](double share10, double share11, double offset) {
    TsvTable pub = table({"weight", "operator", "function", "numerical"}, "10,11");
    add(pub, {{"weight", "quartic_polynomial"}, {"operator", "grad"}, {"function", "case2"},
              {"numerical", fmt(rate_eps + offset)}});
    add(pub, {{"weight", "quartic_polynomial"}, {"operator", "lap"}, {"function", "case2"}, {"numerical", "1.93"}});
    TsvTable data = table({"h_reading", "volumes", "level", "weight", "operator", "function", "h", "rel_error"});
    for (auto [level, h, e] : {std::tuple{"10", h10, e10 * share10}, std::tuple{"11", h11, e11 * share11}}) {
      add(data, {{"h_reading", "printed"}, {"volumes", "voronoi"}, {"level", level}, {"weight", "quartic_polynomial"},
                 {"operator", "grad"}, {"function", "case2"}, {"h", fmt(h)}, {"rel_error", fmt(e)}});
      // Rows of other readings, volumes and levels are not the slice's.
      add(data, {{"h_reading", "scaled"}, {"volumes", "voronoi"}, {"level", level}, {"weight", "quartic_polynomial"},
                 {"operator", "grad"}, {"function", "case2"}, {"h", fmt(h)}, {"rel_error", "1"}});
      add(data, {{"h_reading", "printed"}, {"volumes", "uniform"}, {"level", level}, {"weight", "quartic_polynomial"},
                 {"operator", "grad"}, {"function", "case2"}, {"h", fmt(h)}, {"rel_error", "1"}});
    }
    add(data, {{"h_reading", "printed"}, {"volumes", "voronoi"}, {"level", "9"}, {"weight", "quartic_polynomial"},
               {"operator", "grad"}, {"function", "case2"}, {"h", "0.1"}, {"rel_error", "1"}});
    TsvTable out = reasons();
    add_gradient_smoothing_reasons(pub, data, "printed", kRateTolerance, out);
    REQUIRE(out.rows.size() == 1);
    CHECK(out.text(0, "table") == "thesis_table4_3");
    CHECK(out.text(0, "slice") == "printed_voronoi");
    CHECK(out.text(0, "key") == "quartic_polynomial grad case2");
    CHECK(out.text(0, "restores") == "no");  // no run gives the published rate
    return out.text(0, "check");
  };
  SECTION("the error is eps_grad within 1 % and the published rate is out of its reach: pass") {
    CHECK(check(1.005, 0.995, 0.5) == "pass");
  }
  SECTION("a particle part left (2 % above eps_grad at one level): fail") { CHECK(check(1.0, 1.02, 0.5) == "fail"); }
  SECTION("the published rate within the tolerance of eps_grad's: fail") { CHECK(check(1.0, 1.0, 0.1) == "fail"); }
  SECTION("a weight at one rate level only gives no row") {
    TsvTable pub = table({"weight", "operator", "function", "numerical"}, "10,11");
    add(pub, {{"weight", "quartic_polynomial"}, {"operator", "grad"}, {"function", "case2"}, {"numerical", "2.16"}});
    TsvTable data = table({"h_reading", "volumes", "level", "weight", "operator", "function", "h", "rel_error"});
    add(data, {{"h_reading", "printed"}, {"volumes", "voronoi"}, {"level", "10"}, {"weight", "quartic_polynomial"},
               {"operator", "grad"}, {"function", "case2"}, {"h", fmt(h10)}, {"rel_error", fmt(e10)}});
    TsvTable out = reasons();
    add_gradient_smoothing_reasons(pub, data, "printed", kRateTolerance, out);
    CHECK(out.rows.empty());
  }
}

TEST_CASE("checked reasons: Table 4.2's interpolant smoothing part", "[unit][checked_reasons]") {
  // cubic_spike's interpolant error at 2^-11 and 2^-12 is its closed-form smoothing part
  // divided by share11, share12; the published rate lies `offset` from the smoothing part's.
  const double h11 = 0.02, h12 = 0.01;
  const WeightFunction& w = weight("cubic_spike");
  const double s11 = interpolant_smoothing_error_case1(w, h11), s12 = interpolant_smoothing_error_case1(w, h12);
  const double rate_smoothing = two_level_rate(h11, s11, h12, s12);
  auto check = [&](double share11, double share12, double offset) {
    TsvTable pub = table({"weight", "function", "numerical"}, "11,12");
    add(pub, {{"weight", "cubic_spike"}, {"function", "case1"}, {"numerical", fmt(rate_smoothing + offset)}});
    TsvTable data = table({"h_reading", "volumes", "level", "weight", "operator", "function", "h", "rel_error"});
    add(data, {{"h_reading", "scaled"}, {"volumes", "voronoi"}, {"level", "11"}, {"weight", "cubic_spike"},
               {"operator", "interp"}, {"function", "case1"}, {"h", fmt(h11)}, {"rel_error", fmt(s11 / share11)}});
    add(data, {{"h_reading", "scaled"}, {"volumes", "voronoi"}, {"level", "12"}, {"weight", "cubic_spike"},
               {"operator", "interp"}, {"function", "case1"}, {"h", fmt(h12)}, {"rel_error", fmt(s12 / share12)}});
    TsvTable out = reasons();
    add_interpolant_smoothing_reasons(pub, data, "scaled", kRateTolerance, out);
    REQUIRE(out.rows.size() == 1);
    CHECK(out.text(0, "slice") == "scaled_voronoi");
    CHECK(out.text(0, "key") == "cubic_spike case1");
    CHECK(out.text(0, "restores") == "no");
    CHECK(out.text(0, "evidence").rfind("smoothing part / error " + format_share(share11) + " at 2^-11, ", 0) == 0);
    return out.text(0, "check");
  };
  // share 0.1 then 0.05: the error falls a whole order slower than the smoothing part.
  SECTION("a small share at both levels, the published rate the smoothing part's: pass") {
    CHECK(check(0.1, 0.05, 0.05) == "pass");
  }
  SECTION("the smoothing part above a fifth of the error at one level: fail") { CHECK(check(0.1, 0.3, 0.0) == "fail"); }
  SECTION("the published rate not the smoothing part's: fail") { CHECK(check(0.1, 0.05, 0.3) == "fail"); }
  SECTION("the measured rate is the smoothing part's too (same share at both levels): fail") {
    CHECK(check(0.1, 0.1, 0.0) == "fail");
  }
}

TEST_CASE("checked reasons: the heat tables' one-mode model", "[unit][checked_reasons]") {
  TsvTable pub = table({"weight", "theta", "numerical"}, "8,9");
  for (const char* w : {"a", "b", "c", "d", "e"}) add(pub, {{"weight", w}, {"theta", "0.5"}, {"numerical", "2.00"}});
  add(pub, {{"weight", "f"}, {"theta", "0.5"}, {"numerical", "unstable"}});
  auto rate = [](const char* key, double ratio_fine, double predicted, std::optional<double> cell) {
    ModeRate r;
    r.key = key, r.reproduced = 3.0, r.predicted = predicted, r.no_mismatch = 2.0, r.cell = cell;
    r.ratio_coarse = 1.0, r.ratio_fine = ratio_fine, r.mismatch_coarse = 0.0013, r.mismatch_fine = -0.002;
    return r;
  };
  const std::vector<ModeRate> rates = {
      rate("a 0.5", 1.05, 3.1, 2.05),        // the model accounts, V_i = dx^2 restores: pass
      rate("b 0.5", 1.05, 3.1, std::nullopt),  // no V_i = dx^2 run: fail
      rate("c 0.5", 1.2, 3.1, 2.05),         // measured/predicted outside [0.9, 1.1]: fail, restores
      rate("d 0.5", 1.0, 3.3, 2.05),         // the predicted rate 0.3 from the reproduced: fail, restores
      rate("e 0.5", 1.0, 3.0, 2.5),          // V_i = dx^2 does not give the published rate: fail
      rate("f 0.5", 1.0, 3.0, 2.0),          // no published number: no row
      rate("g 0.5", 1.0, 3.0, 2.0),          // not published: no row
  };
  TsvTable out = reasons();
  add_heat_mode_reasons("thesis_table4_6", "h10", pub, rates, kRateTolerance, out);
  REQUIRE(out.rows.size() == 5);
  auto at = [&](const char* key, const char* column) { return out.text(row_of(out, key), column); };
  CHECK(at("a 0.5", "check") == "pass");
  CHECK(at("a 0.5", "restores") == "yes");
  CHECK(at("a 0.5", "evidence") ==
        "measured/predicted 1.000, 1.050; rate predicted 3.10, reproduced 3.00; without the mismatch the model gives "
        "2.00; with V_i = dx^2 measured 2.05 (published 2.00)");
  CHECK(at("a 0.5", "reason").find("mu(1+delta)(1-eps): time step") != std::string::npos);
  CHECK(at("a 0.5", "reason").find("+0.13% and -0.20% at the rate levels") != std::string::npos);
  CHECK(at("b 0.5", "check") == "fail");
  CHECK(at("b 0.5", "restores") == "no");
  CHECK(at("b 0.5", "evidence").find("with V_i = dx^2 measured not run (published 2.00)") != std::string::npos);
  CHECK(at("c 0.5", "check") == "fail");
  CHECK(at("c 0.5", "restores") == "yes");
  CHECK(at("d 0.5", "check") == "fail");
  CHECK(at("d 0.5", "restores") == "yes");
  CHECK(at("e 0.5", "check") == "fail");
  CHECK(at("e 0.5", "restores") == "no");
  CHECK(out.text(0, "table") == "thesis_table4_6");
  CHECK(out.text(0, "slice") == "h10");
}

TEST_CASE("checked reasons: a heat table's V_i = dx^2 run counts under the same time step only",
          "[unit][checked_reasons]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("gpm_checked_reasons_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "store");
  fs::create_directories(dir / "published");
  TsvTable pub = table({"weight", "theta", "numerical"}, "8,9");
  add(pub, {{"weight", "quartic_polynomial"}, {"theta", "0.5"}, {"numerical", "2.00"}});
  pub.save((dir / "published" / "thesis_table4_6_long.tsv").string());
  // One series at 2^-8 and 2^-9, run with the given volumes and time-step rule.
  auto heat = [&](const std::string& file, const std::string& volumes, const std::string& steps, double e9) {
    TsvTable t = table({"weight", "theta", "level", "dx", "h", "N", "K", "dt", "rel_error", "blew_up"});
    t.set("volumes", volumes);
    t.set("steps", steps);
    add(t, {{"weight", "quartic_polynomial"}, {"theta", "0.5"}, {"level", "8"}, {"dx", fmt(std::ldexp(1.0, -8))},
            {"h", "0.05"}, {"N", "94249"}, {"K", "100"}, {"dt", "0.001"}, {"rel_error", "0.001"}, {"blew_up", "no"}});
    add(t, {{"weight", "quartic_polynomial"}, {"theta", "0.5"}, {"level", "9"}, {"dx", fmt(std::ldexp(1.0, -9))},
            {"h", "0.025"}, {"N", "378225"}, {"K", "200"}, {"dt", "0.0005"}, {"rel_error", fmt(e9)}, {"blew_up", "no"}});
    t.save((dir / "store" / file).string());
  };
  const std::string fit = "K = ceil(T/dt_nominal), dt = T/K", exact = "dt = dt_nominal";
  heat("thesis_table4_6.tsv", "lattice (|Omega_H|/N)", fit, 0.0003);
  heat("thesis_table4_6_cellvol.tsv", "cell (dx^2)", exact, 0.00025);  // another time step: not this one's
  const auto evidence = [&] {
    const TsvTable out = checked_reasons(StoreSnapshot((dir / "store").string()), (dir / "published").string(), kRateTolerance);
    REQUIRE(out.rows.size() == 1);
    CHECK(out.text(0, "table") == "thesis_table4_6");
    CHECK(out.text(0, "slice") == "h10");
    return out.text(0, "evidence");
  };
  CHECK(evidence().find("with V_i = dx^2 measured not run") != std::string::npos);
  heat("thesis_table4_6_cellvol.tsv", "cell (dx^2)", fit, 0.00025);  // the same rule: its rate 2.00
  CHECK(evidence().find("with V_i = dx^2 measured 2.00 (published 2.00)") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("checked reasons: one row per mechanism", "[unit][checked_reasons]") {
  // The report's fixture (tests/report/fixture/tables/reasons.tsv): reasons that differ only
  // after their first ':' or ';' are one mechanism.
  TsvTable checked = reasons();
  add(checked, {{"table", "t1"}, {"slice", "a"}, {"key", "w1"}, {"reason", "volume mismatch: +0.1% at level 8"},
                {"evidence", "e1"}, {"check", "pass"}, {"restores", "yes"}});
  add(checked, {{"table", "t1"}, {"slice", "a"}, {"key", "w2"}, {"reason", "volume mismatch: -0.2% at level 9"},
                {"evidence", "e2"}, {"check", "fail"}, {"restores", "no"}});
  add(checked, {{"table", "t2"}, {"slice", "b"}, {"key", "w1"}, {"reason", "smoothing part; small"},
                {"evidence", "e3"}, {"check", "pass"}, {"restores", "no"}});
  add(checked, {{"table", "t3"}, {"slice", "c"}, {"key", "w1"}, {"reason", "volume mismatch: x"},
                {"evidence", "e4"}, {"check", "fail"}, {"restores", "yes"}});
  add(checked, {{"table", "t3"}, {"slice", "c"}, {"key", "w2"}, {"reason", "volume mismatch: y"},
                {"evidence", "e5"}, {"check", "fail"}, {"restores", "no"}});
  const TsvTable by = reasons_by_mechanism(checked);
  REQUIRE(by.rows.size() == 2);
  CHECK(by.text(0, "mechanism") == "volume mismatch");
  CHECK(by.text(0, "rows") == "t1 a: 2 rows, 1 pass (w1); t3 c: 2 rows, none pass");
  CHECK(by.text(0, "checked") == "4");
  CHECK(by.text(0, "passed") == "1");
  CHECK(by.text(0, "restores") == "2");  // restores counts whether or not the check passed
  CHECK(by.text(1, "mechanism") == "smoothing part");
  CHECK(by.text(1, "rows") == "t2 b: 1 row, all pass");
  CHECK(by.text(1, "checked") == "1");
  CHECK(by.text(1, "passed") == "1");
  CHECK(by.text(1, "restores") == "0");

  TsvTable no_check = table({"table", "slice", "key", "reason", "restores"});
  CHECK_THROWS_AS(reasons_by_mechanism(no_check), InputError);
}
