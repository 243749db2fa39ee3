#!/usr/bin/env bash
# configs/tree.json on seeds 1-3 (6,100 births each, 2 threads), then each
# best's architecture measures and a coloured contact sheet. Usage:
#   tree_runs.sh MORPHOGEN OUT_DIR
set -euo pipefail
exe=$1 out=$2
mkdir -p "$out"
for s in 1 2 3; do
  /usr/bin/time -f "seed $s wall %e s" "$exe" evolve configs/tree.json --seed "$s" --threads 2 --out "$out/s$s" --no-report
  "$exe" grow --config configs/tree.json --genome "$out/s$s/best/gen_0060.genome.json" --colour -o "$out/seed$s.glb"
  "$exe" score --config configs/tree.json --genome "$out/s$s/best/gen_0060.genome.json" --json > "$out/seed$s.json"
done
"$exe" render "$out"/seed{1,2,3}.glb -o "$out/bests.png" --columns 3 --size 256
