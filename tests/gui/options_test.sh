#!/usr/bin/env bash
# A window program's command line, which it parses before opening any window (no display
# needed): --help lists the world and GUI options; a bad option or value fails with status 2
# and names it. COUNT is its option for the number of objects (SpherusWx: --objects).
# Usage: options_test.sh path/to/program [COUNT]
set -uo pipefail
APP=$1
COUNT=${2:---objects}
status=0
check() {  # expected status, text the output must contain, then the arguments
  local want=$1 text=$2 out got
  shift 2
  out=$(env -u DISPLAY "$APP" "$@" 2>&1)
  got=$?
  if [ "$got" != "$want" ] || ! grep -q -- "$text" <<<"$out"; then
    echo "FAIL: $(basename "$APP") $* gave status $got (expected $want) and:"
    echo "$out"
    status=1
  fi
}
check 0 '--screenshot FILE' --help
check 0 '--print-drag' --help
check 0 '--seed S' --help
check 2 '--steps needs a whole number' --steps nope
check 2 "$COUNT needs a whole number" "$COUNT" -3
check 2 '--solver must be baraff or gauss-seidel' --solver simplex
check 2 '--speed needs a positive number' --speed fast
check 2 '--geometry needs WIDTHxHEIGHT' --geometry 800by600
check 2 '--after needs a value' --after
check 2 'unknown option: --bogus' --bogus
[ $status = 0 ] && echo "PASS"
exit $status
