#!/usr/bin/env bash
# SpherusWx --genome under Xvfb: a hand-made genome whose biases fire both forward rockets (no
# weights) drives Spherus forward at 0.99505 m/s in an empty arena, so at the screenshot of
# step 200 its circles (objects 5 and 6) are at y = 5 + 1.99 * 0.99505 = 6.980 (the first step
# comes before the controller acts). A missing or mismatched genome fails with status 1 before
# any window opens.
# Usage: genome_test.sh path/to/SpherusWx
set -euo pipefail
APP=$1
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/xvfb.sh"
start_xvfb

{
  printf 'thyrix-genome 1\nkind feed-forward\nactivation tanh\nlayers 35 5\nparameters 180\n'
  printf '3\n-3\n3\n-3\n0\n'
  for _ in $(seq 175); do printf '0\n'; done
} >"$WORK/forward.genome"
"$APP" --genome "$WORK/forward.genome" --objects 0 --screenshot "$WORK/view.png" --after 200 \
  --geometry 800x600+0+0 >"$WORK/app.out" 2>"$WORK/app.err" &
APP_PID=$!
register_pid $APP_PID
wait_for_exit $APP_PID 30 || fail "$(basename "$APP") did not exit within 30 s"
[ "$EXIT_STATUS" = 0 ] || fail "$(basename "$APP") exited with status $EXIT_STATUS"
for object in 5 6; do
  grep -Eq "^object $object circle [0-9.]+ 6\.980[0-9]* " "$WORK/app.out" ||
    fail "object $object is not at y = 6.980: $(grep "^object $object " "$WORK/app.out")"
done

printf 'thyrix-genome 1\nkind feed-forward\nactivation tanh\nlayers 3 2\nparameters 8\n0\n0\n0\n0\n0\n0\n0\n0\n' \
  >"$WORK/small.genome"
for case in "missing.genome:cannot be opened" "small.genome:but the agent has 35 sensors"; do
  set +e
  out=$(env -u DISPLAY "$APP" --genome "$WORK/${case%%:*}" 2>&1)
  status=$?
  set -e
  [ $status = 1 ] && grep -q -- "${case#*:}" <<<"$out" ||
    fail "--genome ${case%%:*} should fail with status 1 saying '${case#*:}': $status $out"
done
echo "PASS"
