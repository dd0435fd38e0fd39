// The study registry: each study of the plan as one object — the data files it writes, how
// its units are priced before a run, and how a data file records what each unit cost.  The
// plan (plan_units, planned_studies), the plan-vs-actual comparison (recorded_units) and the
// tests read it; a study added here is priced and compared with no other list to edit.
// (The study programs, the catalog of `gpm study` and make still keep their own lists: the
// registry is to absorb them, one at a time.)
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "gpm/io/tsv.hpp"
#include "gpm/studies/study_plan.hpp"

namespace gpm {

struct RegisteredStudy {
  std::string name;                // the study (its catalog name)
  std::vector<std::string> files;  // the data files it writes, as the plan names its units
  // Appends the units of the profile (pricer.paper()) to pricer.units().
  std::function<void(UnitPricer& pricer)> plan;
  // What the data file `files[i]` recorded per (variant, level): seconds and work.
  std::function<void(const std::string& file, const TsvTable& data, const PlannedPairs& planned,
                     RecordedUnits& out)>
      recorded;
};

// Every modelled study, in plan order.
const std::vector<RegisteredStudy>& study_registry();
// The entry that writes data file `file`; InputError if none.
const RegisteredStudy& registered_study_of_file(const std::string& file);

}  // namespace gpm
