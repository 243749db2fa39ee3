#!/usr/bin/env bash
# The export-time cost of --colour --leaves per plant at configs/tree.json
# (the largest shipped growth: 150 steps, up to 1,000 vertices, branching with
# exposure), against the plant's growth time. Grows N random genomes twice,
# writing the plain GLB and then the GLB with colours and leaves, five times
# each; the cost is the median difference in wall time per plant, the growth
# time the median that grow prints. Usage: colour_leaves_cost.sh MORPHOGEN [N]
set -euo pipefail
exe=$1
n=${2:-20}
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
now() { date +%s.%N; }
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
for seed in $(seq 1 "$n"); do
  plain=() extra=()
  for rep in 1 2 3 4 5; do
    t0=$(now); "$exe" grow --config "$src/configs/tree.json" --random "$seed" -o "$work/p.glb" >"$work/p.txt"; t1=$(now)
    "$exe" grow --config "$src/configs/tree.json" --random "$seed" -o "$work/c.glb" --colour --leaves >"$work/c.txt" 2>/dev/null; t2=$(now)
    plain+=("$(echo "$t1 - $t0" | bc -l)") extra+=("$(echo "$t2 - $t1" | bc -l)")
  done
  grow_s=$(sed -E 's/.* in ([0-9.]+) s$/\1/' "$work/p.txt")
  p=$(printf '%s\n' "${plain[@]}" | median) c=$(printf '%s\n' "${extra[@]}" | median)
  vertices=$(sed -E 's/.*: ([0-9]+) vertices.*/\1/' "$work/p.txt")
  echo "$seed $vertices $grow_s $(echo "$c - $p" | bc -l)"
done >"$work/rows.txt"
awk '{printf "seed %2d: %4d vertices, growth %.4f s, colour+leaves %+.4f s (%.1f %%)\n", $1, $2, $3, $4, 100 * $4 / $3}' "$work/rows.txt"
g=$(awk '{print $3}' "$work/rows.txt" | median) d=$(awk '{print $4}' "$work/rows.txt" | median)
awk -v g="$g" -v d="$d" -v n="$n" 'BEGIN {printf "median of %d plants: growth %.4f s, colour+leaves %.4f s: %.1f %% of growth\n", n, g, d, 100 * d / g}'
