#!/usr/bin/env bash
# The bug hunt, end to end (tools/workbench --bug/--reveal/--next-bug), in a scratch copy
# of the repository's tracked files, so that the repository's own build and workbench/
# are never touched:
#   - refusals: no such stage, not a stage number, a stage without planted bugs, a bad
#     BUG_SEED, --reveal and --next-bug with no hunt, a second hunt, the reader's own
#     folder in the way;
#   - BUG_SEED=k plants bug k (mod the list's length) of tests/mutants/s3_2.txt, in one
#     file, and nothing in the folder names it;
#   - the stage's tests fail on it; --reveal names it and shows its diff;
#   - our file copied back: --reveal says fixed, and the tests that caught it pass;
#   - --next-bug plants the next bug of the list.
# Builds only wb_s3_2. KEEP=1 keeps the copy.
set -euo pipefail
source "$(dirname "$0")/scratch_copy.sh" check_bug_hunt
jobs=$(nproc)
stage=3.2
ours=ch3_collision/3.2_circle_collision
list=tests/mutants/s3_2.txt
hunt=workbench/3.2_bug_hunt

# Field <key> of the <k>th mutant (from 0) of the list, read here, not by tools/workbench.
field() { sed -n "s/^$2: *//p" "$list" | sed -n "$(($1 + 1))p" | sed 's/[[:space:]]*$//'; }

echo "== refusals"
refused "no stage 9.9" --bug 9.9
refused "not a stage number" --bug 3.2/x
refused "not a stage number" --bug "3.2;rm"
refused "takes one stage number" --bug
refused "has no planted bugs" --bug 2.1
BUG_SEED=x refused "BUG_SEED must be a whole number" --bug $stage
BUG_SEED=-1 refused "BUG_SEED must be a whole number" --bug $stage
BUG_SEED=1e3 refused "BUG_SEED must be a whole number" --bug $stage
BUG_SEED=$(printf '9%.0s' {1..101}) refused "BUG_SEED must be a whole number of 1 to 100 digits" --bug $stage
# Stage numbers are text: 03.2 and 3.20 are no stages (issue 36).
refused "no stage 03.2" --bug 03.2
refused "no stage 3.20" --bug 3.20
refused "no stage 03.2" --next-bug 03.2
refused "no bug hunt for $stage" --reveal $stage
refused "no bug hunt for $stage" --next-bug $stage
[[ ! -e workbench ]] || fail "a refusal left workbench/ behind"
ok "refusals made nothing"

echo "== BUG_SEED=15 plants bug 15 mod the list's length"
count=$(grep -c '^mutant:' "$list")
((count >= 8)) || fail "$list has $count bugs, fewer than 8"
seed=15
index=$((seed % count))
name=$(field $index mutant)
file=$(field $index file)
# ccache when there is one: a scratch copy under ccache's base_dir shares its objects.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPHYSICS_WERROR=ON "${launcher[@]}" >build.log 2>&1 ||
  { cat build.log; exit 1; }
BUG_SEED=$seed tools/workbench --bug $stage >made.log
[[ -f $hunt/.bug && -f $hunt/README.md ]] || fail "no $hunt with its .bug and README.md"
differing=$(diff -rq --exclude=README.md --exclude=STEP --exclude=expected --exclude=.bug --exclude=.written --exclude=main.cpp "$ours" "$hunt" || true)
[[ "$differing" == "Files $ours/$file and $hunt/$file differ" ]] || fail "not one file planted: $differing"
[[ $(diff "$ours/$file" "$hunt/$file" | grep -c '^[<>]') -eq 2 ]] || fail "$file: more than one line changed"
grep -qrF -- "$name" "$hunt" && fail "the folder names its bug"
grep -qF "$(field $index from)" "$hunt/$file" && fail "the planted file still has the original text"
ok "one line of $file changed, and nothing in $hunt names the bug"
refused "is there already" --bug $stage

echo "== wb_s3_2 on the planted bug: the tests that catch it fail"
SECONDS=0
ctest --test-dir build -L '^wb_s3_2$' -j "$jobs" >planted.log 2>&1 || true
caught=$(field $index caught)
failed=""
for test in $caught; do
  [[ "$(verdict planted.log "wb_$test")" == Failed ]] && failed+=" wb_$test"
done
[[ -n "$failed" ]] || fail "none of $caught failed as wb_ (log: planted.log)"
[[ "$(verdict planted.log wb_s3_2.build)" == Passed ]] || fail "the bug hunt does not build (log: planted.log)"
ok "failed:$failed ($SECONDS s)"

echo "== --reveal names it and shows its diff"
tools/workbench --reveal $stage >reveal.log
[[ "$(head -n 1 reveal.log)" == "the bug planted in $hunt: $name" ]] || fail "--reveal: $(head -n 1 reveal.log)"
grep -qxF -- "-$(grep -F "$(field $index from)" "$ours/$file")" reveal.log || fail "--reveal shows no - line"
grep -qxF -- "+$(grep -F "$(field $index to)" "$hunt/$file" | head -n 1)" reveal.log || fail "--reveal shows no + line"
grep -qx "your $file still has it." reveal.log || fail "--reveal does not say the bug is still there"
ok "--reveal: $name"

echo "== our $file copied back: fixed, and the tests that caught it pass"
cp "$ours/$file" "$hunt/$file"
tools/workbench --reveal $stage | grep -qx "your $file is ours again: found and fixed." || fail "--reveal misses the fix"
ctest --test-dir build -R "^(wb_s3_2\.build|$(sed 's/^ //; s/ /|/g; s/\./\\./g' <<<"$failed"))\$" >fixed.log 2>&1 ||
  fail "the tests that caught it still fail after the fix (log: fixed.log)"
ok "fixed:$failed pass"

echo "== --next-bug plants the next one"
# The fixed file is ours again: nothing of the reader's to lose, so it does not ask.
tools/workbench --next-bug $stage </dev/null >/dev/null
next=$(field $(((index + 1) % count)) mutant)
[[ "$(tools/workbench --reveal $stage | head -n 1)" == "the bug planted in $hunt: $next" ]] ||
  fail "--next-bug did not plant \"$next\""
ok "next: $next"

echo "== --next-bug keeps the reader's own files, and asks before it replaces a changed one"
# It used to remove the folder whole: notes, experiments and fixes tried went with it,
# and a read-only subfolder left a half-removed hunt (issue 36). BUILD_DIR=none: no
# build to configure again, these only look at the folder.
echo "what I suspect: the normal" >"$hunt/notes.txt"
mkdir -p "$hunt/experiments/read_only"
echo "a scene of mine" >"$hunt/experiments/read_only/scene.json"
chmod a-w "$hunt/experiments/read_only"
echo "// a fix I tried" >>"$hunt/physics.cpp"
listing() { (cd "$hunt" && find . -print0 | sort -z | xargs -0 ls -ld --time-style=+ | awk '{print $1, $NF}'; cat physics.cpp .bug); }
before=$(listing)
BUILD_DIR=none refused "your changes to physics.cpp" --next-bug $stage </dev/null
[[ "$(listing)" == "$before" ]] || fail "a refused --next-bug changed $hunt"
BUILD_DIR=none refused "left as it was" --next-bug $stage <<<"n"
[[ "$(listing)" == "$before" ]] || fail "--next-bug answered n changed $hunt"
ok "refused without a yes, the folder as it was"
echo y | BUILD_DIR=none tools/workbench --next-bug $stage >next.log 2>&1 || fail "--next-bug answered y: $(cat next.log)"
after=$(field $(((index + 2) % count)) mutant)
[[ "$(tools/workbench --reveal $stage | head -n 1)" == "the bug planted in $hunt: $after" ]] ||
  fail "--next-bug answered y did not plant \"$after\""
[[ "$(cat "$hunt/notes.txt")" == "what I suspect: the normal" ]] || fail "notes.txt did not stay"
[[ -f "$hunt/experiments/read_only/scene.json" ]] || fail "experiments/ did not stay"
grep -q "a fix I tried" "$hunt/physics.cpp" && fail "the changed physics.cpp was not replaced"
grep -q '^kept as they were, yours: `experiments`, `notes.txt`$' next.log || fail "it does not say what it kept: $(cat next.log)"
ok "replaced after a yes; notes.txt and experiments/ (read-only inside) kept"
chmod u+w "$hunt/experiments/read_only"

echo "== two --next-bug at once: one after the other, nothing nested"
# Both used to remove the folder and move theirs in: the second into the first's.
BUILD_DIR=none tools/workbench --next-bug $stage </dev/null >concurrent.1.log 2>&1 & first=$!
BUILD_DIR=none tools/workbench --next-bug $stage </dev/null >concurrent.2.log 2>&1 & second=$!
wait $first || fail "the first --next-bug failed: $(cat concurrent.1.log)"
wait $second || fail "the second --next-bug failed: $(cat concurrent.2.log)"
nested=$(find workbench -mindepth 1 -name '.making.*')
[[ -z "$nested" ]] || fail "a copy left inside: $nested"
after=$(field $(((index + 4) % count)) mutant)
[[ "$(tools/workbench --reveal $stage | head -n 1)" == "the bug planted in $hunt: $after" ]] ||
  fail "two --next-bug did not plant the bug two further on, \"$after\""
ok "each took its turn: $after"

echo "== BUG_SEED read as a number of any length, in base 10"
for seed in 08 12345678901234567890; do
  rm -rf "$hunt"
  BUG_SEED=$seed BUILD_DIR=none tools/workbench --bug $stage >/dev/null 2>seed.log || fail "BUG_SEED=$seed: $(cat seed.log)"
  wanted=$(field "$(python3 -c "print(int('$seed') % $count)")" mutant)
  [[ "$(tools/workbench --reveal $stage | head -n 1)" == "the bug planted in $hunt: $wanted" ]] ||
    fail "BUG_SEED=$seed did not plant \"$wanted\""
done
ok "08 and a 20-digit seed plant the bug their remainder names"

echo "== two --bug at once: one plants, the other is refused"
rm -rf "$hunt"
BUILD_DIR=none tools/workbench --bug $stage >concurrent.1.log 2>&1 & first=$!
BUILD_DIR=none tools/workbench --bug $stage >concurrent.2.log 2>&1 & second=$!
statuses=()
for pid in $first $second; do status=0; wait "$pid" || status=$?; statuses+=("$status"); done
[[ "$(printf '%s\n' "${statuses[@]}" | sort | xargs)" == "0 2" ]] ||
  fail "the two exited with ${statuses[*]}, not 0 and 2: $(cat concurrent.*.log)"
[[ -z "$(find workbench -mindepth 1 -name '.making.*')" ]] || fail "a copy left inside"
ok "one planted, one refused"

echo "== the reader's own 3.2 in the way"
rm -rf "$hunt"
mkdir -p workbench/3.2_circle_collision
refused "is your own $stage" --bug $stage
echo "check_bug_hunt: all passed"
