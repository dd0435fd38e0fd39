// The store's numbers as typed evidence (issue 57, item 1; first part): a series is an error
// against h per level, read once from a store table with its finite, positive errors, and
// its rate between two levels and its error constant are defined here, once, for every
// judge that takes a series.  Numbers stay numbers until a writer formats them.
//
// So far the rate-against-level judge (rate_levels.hpp), the set-up identification's
// fingerprint rates (setup_identification.hpp) and the error constants (error_constants.hpp)
// read their series and take their rates and constants here; the published-rate join
// (rates.hpp), the checked reasons, the heat mode model and the decisions still read cells.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/registry.hpp"

namespace gpm {

// A cell read as a number, the one reader the judges share: a plain decimal (an optional
// '-', digits and points, an optional exponent) and nothing else; false for NA, an empty
// cell, nan, inf or a word (a document's "unstable").
bool cell_number(const std::string& text, double& value);
// The same, `otherwise` where the cell holds no number.
double cell_number_or(const std::string& text, double otherwise);
// A number for a writer: NA for NaN (what the judges read as no number), else fmt().
std::string number_cell(double v);

// A store file's identity, from its registered arguments (what its program ran with), never
// from its name or its slice's.
// The value of an option in its arguments ("--jitter" → "0"); "" where they do not name it.
std::string file_arg(const StoreFile& f, const std::string& option);
// The jitter realization: --seed, 1 where the arguments name none.
int file_seed(const StoreFile& f);
// The arguments that fix its numbers' set-up: its own, less --seed (the realization) and
// --solver (a path to the same numbers, kStoreSolverPathRelTol apart).
std::vector<std::string> setup_args(const StoreFile& f);
// The solver its rows were computed by: --solver, "" where the arguments name none (plain CG).
std::string file_solver(const StoreFile& f);
// The other jitter realizations of `f`'s set-up and solver: the study's files with f's
// set-up arguments and solver and another seed than f's, in the registry's order.
std::vector<const StoreFile*> realizations_of(const RegisteredStudy& study, const StoreFile& f);
// The file of `f`'s set-up and solver at seed 1 (f itself there); none where the study keeps
// no such file.
const StoreFile* seed_one_of(const RegisteredStudy& study, const StoreFile& f);

// One stored error: the influence radius and the relative error of its level.
struct EvidencePoint {
  double h = 0, error = 0;
};
// A series: level → point, only levels whose error is finite and positive.
using EvidenceSeries = std::map<int, EvidencePoint>;
// A table's series by the values of its key columns (in the order given).
using EvidenceSeriesMap = std::map<std::vector<std::string>, EvidenceSeries>;

// The series of `t` keyed by `keys` (InputError naming the file for a missing column or a
// level or h that is no number); a row whose error is no finite positive number (NA: a
// blown-up series) is left out.
EvidenceSeriesMap read_series(const TsvTable& t, const std::vector<std::string>& keys,
                              const std::string& error = "rel_error");

// The rate between two points, log(e_a/e_b)/log(h_a/h_b): the judges' one rate formula (every
// rate a judge states comes through here).
double point_rate(const EvidencePoint& a, const EvidencePoint& b);
// The same for any quantity of two points that carry h (a member pointer or a function of the
// point): the rate of an error, of its smoothing part, of a prediction.
template <class Point, class Quantity>
double point_rate(const Point& a, const Point& b, Quantity q) {
  return point_rate(EvidencePoint{a.h, std::invoke(q, a)}, EvidencePoint{b.h, std::invoke(q, b)});
}

// The rate log(e_lo/e_hi)/log(h_lo/h_hi) between two stored levels; NaN where the series
// lacks either.
double series_rate(const EvidenceSeries& s, int lo, int hi);

// The error constant e/h^p of a point for the theory's rate p.
double error_constant(const EvidencePoint& pt, double p);

}  // namespace gpm
