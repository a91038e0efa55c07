#!/usr/bin/env bash
# check_knows_no_engine.sh ROOT [COMMON]: common/ (or COMMON) knows no engine
# (DESIGN.md): no shape kind, body key, solver or stage id, in its code or its comments.
# A stage declares its own words (its scene_io.cpp); docs/scene_format.md tables them, and
# each stage's tests hold the tables against its declaration, so the words looked for here
# are the tables' own, and the stage ids those of the stage folders.
#   - shape kinds and body keys: every word of the body-key table (its `shape` row's words
#     and every key); a key that is also plain geometry (center, width, height, angle,
#     velocity) only where it is spelled as a scene key, "center";
#   - solvers: the words of the `solver` row and "solver", "relaxation";
#   - stage ids: X.Y and sX_Y of every stage folder.
# Two places are let off, each for its own words only:
#   - canvas.h and canvas.cpp: the HTML5 canvas's own geometry (arc of a radius, rect),
#     what a browser draws with;
#   - the state dump's columns, shape, angle and angular_velocity (state_dump, dump_divergence
#     and stage_main's ObjectState, which the dump writes): the dump's format.
# Prints every hit as FILE:LINE: WORD and exits 1 when there is one.
# With --planted as COMMON, the check proves it can fail: it plants a body key in a copy
# of common/ and passes only when that one line is what it reports.
set -euo pipefail
root=$1
common=${2:-$root/common}
if [[ $common == --planted ]]; then
  copy=$(mktemp -d)
  trap 'rm -rf "$copy"' EXIT
  cp -r "$root/common" "$copy/common"
  echo "// the restitution of a bounce" >>"$copy/common/page.h"
  found=$("$0" "$root" "$copy/common" || true)
  [[ $found == "$copy/common/page.h:"*":restitution" ]] && exit 0
  echo "check_knows_no_engine: a planted body key was not found alone; it reported: $found" >&2
  exit 1
fi
format=$root/docs/scene_format.md

table_after() {  # the table rows that follow the heading $1
  awk -v heading="$1" '$0 == heading { on = 1; next } on && /^\|/ { print; seen = 1; next } seen { exit }' "$format"
}
body_rows=$(table_after "## Body keys" | tail -n +3)
world_rows=$(table_after "## Which stage reads which world key" | tail -n +3)
[[ -n $body_rows && -n $world_rows ]] || { echo "check_knows_no_engine: no key tables in $format" >&2; exit 2; }

keys=$(sed -n 's/^| `\([a-z_]*\)`.*/\1/p' <<<"$body_rows")
kinds=$(grep '^| `shape`' <<<"$body_rows" | cut -d'|' -f4 | grep -o '"[a-z_]*"' | tr -d '"')
solvers=$(grep '^| `solver`' <<<"$world_rows" | cut -d'|' -f3 | grep -o '"[a-z_]*"' | tr -d '"' | grep -vx book || true)
geometry="shape center width height angle velocity"
plain=() quoted=()
for word in $keys $kinds $solvers solver relaxation; do
  if [[ " $geometry " == *" $word "* ]]; then quoted+=("$word"); else plain+=("$word"); fi
done
stages=$(ls -d "$root"/ch*_*/[0-9]*.[0-9]*_* | sed 's|.*/\([0-9]*\)\.\([0-9]*\)_.*|\1.\2 s\1_\2|')
ids=()
for id in $stages; do ids+=("${id//./\\.}"); done

plain_pattern="\\b($(IFS='|'; echo "${plain[*]}"))s?\\b"
quoted_pattern="\"($(IFS='|'; echo "${quoted[*]}"))\""
id_pattern="(^|[^0-9.])($(IFS='|'; echo "${ids[*]}"))([^0-9]|$)"

hits=$( (grep -rnoiE "$plain_pattern" "$common" || true; grep -rnoE "$quoted_pattern" "$common" || true;
         grep -rnoE "$id_pattern" "$common" || true) | sort -u)
let_off() {  # FILE:LINE:WORD -> whether a let-off place may say it
  local file=${1%%:*} word=${1##*:}
  word=$(tr -d '"' <<<"$word" | tr 'A-Z' 'a-z')
  case $(basename "$file") in
    canvas.h | canvas.cpp) [[ $word =~ ^(radius|radii|rectangles?|circles?)$ ]] ;;
    state_dump.h | state_dump.cpp | dump_divergence.h | dump_divergence.cpp | stage_main.h | stage_main.cpp)
      [[ $word =~ ^(shape|angle|angular_velocity|rectangle)$ ]] ;;
    *) false ;;
  esac
}
status=0
while IFS= read -r hit; do
  [[ -z $hit ]] && continue
  let_off "$hit" && continue
  echo "$hit"
  status=1
done <<<"$hits"
exit $status
