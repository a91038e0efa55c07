#!/usr/bin/env bash
# Checks a stage's name map (its names.md): every C++ name in backquotes in the second
# column ("ours") is in one of the files the third column ("in") names, and those files
# exist. A file name in the second column (core.h) must be a file of the stage.
# A qualified name (Core::width, world.gravity) passes when it is there as written or
# when each of its parts is.
#
# usage: check_name_map.sh STAGE_FOLDER            the map passes: exit 0, else 1
#        check_name_map.sh --mutated STAGE_FOLDER  the checker can fail: every name of
#            the map, each changed by two letters, must then be reported missing (exit
#            0 when all of them are, else 1)
# Each problem is one line naming the map's row and the name.
set -uo pipefail

mutate=no
if [[ "${1:-}" == --mutated ]]; then mutate=yes; shift; fi
folder=${1:?usage: check_name_map.sh [--mutated] STAGE_FOLDER}
map="$folder/names.md"
[[ -f "$map" ]] || { echo "$map: no such file"; exit 1; }

# A name as the map writes it, changed so that it can be nowhere: Zq after its last
# part, or before a file name's extension.
mutated() {
  local name=$1
  if [[ "$name" =~ ^(.*)(\.(h|cpp|json))$ ]]; then echo "${BASH_REMATCH[1]}Zq${BASH_REMATCH[2]}"; else echo "${name}Zq"; fi
}

# Whether `name` is in one of the files: as written, or each of its parts.
found_in() {
  local name=$1; shift
  grep -qwF -- "$name" "$@" 2>/dev/null && return 0
  local part parts=${name//::/ }
  for part in ${parts//./ }; do
    grep -qwF -- "$part" "$@" 2>/dev/null || return 1
  done
  return 0
}

# One line a problem; the --mutated run counts them only.
report() { [[ $mutate == yes ]] || echo "$map:$line_number: $*"; }

checked=0 missing=0 line_number=0
while IFS= read -r line; do
  line_number=$((line_number + 1))
  [[ "$line" == "| "* && "$line" != "| book |"* && "$line" != "| --- "* ]] || continue
  IFS='|' read -r _ book ours in note <<<"$line"
  files=()
  for quoted in $(grep -o '`[^`]*`' <<<"$in" | tr -d '`'); do
    if [[ ! -f "$folder/$quoted" ]]; then
      report "the file \`$quoted\` is not there"
      missing=$((missing + 1))
    fi
    files+=("$folder/$quoted")
  done
  while IFS= read -r name; do
    [[ -n "$name" ]] || continue
    [[ $mutate == yes ]] && name=$(mutated "$name")
    checked=$((checked + 1))
    if [[ "$name" =~ \.(h|cpp|json)$ ]]; then
      [[ -f "$folder/$name" ]] && continue
      report "\`$name\` is no file of the stage"
    else
      found_in "$name" "${files[@]}" && continue
      report "\`$name\` is not in$(tr -s ' ' <<<"${in//\`/}")"
    fi
    missing=$((missing + 1))
  done < <(grep -o '`[^`]*`' <<<"$ours" | tr -d '`')
done <"$map"

if [[ $mutate == yes ]]; then
  if ((checked > 0 && missing == checked)); then
    echo "every one of the $checked names, changed, is reported missing"
    exit 0
  fi
  echo "FAILED: only $missing of the $checked changed names are reported missing"
  exit 1
fi
((checked > 0)) || { echo "$map: no names in backquotes to check"; exit 1; }
if ((missing > 0)); then
  echo "FAILED: $missing of the $checked names of $map are not where it says"
  exit 1
fi
echo "all $checked names of $map are where it says"
