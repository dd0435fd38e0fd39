// gpm — the common core on the command line, for ad hoc studies.
//
//   gpm weights     the weight-function registry with computed properties
//   gpm particles   a jittered-grid distribution
//   gpm voronoi     Voronoi cell areas and covering distances, r_c
//   gpm trunc       relative ℓ∞ error of one operator at one resolution
//   gpm poisson, gpm heat, gpm smoothing   one PDE problem or one smoothing error
//   gpm study       the study catalog: list the studies, or run one by name
//   gpm store-rates the documents' rates judged against the result store (verdicts, boards;
//                   written to the files it is given, not to stdout)
//   gpm checked-reasons  the reasons for differing rates, each checked against the store
//                   (written to the files it is given, not to stdout)
//   gpm verdicts    page one of the report: a verdict per document item (written to --out)
//   gpm decisions   the documents' open set-up questions with the store's evidence (to --out)
//
// Every subcommand writes TSV to stdout (a `# key = value` header, then columns) and
// has --help.  Errors are one line on stderr and a non-zero exit.
//
// The subcommands live in src/cli/*.cpp (commands.hpp lists them).
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "gpm/error.hpp"

using namespace gpm;
using namespace gpm::cli;

namespace {

int dispatch(int argc, char** argv) {
  const std::string usage =
      "usage: gpm SUBCOMMAND [options]   (gpm SUBCOMMAND --help for its options)\n"
      "  weights     weight functions and their computed properties\n"
      "  particles   a jittered-grid distribution\n"
      "  voronoi     Voronoi cell areas, covering distances and r_c\n"
      "  trunc       relative l-infinity error of an operator\n"
      "  poisson     one discrete Poisson problem: error, where it sits, CG counts\n"
      "  heat        one discrete heat problem (theta-method): error (4.2), steps, CG counts\n"
      "  smoothing   the Laplacian's smoothing error for a Fourier mode (no particles)\n"
      "  fingerprint the code fingerprint of programs (result-store rows)\n"
      "  store-seal  seal result-store files (unsealed ones; or sealed before the seal covered `checked`)\n"
      "  store-add-columns  add a column with one value to stored rows made before it existed\n"
      "  store-rates the documents' rates judged against the result store: verdicts, boards\n"
      "  rate-levels the heat tables' rates at every pair of stored levels: toward the theory?\n"
      "  checked-reasons  the reasons for differing rates, each checked against the result store\n"
      "  verdicts    page one of the report: a verdict per figure and table of the documents\n"
      "  decisions   the documents' open set-up questions with the result store's evidence\n"
      "  study       the study catalog: --list, or run one study by name\n";
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << usage;
    return argc < 2 ? 2 : 0;
  }
  const std::string sub = argv[1];
  if (sub == "weights") return cmd_weights(argc, argv);
  if (sub == "particles") return cmd_particles(argc, argv);
  if (sub == "voronoi") return cmd_voronoi(argc, argv);
  if (sub == "trunc") return cmd_trunc(argc, argv);
  if (sub == "poisson") return cmd_poisson(argc, argv);
  if (sub == "heat") return cmd_heat(argc, argv);
  if (sub == "smoothing") return cmd_smoothing(argc, argv);
  if (sub == "fingerprint") return cmd_fingerprint(argc, argv);
  if (sub == "study") return cmd_study(argc, argv);
  if (sub == "store-seal") return cmd_store_seal(argc, argv);
  if (sub == "store-add-columns") return cmd_store_add_columns(argc, argv);
  if (sub == "store-rates") return cmd_store_rates(argc, argv);
  if (sub == "rate-levels") return cmd_rate_levels(argc, argv);
  if (sub == "checked-reasons") return cmd_checked_reasons(argc, argv);
  if (sub == "verdicts") return cmd_verdicts(argc, argv);
  if (sub == "decisions") return cmd_decisions(argc, argv);
  throw InputError("unknown subcommand '" + sub + "'; valid: weights, particles, voronoi, trunc, poisson, "
                   "heat, smoothing, fingerprint, study, store-seal, store-add-columns, store-rates, rate-levels, checked-reasons, verdicts, decisions");
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("gpm", dispatch, argc, argv); }
