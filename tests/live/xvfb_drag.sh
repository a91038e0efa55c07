#!/usr/bin/env bash
# A drag with the mouse as a person makes it, on a virtual X display: start stage 5.9
# with --live --record --dump on a room with a box, press the left button on the box
# (xdotool's XTEST events, which the X server delivers like real ones), move the pointer
# up and to the right in steps, let go, pause with Space, save the page with F12, end
# with Escape. Then: the recorded script holds one drag token (common/pointer.h); the
# replay command the program printed (which keeps --dump) writes the live session's dump
# byte for byte, and its final.png is the page F12 saved, pixel for pixel; and the box
# really moved toward where the pointer went.
#
# usage: xvfb_drag.sh PROGRAM COMPARE_PNG HAS_WINDOW SCENE
# Exit status 77 (CTest's "skipped") with a message where the build has no window or
# Xvfb or xdotool is missing, as xvfb_session.sh.
set -euo pipefail
program=$1 compare_png=$2 has_window=$3 scene=$4

source "$(dirname "$0")/xvfb_display.sh"
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" SDL_VIDEODRIVER=x11 \
  "$program" --scene "$scene" --live --record session.keys --dump live.csv >live_out.txt 2>live_err.txt &
live_pid=$!
window=$(timeout 10 xdotool search --sync --name 's5_9' | head -n 1) || fail "no window appeared"
# The canvas is the window's top-left corner at --scale 1: window px are canvas px. The
# box's centre is at (300, 400).
xdotool mousemove --window "$window" 310 390
sleep 0.3
xdotool mousedown 1
for step in $(seq 1 10); do
  sleep 0.05
  xdotool mousemove --window "$window" $((310 + 10 * step)) $((390 - 15 * step))
done
sleep 0.5
xdotool mouseup 1
sleep 0.3
end_session

script=$(cat session.keys)
echo "recorded: $script"
[[ "$script" =~ ^drag:310,390(\*[0-9]+)?/[0-9,/*]+@[0-9]+$ ]] || fail "not one drag from the box's (310, 390): \"$script\""
[[ "$script" == *"/410,240"* ]] || fail "the drag does not reach (410, 240): \"$script\""

read_saved_page s5_9
command=$(sed -n 's/^  //p' live_out.txt)
[[ "$command" == *"--frames $((shown + 1)) "* ]] || fail "no replay command ending at the frame F12 saved: $command"
# The command keeps the session's --dump live.csv: the replay writes its dump there anew.
mv live.csv session.csv
bash -c "$command" >replay_out.txt 2>&1 || fail "the replay command failed: $command"

cmp session.csv live.csv >cmp.txt || fail "the replay's dump differs from the live session's: $(cat cmp.txt)"
echo "the replay wrote the live session's dump, byte for byte ($(wc -l <session.csv) lines)"
compare_with_saved s5_9
# The box (object 1) went up: its highest centre over the session is far above where it
# started (400), toward the pointer's 240.
highest=$(awk -F, '$2 == 1 && ($6 < best || best == "") { best = $6 } END { print int(best) }' session.csv)
((highest < 330)) || fail "the box never rose above y = 330 (its highest centre: $highest)"
echo "the dragged box rose to y = $highest"
