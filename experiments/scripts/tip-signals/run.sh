#!/usr/bin/env bash
# The tip-signals study (experiments/2026-11-27-tip-signals.md): contact
# sheets of the same random genomes at tree.json's growth settings (collisions
# allowed) without and with the signals of docs/algorithm.md §5.9, their
# exposures, and what the signals cost (morphogen bench).
set -euo pipefail
cd "$(dirname "$0")/../../.."
OUT=${OUT:-out/tip-signals}
HERE=experiments/scripts/tip-signals
mkdir -p "$OUT"
for variant in allow signals; do
    build/morphogen gallery --config "$HERE/tree_$variant.json" --count 36 --seed 1 --format obj \
        --out "$OUT/gallery-$variant" --png "$OUT/sheet-$variant.png" --columns 6 --threads 2
    python3 "$HERE/exposure_summary.py" "$OUT/gallery-$variant"/*.obj > "$OUT/exposure-$variant.txt"
done
for variant in allow signals; do
    build/morphogen bench --config "$HERE/tree_$variant.json" --genomes 16 --repeat 3 --threads 1 --json \
        > "$OUT/bench-$variant.json"
done
