#!/usr/bin/env bash
# Closing SpherusWx while its simulation thread runs flat out must end the process cleanly
# (status 0) within a few seconds: once through the window (the Quit shortcut, Ctrl+Q), once
# through SIGTERM, which the program turns into a window close.
# Usage: close_test.sh path/to/SpherusWx
set -euo pipefail
APP=$1
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/xvfb.sh"
start_xvfb

for how in window sigterm; do
  "$APP" --print-drag --speed max --geometry 640x480+0+0 \
    >"$WORK/$how.out" 2>"$WORK/$how.err" &
  APP_PID=$!
  register_pid $APP_PID
  wait_for_line "$WORK/$how.out" '^ready$' 20 || fail "$how: SpherusWx never became ready"
  sleep 0.5  # stepping as fast as it can, drawing at 60 frames per second
  if [ "$how" = window ]; then
    WINDOW=$(timeout 10 xdotool search --sync --onlyvisible --name '^SpherusWx' | head -n 1)
    [ -n "$WINDOW" ] || fail "no SpherusWx window"
    xdotool windowfocus --sync "$WINDOW"
    xdotool key --clearmodifiers ctrl+q
  else
    kill -TERM $APP_PID
  fi
  wait_for_exit $APP_PID 5 || fail "$how: SpherusWx did not exit within 5 s of being closed"
  [ "$EXIT_STATUS" = 0 ] || fail "$how: SpherusWx exited with status $EXIT_STATUS"
  echo "$how: closed cleanly"
done
echo "PASS"
