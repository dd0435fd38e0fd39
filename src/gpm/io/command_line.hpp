// The command line of the running program, recorded once by run_main (args.cpp) and
// written by add_provenance (tsv.cpp) into every data file's header as `command`, so the
// report can print the exact command that regenerates each table and figure.
// Kept out of tsv.hpp so that only those two files depend on it.
#pragma once
#include <string>

namespace gpm {

// Joins argv with spaces, single-quoting any argument that is empty or holds a character
// a shell would interpret.
void set_command_line(int argc, char** argv);
const std::string& command_line();  // empty until set_command_line was called

}  // namespace gpm
