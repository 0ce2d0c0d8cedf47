# Sourced by the GUI tests: a private X server for one test, and the clean-up of everything the
# test started. Exits with 77 (CTest's "skipped", see SKIP_RETURN_CODE) when a tool is missing.
#
#   start_xvfb            starts Xvfb on a free display (it picks the number itself and says
#                         which once it accepts connections) and exports DISPLAY
#   register_pid PID      PID is killed by the clean-up if still running
#   wait_for_line FILE REGEX SECONDS   waits until a line of FILE matches REGEX
#   wait_for_exit PID SECONDS          waits for PID to end; sets EXIT_STATUS (124 on timeout)

for tool in Xvfb xdotool python3; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIP: $tool is not installed (Debian: apt-get install xvfb xdotool python3)"
    exit 77
  fi
done

# Under AddressSanitizer (the sanitizer configuration of scripts/test.sh), leak checking is off
# for the window programs: GTK and fontconfig keep caches until exit that LeakSanitizer reports,
# none of them Thyrix's. Every other error still aborts the program and fails the test.
if [ -n "${ASAN_OPTIONS:-}" ]; then export ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0"; fi

WORK=$(mktemp -d)
PIDS=()
cleanup() {
  local pid
  for pid in "${PIDS[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$WORK"
}
trap cleanup EXIT

register_pid() { PIDS+=("$1"); }

fail() {
  echo "FAIL: $*"
  for f in "$WORK"/*.out "$WORK"/*.err; do
    [ -f "$f" ] && { echo "--- $(basename "$f")"; tail -n 40 "$f"; }
  done
  exit 1
}

start_xvfb() {
  Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$WORK/display" 2>"$WORK/xvfb.log" &
  register_pid $!
  local i
  for i in $(seq 200); do
    [ -s "$WORK/display" ] && break
    sleep 0.05
  done
  [ -s "$WORK/display" ] || fail "Xvfb did not start: $(cat "$WORK/xvfb.log")"
  export DISPLAY=":$(head -n 1 "$WORK/display")"
  # -displayfd reports the number once the server accepts connections; check anyway.
  xdotool getmouselocation >/dev/null 2>&1 || fail "cannot connect to Xvfb on $DISPLAY"
  # GTK: no accessibility bus to look for, no theme or settings daemons.
  export NO_AT_BRIDGE=1 GTK_THEME=Adwaita GSETTINGS_BACKEND=memory
}

wait_for_line() {
  local file=$1 regex=$2 seconds=$3 i
  for i in $(seq $((seconds * 20))); do
    grep -Eq "$regex" "$file" 2>/dev/null && return 0
    sleep 0.05
  done
  return 1
}

wait_for_exit() {
  local pid=$1 seconds=$2 i
  for i in $(seq $((seconds * 20))); do
    if ! kill -0 "$pid" 2>/dev/null; then
      EXIT_STATUS=0
      wait "$pid" || EXIT_STATUS=$?
      return 0
    fi
    sleep 0.05
  done
  EXIT_STATUS=124
  return 1
}
