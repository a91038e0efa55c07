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
#   - tools/workbench --list counts the passing tests.
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
features_of() { grep -E "^- (New in|From the projects before)" "workbench/$1/README.md" | grep -oE '`wb_s[0-9_]+\.[a-z_]+`' | tr -d '`'; }

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
[[ ! -e workbench ]] || fail "a refusal left workbench/ behind"
ok "refusals made nothing"

echo "== an empty workbench/ adds nothing to the build"
# The reader's build (Release: test programs at -O1, cmake/Stage.cmake). Under .ci/run's
# compiler cache, what the scratch copy shares with the clone (common/, oracle/, Catch2's
# main) comes from the full build's objects.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPHYSICS_WERROR=ON >build.log 2>&1 || { cat build.log; exit 1; }
[[ $(ctest --test-dir build -N -L workbench | grep -c "Test *#") -eq 0 ]] || fail "workbench tests without workbench/"
ok "no workbench tests"

echo "== tools/workbench 3.3, 4.3 and 1.1 (build/ is configured: it learns of them)"
for number in 3.3 4.3 1.1; do tools/workbench "$number" >/dev/null; done
refused "already exists" 3.3
[[ -f workbench/3.3_rectangle_collision/README.md && -f workbench/4.3_collision_impulse/README.md ]] ||
  fail "no README"
diff -r --exclude=README.md --exclude=STEP --exclude=expected --exclude=main.cpp ch3_collision/3.2_circle_collision \
  workbench/3.3_rectangle_collision >/dev/null || fail "workbench/3.3 is not 3.2's copy"
grep -q '\.id = "wb_s3_3"' workbench/3.3_rectangle_collision/main.cpp || fail "3.3's main.cpp does not run as wb_s3_3"
grep -q '^- New in 3.3, failing until you write it: `wb_s3_3.rectangle_collision`.$' \
  workbench/3.3_rectangle_collision/README.md || fail "3.3's README does not name rectangle_collision as new"
grep -q '^- New in 4.3, failing until you write it: `wb_s4_3.collision_impulse`, `wb_s4_3.impulse_overlay`.$' \
  workbench/4.3_collision_impulse/README.md || fail "4.3's README does not name collision_impulse as new"
ok "3.3 is 3.2 with 3.3's default run; the READMEs name the new features"

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
  grep -q "^$wb.$new: feature $new fails (the checks above say where); it comes from book project $number, " \
    "$wb.before.log" || fail "$wb.$new's failure does not name book project $number"
  ok "the failure names book project $number ($SECONDS s)"

  echo "== tools/workbench --check $number: the first failing check, and the book project"
  SECONDS=0
  status=0
  tools/workbench --check "$number" >"$wb.check.log" 2>&1 || status=$?
  [[ $status -eq 1 ]] || fail "--check $number exited with $status, not 1 (log: $wb.check.log)"
  grep -q "^FAIL  $wb.$new" "$wb.check.log" || fail "--check $number does not stop at $new first (log: $wb.check.log)"
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
done

echo "== wb_s1_1 from an empty program: builds, and its tests fail, not skipped"
run_tests wb_s1_1 wb_s1_1.log
expect wb_s1_1.log Passed wb_s1_1.build
expect wb_s1_1.log Failed wb_s1_1.stage wb_s1_1.pictures
grep -q '^wb_s1_1.stage: .* does not build yet; it comes from book project 1.1, "HTML5 Canvas Project"' wb_s1_1.log ||
  fail "wb_s1_1.stage does not say it does not build yet"
grep -q "first error: .*core.h" wb_s1_1.log || fail "wb_s1_1.stage does not quote the first error"
ok "wb_s1_1.stage names book project 1.1 and quotes the first error"

echo "== tools/workbench --list"
tools/workbench --list >list.log
cat list.log
grep -qx "3.3_rectangle_collision  wb_s3_3  13 of 13 tests pass" list.log || fail "--list: wb_s3_3"
grep -qx "4.3_collision_impulse  wb_s4_3  23 of 23 tests pass" list.log || fail "--list: wb_s4_3"
grep -qx "1.1_canvas  wb_s1_1  0 of 3 tests pass" list.log || fail "--list: wb_s1_1"
ok "--list counts them"
echo "check_workbench: all passed"
