#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/make_rules.hpp"
#include "gpm/error.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/registry.hpp"

namespace gpm::cli {

// gpm study: the study registry (registry.hpp) on the command line.  `--list` prints every
// study with its document item and levels; `--make FILE` writes the studies' make rules
// (make build does, to build/studies.mk); `gpm study NAME [options]` runs the study's program
// (from the directory of this gpm) with the study's fixed arguments and the options given,
// so it takes the program's --profile, --levels, --out, --help as they are.
int cmd_study(int argc, char** argv) {
  const std::string first = argc >= 3 ? argv[2] : "";
  if (first == "--help" || first == "-h") {
    std::cout << "usage: gpm study --list | --store-files | --store-rows | --make FILE | NAME [options]\n"
                 "  --list      every registered study: document item, program, levels per profile\n"
                 "  --make FILE the studies' make rules and lists (make build writes build/studies.mk)\n"
                 "  --store-files  every study's files in the result store: program and arguments, the\n"
                 "              units each must hold (census) and the ones the store check recomputes\n"
                 "  --store-rows   the same rows for a shell loop: no header, an empty cell written '-'\n"
                 "              (while IFS=$'\\t' read -r study file program args census coarse slice)\n"

                 "  NAME        runs the study's program with its fixed arguments, then the\n"
                 "              options given (e.g. --profile quick --out FILE); see\n"
                 "              gpm study NAME --help for them\n";
    return 0;
  }
  if (first.empty() || first == "--list") {
    TsvTable t;
    t.set("program", "gpm study");
    add_provenance(t);
    t.columns = {"study", "item", "program", "quick_levels", "paper_levels", "header"};
    auto levels = [](const std::vector<int>& k) {
      std::vector<std::string> s;
      for (int v : k) s.push_back(fmt(v));
      return join(s, ",");
    };
    for (auto& e : study_registry()) {
      std::vector<std::string> command = {e.program};
      command.insert(command.end(), e.fixed_args.begin(), e.fixed_args.end());
      TsvRow row = t.named_row();
      row["study"] = e.name, row["item"] = e.item, row["program"] = join(command, " ");
      row["quick_levels"] = levels(e.levels.quick), row["paper_levels"] = levels(e.levels.paper);
      row["header"] = join(e.header(), ",");
      t.add_row(row);
    }
    print(t);
    return first.empty() ? 2 : 0;
  }
  if (first == "--store-files") {
    TsvTable t = store_file_table(study_registry());
    t.set("program", "gpm study --store-files");
    add_provenance(t);
    print(t);
    return 0;
  }
  // The shell scripts' listing (the store check, the census, the whitelist, the sample and full
  // verifications): `read` merges two tabs, so an empty cell is written "-"; the columns are
  // --store-files' in its order.
  if (first == "--store-rows") {
    const TsvTable t = store_file_table(study_registry());
    for (const auto& row : t.rows) {
      for (std::size_t i = 0; i < row.size(); ++i) std::cout << (i ? "\t" : "") << (row[i].empty() ? "-" : row[i]);
      std::cout << "\n";
    }
    return 0;
  }
  if (first == "--make") {
    if (argc != 4) throw InputError("gpm study --make: give one output file (e.g. build/studies.mk)");
    save_text(argv[3], make_rules(study_registry()));
    return 0;
  }
  const RegisteredStudy& e = study_registry().study(first);
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe");
  const std::string program = (self.parent_path() / e.program).string();
  if (access(program.c_str(), X_OK) != 0)
    throw InputError("gpm study " + first + ": its program " + program +
                     " is not built (make build)");
  std::vector<std::string> args = {program};
  args.insert(args.end(), e.fixed_args.begin(), e.fixed_args.end());
  for (int i = 3; i < argc; ++i) {
    // An option the study fixes (its --table, …) cannot be given again: it names the study.
    const std::string name = std::string(argv[i]).substr(0, std::string(argv[i]).find('='));
    for (std::size_t f = 0; f < e.fixed_args.size(); ++f)
      if (e.fixed_args[f] == name)
        throw InputError("gpm study " + first + ": " + name + " is fixed by the study (" + name + " " +
                         (f + 1 < e.fixed_args.size() ? e.fixed_args[f + 1] : "") + "); run another study for another value");
    args.push_back(argv[i]);
  }
  std::vector<char*> cargs;
  for (auto& a : args) cargs.push_back(a.data());
  cargs.push_back(nullptr);
  std::cout.flush();
  execv(program.c_str(), cargs.data());
  throw std::runtime_error("gpm study: cannot run " + program + ": " + std::strerror(errno));
}

}  // namespace gpm::cli
