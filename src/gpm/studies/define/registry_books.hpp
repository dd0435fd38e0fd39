// The registry's bookkeeping half (registry.hpp): for each study, the data files a make run
// writes and the rate tables cut from them, the files the result store holds (readings, seeds,
// census and coarse levels), the published rates it is judged against, its figures, and how
// the plan prices its units and reads back what a run recorded.  None of this decides a
// number a row stores, so this file is out of the code fingerprints (cmake/fingerprint.cmake):
// a seed, a figure, a store file or a price changed here re-stamps no stored row.  What does
// decide numbers — each study's program, levels, columns and units (level, h, key) — is
// registry.cpp's, and in the fingerprints.
#pragma once
#include <string>

#include "gpm/geometry/influence_radius.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry.hpp"
#include "gpm/studies/define/thesis_tables.hpp"

namespace gpm {

// Each fills the bookkeeping fields of its study's entry (files, store_files, published,
// figures, price, recorded); registry.cpp calls it after the entry's definition.
void imoto_books(RegisteredStudy& s);
void truncation_books(RegisteredStudy& s, const ThesisTableSpec& t);
void poisson_books(RegisteredStudy& s);
void heat_books(RegisteredStudy& s, const HeatTable& hp);
void poisson_diagnostic_books(RegisteredStudy& s);
void voronoi_books(RegisteredStudy& s);

// The data file of a heat table under an h rule (the catalog's two readings; registry.cpp).
std::string heat_file(const HeatTable& hp, HRule rule);

}  // namespace gpm
