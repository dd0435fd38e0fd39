// The studies' parameters, defined once: levels per profile, weights, orders, columns.  The
// programs run them, and the study registry (registry.hpp) names every study with these
// (the thesis' truncation and heat tables keep theirs in thesis_tables.hpp and
// heat_tables.hpp).  Adding a level to a study is one edit here: its program, the plan, make
// and the tests follow.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "gpm/geometry/volumes.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/studies/define/profile.hpp"

namespace gpm {

// Levels k (Δx = 2^-k) per profile.
struct ProfileLevels {
  std::vector<int> quick, paper;
  const std::vector<int>& of(Profile p) const { return pick(p, quick, paper); }
  // "quick (levels 5-10) or paper (levels 5-12)": the --profile help of every program.
  std::string help() const;
};

// imoto §5 (Figure 5, Table 1): v = sin 2π(x+y), the nine reference weights, each for its
// operator, h_N = 2.6·2^(5/m−5)·Δx^(1/m) for the regular orders m.
struct ImotoWeight {
  std::string weight;    // registry name, the document's label: Pi1 … Lap3
  Operator op;
  std::string op_label;  // the data file's `operator` column
};
struct ImotoStudy {
  ProfileLevels levels;
  std::vector<double> orders;        // m
  std::string function;              // test-function registry name
  std::vector<ImotoWeight> weights;  // all in one fused pass per (level, m)
  std::vector<uint64_t> paper_seeds;  // the seed ensemble stored at paper scale
  std::vector<std::string> columns;  // of its data file; the first two are the unit's key
  std::vector<ErrorRequest> requests() const;
};
const ImotoStudy& imoto_study();

// The weights of the thesis' PDE problems (§4.2–4.3: Tables 4.4–4.7, the stability and
// volume diagnostics): quartic, piecewise cubic and piecewise quintic polynomial.
const std::vector<std::string>& pde_weights();

// Table 4.4 (the discrete Poisson problem), under both readings of h (influence_radius.hpp).
struct PoissonTable {
  ProfileLevels levels;
  std::string rate_levels;  // the thesis' rate levels
  std::vector<std::string> columns;  // of its data file; the first three are the unit's key
};
const PoissonTable& poisson_table();

// thesis_poisson_diagnostic: Table 4.4's Poisson problem on several particle sets, with
// where its error sits and the operator's consistency (why the table's rates differ).
// One of its particle sets: a jitter realization (seed, amplitude as a fraction of dx; 0 the
// plain grid) with the volumes V_i of (A.10) or V_i = dx^2.
struct ParticleSet {
  std::string name;
  std::uint64_t seed = 1;
  double jitter = 0;
  PdeVolumes volumes = PdeVolumes::lattice;
};
struct PoissonDiagnostic {
  ProfileLevels levels;               // the thesis' rate levels are 8, 9
  std::vector<ParticleSet> variants;  // its particle sets
  std::vector<std::string> columns;   // of its data file; the first four are the unit's key
  std::vector<std::string> variant_names() const;
  // The particle set of that name; an InputError naming it and the known ones.
  const ParticleSet& variant(const std::string& name) const;
};
const PoissonDiagnostic& poisson_diagnostic();

// core_voronoi: Voronoi cells of the plain and jittered grids (covering radius, areas).
struct VoronoiStudy {
  ProfileLevels levels;
  std::vector<int> seeds;  // the jittered grid's seeds (the plain grid runs once per level)
  std::vector<std::string> columns;  // of its data file
  std::string seeds_option() const;  // "1,2,3": the default of --seeds
};
const VoronoiStudy& voronoi_study();

}  // namespace gpm
