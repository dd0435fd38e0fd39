// The gpm subcommands (src/cli/*.cpp), each `int cmd_NAME(argc, argv)` with argv[1] the
// subcommand's name, and what they share: a table to stdout, a header naming the options.
#pragma once
#include <string>

#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"

namespace gpm::cli {

// The table to stdout; a failed write (a full disk) stops the subcommand with the reason.
void print(const TsvTable& t);
// A header naming the subcommand (gpm SUB), every option's value and the provenance.
TsvTable header_from(const Args& a, const std::string& sub);
const char* yes(bool b);

// The core on the command line (core_commands.cpp).
int cmd_weights(int argc, char** argv);
int cmd_particles(int argc, char** argv);
int cmd_voronoi(int argc, char** argv);
int cmd_trunc(int argc, char** argv);
int cmd_poisson(int argc, char** argv);
int cmd_heat(int argc, char** argv);
int cmd_smoothing(int argc, char** argv);
// The result store and its verdicts (store_commands.cpp).
int cmd_fingerprint(int argc, char** argv);
int cmd_store_seal(int argc, char** argv);
int cmd_store_add_columns(int argc, char** argv);
int cmd_store_rates(int argc, char** argv);
int cmd_rate_levels(int argc, char** argv);
int cmd_checked_reasons(int argc, char** argv);
int cmd_verdicts(int argc, char** argv);
int cmd_decisions(int argc, char** argv);
// The study registry (study_command.cpp).
int cmd_study(int argc, char** argv);

}  // namespace gpm::cli
