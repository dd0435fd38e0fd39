// setup_identification — the rule of paper/04-setup-rule.md applied to the result store: which
// reading of the thesis' Chapter 4 set-up (h rule, volumes, time-step rule) the documents' own
// fingerprint identifies.
//
// The fingerprint: Table 4.6's published θ = 0 rates (explicit Euler with Δt = 0.5h², which
// is unstable).  Run to T without a growth guard, the error grows by a factor g per step that
// hardly depends on h, so the two-level rate ≈ −(K₉ − K₈)·ln g / ln(h₈/h₉) counts the steps
// K = ⌈T/Δt₀⌉ and so fixes h (and, through g, Δt and the volumes slightly).  These rates do
// not measure the convergence the other tables judge.
//
// For each of the eight readings stored (thesis_table4_6{,_h15}{,_dtexact}{,_cellvol}.tsv):
// the θ = 0 rate of each weight at 2^-8/2^-9, and the distance to the published rates, the
// mean over the weights of |ln(r/r_published)| (a rate of the other sign or none: infinitely
// far).  Then the details are decided one at a time (h rule, volumes, time-step rule): a
// value is identified when its closest reading is closer by a factor of two than the closest
// reading of every other value; otherwise the detail stays as printed.
//
//   setup_identification --store results/paper --published tables/published/thesis_table4_6_long.tsv
//     --out data/paper/setup_identification.tsv
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/norms.hpp"
#include "gpm/studies/heat_tables.hpp"

using namespace gpm;

namespace {

// One reading of the set-up (h rule, volumes, time step): HeatReading (heat_tables.hpp),
// whose file_suffix() names its store file.
using Reading = HeatReading;
std::string reading_file(const Reading& r, const std::string& table) {
  return "thesis_table" + table + r.file_suffix() + ".tsv";
}

// The details in the order they are decided, each with its printed value first.
const std::vector<std::pair<std::string, std::vector<std::string>>> kDetails = {
    {"h_rule", {"h10", "h15"}}, {"volumes", {"lattice", "cell"}}, {"dt_rule", {"fit", "exact"}}};

const std::string& detail(const Reading& r, const std::string& d) {
  return d == "h_rule" ? r.h_rule : d == "volumes" ? r.volumes : r.dt_rule;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

// The θ = 0 rate of `weight` between the levels of `levels`, NaN where a level is missing or
// an error is not a positive finite number.
double theta0_rate(const TsvTable& t, const std::string& weight, int l1, int l2) {
  double h[2] = {NAN, NAN}, e[2] = {NAN, NAN};
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (t.text(i, "weight") != weight || t.text(i, "theta") != "0") continue;
    const long long k = t.integer(i, t.require_column("level"));
    const int slot = k == l1 ? 0 : k == l2 ? 1 : -1;
    if (slot < 0 || t.text(i, "rel_error") == "NA") continue;
    h[slot] = t.number(i, t.require_column("h"));
    e[slot] = t.number(i, t.require_column("rel_error"));
  }
  if (!(e[0] > 0 && e[1] > 0 && std::isfinite(e[0]) && std::isfinite(e[1]))) return NAN;
  return two_level_rate(h[0], e[0], h[1], e[1]);
}

int body(int argc, char** argv) {
  Args a("setup_identification",
         "Which reading of the thesis' Chapter 4 set-up the published theta = 0 rates of\n"
         "Table 4.6 identify (paper/04-setup-rule.md), from the result store (TSV).");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published/thesis_table4_6_long.tsv", "Table 4.6's published rates")
      .output("out", "", "output TSV (required)");
  a.parse(argc, argv);
  const std::string out = a.required("out"), store = a.str("store");
  const TsvTable pub = TsvTable::load(a.str("published"));
  const auto levels_text = pub.get("rate_levels").value_or("");
  int l1 = 0, l2 = 0;
  if (std::sscanf(levels_text.c_str(), "%d,%d", &l1, &l2) != 2)
    throw InputError(a.str("published") + ": no '# rate_levels = A,B' line");
  std::map<std::string, double> published;
  for (std::size_t i = 0; i < pub.rows.size(); ++i)
    if (pub.text(i, "theta") == "0") published[pub.text(i, "weight")] = pub.number(i, pub.require_column("numerical"));
  if (published.empty()) throw InputError(a.str("published") + ": no theta = 0 rate");

  // --- Every reading: its θ = 0 rates and distance. -----------------------------------------
  const std::vector<Reading> readings =
      heat_reading_matrix(kDetails[0].second, kDetails[1].second, kDetails[2].second);
  TsvTable t;
  t.set("program", "setup_identification");
  t.set("rule", "paper/04-setup-rule.md: details decided in the order h_rule, volumes, dt_rule; a value "
                "is identified when its closest reading is closer by a factor of two than every other "
                "value's; otherwise as printed (h10, lattice, fit)");
  t.set("fingerprint", "Table 4.6, theta = 0, rates in h between levels " + levels_text);
  t.set("distance", "mean over the weights of |ln(rate/published)|; inf: a rate missing or of the other sign");
  t.set("store", store);
  t.columns = {"reading", "h_rule", "volumes", "dt_rule", "file"};
  for (const auto& entry : published) t.columns.push_back("rate_" + entry.first);
  t.columns.push_back("distance");
  std::map<std::string, double> distance;
  std::vector<std::string> incomplete;  // readings without a θ = 0 rate for some weight
  for (const Reading& r : readings) {
    const std::string path = store + "/" + reading_file(r, "4_6");
    std::vector<std::string> row = {r.name(), r.h_rule, r.volumes, r.dt_rule, reading_file(r, "4_6")};
    double sum = 0;
    const bool present = std::filesystem::exists(path);
    const TsvTable data = present ? TsvTable::load(path) : TsvTable{};
    for (auto& [w, p] : published) {
      const double rate = present ? theta0_rate(data, w, l1, l2) : NAN;
      row.push_back(std::isnan(rate) ? "NA" : fmt(rate));
      if (std::isnan(rate) && (incomplete.empty() || incomplete.back() != r.name())) incomplete.push_back(r.name());
      sum += (rate / p > 0) ? std::fabs(std::log(rate / p)) : kInf;
    }
    distance[r.name()] = sum / static_cast<double>(published.size());
    row.push_back(fmt(distance[r.name()]));
    t.add_row(row);
  }

  // A reading not yet computed could be the closest: no decision until all are there.
  if (!incomplete.empty()) {
    std::string names;
    for (auto& n : incomplete) names += (names.empty() ? "" : ", ") + n;
    t.set("identified", "NA");
    t.set("printed", readings.front().name());
    t.set("incomplete", "no theta = 0 rate yet for " + names + ": nothing is identified until every reading has one");
    add_provenance(t);
    t.save(out);
    std::printf("setup_identification: undecided, %zu readings still without a rate (%s); wrote %s\n",
                incomplete.size(), names.c_str(), out.c_str());
    return 0;
  }

  // --- The details, one at a time. ------------------------------------------------------------
  std::vector<Reading> left = readings;
  std::string decisions;
  Reading identified;
  for (auto& [name, values] : kDetails) {
    std::map<std::string, double> best;
    for (auto& v : values) best[v] = kInf;
    for (const Reading& r : left) best[detail(r, name)] = std::min(best[detail(r, name)], distance[r.name()]);
    std::string chosen = values.front();  // as printed unless a value stands out
    std::string why = "as printed: no value is closer than the others by a factor of two";
    for (auto& v : values) {
      bool stands_out = std::isfinite(best[v]);
      for (auto& o : values)
        if (o != v && !(2 * best[v] < best[o])) stands_out = false;
      if (stands_out) {
        chosen = v;
        char b[160];
        std::snprintf(b, sizeof b, "identified: closest distance %.3g against %.3g for the other value", best[v],
                      best[values[0] == v ? values[1] : values[0]]);
        why = b;
      }
    }
    std::erase_if(left, [&](const Reading& r) { return detail(r, name) != chosen; });
    t.set("decided_" + name, chosen + " (" + why + ")");
    decisions += (decisions.empty() ? "" : ", ") + name + " = " + chosen;
  }
  identified = left.front();
  t.set("identified", identified.name());
  t.set("printed", readings.front().name());
  add_provenance(t);
  t.save(out);
  std::printf("setup_identification: %s identified (%s); wrote %s\n", identified.name().c_str(),
              decisions.c_str(), out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return run_main("setup_identification", body, argc, argv); }
