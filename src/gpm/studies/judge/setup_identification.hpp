// The rule of paper/04-setup-rule.md applied to the result store: which reading of the thesis'
// Chapter 4 set-up (h rule, volumes, time-step rule) the documents' own fingerprint identifies.
// setup_identification writes it to a file; gpm store-rates (verdicts.hpp) takes Chapter 4's
// identified board from it.
//
// The fingerprint: Table 4.6's published θ = 0 rates (explicit Euler with Δt = 0.5h², which
// is unstable).  Run to T without a growth guard, the error grows by a factor g per step that
// hardly depends on h, so the two-level rate ≈ −(K₉ − K₈)·ln g / ln(h₈/h₉) counts the steps
// K = ⌈T/Δt₀⌉ and so fixes h (and, through g, Δt and the volumes slightly).  These rates do
// not measure the convergence the other tables judge.
//
// The study and its key column come from the registry (setup_fingerprint_study: the one whose
// PublishedRates::fingerprint is set, Table 4.6's theta = 0).  For each of the eight
// readings, its store file (RegisteredStudy::store_file_of: thesis_table4_6{,_h15}{,_dtexact}
// {,_cellvol}.tsv):
// the θ = 0 rate of each weight at the published rate levels, and the distance to the
// published rates, the mean over the weights of |ln(r/r_published)| (a rate of the other sign
// or none: infinitely far).  Then the details are decided one at a time (h rule, volumes,
// time-step rule): a value is identified when its closest reading is closer by a factor of two
// than the closest reading of every other value; otherwise the detail stays as printed.  A
// reading not yet computed could be the closest: nothing is identified until all are there.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/judge/snapshot.hpp"

namespace gpm {

struct SetupIdentification {
  // One row per reading (its rates and distance); header lines naming the rule, each decided
  // detail with its reason, `identified` (a reading's name, or NA) and `printed`.  No
  // provenance: the caller adds it when it writes the table.
  TsvTable table;
  std::optional<PdeReading> identified;  // none while a reading has no θ = 0 rate yet
  std::vector<std::string> incomplete;    // the readings without a θ = 0 rate for some weight
  std::string decisions;                  // "h_rule = h15, volumes = cell, dt_rule = exact"
};

// From the store's Table 4.6 files and the published rates (their rate_levels, their θ = 0
// rows).  InputError for a published file without rate_levels or θ = 0 rates, or a store file
// that cannot be read.
// `study`: the fingerprint's study (its published file is `published`).
SetupIdentification identify_setup(const StoreSnapshot& store, const RegisteredStudy& study, const TsvTable& published);

}  // namespace gpm
