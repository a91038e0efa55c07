#!/usr/bin/env bash
# The determinism check can fail: a stand-in for the clang build runs the g++ build's
# program and then changes one digit of the dump (step 3, body 0, cx). The check must
# exit 1 and name that step and body. Used by ctest (determinism.sees_a_difference):
#   tests/determinism/sees_a_difference.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(cd "$1" && pwd)
source tools/lib/stages.sh
program=$(stage_id "$(stage_newest)")_$(stage_program "$(stage_newest)")
stand_in=$(mktemp -d)
trap 'rm -rf "$stand_in"' EXIT
cat >"$stand_in/$program" <<STANDIN
#!/usr/bin/env bash
set -euo pipefail
"$build/$program" "\$@"
dump=""
while ((\$#)); do [[ \$1 == --dump ]] && dump=\$2; shift; done
# The first row of step 3: its cx, one more in its last digit.
awk -F, 'BEGIN { OFS = "," } \$1 == 3 && \$2 == 0 && !done { \$4 = \$4 "1"; done = 1 } { print }' "\$dump" >"\$dump.changed"
mv "\$dump.changed" "\$dump"
STANDIN
chmod +x "$stand_in/$program"
status=0
said=$(GXX_BUILD_DIR=$build FUZZ_BUILD_DIR=$stand_in tests/determinism/check.sh --frames 5 2>&1) || status=$?
if [[ $status -ne 1 || $said != *"first at step 3, body 0"* ]]; then
  echo "the determinism check did not see the changed digit (status $status):" >&2
  echo "$said" >&2
  exit 1
fi
echo "the determinism check saw it: $(grep -m1 DIFFERENT <<<"$said")"
