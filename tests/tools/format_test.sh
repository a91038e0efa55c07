#!/usr/bin/env bash
# tools/format given files by name (CTest tools.format, label tools): clang-format lays
# out whatever it is handed as C++, so a Markdown file or a scene named by mistake must be
# refused, in one line with status 2, and nothing rewritten, not even the C++ files named
# beside it. A misplaced C++ file is laid out.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
command -v clang-format-14 >/dev/null || { echo "SKIP: clang-format-14 is not installed"; exit 0; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
cp "$repo/.clang-format" "$scratch/"
mkdir -p "$scratch/tools"
cp "$repo/tools/format" "$scratch/tools/"
cd "$scratch"
printf '# Title\n\n| a | b |\n|---|---|\n| `x` | long text, long text, long text, long text, long text, long text, long text, long |\n' >notes.md
printf 'int   f( ){return 1;}\n' >code.cpp
cp notes.md notes.before
cp code.cpp code.before
status=0
message=$(tools/format notes.md code.cpp 2>&1) || status=$?
[[ $status == 2 ]] || fail "a Markdown file named: status $status, 2 expected"
[[ $(printf '%s\n' "$message" | wc -l) == 1 && $message == *"notes.md is not a C++ file"* ]] ||
  fail "a Markdown file named: \"$message\""
cmp -s notes.md notes.before || fail "the Markdown file was rewritten"
cmp -s code.cpp code.before || fail "the C++ file named beside it was rewritten"
status=0
message=$(tools/format missing.cpp 2>&1) || status=$?
[[ $status == 2 && $message == *"missing.cpp is not a file"* ]] || fail "a missing file: status $status, \"$message\""
tools/format code.cpp
[[ $(cat code.cpp) == "int f() { return 1; }" ]] || fail "code.cpp was not laid out: $(cat code.cpp)"
echo "ok: tools/format refuses what is not C++ and changes nothing; lays out what is"
