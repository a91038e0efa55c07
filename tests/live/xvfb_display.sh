# What both live-window scripts under Xvfb share (xvfb_session.sh: keys; xvfb_drag.sh:
# the mouse), sourced after they set has_window: the skip where the build has no window
# or Xvfb or xdotool is missing (exit 77, CTest's "skipped" here; tools/setup installs
# libsdl2-dev, xvfb and xdotool), a scratch folder $work that is the current folder, a
# virtual display in DISPLAY, fail() that shows the *.txt files written there, and a
# cleanup that ends the display and the program started as $live_pid.
if [[ "$has_window" != yes ]]; then
  echo "SKIPPED: this build has no live window (SDL2); live.program checks that --live says so"
  exit 77
fi
for tool in Xvfb xdotool; do
  if ! command -v "$tool" >/dev/null; then
    echo "SKIPPED: $tool is not installed (tools/setup installs xvfb and xdotool)"
    exit 77
  fi
done

work=$(mktemp -d)
xvfb_pid='' live_pid=''
cleanup() {
  if [[ -n "$live_pid" ]]; then kill "$live_pid" 2>/dev/null || true; fi
  if [[ -n "$xvfb_pid" ]]; then kill "$xvfb_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAILED: $*"; for f in "$work"/*.txt; do [[ -f "$f" ]] && { echo "--- $(basename "$f")"; cat "$f"; }; done; exit 1; }

# Xvfb picks a free display number and writes it to file descriptor 3 once it is ready.
Xvfb -displayfd 3 -screen 0 1400x700x24 -nolisten tcp 3>"$work/display" 2>"$work/xvfb.txt" &
xvfb_pid=$!
for _ in $(seq 100); do [[ -s "$work/display" ]] && break; sleep 0.1; done
[[ -s "$work/display" ]] || fail "Xvfb did not start"
export DISPLAY=":$(cat "$work/display")"
cd "$work"
