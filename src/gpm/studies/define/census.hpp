// Which rows the result store must hold (its census), and nothing else: which readings and
// jitter seeds of a table are stored files, and the levels each file must hold, beyond the
// profile's.  No number a row stores depends on these lists, so this file stays out of the
// code fingerprints (cmake/fingerprint.cmake): a level or seed added to the store, as it
// lands, leaves every stored row current.  The registry (registry.cpp) turns them into its
// store files.
#pragma once
#include <string>
#include <vector>

namespace gpm {

// A heat table's reading the store holds (a reading's name, heat_tables.hpp) with the levels
// its file must hold ("" for the table's paper levels).
struct HeatStoreReading {
  std::string reading, census;
};
// The printed reading and h15 at the paper levels, the others at 2^-5 and the rate levels,
// Table 4.6 at every level under each time step (its θ = 0 rates are the set-up rule's
// fingerprint, setup_identification), and the identified reading (h15, V_i = Δx², Δt = Δt₀)
// at every level of Tables 4.5 and 4.6.
std::vector<HeatStoreReading> heat_store_readings(const std::string& table);

// The seeds beside seed 1 stored for a heat table's reading, at level 5 and the table's rate
// levels (the seed bands of the verdicts and of the set-up identification).
std::vector<std::string> heat_band_seeds(const std::string& table, const std::string& reading);

// The levels a file stores past the documents' finest (the thesis' conjecture, that its rates
// had not reached the asymptotic regime: gpm rate-levels), and the band seeds stored at the
// first of them too.  No published value exists there: the boards never use these rows.
struct StoreBeyond {
  std::vector<int> levels;
  std::vector<std::string> seeds;
  // The levels past the documents that the file of `seed` (2, 3, ...) holds: {levels.front()}
  // for the seeds named, none for the others (their census stops at the documents' levels).
  // Seed 1's file holds all of `levels`.
  std::vector<int> levels_for(const std::string& seed) const;
};
StoreBeyond heat_beyond(const std::string& table, const std::string& reading);
// Table 4.4 under V_i = Δx² (both h rules, one file): the levels past the thesis' 2^-9.
StoreBeyond poisson_beyond();

// A census' comma-separated levels with `more` appended ("5,8,9" + {10} → "5,8,9,10").
std::string with_levels(std::string census, const std::vector<int>& more);

}  // namespace gpm
