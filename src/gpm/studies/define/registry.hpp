// The study registry: every study of the package as one object.  An entry names
//   * what it is: its program and fixed arguments, the document item, its levels per profile
//     and its data file's columns (the catalog of `gpm study --list`);
//   * what make builds from it: its data files with their arguments and side outputs, and
//     the rate tables cut from them (`gpm study --make` writes build/studies.mk from these:
//     no study list is typed in mk/ or the Makefile);
//   * how the plan prices its units before a run and reads back what a run recorded;
//   * how the committed store's files of the study are cut into slices and judged against
//     its published rates (`gpm store-rates`, verdicts.hpp).
// A study is added by one entry here (its program holds the unit body); the example test
// (tests/unit/test_registry_example.cpp) registers one and checks that the catalog, the
// plan, the make rules and the verdicts all pick it up.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/pricing.hpp"

namespace gpm {

// A rate table made from one data file: rate_table's input, the rows it keeps, its key.
struct RateTableRule {
  std::string name = {};  // written as data/<profile>/<name>.tsv
  std::string input = {};  // the data file (stem) it reads: the study file or a side output
  std::vector<std::pair<std::string, std::string>> where = {};  // rows kept: column = value
  bool scored = false;  // one of the profile's front-page scoreboard tables
};

// A data file a study's program writes in a make run (data/<profile>/<name>.tsv).
struct StudyFile {
  std::string name = {};
  std::vector<std::string> args = {};  // the program's arguments beyond the study's fixed ones
  // Further files the same run writes: (option, file stem), e.g. ("--rates-input",
  // "thesis_table4_5_finite"); make passes them and rate tables may read them.
  std::vector<std::pair<std::string, std::string>> side_outputs = {};
  std::vector<RateTableRule> rates = {};
};

// A file of the study in the committed result store (results/paper/<name>.tsv): how it was
// made, what it must hold and which of its units the store check recomputes
// (tests/store/verify_store.sh reads these from `gpm study --store-files`).
struct StoreFile {
  std::string name = {};
  std::string slice = {};  // its slice's name in the verdicts: all, seed2, h15_cell, …
  std::vector<std::string> args = {};  // the program's arguments beyond the study's fixed ones
  std::vector<std::string> census = {};  // options naming the units it must hold (none: the paper levels)
  std::vector<std::string> coarse = {};  // options naming the cheap units recomputed by the check
  // The set-up readings whose rows it holds, named as PublishedRates::identified_slice names
  // them (a heat file: its one reading; Table 4.4: both h rules of one volume choice); none
  // for a file of another jitter realization.  The per-reading figures find their file here.
  std::vector<std::string> readings = {};
};

// A figure of the document drawn from a study's data: figures/<name>.gp reads the study's
// (first) data file and its published rates.  make draws it from the run's data
// (figures/out/<name>.svg) and from the store (store_<name>.svg); a per-reading figure is
// drawn from the store twice, in the identified reading and in the printed one
// (store_printed_<name>.svg; figures/store_reading.sh draws the file that gpm store-rates
// --figure-files names for each).
struct StudyFigure {
  std::string name = {};  // thesis_fig4_8
  std::vector<std::string> scripts = {};  // further gnuplot files it loads
  bool per_reading = false;
};

// The provenance columns every store row ends with (run/store.hpp seals them).
const std::vector<std::string>& row_provenance_columns();

// A slice of a stored file: the rows of one reading (PdeReading, HReading) and one jitter
// realization, named by both (h15_cell, seed2, h15_cell_exact_seed3); a reading is a set-up as
// the text admits it, a slice is where its rows sit in the store.
struct StoreSlice {
  std::string slice;  // its name in the verdicts: printed_voronoi, h15_cell, seed2, …
  TsvTable data;
};

// The published rates a study is judged against in the store (verdicts.hpp).
struct PublishedRates {
  std::string table = {};  // the verdicts' table name: thesis_table4_2, imoto_table1
  std::string file = {};  // under tables/published/
  std::vector<std::string> key = {};  // columns shared by the data and the published file
  std::string printed_slice = {};  // the slice of the reading the document prints
  // The slice the set-up rule's identified reading selects (setup_identification.hpp);
  // unset: the printed one.
  std::function<std::string(const PdeReading&)> identified_slice = {};
  bool finite_series = false;     // rates from the series that never blew up (heat)
  // How a stored file is cut into slices (one file holding several set-ups); unset: the
  // file is one slice, its StoreFile::slice.
  std::function<std::vector<StoreSlice>(const StoreFile& file, const TsvTable& data)> cut = {};
  // A key column whose value leads the name of a rate's slice (Table 4.4: h_rule, so h10,
  // h15_seed2, h10_cell, …: the file's slice follows unless it is "all"); the rate's key is
  // then the others.  "": none.
  std::string split_by = "";
  // The published rates that are the set-up rule's fingerprint (Table 4.6: theta = 0): a key
  // column and its value.  On the identified board they identify the reading and are not
  // judged (setup_identification.hpp).  Empty: none.
  std::pair<std::string, std::string> setup_fingerprint = {};

  // The columns of a rate's key, in order: `key` less split_by.
  std::vector<std::string> rate_key() const;
};

// One unit of a study: what its program computes at once and caches, the rows keyed by
// `key` (the data file's first columns), at a level and h.  An entry that lists its units
// (RegisteredStudy::units) has one loop for both its program (StudyRunner::units(), in this
// order) and the plan (RegisteredStudy::price, one unit at a time).
struct StudyUnit {
  int level = 0;
  double h = 0;
  std::vector<std::string> key;
  std::string variant;  // the plan's name of it within the level (h10/quartic_polynomial)
  // The part of the study it belongs to where a make run writes one data file per part
  // (heat: the h rule), else empty.
  std::string part = "";
  // Why the profile skips it (a trim of the catalog: priced by the plan, never run); empty:
  // it runs.
  std::string trimmed = "";
};

// Which units a run asks for: the profile and the levels, --levels where given (then every
// part of the study runs at them), else the profile's (a study may trim some of its units
// there, or give its parts levels of their own).
struct UnitScope {
  bool paper = false;
  std::vector<int> levels;
  bool levels_given = false;
};

struct RegisteredStudy {
  std::string name;     // the catalog's name (gpm study NAME)
  std::string program;  // the executable that runs it
  std::vector<std::string> fixed_args;  // e.g. --table 4.6
  std::string item;     // the document item it reproduces
  std::string group;    // make's STUDIES_<group> list (truncation, heat, …)
  ProfileLevels levels;
  std::vector<std::string> columns;  // the data file's own columns
  // The program names its particle sets itself (core_voronoi's --seeds): no --seed, no --parts
  // (StudyRunner::Kind::units_without_seed).  Every study's rows are cached per unit in the
  // result store (store.hpp).
  bool own_seeds = false;
  std::vector<int> recheck_levels;   // the coarse units the paper profile re-checks first
  std::vector<StudyFile> files;      // what a make run writes
  std::vector<StoreFile> store_files;  // what the committed store holds of it
  std::optional<PublishedRates> published;
  std::vector<StudyFigure> figures;
  // The units of a scope, in the order the program computes them (StudyRunner::units()), and
  // `price`, which appends one unit's cost to pricer.units(): the plan prices exactly the
  // units of the profile's levels (plan_units).  Both required (StudyRegistry::add).
  std::function<std::vector<StudyUnit>(const UnitScope& scope)> units;
  std::function<void(UnitPricer& pricer, const StudyUnit& unit)> price;
  // What the data file `file` recorded per (variant, level): seconds and work.
  std::function<void(const std::string& file, const TsvTable& data, const PlannedPairs& planned,
                     RecordedUnits& out)>
      recorded;

  // The header of the data file its program writes: its columns, and for a cached study
  // the provenance of each row (code, made_on, checked).
  std::vector<std::string> header() const;
  // The program's arguments for one of its files: the fixed ones, then the file's.
  std::vector<std::string> command_args(const std::vector<std::string>& file_args) const;
  // The store file holding the rows of a set-up reading (a PdeReading name: h10,
  // h15_cell_exact, …; Table 4.4 ignores the time step); InputError if the reading is unknown
  // or the study stores none of it.
  const StoreFile& store_file_of(const std::string& reading) const;
  // The same lookup without the refusal: none where the study keeps no set-up readings or no
  // file of this one (the judges ask for readings a study may not store).
  const StoreFile* find_store_file_of(const std::string& reading) const;
};

class StudyRegistry {
 public:
  // A study added last; InputError if its name or one of its data files is taken, or it
  // lacks its units or their price.
  void add(RegisteredStudy s);
  const std::vector<RegisteredStudy>& studies() const { return studies_; }
  auto begin() const { return studies_.begin(); }
  auto end() const { return studies_.end(); }
  // By name; InputError naming the valid ones.
  const RegisteredStudy& study(const std::string& name) const;
  // The entry that writes data file `file` in a make run; InputError if none.
  const RegisteredStudy& study_of_file(const std::string& file) const;

 private:
  std::vector<RegisteredStudy> studies_;
};

// The store files of every study: study, file, program, args (the fixed ones first), census,
// coarse, slice (`gpm study --store-files`).
TsvTable store_file_table(const StudyRegistry& registry);

// The package's studies, in plan order.
const StudyRegistry& study_registry();
// The one study whose published rates carry the set-up rule's fingerprint; InputError if
// none or several.
const RegisteredStudy& setup_fingerprint_study(const StudyRegistry& registry);
// The entry that writes data file `file`; InputError if none.
const RegisteredStudy& registered_study_of_file(const std::string& file);


}  // namespace gpm
