#!/usr/bin/env bash
# Determinism as a test (issue 36): the newest stage's program as g++ builds it (build/)
# and as clang builds it (build-fuzz/, tools/fuzz's build, under the sanitizers) runs
# each scene of the library and of the stage's own folder on both solvers, sleeping and
# continuous collision on, and the default demo (its keys throw new shapes and excite
# them all); every state dump must be the same bytes. A difference names the run, the
# first step and body whose row differs, both rows, and first_divergence's verdict at
# zero tolerance (which field).
#
#   tests/determinism/check.sh [--frames N]     (300 by default; the demo runs 360)
#
# Needs build/ (tools/test) and build-fuzz/ (tools/fuzz) built; GXX_BUILD_DIR and
# FUZZ_BUILD_DIR name others. Exit status: 0 every dump the same, 1 some differ, 2 a
# program is missing or a run failed. tests/determinism/sees_a_difference.sh shows that
# it can fail (ctest: determinism.sees_a_difference).
set -euo pipefail
cd "$(dirname "$0")/../.."
frames=300
while (($#)); do
  case $1 in
    --frames) [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [--frames N]" >&2; exit 2; }; frames=$2; shift 2 ;;
    *) echo "usage: $0 [--frames N]" >&2; exit 2 ;;
  esac
done

source tools/lib/stages.sh
newest=$(stage_newest)
id=$(stage_id "$newest")
folder=$(stage_folder "$newest")
program=${id}_$(stage_program "$newest")
gxx_build=${GXX_BUILD_DIR:-build}
gxx=$gxx_build/$program clang=${FUZZ_BUILD_DIR:-build-fuzz}/$program
for built in "$gxx" "$clang" "$gxx_build/first_divergence"; do
  [[ -x $built ]] || { echo "determinism: no $built (build/: tools/test; build-fuzz/: tools/fuzz)" >&2; exit 2; }
done

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Runs both programs with the same arguments; compares their dumps.
differences=0 runs=0
compare() {
  local name=$1
  shift
  local run
  for run in gxx clang; do
    local binary=$gxx
    [[ $run == clang ]] && binary=$clang
    if ! "$binary" "$@" --every 0 --no-gif --out "$scratch/out_$run" --dump "$scratch/$run.csv" \
        >/dev/null 2>"$scratch/$run.err"; then
      echo "determinism: $name: the $run build's run failed: $(head -1 "$scratch/$run.err")" >&2
      exit 2
    fi
  done
  runs=$((runs + 1))
  if cmp -s "$scratch/gxx.csv" "$scratch/clang.csv"; then return; fi
  differences=$((differences + 1))
  # The first line that differs: its step and body (the dump's first two columns).
  local at
  at=$(cmp "$scratch/gxx.csv" "$scratch/clang.csv" | sed -E 's/.* line ([0-9]+).*/\1/') || true
  local ours theirs
  ours=$(sed -n "${at}p" "$scratch/gxx.csv")
  theirs=$(sed -n "${at}p" "$scratch/clang.csv")
  echo "DIFFERENT: $name: first at step ${ours%%,*}, body $(cut -d, -f2 <<<"$ours") (line $at)"
  echo "  g++:   $ours"
  echo "  clang: ${theirs:-(no such line)}"
  "$gxx_build/first_divergence" "$scratch/gxx.csv" "$scratch/clang.csv" --absolute 0 --relative 0 | head -1 | sed 's/^/  /' || true
}

# A scene with the solver, sleeping and continuous collision set in its world.
variant() {
  python3 - "$1" "$2" "$3" <<'PYTHON'
import json, sys
source, solver, target = sys.argv[1:]
with open(source) as f:
    scene = json.load(f)
scene.setdefault("world", {}).update({"solver": solver, "sleep": True, "continuous": True})
with open(target, "w") as f:
    json.dump(scene, f)
PYTHON
}

for scene in ch5_demo/scenes/*.json "$folder"/*.json; do
  for solver in book sequential_impulse; do
    # 5.9's joints are refused on the book's passes (its README says why): a scene with
    # joints runs on the sequential impulses only.
    if [[ $solver == book ]] && grep -q '"joints"' "$scene"; then continue; fi
    variant "$scene" "$solver" "$scratch/scene.json"
    compare "$(basename "$scene") ($solver)" --scene "$scratch/scene.json" --frames "$frames"
  done
done
compare "the default demo, its keys" --frames $((frames + 60))

if ((differences > 0)); then
  echo "determinism: $differences of $runs runs differ between the g++ and clang builds of $id" >&2
  exit 1
fi
echo "determinism: $runs runs of $id ($frames frames each), g++ and clang: every dump the same bytes"
