#!/usr/bin/env bash
# OrbitWorldWx --screenshot under Xvfb: GUIWx steps and draws a World that is not a Simulator;
# the program runs 200 steps, saves a PNG of its view and exits 0 on its own; orbit_check.py
# then finds the moving point where the closed form puts it.
# Usage: orbit_test.sh path/to/OrbitWorldWx
set -euo pipefail
APP=$1
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/xvfb.sh"
start_xvfb

"$APP" --screenshot "$WORK/view.png" --after 200 --geometry 800x600+0+0 \
  >"$WORK/app.out" 2>"$WORK/app.err" &
APP_PID=$!
register_pid $APP_PID
wait_for_exit $APP_PID 30 || fail "$(basename "$APP") did not exit within 30 s"
[ "$EXIT_STATUS" = 0 ] || fail "$(basename "$APP") exited with status $EXIT_STATUS"
[ -s "$WORK/view.png" ] || fail "no screenshot written"
grep -q '^screenshot .* step 200$' "$WORK/app.out" || fail "the screenshot is not of step 200"
python3 "$HERE/orbit_check.py" "$WORK/view.png" "$WORK/app.out" || fail "the screenshot is wrong"
echo "PASS"
