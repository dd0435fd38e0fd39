#!/usr/bin/env bash
# The software environment the report was built in: CPU, memory, OS, compiler and library
# versions, each read from the machine (never typed), one row per item.
# usage: environment.sh BUILD_DIR OUT
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -euo pipefail
build=$1 out=$2
first() { "$@" 2>/dev/null | head -1 || true; }
pkg() { dpkg-query -W -f='${Version}' "$1" 2>/dev/null || echo "not installed"; }
{
  echo "# program = tables/environment.sh"
  echo "# git_revision = $(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "# written_utc = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  printf 'item\tvalue\n'
  printf 'CPU\t%s\n' "$(lscpu | sed -n 's/^Model name: *//p' | head -1), family $(sed -n 's/^cpu family\t*: //p' /proc/cpuinfo | head -1) model $(sed -n 's/^model\t*: //p' /proc/cpuinfo | head -1)"
  printf 'cores (online)\t%s\n' "$(nproc)"
  printf 'memory\t%s\n' "$(awk '/MemTotal/ { printf "%.1f GiB", $2 / 1048576 }' /proc/meminfo)"
  printf 'operating system\t%s\n' "$(. /etc/os-release && echo "$PRETTY_NAME")"
  printf 'C++ compiler\t%s\n' "$(first c++ --version)"
  printf 'compile flags (Release)\t%s\n' "$(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:STRING=//p' "$build/CMakeCache.txt" 2>/dev/null)$(grep -q '^GPM_NATIVE:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null && echo ' -march=native')"
  printf 'CMake\t%s\n' "$(first cmake --version)"
  printf 'Eigen (libeigen3-dev)\t%s\n' "$(pkg libeigen3-dev)"
  printf 'CGAL (libcgal-dev)\t%s\n' "$(pkg libcgal-dev)"
  printf 'GSL (libgsl-dev)\t%s\n' "$(pkg libgsl-dev)"
  printf 'GLPK (libglpk-dev)\t%s\n' "$(pkg libglpk-dev)"
  printf 'Catch2 (catch2)\t%s\n' "$(pkg catch2)"
  printf 'gnuplot\t%s\n' "$(first gnuplot --version)"
  printf 'pandoc\t%s\n' "$(first pandoc --version)"
} > "$out.tmp"
mv "$out.tmp" "$out"
