// The make rules of the package's studies (build/studies.mk), from the study registry.
#pragma once
#include <string>

#include "gpm/studies/define/registry.hpp"

namespace gpm {

// The make rules of every study (build/studies.mk): the lists STUDIES, STUDIES_<group>,
// STUDY_FILES(_<group>), STUDY_RATES, STUDY_SCORED_RATES, each data file's rule (re-check in
// the paper profile, then the run) and each rate table's rule.
std::string make_rules(const StudyRegistry& registry);

}  // namespace gpm
