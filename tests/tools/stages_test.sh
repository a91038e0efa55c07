#!/usr/bin/env bash
# The stage tools on scratch trees, never on the repository's own folders (CTest
# tools.stages, label tools):
#   - tools/stage_diff finds a stage by its exact number: 5.1 is not 5.10, with a 5.10
#     folder listed in stages.txt or only lying about;
#   - tools/stages check passes on a copy of the stages as they are, and fails on each
#     planted drift, naming the file (and line) and the stage it drifted in;
#   - tools/stages forward carries a fix into every later stage, stops at the first that
#     conflicts (leaving it and the ones after as they were), and refuses bad input with
#     one line, exit status 2, writing nothing.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
ok() { echo "ok: $*"; }
# A tree with the stage tools and <stages.txt>, in <dir>.
tools_tree() {
  mkdir -p "$1/tools/lib"
  cp "$repo/tools/stage_diff" "$repo/tools/stages" "$1/tools/"
  cp "$repo/tools/lib/stages.sh" "$1/tools/lib/"
}
# Runs <command...>: its exit status in $status, its output in $out and $err.
run() {
  status=0
  "$@" >"$scratch/out" 2>"$scratch/err" || status=$?
  out=$(cat "$scratch/out")
  err=$(cat "$scratch/err")
}
# The tree's files and their contents, to see that a refusal wrote nothing.
fingerprint() { (cd "$1" && find . -path ./.git -prune -o -type f -print0 | sort -z | xargs -0 sha1sum); }

echo "== stage_diff: 5.1 is 5.1, not 5.10"
tree=$scratch/diff
tools_tree "$tree"
for stage in 5.1_first 5.2_second 5.10_tenth 5.9_ninth; do
  mkdir -p "$tree/ch5_demo/$stage"
  echo "the engine of ${stage%%_*}" >"$tree/ch5_demo/$stage/engine.h"
done
printf '%s\n' ch5_demo/5.1_first ch5_demo/5.2_second ch5_demo/5.9_ninth ch5_demo/5.10_tenth >"$tree/stages.txt"
run "$tree/tools/stage_diff" 5.1 5.2
[[ $status -eq 0 ]] || fail "stage_diff 5.1 5.2: exit status $status: $err"
grep -qx -- '-the engine of 5.1' <<<"$out" || fail "stage_diff 5.1 5.2 does not show 5.1's line: $out"
grep -qx -- '+the engine of 5.2' <<<"$out" || fail "stage_diff 5.1 5.2 does not show 5.2's line: $out"
grep -q '5\.10' <<<"$out" && fail "stage_diff 5.1 5.2 shows 5.10: $out"
run "$tree/tools/stage_diff" s5_9 ch5_demo/5.10_tenth/
grep -qx -- '+the engine of 5.10' <<<"$out" || fail "stage_diff s5_9 <5.10's folder> does not show 5.10: $out"
# A 5.10 folder that the list does not name changes nothing either.
printf '%s\n' ch5_demo/5.1_first ch5_demo/5.2_second >"$tree/stages.txt"
run "$tree/tools/stage_diff" 5.1 5.2
grep -qx -- '-the engine of 5.1' <<<"$out" && ! grep -q '5\.10' <<<"$out" ||
  fail "with 5.10 left out of the list, stage_diff 5.1 5.2: $out"
run "$tree/tools/stage_diff" 5.1 5.3
[[ $status -eq 2 && -z "$out" && $(wc -l <<<"$err") -eq 1 ]] ||
  fail "stage_diff 5.1 5.3 (no such stage): status $status, output '$out', error '$err'"
ok "stage_diff 5.1 5.2 with 5.10 listed and not; a stage that is not there is one line, status 2"

echo "== stages check: the stages as they are, then planted drifts"
tree=$scratch/check
tools_tree "$tree"
cp "$repo/stages.txt" "$tree/"
(cd "$repo" && tar --exclude=expected -cf - ch[0-9]*_*) | tar -xf - -C "$tree"
run "$tree/tools/stages" check
[[ $status -eq 0 ]] || fail "tools/stages check on a copy of the stages: status $status: $out $err"
ok "the stages as they are pass"

grid=ch5_demo/5.3_speed_vs_accuracy/spatial_grid.h
echo "// a fix made in 5.3 only" >>"$tree/$grid"
run "$tree/tools/stages" check
[[ $status -eq 1 ]] || fail "a drifted $grid: status $status"
grep -qx "$grid: differs from 5.2's, and STEP does not name it" <<<"$out" || fail "a drifted $grid: $out"
grep -qx "ch5_demo/5.4_contact_solver/spatial_grid.h: differs from 5.3's, and STEP does not name it" <<<"$out" ||
  fail "5.4, which does not carry 5.3's drift: $out"
cp "$repo/$grid" "$tree/$grid"
ok "a file changed in one stage only: that stage and file, and the next"

overlay=ch5_demo/5.5_sleeping/contact_overlay.h
for stage in 5.4_contact_solver 5.5_sleeping 5.6_continuous_collision; do
  sed -i '2s|^// 5.4.s part|// This stage'"'"'s part|' "$tree/ch5_demo/$stage/contact_overlay.h"
done
run "$tree/tools/stages" check
[[ $status -eq 1 ]] || fail "\"this stage\" carried: status $status"
grep -qx "$overlay:2: carried from 5.4, and says \"this stage\" (name the stage, or none)" <<<"$out" ||
  fail "\"this stage\" carried into 5.5: $out"
grep -q "5.4_contact_solver/contact_overlay.h" <<<"$out" && fail "5.4 wrote its own \"this stage\": $out"
for stage in 5.4_contact_solver 5.5_sleeping 5.6_continuous_collision; do
  cp "$repo/ch5_demo/$stage/contact_overlay.h" "$tree/ch5_demo/$stage/"
done
ok "a line saying \"this stage\", carried: the stage, file and line"

step=ch5_demo/5.3_speed_vs_accuracy/STEP
echo "changed  broad_phase.h  (planted: not changed at all)" >>"$tree/$step"
echo "removed  no_such_file.h" >>"$tree/$step"
touch "$tree/ch5_demo/5.3_speed_vs_accuracy/stray.h"
run "$tree/tools/stages" check
grep -qx "ch5_demo/5.3_speed_vs_accuracy/broad_phase.h: STEP says changed, but it is 5.2's byte for byte" <<<"$out" &&
  grep -qx "ch5_demo/5.3_speed_vs_accuracy/no_such_file.h: STEP says removed, but 5.2 has no no_such_file.h" <<<"$out" &&
  grep -qx "ch5_demo/5.3_speed_vs_accuracy/stray.h: not in 5.2, and STEP does not say added" <<<"$out" &&
  grep -qx "ch5_demo/5.4_contact_solver/stray.h: gone (5.3 has it), and STEP does not say removed" <<<"$out" ||
  fail "a STEP naming an unchanged file and a file never there, and a stray file: $out"
[[ $status -eq 1 && $(wc -l <<<"$out") -eq 4 ]] || fail "status $status, or other problems too: $out"
rm "$tree/ch5_demo/5.3_speed_vs_accuracy/stray.h"
ok "a STEP that names an unchanged file or one that never was; a file nobody named"

echo "renamed  physics.cpp" >>"$tree/$step"
before=$(fingerprint "$tree")
run "$tree/tools/stages" check
[[ $status -eq 2 && -z "$out" && "$err" == "stages: $step:"*": \"renamed\" is not added, changed or removed" ]] ||
  fail "a STEP that cannot be read: status $status, output '$out', error '$err'"
[[ "$(fingerprint "$tree")" == "$before" ]] || fail "check wrote something"
cp "$repo/$step" "$tree/$step"
rm "$tree/ch5_demo/5.6_continuous_collision/STEP"
run "$tree/tools/stages" check
[[ $status -eq 2 && "$err" == "stages: ch5_demo/5.6_continuous_collision has no STEP"* ]] ||
  fail "no STEP: status $status, error '$err'"
cp "$repo/ch5_demo/5.6_continuous_collision/STEP" "$tree/ch5_demo/5.6_continuous_collision/"
run "$tree/tools/stages" check
[[ $status -eq 0 ]] || fail "the copy put back: $out"
ok "a STEP with an unknown word, and none at all: one line, status 2"

echo "== stages forward: a fix carried, a conflict stops it, bad input refused"
tree=$scratch/forward
tools_tree "$tree"
printf '%s\n' ch1_a/1.1_one ch1_a/1.2_two ch1_a/1.3_three ch1_a/1.4_four ch1_a/1.5_five >"$tree/stages.txt"
mkdir -p "$tree"/ch1_a/1.{1_one,2_two,3_three,4_four,5_five}
printf '%s\n' alpha beta gamma one two three delta epsilon >"$tree/ch1_a/1.1_one/shape.h"
cp "$tree/ch1_a/1.1_one/shape.h" "$tree/ch1_a/1.2_two/"
cp "$tree/ch1_a/1.1_one/shape.h" "$tree/ch1_a/1.3_three/"
printf '%s\n' alpha beta gamma one two three DELTA epsilon >"$tree/ch1_a/1.4_four/shape.h"  # 1.4 changed delta
cp "$tree/ch1_a/1.4_four/shape.h" "$tree/ch1_a/1.5_five/"
(cd "$tree" && git init -q && git add -A && git -c user.name=test -c user.email=test@example.invalid commit -qm start)

before=$(fingerprint "$tree")
for bad in "forward 9.9 shape.h" "forward 1.2 nothing.h" "forward 1.2 ../1.1_one/shape.h" "forward 1.2" \
  "forward 1.2 shape.h extra" "forward --base nonsense 1.2 shape.h"; do
  # shellcheck disable=SC2086
  run "$tree/tools/stages" $bad
  [[ $status -eq 2 && -z "$out" && $(wc -l <<<"$err") -eq 1 && "$err" == "stages: "* ]] ||
    fail "tools/stages $bad: status $status, output '$out', error '$err'"
done
run "$tree/tools/stages" forward 1.2 shape.h
[[ $status -eq 2 && "$err" == *"make the fix first"* ]] || fail "forward with no fix made: $status '$err'"
[[ "$(fingerprint "$tree")" == "$before" ]] || fail "a refusal wrote something"
ok "refusals: no such stage or file, a path, too few or many words, no commit, no fix; nothing written"

# A fix to gamma in 1.2: 1.3 carries it verbatim, 1.4 and 1.5 changed another line.
sed -i 's/^gamma$/GAMMA (fixed)/' "$tree/ch1_a/1.2_two/shape.h"
run "$tree/tools/stages" forward 1.2 shape.h
[[ $status -eq 0 && "$out" == "stages forward: 1.2's shape.h carried into 1.3 1.4 1.5" ]] ||
  fail "forward 1.2: status $status, '$out' '$err'"
[[ "$err" == *"1.2 had 1.1's shape.h"* ]] || fail "forward 1.2 does not say the fix may be 1.1's: '$err'"
cmp -s "$tree/ch1_a/1.2_two/shape.h" "$tree/ch1_a/1.3_three/shape.h" || fail "1.3 is not 1.2's"
[[ "$(cat "$tree/ch1_a/1.5_five/shape.h" | xargs)" == "alpha beta GAMMA (fixed) one two three DELTA epsilon" ]] ||
  fail "1.5's shape.h: $(cat "$tree/ch1_a/1.5_five/shape.h")"
[[ "$(cat "$tree/ch1_a/1.1_one/shape.h" | xargs)" == "alpha beta gamma one two three delta epsilon" ]] || fail "1.1 was touched"
(cd "$tree" && git checkout -q .)
ok "a fix merged into the copy and into the stages that changed the file elsewhere"

# A fix to delta in 1.1: 1.2 and 1.3 take it, 1.4 changed that very line: a conflict.
sed -i 's/^delta$/delta (fixed)/' "$tree/ch1_a/1.1_one/shape.h"
run "$tree/tools/stages" forward 1.1 shape.h
[[ $status -eq 1 && -z "$out" ]] || fail "a conflict: status $status, output '$out'"
[[ "$err" == "stages forward: ch1_a/1.4_four/shape.h conflicts with the fix (left as it was); carried into 1.2 1.3;"* ]] ||
  fail "a conflict's message: '$err'"
grep -qx "delta (fixed)" "$tree/ch1_a/1.3_three/shape.h" || fail "1.3, before the conflict, did not get the fix"
(cd "$tree" && git diff --quiet -- ch1_a/1.4_four ch1_a/1.5_five) || fail "1.4 or 1.5 written despite the conflict"
grep -q "<<<<<<<\|>>>>>>>" -r "$tree/ch1_a" && fail "conflict markers written"
ok "a conflict stops at 1.4, naming it; 1.2 and 1.3 carried, 1.4 and 1.5 untouched"
echo "all passed"
