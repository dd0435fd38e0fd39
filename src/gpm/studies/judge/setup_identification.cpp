#include "gpm/studies/judge/setup_identification.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

#include "gpm/error.hpp"
#include "gpm/studies/judge/evidence.hpp"
#include "gpm/studies/judge/rates.hpp"
#include "gpm/studies/judge/verdicts.hpp"  // kSeedBandDecides

namespace gpm {

namespace {

// The details in the order they are decided, each with its printed value first, by name:
// the rule compares values of any detail alike.
const std::vector<std::pair<std::string, std::vector<std::string>>> kDetails = {
    {"h_rule", {"h10", "h15"}}, {"volumes", {"lattice", "cell"}}, {"dt_rule", {"fit", "exact"}}};

std::string detail(const PdeReading& r, const std::string& d) {
  return d == "h_rule" ? h_rule_name(r.h_rule) : d == "volumes" ? pde_volumes_name(r.volumes) : dt_rule_name(r.dt_rule);
}

constexpr double kInf = std::numeric_limits<double>::infinity();

// The fingerprint rate of `weight` (rows where column = value: θ = 0) between the levels l1,
// l2, NaN where a level is missing or an error is not a positive finite number.
double setup_fingerprint_rate(const TsvTable& t, const std::pair<std::string, std::string>& fp, const std::string& weight,
                        int l1, int l2) {
  const EvidenceSeriesMap series = read_series(t, {"weight", fp.first});
  const auto s = series.find({weight, fp.second});
  return s == series.end() ? NAN : series_rate(s->second, l1, l2);
}

// The mean over the weights of |ln(rate/published)| of one data file (inf: a rate missing or
// of the other sign); `rates` gets each weight's rate (NaN where none).
double setup_fingerprint_distance(const TsvTable& data, const std::pair<std::string, std::string>& fp,
                            const std::map<std::string, double>& published, int l1, int l2,
                            std::vector<double>* rates = nullptr) {
  double sum = 0;
  for (auto& [w, p] : published) {
    const double rate = data.rows.empty() ? NAN : setup_fingerprint_rate(data, fp, w, l1, l2);
    if (rates) rates->push_back(rate);
    sum += (rate / p > 0) ? std::fabs(std::log(rate / p)) : kInf;
  }
  return sum / static_cast<double>(published.size());
}

// The distances of a reading over its stored jitter realizations: seed 1 (its main file) and
// every stored file of another realization of the reading's file (realizations_of).
struct DistanceBand {
  int seeds = 0;
  double lo = kInf, hi = -kInf;
  void add(double d) { ++seeds, lo = std::min(lo, d), hi = std::max(hi, d); }
};
DistanceBand distance_band(const StoreSnapshot& store, const RegisteredStudy& study, const std::string& reading,
                           double seed1, const std::pair<std::string, std::string>& fp,
                           const std::map<std::string, double>& published, int l1, int l2) {
  DistanceBand b;
  b.add(seed1);
  const StoreFile* file = study.find_store_file_of(reading);
  for (const StoreFile* f : file ? realizations_of(study, *file) : std::vector<const StoreFile*>{})
    if (store.has(f->name + ".tsv")) b.add(setup_fingerprint_distance(store.table(f->name + ".tsv"), fp, published, l1, l2));
  return b;
}

}  // namespace

SetupIdentification identify_setup(const StoreSnapshot& store, const RegisteredStudy& study, const TsvTable& pub) {
  if (!study.published || study.published->setup_fingerprint.first.empty())
    throw InputError("study '" + study.name + "' carries no set-up fingerprint");
  const auto& fp = study.published->setup_fingerprint;
  const auto [l1, l2] = documents_levels(pub);
  std::map<std::string, double> published;
  for (std::size_t i = 0; i < pub.rows.size(); ++i)
    if (pub.text(i, fp.first) == fp.second) published[pub.text(i, "weight")] = pub.number(i, pub.require_column("numerical"));
  if (published.empty()) throw InputError(pub.source + ": no " + fp.first + " = " + fp.second + " rate");

  // --- Every reading: its θ = 0 rates and distance. -----------------------------------------
  // The eight readings, the printed one (h10, lattice, fit) first.
  const std::vector<PdeReading>& readings = pde_readings();
  SetupIdentification id;
  TsvTable& t = id.table;
  t.set("program", "setup_identification");
  t.set("rule", "paper/04-setup-rule.md: details decided in the order h_rule, volumes, dt_rule; a value "
                "is identified when its closest reading is closer by a factor of two than every other "
                "value's; otherwise as printed (h10, lattice, fit)");
  // "Table 4.6, theta = 0": the study's document item without the document's name.
  const std::string item = study.item.substr(study.item.find("Table"));
  t.set("fingerprint", item + ", " + fp.first + " = " + fp.second + ", rates in h between levels " + documents_levels_text(pub));
  t.set("distance", "mean over the weights of |ln(rate/published)|; inf: a rate missing or of the other sign");
  t.set("store", store.dir());
  t.columns = {"reading", "h_rule", "volumes", "dt_rule", "file"};
  for (const auto& entry : published) t.columns.push_back("rate_" + entry.first);
  t.columns.push_back("distance");
  // The uncertainty of a distance: the same distance for every stored jitter realization of
  // the reading (seed 1 and its seed files), as a band.  It does not enter the rule (written
  // before it was asked for); it says whether each decision would stand for any realization.
  for (const char* c : {"seeds", "distance_lo", "distance_hi"}) t.columns.push_back(c);
  t.set("distance_band", "distance over the stored jitter realizations of the reading (seed 1 and its seed files): "
                         "lowest, highest, how many");
  std::map<std::string, double> distance;
  std::map<std::string, DistanceBand> band;
  for (const PdeReading& r : readings) {
    const std::string file = study.store_file_of(r.name()).name + ".tsv";
    std::vector<std::string> row = {r.name(), detail(r, "h_rule"), detail(r, "volumes"), detail(r, "dt_rule"), file};
    const bool present = store.has(file);
    std::vector<double> rates;
    distance[r.name()] = setup_fingerprint_distance(present ? store.table(file) : TsvTable{}, fp, published, l1, l2, &rates);
    for (double rate : rates) {
      row.push_back(std::isnan(rate) ? "NA" : fmt(rate));
      if (std::isnan(rate) && (id.incomplete.empty() || id.incomplete.back() != r.name()))
        id.incomplete.push_back(r.name());
    }
    row.push_back(fmt(distance[r.name()]));
    const DistanceBand& b = band[r.name()] =
        distance_band(store, study, r.name(), distance[r.name()], fp, published, l1, l2);
    row.push_back(fmt(b.seeds)), row.push_back(fmt(b.lo)), row.push_back(fmt(b.hi));
    t.add_row(row);
  }

  // A reading not yet computed could be the closest: no decision until all are there.
  if (!id.incomplete.empty()) {
    t.set("identified", "NA");
    t.set("printed", readings.front().name());
    t.set("incomplete", "no " + fp.first + " = " + fp.second + " rate yet for " + join(id.incomplete, ", ") +
                            ": nothing is identified until every reading has one");
    return id;
  }

  // --- The details, one at a time. ------------------------------------------------------------
  std::vector<PdeReading> left = readings;
  for (auto& [name, values] : kDetails) {
    std::map<std::string, double> best;
    for (auto& v : values) best[v] = kInf;
    for (const PdeReading& r : left) best[detail(r, name)] = std::min(best[detail(r, name)], distance[r.name()]);
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
    // The decision's uncertainty, between the closest reading of the chosen value and the
    // closest of each other value: firm when the chosen one's highest distance is below half
    // the other's lowest, with five realizations of each (kSeedBandDecides, as a seed band of
    // a rate needs); "suggested" when not; with fewer realizations, not assessed.
    auto closest = [&](const std::string& v) {
      const PdeReading* c = nullptr;
      for (const PdeReading& r : left)
        if (detail(r, name) == v && (!c || distance[r.name()] < distance[c->name()])) c = &r;
      return c;
    };
    std::string robust = "yes";
    for (auto& o : values) {
      if (o == chosen) continue;
      const PdeReading *a = closest(chosen), *b = closest(o);
      if (!a || !b) continue;
      const DistanceBand &ba = band[a->name()], &bb = band[b->name()];
      char txt[200];
      if (ba.seeds < kSeedBandDecides || bb.seeds < kSeedBandDecides) {
        std::snprintf(txt, sizeof txt, "not assessed: %d realizations of %s, %d of %s (%d needed)", ba.seeds,
                      a->name().c_str(), bb.seeds, b->name().c_str(), kSeedBandDecides);
        robust = txt;
      } else if (!(2 * ba.hi < bb.lo)) {
        std::snprintf(txt, sizeof txt, "suggested: %s's distances %.3g-%.3g and %s's %.3g-%.3g are not a factor of two apart",
                      a->name().c_str(), ba.lo, ba.hi, b->name().c_str(), bb.lo, bb.hi);
        if (robust == "yes" || robust.rfind("not assessed", 0) == 0) robust = txt;
      } else if (robust == "yes") {
        std::snprintf(txt, sizeof txt, "firm: %s's distances %.3g-%.3g, %s's %.3g-%.3g", a->name().c_str(), ba.lo,
                      ba.hi, b->name().c_str(), bb.lo, bb.hi);
        robust = txt;
      }
    }
    if (robust == "yes") robust = "firm";
    std::erase_if(left, [&](const PdeReading& r) { return detail(r, name) != chosen; });
    t.set("decided_" + name, chosen + " (" + why + ")");
    t.set("robust_" + name, robust);
    id.decisions += (id.decisions.empty() ? "" : ", ") + name + " = " + chosen;
  }
  id.identified = left.front();
  t.set("identified", id.identified->name());
  t.set("printed", readings.front().name());
  return id;
}

}  // namespace gpm
