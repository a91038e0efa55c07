# Sourced by the workbench checks (check_workbench.sh, check_bug_hunt.sh), with the
# check's name: `source "$(dirname "$0")/scratch_copy.sh" NAME`. Makes a scratch copy of
# the repository's tracked files and goes into it, so that the repository's own build
# and workbench/ are never touched (KEEP=1 keeps the copy), and gives the checks their
# verdicts: fail, ok, refused (a tools/workbench call that must be refused) and
# verdict (what ctest said of one test).
check_name=${1:?usage: source scratch_copy.sh NAME}
repository=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
scratch=$(mktemp -d "${TMPDIR:-/tmp}/$check_name.XXXXXX")
if [[ "${KEEP:-}" == 1 ]]; then echo "scratch copy: $scratch"; else trap 'rm -rf "$scratch"' EXIT; fi
if git -C "$repository" rev-parse --git-dir >/dev/null 2>&1; then
  git -C "$repository" ls-files -z | (cd "$repository" && tar --null -T - -cf -) | tar -xf - -C "$scratch"
else  # not a clone: everything but build folders, pictures and workbenches
  tar -C "$repository" --exclude='./build*' --exclude=./out --exclude=./workbench -cf - . | tar -xf - -C "$scratch"
fi
cd "$scratch"

fail() {
  echo "$check_name: FAILED: $*" >&2
  exit 1
}
ok() { echo "  ok: $*"; }

# tools/workbench <arguments> must refuse in one line containing <words>, with status 2.
refused() {
  local words=$1 output status=0
  shift
  output=$(tools/workbench "$@" 2>&1) || status=$?
  [[ $status -eq 2 ]] || fail "tools/workbench $* exited with $status, not 2: $output"
  [[ $(wc -l <<<"$output") -eq 1 ]] || fail "tools/workbench $* said more than one line: $output"
  [[ "$output" == *"$words"* ]] || fail "tools/workbench $* did not say \"$words\": $output"
  ok "tools/workbench $* refused: $output"
}

# ctest's verdict on test <name> in <log>: Passed, Failed, Not Run, ... or nothing.
verdict() { sed -nE "s/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: $2 \.+ *(\*\*\*)?([A-Za-z ]*[A-Za-z]).*/\2/p" "$1"; }
