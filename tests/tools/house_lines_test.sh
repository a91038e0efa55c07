#!/usr/bin/env bash
# tools/house_lines on a scratch repository whose line counts are known (CTest
# tools.house_lines, label tools): the book's engine is what names.md's Files table gives
# as ours for a book file, index.html aside; the page is main.cpp, page_world.* and
# scene_io.*; the rest is every other .h and .cpp; files are every file of the folder.
# Two revisions side by side give "before → after"; a revision that is not one is
# refused in one line with a non-zero status.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
lines() { # <file> <n>: a file of n lines
  mkdir -p "$(dirname "$1")"
  for ((k = 0; k < $2; k++)); do echo "// $k"; done > "$1"
}
cd "$scratch"
git init -q . && git config user.email t@t && git config user.name t
stage=ch4_response/4.1_moves
mkdir -p "$stage"
cat > "$stage/names.md" <<'MD'
# names

## Files

| book | ours | in | note |
| --- | --- | --- | --- |
| `index.html` | `main.cpp` | `main.cpp` | the page |
| `EngineCore/Core.js` | `core.h`, `core.cpp` | `core.h` |  |
| `Lib/Vec2.js` | `Vec2` | `../../common/vec2.h` | shared |

## Classes and functions

| book | ours | in | note |
| --- | --- | --- | --- |
| `update` | `overlay.cpp` | `core.h` | not a file table: not counted as the book's |
MD
lines "$stage/core.h" 10
lines "$stage/core.cpp" 20
lines "$stage/main.cpp" 7
lines "$stage/scene_io.cpp" 5
lines "$stage/page_world.h" 3
lines "$stage/overlay.cpp" 11
echo "text" > "$stage/README.md"
git add -A && git commit -qm before
before=$(git rev-parse HEAD)
lines "$stage/core.cpp" 25
lines "$stage/grid.cpp" 4
git add -A && git commit -qm after

out=$("$repo/tools/house_lines" "$before")
# book 10 + 20; page 7 + 5 + 3; rest 11; files: 8 (names.md and README.md included)
grep -qx '| 4.1 | 30 | 15 | 11 | 8 |' <<< "$out" || fail "one revision: $out"
echo "ok: one revision"
out=$("$repo/tools/house_lines" "$before" HEAD)
grep -qx '| 4.1 | 30 → 35 | 15 → 15 | 11 → 15 | 8 → 9 |' <<< "$out" || fail "two revisions: $out"
echo "ok: two revisions"
status=0
err=$("$repo/tools/house_lines" no-such-rev 2>&1 >/dev/null) || status=$?
[[ $status -ne 0 && $(wc -l <<< "$err") -eq 1 && "$err" == *"no such revision"* ]] || fail "bad revision: $status $err"
echo "ok: a revision that is not one is refused in one line"
