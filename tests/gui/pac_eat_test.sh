#!/usr/bin/env bash
# PacWx --eat under Xvfb: the eating script, which PacEatingSimulator runs in its advanceTime(),
# runs in the window's simulation thread as in PacText --eat. After 1500 steps the program saves
# its view and exits; pac_eat_check.py then finds food inside Pac 0's ring in the objects the
# program printed.
# Usage: pac_eat_test.sh path/to/PacWx
set -euo pipefail
APP=$1
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/xvfb.sh"
start_xvfb

"$APP" --eat --screenshot "$WORK/view.png" --after 1500 --geometry 800x600+0+0 \
  >"$WORK/app.out" 2>"$WORK/app.err" &
APP_PID=$!
register_pid $APP_PID
wait_for_exit $APP_PID 60 || fail "$(basename "$APP") did not exit within 60 s"
[ "$EXIT_STATUS" = 0 ] || fail "$(basename "$APP") exited with status $EXIT_STATUS"
grep -q '^screenshot .* step 1500$' "$WORK/app.out" || fail "the screenshot is not of step 1500"
python3 "$HERE/pac_eat_check.py" "$WORK/app.out" || fail "Pac 0 ate nothing"
echo "PASS"
