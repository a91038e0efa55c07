#!/usr/bin/env bash
# A live session as a person plays it, on a virtual X display: start the stage with
# --live --record, press F, G, H and comma on the keyboard (xdotool's XTEST presses,
# which the X server delivers like real ones), pause with Space, save the page with F12,
# end with Escape. Then: the recorded script names those four keys in that order, F12
# saved the page of the last frame shown as s4_4_frame_NNNN.png, and the replay command
# the program printed draws a final.png equal to it, pixel for pixel.
#
# usage: xvfb_session.sh PROGRAM COMPARE_PNG HAS_WINDOW
# HAS_WINDOW is "yes" when the build has SDL2's window. Exit status 77 (CTest's
# "skipped" here) with a message when it has not, or when Xvfb or xdotool is missing:
# tools/setup installs libsdl2-dev, xvfb and xdotool.
set -euo pipefail
program=$1 compare_png=$2 has_window=$3

source "$(dirname "$0")/xvfb_display.sh"
# In the sanitizer build (.ci/run) leak checking is off for this one run: under X11,
# SDL's system libraries leave about 1 KB behind at exit (libdbus, and libraries SDL
# loads and unloads itself, so LeakSanitizer cannot even name them). The same session
# code runs with leak checking on in live.program, under SDL's dummy driver.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" SDL_VIDEODRIVER=x11 \
  "$program" --live --record session.keys >live_out.txt 2>live_err.txt &
live_pid=$!
window=$(timeout 10 xdotool search --sync --name 's4_4' | head -n 1) || fail "no window appeared"
# No window manager gives focus here: the keyboard goes to the window under the pointer.
xdotool mousemove --window "$window" 20 20
xdotool key --delay 100 f g h comma
sleep 0.3
end_session   # Space pauses: the page stands still while F12 saves it

script=$(cat session.keys)
echo "recorded: $script"
[[ "$script" =~ ^f@([0-9]+)\ g@([0-9]+)\ h@([0-9]+)\ comma@([0-9]+)$ ]] || fail "unexpected key script \"$script\""
frames=("${BASH_REMATCH[@]:1}")
for i in 1 2 3; do
  ((frames[i] >= frames[i - 1])) || fail "keys out of order in \"$script\""
done

# What the session printed: "F12: saved frame N to s4_4_frame_NNNN.png", then what it
# recorded, then the replay command, indented.
read_saved_page s4_4
command=$(sed -n 's/^  //p' live_out.txt)
[[ "$command" == *"--keys \"\$(cat session.keys)\" --frames $((shown + 1)) --from ${frames[0]} "* ]] ||
  fail "no replay command ending at the frame F12 saved, from the first key on: $command"
bash -c "$command" >replay_out.txt 2>&1 || fail "the replay command failed: $command"

compare_with_saved s4_4
