#!/usr/bin/env bash
# The limb-measure study (experiments/2026-11-28-limb-measure-controls.md):
# writes the labelled controls at 500-5,000 vertices and tabulates what each
# binary's `score --json` reads on them.
#   experiments/scripts/limb-controls/study.sh OUT_DIR before=OLD/build/morphogen after=build/morphogen
#   GRID=1 experiments/scripts/limb-controls/study.sh ...   uniform grids instead of decimation
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=$1
shift
grid=()
[[ -n "${GRID:-}" ]] && grid=(--grid)
mkdir -p "$out"
g++ -std=c++20 -O2 -I. -isystem /usr/include/eigen3 experiments/scripts/limb-controls/controls.cpp \
    tests/fitness/limb_controls.cpp -o "$out/controls" -lgmp -lmpfr
"$out/controls" "$out" "${grid[@]}" >/dev/null
python3 experiments/scripts/limb-controls/table.py "$out" "$@"
