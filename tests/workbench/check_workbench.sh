#!/usr/bin/env bash
# The reader's workbench, end to end (tools/workbench, cmake/Workbench.cmake), in a
# scratch copy of the repository's tracked files, so that the repository's own build
# and workbench/ are never touched:
#   - refusals: not a stage number, no such stage, a path, a folder already there;
#   - with workbench/ empty the build has no workbench tests;
#   - 3.3 and 4.3 made from 3.2 and 4.2: the new feature's tests fail, naming the book's
#     project, and the features the stage before had pass; with our 3.3 and 4.3 files
#     copied in, every test of wb_s3_3 and wb_s4_3 passes, pictures included;
#   - 1.1 starts from an empty program: the build works, and its tests fail, saying
#     that they do not build yet, never skipped;
#   - tools/workbench --check (the reader's loop) stops at the new feature's first failing
#     check, naming the book project, and passes every check once our files are in;
#   - tools/workbench --list counts the passing tests from the last runs' verdicts, at once;
#   - ids parsed exactly (03.3, 3.30, 1.10 refused), a feature is no pattern, two
#     tools/workbench 3.3 at once make one folder; a stage's own label passes after
#     building only its target; --check never runs a program older than main.cpp.
# Builds only what the workbench stages need. Used by .ci/run; KEEP=1 keeps the copy.
set -euo pipefail
source "$(dirname "$0")/scratch_copy.sh" check_workbench
jobs=$(nproc)

expect() {  # expect <log> <Passed|Failed> <test>...
  local log=$1 wanted=$2 name
  shift 2
  for name in "$@"; do
    [[ "$(verdict "$log" "$name")" == "$wanted" ]] ||
      fail "$name: expected $wanted, ctest says \"$(verdict "$log" "$name")\" (log: $log)"
  done
  ok "$wanted: $*"
}
# Runs stage <wb>'s tests into <log>; ctest's own status does not matter, the verdicts do.
run_tests() { ctest --test-dir build -L "^$1\$" -j "$jobs" --output-on-failure >"$2" 2>&1 || true; }
# The features stages.txt gives stage <id>, through tools/workbench's own reading.
features_of() { grep -E "^- (new in|from the projects before)" "workbench/$1/README.md" | grep -oE 'wb_s[0-9_]+\.[a-z_]+' | grep -v '\.stage$'; }

echo "== refusals"
refused "no stage 9.9" 9.9
refused "is a path" ../3.3
refused "is a path" workbench/3.3
refused "is a path" 3.3/x
refused "not a stage number" 3
refused "not a stage number" "3.3;rm"
refused "no check \"nothing\"" --check 3.3 nothing
refused "no workbench/2.2_* yet" --check 2.2
refused "not a stage number" --check 3
# Stage numbers are text, not numbers: 03.3, 3.30 and 1.10 are no stages (issue 36).
for number in 03.3 3.30 1.10; do
  refused "no stage $number" "$number"
  refused "no stage $number" --check "$number"
done
for number in 3.3.0 " 3.3" "3.3 " "3.3
"; do refused "not a stage number" "$number"; done
# A feature is a name, not a pattern.
refused 'no check ".*"' --check 3.3 '.*'
refused 'no check "rectangle_.*"' --check 3.3 'rectangle_.*'
[[ ! -e workbench ]] || fail "a refusal left workbench/ behind"
ok "refusals made nothing"

echo "== two tools/workbench 3.3 at once: one makes it, the other is refused"
# Both used to find workbench/3.3_* missing and both succeed, the second moving its copy
# into the first's (workbench/3.3_rectangle_collision/.making.<pid>/).
for round in 1 2 3; do
  rm -rf workbench
  statuses=()
  tools/workbench 3.3 >concurrent.1.log 2>&1 & first=$!
  tools/workbench 3.3 >concurrent.2.log 2>&1 & second=$!
  for pid in $first $second; do status=0; wait "$pid" || status=$?; statuses+=("$status"); done
  [[ "$(printf '%s\n' "${statuses[@]}" | sort | xargs)" == "0 2" ]] ||
    fail "round $round: the two exited with ${statuses[*]}, not 0 and 2: $(cat concurrent.*.log)"
  grep -q "already exists" concurrent.*.log || fail "round $round: the refusal does not say the folder exists"
  nested=$(find workbench -mindepth 1 -name '.making.*')
  [[ -z "$nested" ]] || fail "round $round: a copy left inside: $nested"
  [[ $(find workbench -mindepth 1 -maxdepth 1 ! -name .lock | wc -l) -eq 1 ]] ||
    fail "round $round: workbench/ holds $(ls -A workbench | xargs)"
done
rm -rf workbench
ok "three rounds: one made, one refused, nothing nested"

echo "== an empty workbench/ adds nothing to the build"
# The reader's build (Release: test programs at -O1, cmake/Stage.cmake). Under .ci/run's
# compiler cache, what the scratch copy shares with the clone (common/, oracle/, Catch2's
# main) comes from the full build's objects.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPHYSICS_WERROR=ON >build.log 2>&1 || { cat build.log; exit 1; }
[[ $(ctest --test-dir build -N -L workbench | grep -c "Test *#") -eq 0 ]] || fail "workbench tests without workbench/"
ok "no workbench tests"

echo "== a stage's label passes after building only the stage's target"
# Its pictures tests need compare_png, which the stage's target builds too; before it
# did, s1_1.pictures failed here, pointing to a diff folder that was never made.
SECONDS=0
cmake --build build -j "$jobs" --target s1_1 >s1_1.build.log 2>&1 || { cat s1_1.build.log; fail "s1_1 does not build"; }
ctest --test-dir build -L '^s1_1$' --output-on-failure >s1_1.log 2>&1 || fail "ctest -L '^s1_1\$' fails after building s1_1 (log: s1_1.log)"
ok "cmake --build build --target s1_1 && ctest -L '^s1_1\$' passes ($SECONDS s)"

echo "== tools/workbench 3.3, 4.3 and 1.1 (build/ is configured: it learns of them)"
for number in 3.3 4.3 1.1; do tools/workbench "$number" >/dev/null; done
refused "already exists" 3.3
[[ -f workbench/3.3_rectangle_collision/README.md && -f workbench/4.3_collision_impulse/README.md ]] ||
  fail "no README"
# names.md is one of the ready-made files: our 3.3's (3.3's overlay is 3.2's).
diff -r --exclude=README.md --exclude=STEP --exclude=expected --exclude=main.cpp --exclude=names.md ch3_collision/3.2_circle_collision \
  workbench/3.3_rectangle_collision >/dev/null || fail "workbench/3.3 is not 3.2's copy"
cmp -s ch3_collision/3.3_rectangle_collision/names.md workbench/3.3_rectangle_collision/names.md ||
  fail "workbench/3.3 has not our 3.3's names.md"
grep -q '\.id = "wb_s3_3"' workbench/3.3_rectangle_collision/main.cpp || fail "3.3's main.cpp does not run as wb_s3_3"
grep -q '^- new in 3.3, failing until you write it: the rectangle-rectangle test .* (wb_s3_3.rectangle_collision)$' \
  workbench/3.3_rectangle_collision/README.md || fail "3.3's README does not name rectangle_collision as new"
grep -q '^- new in 4.3, failing until you write it: the impulse method: .* (wb_s4_3.collision_impulse)$' \
  workbench/4.3_collision_impulse/README.md || fail "4.3's README does not name collision_impulse as new"
grep -q "^- new in 4.3: ours, not the book's: the overlay of impulses: .* (wb_s4_3.impulse_overlay)$" \
  workbench/4.3_collision_impulse/README.md || fail "4.3's README does not name impulse_overlay as ours"
ok "3.3 is 3.2 with 3.3's default run; the READMEs name the new features, the book's and ours"
# Our 4.3's overlay draws the impulses 4.2's engine does not record: it waits in
# ready_made/, saying what it needs; the rest of the ready-made files are in.
[[ -f workbench/4.3_collision_impulse/ready_made/overlay.cpp ]] || fail "4.3's overlay.cpp does not wait in ready_made/"
cmp -s ch4_response/4.2_positional_correction/overlay.cpp workbench/4.3_collision_impulse/overlay.cpp ||
  fail "4.3's folder does not keep 4.2's overlay.cpp"
grep -q "is a name of ours, not the book's" workbench/4.3_collision_impulse/ready_made/NEEDS.md ||
  fail "ready_made/NEEDS.md does not say what the overlay needs"
cmp -s ch4_response/4.3_collision_impulse/scene_io.cpp workbench/4.3_collision_impulse/scene_io.cpp ||
  fail "4.3's folder does not have our 4.3's scene_io.cpp"
ok "4.3's overlay waits in ready_made/ with what it needs; scene_io.cpp is ready-made"

# stage, our folder, its new feature, a feature that checks the stage's own book scene
# (4.3's MyGame adds a platform, so scene_files waits for the reader's my_game.cpp too),
# and the overlay's layer of the new feature (4.3 draws the impulses it adds), if any
for made in "3.3 ch3_collision/3.3_rectangle_collision rectangle_collision" \
            "4.3 ch4_response/4.3_collision_impulse collision_impulse scene_files impulse_overlay"; do
  read -r number ours new scene_feature overlay_feature <<<"$made"
  wb=wb_s${number/./_}
  folder=workbench/$(basename "$ours")
  echo "== $wb as made: $new fails, what the stage before had passes"
  SECONDS=0
  run_tests "$wb" "$wb.before.log"
  mapfile -t had < <(features_of "$(basename "$ours")" | grep -vx "$wb.$new" | grep -vx "$wb.${scene_feature:-none}" |
    grep -vx "$wb.${overlay_feature:-none}")
  ((${#had[@]} >= 7)) || fail "$wb: the README lists only ${#had[@]} earlier features"
  expect "$wb.before.log" Failed "$wb.$new"
  expect "$wb.before.log" Passed "${had[@]}"
  grep -q "^$wb.$new: .* (feature $new) fails (the checks above say where); it comes from book project $number, " \
    "$wb.before.log" || fail "$wb.$new's failure does not name book project $number"
  ok "the failure names book project $number ($SECONDS s)"

  echo "== tools/workbench --check $number: the first failing check, and the book project"
  SECONDS=0
  status=0
  tools/workbench --check "$number" >"$wb.check.log" 2>&1 || status=$?
  [[ $status -eq 1 ]] || fail "--check $number exited with $status, not 1 (log: $wb.check.log)"
  grep -q "^FAIL  .* ($wb.$new): " "$wb.check.log" || fail "--check $number does not stop at $new first (log: $wb.check.log)"
  tail -n 1 "$wb.check.log" | grep -q "^  it comes from book project $number, " ||
    fail "--check $number's last line does not name book project $number (log: $wb.check.log)"
  ok "--check $number stops at $new and names book project $number ($SECONDS s)"

  echo "== $wb with our $number files copied in: every test passes, pictures included"
  SECONDS=0
  find "$ours" -maxdepth 1 -type f ! -name README.md -exec cp {} "$folder"/ \;
  run_tests "$wb" "$wb.after.log"
  expect "$wb.after.log" Passed "${had[@]}" "$wb.$new" ${scene_feature:+"$wb.$scene_feature"} \
    ${overlay_feature:+"$wb.$overlay_feature"} "$wb.stage" "$wb.pictures"
  grep -q "100% tests passed" "$wb.after.log" || fail "$wb: not every test passed (log: $wb.after.log)"
  ok "all of $wb's tests pass ($SECONDS s)"
  tools/workbench --check "$number" >"$wb.check.log" 2>&1 || fail "--check $number fails with our files (log: $wb.check.log)"
  tail -n 1 "$wb.check.log" | grep -qx "every check of your $number passes, pictures included" ||
    fail "--check $number does not say every check passes (log: $wb.check.log)"
  ok "--check $number passes every check"
  program=build/${wb}_$(basename "$ours" | sed 's/^[0-9.]*_//')
  # The loop never runs a program older than its sources: stage_keys runs the program.
  sleep 1
  sed -i 's/\.title = "/.title = "(mine) /' "$folder/main.cpp"
  tools/workbench --check "$number" stage_keys >"$wb.keys.log" 2>&1 || fail "--check $number stage_keys (log: $wb.keys.log)"
  [[ "$program" -nt "$folder/main.cpp" ]] || fail "--check $number stage_keys ran $program, older than main.cpp"
  ok "--check $number stage_keys built $program again after main.cpp changed"
done

echo "== wb_s1_1 from an empty program: builds, and its tests fail, not skipped"
run_tests wb_s1_1 wb_s1_1.log
expect wb_s1_1.log Passed wb_s1_1.build
expect wb_s1_1.log Failed wb_s1_1.stage wb_s1_1.pictures
grep -q '^wb_s1_1.stage: .* does not build yet; it comes from book project 1.1, "HTML5 Canvas Project"' wb_s1_1.log ||
  fail "wb_s1_1.stage does not say it does not build yet"
grep -q "first error: .*core.h" wb_s1_1.log || fail "wb_s1_1.stage does not quote the first error"
ok "wb_s1_1.stage names book project 1.1 and quotes the first error"

echo "== tools/workbench --list: the verdicts of the last runs, at once"
SECONDS=0
tools/workbench --list >list.log
cat list.log
# 3.3 and 4.3 each had a file changed after their last full run (main.cpp, above).
grep -qx "3.3_rectangle_collision  wb_s3_3  13 of 13 tests pass (when last run; your files changed since: tools/workbench --check 3.3)" list.log ||
  fail "--list: wb_s3_3"
grep -qx "4.3_collision_impulse  wb_s4_3  23 of 23 tests pass (when last run; your files changed since: tools/workbench --check 4.3)" list.log ||
  fail "--list: wb_s4_3"
grep -qx "1.1_canvas  wb_s1_1  0 of 3 tests pass" list.log || fail "--list: wb_s1_1"
((SECONDS <= 5)) || fail "--list took $SECONDS s"
ok "--list counts them ($SECONDS s)"
echo "check_workbench: all passed"
