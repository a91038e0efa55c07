# The list of stages (stages.txt at the top) for the tools, which source this file:
#   source "$(dirname "$0")/lib/stages.sh"
# Every tool finds a stage here, by its exact number (3.3), id (s3_3) or folder
# (ch3_collision/3.3_rectangle_collision), never by a pattern of folder names: 5.1 is
# never 5.10. A function that finds nothing prints nothing and returns 1.

stages_list=${stages_list:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/stages.txt}

# Each stage of the list, oldest first, as "number folder".
stage_rows() {
  awk '/^[^ \t#]/ {folder = $1; number = folder; sub(/^[^\/]*\//, "", number); sub(/_.*/, "", number)
                   print number, folder}' "$stages_list"
}

# Every stage number, oldest first.
stage_numbers() { stage_rows | cut -d' ' -f1; }

# The number of stage <number, id or folder>: 3.3 for 3.3, s3_3 or
# ch3_collision/3.3_rectangle_collision (a "/" at the end is allowed).
stage_number() {
  local given=${1%/} number folder
  while read -r number folder; do
    if [[ "$given" == "$number" || "$given" == "s${number/./_}" || "$given" == "$folder" ]]; then
      echo "$number"
      return 0
    fi
  done < <(stage_rows)
  return 1
}

# The folder of stage <number>, as ch3_collision/3.3_rectangle_collision.
stage_folder() {
  local number folder
  while read -r number folder; do
    if [[ "$1" == "$number" ]]; then
      echo "$folder"
      return 0
    fi
  done < <(stage_rows)
  return 1
}

# What the folder says of stage <number>: its id (s3_3), program (rectangle_collision;
# build/s3_3_rectangle_collision is the binary) and chapter label (ch3).
stage_id() { stage_folder "$1" >/dev/null && echo "s${1/./_}"; }
stage_program() {
  local folder
  folder=$(stage_folder "$1") || return 1
  folder=${folder#*/}
  echo "${folder#*_}"
}
stage_chapter() {
  local folder
  folder=$(stage_folder "$1") || return 1
  echo "${folder%%_*}"
}

# The stage before <number> and the one after it, or nothing (return 1) at either end.
stage_previous() {
  stage_numbers | awk -v number="$1" '$0 == number {found = 1; if (before != "") print before; exit}
                                      {before = $0} END {exit !(found && before != "")}'
}
stage_next() {
  stage_numbers | awk -v number="$1" 'taken {print; found = 1; exit} $0 == number {taken = 1} END {exit !found}'
}

# The newest stage's number.
stage_newest() { stage_numbers | tail -n 1; }

# The value of <key> (project, page, read, bench) given for stage <number>.
stage_fact() {
  awk -v number="$1" -v key="$2" '
    /^[^ \t#]/ {here = $1; sub(/^[^\/]*\//, "", here); sub(/_.*/, "", here); mine = (here == number); next}
    mine && $1 == key {sub(/^[ \t]+[^ \t]+[ \t]+/, ""); print; found = 1; exit}
    END {exit !found}' "$stages_list"
}

# The feature tests of stage <number>, one a line: with "new", only those that start
# there; otherwise every one it has (a stage keeps the features of the stages before).
stage_features() {
  stage_folder "$1" >/dev/null || return 1
  awk -v number="$1" -v only_new="${2:-}" '
    /^[^ \t#]/ {if (mine) exit; here = $1; sub(/^[^\/]*\//, "", here); sub(/_.*/, "", here); mine = (here == number); next}
    $1 == "features" && (mine || only_new == "") {for (i = 2; i <= NF; i++) print $i}' "$stages_list"
}
