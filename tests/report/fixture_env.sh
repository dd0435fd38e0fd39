# Sourced by the report checks' tests (tests/report/*_test.sh): the source tree from the first
# argument, the fixtures, and a scratch folder removed on exit.  Numbers are read and printed
# with '.' whatever the user's locale.
export LC_ALL=C
set -u
src=${1:?usage: $(basename "$0") SOURCE_DIR}
fx=$src/tests/report/fixture
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
