#!/usr/bin/env bash
# Regenerates the README's pictures, docs/images/{spherus,pac,iunctus}-wx.png: each is the
# window program's own `--screenshot FILE --after 200` output (the view after 200 steps, default
# options), taken under a private Xvfb (tests/gui/xvfb.sh). Builds the three programs with the
# GUI (wxWidgets 3.2, Xvfb, xdotool, python3: THYRIX_WITH_GUI=1 scripts/install-deps.sh) in
# BUILD_DIR, build/screenshots by default.
# Usage: scripts/screenshots.sh [BUILD_DIR]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build/screenshots}
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DTHYRIX_BUILD_GUI=ON >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target SpherusWx PacWx IunctusWx >/dev/null

source "$ROOT/tests/gui/xvfb.sh"
start_xvfb
for name in Spherus Pac Iunctus; do
  program="$BUILD/examples/$name/${name}Wx"
  picture="$ROOT/docs/images/$(echo "$name" | tr '[:upper:]' '[:lower:]')-wx.png"
  "$program" --screenshot "$WORK/$name.png" --after 200 --geometry 1000x700+0+0 \
    >"$WORK/$name.out" 2>"$WORK/$name.err" &
  pid=$!
  register_pid $pid
  wait_for_exit $pid 60 || fail "${name}Wx did not exit within 60 s"
  [ "$EXIT_STATUS" = 0 ] || fail "${name}Wx exited with status $EXIT_STATUS"
  grep -q '^screenshot .* step 200$' "$WORK/$name.out" || fail "${name}Wx's picture is not of step 200"
  cp "$WORK/$name.png" "$picture"
  echo "$picture"
done
