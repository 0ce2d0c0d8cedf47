#!/usr/bin/env bash
# A real mouse drag in SpherusWx under Xvfb: the program prints where each object is on the
# screen; xdotool grabs one and drags it along a free path with the real pointer; the program's
# own log must then show the object grabbed, pulled to where the pointer went, and still once
# released. Finally the window is closed with its Quit shortcut while the simulation runs, and
# the program must exit cleanly within a few seconds.
# Usage: drag_test.sh path/to/SpherusWx
set -euo pipefail
APP=$1
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/xvfb.sh"
start_xvfb

"$APP" --print-drag --geometry 800x600+0+0 --objects 8 --seed 2 \
  >"$WORK/app.out" 2>"$WORK/app.err" &
APP_PID=$!
register_pid $APP_PID
wait_for_line "$WORK/app.out" '^ready$' 20 || fail "SpherusWx never printed its layout"
WINDOW=$(timeout 10 xdotool search --sync --onlyvisible --name '^SpherusWx' | head -n 1)
[ -n "$WINDOW" ] || fail "no SpherusWx window"

# The object to drag and the pointer's path, in screen pixels, from the printed layout.
read -r -a PLAN <<<"$(python3 "$HERE/drag_check.py" plan "$WORK/app.out")"
echo "dragging object ${PLAN[0]}: pixels ${PLAN[*]:1}"
xdotool mousemove "${PLAN[1]}" "${PLAN[2]}"
sleep 0.2
xdotool mousedown 1
sleep 0.2
for ((k = 3; k + 1 < ${#PLAN[@]}; k += 2)); do
  xdotool mousemove "${PLAN[k]}" "${PLAN[k + 1]}"
  sleep 0.2
done
sleep 0.3  # let the object reach the last point before letting go
xdotool mouseup 1
wait_for_line "$WORK/app.out" '^drag settled .* after 50 ' 15 ||
  fail "no 'drag settled ... after 50' line: the drag was not seen"
python3 "$HERE/drag_check.py" check "$WORK/app.out" "${PLAN[@]}" || fail "the drag is wrong"

# Close with the Quit shortcut while the simulation is running.
xdotool windowfocus --sync "$WINDOW"
xdotool key --clearmodifiers ctrl+q
wait_for_exit $APP_PID 5 || fail "SpherusWx did not exit within 5 s of Ctrl+Q"
[ "$EXIT_STATUS" = 0 ] || fail "SpherusWx exited with status $EXIT_STATUS"
echo "PASS"
