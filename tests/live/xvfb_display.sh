# What both live-window scripts under Xvfb share (xvfb_session.sh: keys; xvfb_drag.sh:
# the mouse), sourced after they set has_window: the skip where the build has no window
# or Xvfb or xdotool is missing (exit 77, CTest's "skipped" here; tools/setup installs
# libsdl2-dev, xvfb and xdotool), a scratch folder $work that is the current folder, a
# virtual display in DISPLAY, fail() that shows the *.txt files written there, a
# cleanup that ends the display and the program started as $live_pid, and the end of a
# session both scripts play the same way (end_session, read_saved_page,
# compare_with_saved).
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

# Pauses the session with Space (the page stands still while F12 saves it), saves the
# page with F12, ends it with Escape, and waits for the program ($live_pid) to exit 0.
end_session() {
  xdotool key space
  sleep 0.3
  xdotool key F12
  sleep 0.5
  xdotool key Escape
  for _ in $(seq 100); do kill -0 "$live_pid" 2>/dev/null || break; sleep 0.1; done
  local status=0
  wait "$live_pid" || status=$?
  live_pid=''
  [[ $status -eq 0 ]] || fail "the live session ended with status $status"
}

# From what the session printed ("F12: saved frame N to STAGE_frame_NNNN.png"): sets
# $shown to the frame F12 saved and $shot to its file, or fails.
read_saved_page() {
  local stage=$1 saved
  saved=$(sed -n "s/^F12: saved frame \([0-9]*\) to \(${stage}_frame_[0-9]*\.png\)$/\1 \2/p" live_out.txt)
  read -r shown shot <<<"$saved" || true
  [[ -n "${shot:-}" && -f "$shot" ]] || fail "F12 saved no page"
}

# The replay's final.png in out/STAGE/ is the page F12 saved ($shot), pixel for pixel.
compare_with_saved() {
  local stage=$1
  "$compare_png" --channel 0 --share 0 "out/$stage/final.png" "$shot" >compare.txt ||
    fail "the page F12 saved differs from the replay's final.png: $(cat compare.txt)"
  echo "F12 saved the replay's final.png, pixel for pixel"
}
