#!/bin/bash
# The store's file of each heat reading is named once in C++ (HeatReading::file_suffix,
# thesis_heat's {reading}) and once in shell (tables/store_lib.sh's heat_file, which the rate
# tables read): the two must agree for all eight readings, or a reading's rows would be
# written to one file and looked for in another.
#   heat_file_names_test.sh BUILD_DIR SOURCE_DIR
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
build=$1 src=$2
. "$src/tables/store_lib.sh"
bad=0 n=0
while IFS=$'\t' read -r reading h volumes dt suffix; do
  [ "$reading" = reading ] && continue
  n=$((n + 1))
  want="STORE/thesis_table4_6$suffix.tsv"
  got=$(heat_file STORE 4_6 "$reading") || { echo "FAIL: heat_file refuses $reading"; bad=$((bad + 1)); continue; }
  if [ "$got" != "$want" ]; then echo "FAIL: $reading: store_lib.sh $got, C++ $want"; bad=$((bad + 1)); fi
done < <("$build/gpm" study --readings | grep -v '^#')
echo "heat readings: $n compared, $bad differ"
[ "$n" -eq 8 ] && [ "$bad" -eq 0 ]
