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
differing=$(diff -rq --exclude=README.md --exclude=STEP --exclude=expected --exclude=.bug --exclude=main.cpp "$ours" "$hunt" || true)
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
tools/workbench --next-bug $stage >/dev/null
next=$(field $(((index + 1) % count)) mutant)
[[ "$(tools/workbench --reveal $stage | head -n 1)" == "the bug planted in $hunt: $next" ]] ||
  fail "--next-bug did not plant \"$next\""
ok "next: $next"

echo "== the reader's own 3.2 in the way"
rm -rf "$hunt"
mkdir -p workbench/3.2_circle_collision
refused "is your own $stage" --bug $stage
echo "check_bug_hunt: all passed"
