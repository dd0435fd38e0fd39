// The weight mixes of the studies' fused truncation passes, read from the study catalog:
// imoto §5 (nine weights, one field) and the thesis' Tables 4.1–4.3 (their weights ×
// operators, two fields: Case 1 and Case 2).  bench_limit measures each mix's limit,
// bench_kernel its pass on the benchmark's particles, so that a pass's rate is read as a
// fraction of the limit of its own mix.
#pragma once
#include <string>
#include <vector>

#include "gpm/kernel/kernel.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/thesis_tables.hpp"
#include "gpm/weights/weights.hpp"

namespace bench {

struct StudyMix {
  std::string name;                        // "imoto9", "thesis4_1", …
  std::vector<gpm::KernelWeight> weights;  // one per distinct weight, its operators merged
  int fields = 1;
};

inline std::vector<StudyMix> study_mixes() {
  std::vector<StudyMix> m;
  m.push_back({"imoto9", gpm::kernel_weights(gpm::imoto_study().requests()), 1});
  for (const auto& t : gpm::thesis_table_specs())
    m.push_back({t.mix(), gpm::kernel_weights(t.requests), static_cast<int>(gpm::thesis_cases().size())});
  return m;
}

}  // namespace bench
