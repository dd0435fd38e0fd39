# Build-time script (cmake -P): writes OUT, a C++ source naming the git revision of the tree
# and, for every program, the fingerprint of the code that decides its numbers.
#
# The fingerprint of a program is the SHA-256 (first 12 hex digits) of the SHA-256 of every
# core source that can change its stored numbers, of the compiler and its flags (FLAGS) and of
# the program's own source.  Which core sources can change a number is a rule by folder, not a
# list:
#   in   the numerics (geometry, weights, kernel, operators, solvers, theory), the data
#        format (io/tsv: how a number is written) and the studies' definitions
#        (studies/define: catalog, set-ups, the registry with each unit's level, h, volumes
#        and time step);
#   out  the rest of io (options, progress, provenance, text), error messages, the
#        rooms that run units and keep the store (studies/run), price profiles
#        (studies/plan) and judge stored rates (studies/judge); and four files of
#        studies/define that compute no number a row stores: the store's census (which
#        readings, seeds and levels the store must hold), the cost model (pairs and work
#        predicted for progress lines and the plan), the unit pricer (pricing) and the
#        registry's bookkeeping half (registry_books: make files, store files, published
#        rates, figures, prices; registry.cpp keeps the programs, levels, columns and units).
# A core source that no rule names stops the build: a new folder is placed on purpose.
#
# Of those, a program (src/apps, bench) takes only the ones it is built from: its include
# closure.  From the program's source, every quoted include ("gpm/…", "apps/…", a bench's own
# header) is followed, through headers and sources alike; a header brings its source of the same name (X.hpp,
# X.cpp), and a source named after no header (weights/weight_registry.cpp) comes with any
# header it includes.  So an edit of the heat solvers moves the heat programs' fingerprints
# and not Table 4.2's.  The closure is checked against the linker: every object of the core
# library linked into a program must come from its closure (tests/layers/
# fingerprint_closure_test.sh reads the link maps; OUT.closure lists each program's files).
# The gpm command (src/cli, one executable of many files) takes every core source by the rule.
#
# A data row carries the fingerprint of the program that computed it (src/gpm/studies/run/store.hpp):
# a row is reused as current only under the same fingerprint, otherwise after a recorded
# re-check.  OUT is rewritten only when its content changes, so an unchanged tree recompiles
# nothing.
#
# Inputs: -DSRC=<source dir> -DOUT=<generated .cpp> -DFLAGS=<compiler, version, flags>
cmake_minimum_required(VERSION 3.22)
file(GLOB_RECURSE core ${SRC}/src/gpm/*.cpp ${SRC}/src/gpm/*.hpp)
list(SORT core)
set(core_text "")
foreach(f IN LISTS core)
  file(RELATIVE_PATH r ${SRC}/src/gpm ${f})
  string(MAKE_C_IDENTIFIER "${f}" id)
  if(r MATCHES "^studies/define/(census|cost_model|pricing|registry_books)\\.(c|h)pp$")
    continue()
  elseif(r MATCHES "^(geometry|weights|kernel|operators|solvers|theory)/" OR r MATCHES "^io/tsv\\.(c|h)pp$"
     OR r MATCHES "^studies/define/")
    file(SHA256 ${f} h)
    set(HASHED_${id} "src/gpm/${r} ${h}\n")
    string(APPEND core_text "src/gpm/${r} ${h}\n")
  elseif(r MATCHES "^io/" OR r MATCHES "^error\\.(c|h)pp$" OR r MATCHES "^studies/(run|plan|judge)/")
    continue()
  else()
    message(FATAL_ERROR "fingerprint.cmake: no rule says whether src/gpm/${r} can change a stored "
                        "number (add its folder to the in or out rule)")
  endif()
endforeach()
string(APPEND core_text "build ${FLAGS}\n")

# The files a source includes with quotes: "gpm/…" and "apps/…" from src/, any other next to
# the source (bench/limit_table.hpp).
function(quoted_includes f out)
  file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]+\"[^\"]+\"")
  get_filename_component(dir ${f} DIRECTORY)
  set(r "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" inc "${line}")
    if(EXISTS ${SRC}/src/${inc})
      list(APPEND r ${SRC}/src/${inc})
    elseif(EXISTS ${dir}/${inc})
      list(APPEND r ${dir}/${inc})
    else()
      message(FATAL_ERROR "fingerprint.cmake: ${f} includes \"${inc}\", found neither in src/ nor beside it")
    endif()
  endforeach()
  set(${out} ${r} PARENT_SCOPE)
endfunction()

# What each core, shared-body or bench header file includes (INC_<file>), and the sources
# named after no header that come with each header they include (WITH_<header>).
file(GLOB_RECURSE bodies ${SRC}/src/apps/tables/*.cpp ${SRC}/src/apps/tables/*.hpp ${SRC}/bench/*.hpp)
foreach(f IN LISTS core bodies)
  string(MAKE_C_IDENTIFIER "${f}" id)
  quoted_includes(${f} INC_${id})
  if(f MATCHES "\\.cpp$")
    string(REGEX REPLACE "\\.cpp$" ".hpp" header "${f}")
    if(NOT EXISTS ${header})
      foreach(inc IN LISTS INC_${id})
        string(MAKE_C_IDENTIFIER "${inc}" iid)
        list(APPEND WITH_${iid} ${f})
      endforeach()
    endif()
  endif()
endforeach()

# The include closure of a program's source (header above), as a sorted list in `out`.
function(include_closure start out)
  set(seen "")
  set(work ${start})
  while(work)
    list(POP_FRONT work f)
    if(f IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${f})
    string(MAKE_C_IDENTIFIER "${f}" id)
    if(f STREQUAL start)
      quoted_includes(${f} incs)
      list(APPEND work ${incs})
    else()
      list(APPEND work ${INC_${id}} ${WITH_${id}})
    endif()
    if(f MATCHES "\\.hpp$")
      string(REGEX REPLACE "\\.hpp$" ".cpp" source "${f}")
      if(EXISTS ${source})
        list(APPEND work ${source})
      endif()
    endif()
  endwhile()
  list(REMOVE_ITEM seen ${start})
  list(SORT seen)
  set(${out} ${seen} PARENT_SCOPE)
endfunction()

file(GLOB programs ${SRC}/src/apps/*.cpp ${SRC}/src/cli/*.cpp ${SRC}/bench/*.cpp)
list(SORT programs)
set(entries "")
set(closures "")
foreach(f IN LISTS programs)
  get_filename_component(name ${f} NAME_WE)
  file(SHA256 ${f} h)
  if(f MATCHES "/src/cli/")
    set(code_text "${core_text}")
  else()
    # The program's closure: its core sources that the rule takes in, and its shared bodies.
    include_closure(${f} files)
    set(code_text "")
    foreach(c IN LISTS files)
      string(MAKE_C_IDENTIFIER "${c}" id)
      file(RELATIVE_PATH r ${SRC} ${c})
      string(APPEND closures "${name}\t${r}\n")
      if(DEFINED HASHED_${id})
        string(APPEND code_text "${HASHED_${id}}")
      elseif(r MATCHES "^src/apps/")
        file(SHA256 ${c} bh)
        string(APPEND code_text "${r} ${bh}\n")
      endif()
    endforeach()
    string(APPEND code_text "build ${FLAGS}\n")
  endif()
  string(SHA256 fp "${code_text}${name} ${h}\n")
  string(SUBSTRING ${fp} 0 12 fp)
  string(APPEND entries "    {\"${name}\", \"${fp}\"},\n")
endforeach()
string(SHA256 core_fp "${core_text}")
string(SUBSTRING ${core_fp} 0 12 core_fp)

execute_process(COMMAND git describe --always --dirty --abbrev=12
  WORKING_DIRECTORY ${SRC} OUTPUT_VARIABLE rev OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT rev)
  set(rev "unknown")
endif()

set(text "// Generated by cmake/fingerprint.cmake at build time; do not edit.
#include <string_view>
namespace gpm::generated {
extern const std::string_view kGitRevision = \"${rev}\";
extern const std::string_view kCoreFingerprint = \"${core_fp}\";
struct ProgramFingerprint { std::string_view program, fingerprint; };
extern const ProgramFingerprint kProgramFingerprints[] = {
${entries}    {\"\", \"\"}};
}  // namespace gpm::generated
")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
set(old "")
if(EXISTS ${OUT}.closure)
  file(READ ${OUT}.closure old)
endif()
if(NOT old STREQUAL closures)
  file(WRITE ${OUT}.closure "${closures}")
endif()
