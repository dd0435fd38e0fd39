// What made a number: the git revision of the build, the code fingerprint of what
// decides a program's numbers (cmake/fingerprint.cmake, computed at build time, not at
// configure time), and the machine it ran on.  Every data file's header and every row of a
// result store (store.hpp) carries them.
#pragma once
#include <string>
#include <vector>

namespace gpm {

// `git describe --always --dirty` of the tree this binary was built from.
const std::string& git_revision();
// The running program (set by run_main), and the fingerprint of its numerics: the core's
// numerics sources, the compile flags and the program's own source.
void set_program(const std::string& name);
const std::string& program_name();
std::string code_fingerprint();
// The same for a named program (for a tool that checks another program's rows); the
// core's fingerprint for a name that is not a program.
std::string code_fingerprint(const std::string& program);
// The programs with a fingerprint of their own (the others get the core's).
std::vector<std::string> fingerprinted_programs();
// CPU model, threads and date, e.g. "Intel(R) Xeon(R) Processor, 2 threads, 2026-12-01".
std::string machine_summary();

}  // namespace gpm
