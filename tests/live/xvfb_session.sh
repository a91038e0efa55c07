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
xdotool key space   # paused: the page stands still while F12 saves it
sleep 0.3
xdotool key F12
sleep 0.5
xdotool key Escape
for _ in $(seq 100); do kill -0 "$live_pid" 2>/dev/null || break; sleep 0.1; done
status=0
wait "$live_pid" || status=$?
live_pid=''
[[ $status -eq 0 ]] || fail "the live session ended with status $status"

script=$(cat session.keys)
echo "recorded: $script"
[[ "$script" =~ ^f@([0-9]+)\ g@([0-9]+)\ h@([0-9]+)\ comma@([0-9]+)$ ]] || fail "unexpected key script \"$script\""
frames=("${BASH_REMATCH[@]:1}")
for i in 1 2 3; do
  ((frames[i] >= frames[i - 1])) || fail "keys out of order in \"$script\""
done

# What the session printed: "F12: saved frame N to s4_4_frame_NNNN.png", then what it
# recorded, then the replay command, indented.
saved=$(sed -n 's/^F12: saved frame \([0-9]*\) to \(s4_4_frame_[0-9]*\.png\)$/\1 \2/p' live_out.txt)
read -r shown shot <<<"$saved" || true
[[ -n "${shot:-}" && -f "$shot" ]] || fail "F12 saved no page"
command=$(sed -n 's/^  //p' live_out.txt)
[[ "$command" == *"--keys \"\$(cat session.keys)\" --frames $((shown + 1)) --from ${frames[0]} "* ]] ||
  fail "no replay command ending at the frame F12 saved, from the first key on: $command"
bash -c "$command" >replay_out.txt 2>&1 || fail "the replay command failed: $command"

"$compare_png" --channel 0 --share 0 out/s4_4/final.png "$shot" >compare.txt ||
  fail "the page F12 saved differs from the replay's final.png: $(cat compare.txt)"
echo "F12 saved the replay's final.png, pixel for pixel"
