#include "gpm/studies/judge/open_causes.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "gpm/studies/judge/rates.hpp"

namespace gpm {

namespace {

std::string two(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

// A stored reading of the same published rate that is not a jitter realization of another
// reading (those make the band) and not the open rate's own slice.
bool other_reading(const JudgedRate& j, const JudgedRate& open) {
  return j.rate.table == open.rate.table && j.rate.key == open.rate.key && j.rate.slice != open.rate.slice &&
         j.rate.setup != kJitterSetup && j.rate.seed == 1;
}

}  // namespace

bool open_on_identified_board(const JudgedRate& j) {
  return j.identified && verdict_open(j.verdict_identified);
}

OpenCause open_cause(const JudgedRate& open, const std::vector<JudgedRate>& judged, double tolerance) {
  const double published = open.rate.published, ours = open.rate.reproduced;
  const bool has_published = std::isfinite(published);
  std::string evidence = "published " + fmt(published);
  if (std::isfinite(ours)) evidence += ", ours " + two(ours);
  if (open.band_seeds >= 2)
    evidence += ", band " + two(open.band_lo) + " to " + two(open.band_hi) + " (" + std::to_string(open.band_seeds) +
                " seeds)";

  // The other readings: which give the published rate, and which comes nearest.
  std::string agreeing, nearest;
  double nearest_gap = INFINITY;
  for (const JudgedRate& j : judged) {
    const double rate = j.rate.reproduced;
    if (!has_published || !other_reading(j, open) || !std::isfinite(rate)) continue;
    const double gap = std::fabs(rate - published);
    if (gap <= tolerance) agreeing += (agreeing.empty() ? "" : ", ") + j.rate.slice;
    if (gap < nearest_gap) nearest_gap = gap, nearest = j.rate.slice + " " + two(rate);
  }
  if (!nearest.empty()) evidence += "; nearest other reading " + nearest;

  if (open.verdict_identified == Verdict::sign_only) return {"blow-up rate: both unstable, sign only", evidence};
  if (!agreeing.empty()) return {"another reading gives it: " + agreeing, evidence};
  if (has_published && open.band_seeds >= kSeedBandDecides && (published < open.band_lo || published > open.band_hi))
    return {std::string("robust gap: every realization ") + (published < open.band_lo ? "above" : "below") +
                " the published rate",
            evidence};
  return {"one realization: too few seeds to tell", evidence};
}

TsvTable open_causes(const std::vector<JudgedRate>& judged, double tolerance) {
  // One group per (table, cause): its rates counted and its keys and evidence gathered while
  // they are numbers and lists, written as cells once at the end.
  struct Group {
    std::string table = {}, cause = {};
    int rates = 0;
    std::string keys = {}, evidence = {};
  };
  std::vector<Group> groups;
  std::map<std::pair<std::string, std::string>, std::size_t> group_of;
  for (const JudgedRate& j : judged) {
    if (!open_on_identified_board(j)) continue;
    const OpenCause c = open_cause(j, judged, tolerance);
    const auto place = std::make_pair(j.rate.table, c.cause);
    auto it = group_of.find(place);
    if (it == group_of.end()) {
      it = group_of.emplace(place, groups.size()).first;
      groups.push_back(Group{.table = j.rate.table, .cause = c.cause});
    }
    Group& g = groups[it->second];
    ++g.rates;
    g.keys += (g.keys.empty() ? "" : ", ") + j.rate.key;
    g.evidence += (g.evidence.empty() ? "" : "; ") + j.rate.key + ": " + c.evidence;
  }
  TsvTable t;
  t.columns = {"table", "cause", "rates", "keys", "evidence"};
  for (const Group& g : groups) {
    TsvRow row = t.named_row();
    row["table"] = g.table, row["cause"] = g.cause, row["rates"] = std::to_string(g.rates);
    row["keys"] = g.keys, row["evidence"] = g.evidence;
    t.add_row(row);
  }
  return t;
}

}  // namespace gpm
