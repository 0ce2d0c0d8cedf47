#!/usr/bin/env bash
# SpherusWx --screenshot under Xvfb: the program runs 200 steps, saves a PNG of its view and
# exits 0 on its own; png_check.py then decodes the PNG and checks that each object the program
# says it drew is there, in its colour, at its projected position, and that the walls show.
# Another checker (e.g. orbit_check.py, for a World that is not a Simulator) reads the same
# screenshot and the program's output instead when it is named first with --check.
# Usage: screenshot_test.sh [--check checker.py] path/to/program [checker options: --size ...]
set -euo pipefail
CHECK=png_check.py
if [ "$1" = --check ]; then
  CHECK=$2
  shift 2
fi
APP=$1
shift
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
python3 "$HERE/$CHECK" "$WORK/view.png" "$WORK/app.out" "$@" || fail "the screenshot is wrong"
if [ -n "${THYRIX_KEEP_SCREENSHOT:-}" ]; then cp "$WORK/view.png" "$THYRIX_KEEP_SCREENSHOT"; fi
echo "PASS"
