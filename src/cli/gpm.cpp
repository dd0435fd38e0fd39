// gpm — the common core on the command line, for ad hoc studies, and the commands that keep
// and judge the result store.  The subcommands are listed once, in kSubcommands below (name,
// one line of help, function); `gpm --help` prints that list.  Every subcommand has --help;
// those that judge the store write to the files they are given, the others TSV to stdout (a
// `# key = value` header, then columns).  Errors are one line on stderr and a non-zero exit.
//
// The subcommands live in src/cli/*.cpp (commands.hpp declares them).
#include <algorithm>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "gpm/error.hpp"

using namespace gpm;
using namespace gpm::cli;

namespace {

struct Subcommand {
  const char* name;
  const char* help;
  int (*run)(int, char**);
};

const Subcommand kSubcommands[] = {
    {"weights", "weight functions and their computed properties", cmd_weights},
    {"particles", "a jittered-grid distribution", cmd_particles},
    {"voronoi", "Voronoi cell areas, covering distances and r_c", cmd_voronoi},
    {"trunc", "relative l-infinity error of an operator", cmd_trunc},
    {"poisson", "one discrete Poisson problem: error, where it sits, CG counts", cmd_poisson},
    {"heat", "one discrete heat problem (theta-method): error (4.2), steps, CG counts", cmd_heat},
    {"smoothing", "the Laplacian's smoothing error for a Fourier mode (no particles)", cmd_smoothing},
    {"fingerprint", "the code fingerprint of programs (result-store rows)", cmd_fingerprint},
    {"store-seal", "seal result-store files (unsealed ones; or sealed before the seal covered `checked`)",
     cmd_store_seal},
    {"store-add-columns", "add a column with one value to stored rows made before it existed",
     cmd_store_add_columns},
    {"store-rates", "the documents' rates judged against the result store: verdicts, boards", cmd_store_rates},
    {"rate-levels", "the heat and Poisson rates at every pair of stored levels: toward the theory?", cmd_rate_levels},
    {"checked-reasons", "the reasons for differing rates, each checked against the result store",
     cmd_checked_reasons},
    {"verdicts", "page one of the report: a verdict per figure and table of the documents", cmd_verdicts},
    {"decisions", "the documents' open set-up questions with the result store's evidence", cmd_decisions},
    {"study", "the study catalog: --list, --make FILE (the make rules), or run one study by name", cmd_study},
};

int dispatch(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << "usage: gpm SUBCOMMAND [options]   (gpm SUBCOMMAND --help for its options)\n";
    for (const Subcommand& s : kSubcommands) {
      std::string name = s.name;
      name.resize(std::max<std::size_t>(name.size() + 1, 12), ' ');
      std::cout << "  " << name << s.help << "\n";
    }
    return argc < 2 ? 2 : 0;
  }
  const std::string sub = argv[1];
  std::string valid;
  for (const Subcommand& s : kSubcommands) {
    if (sub == s.name) return s.run(argc, argv);
    valid += (valid.empty() ? "" : ", ") + std::string(s.name);
  }
  throw InputError("unknown subcommand '" + sub + "'; valid: " + valid);
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("gpm", dispatch, argc, argv); }
