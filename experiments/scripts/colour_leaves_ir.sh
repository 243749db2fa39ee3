#!/usr/bin/env bash
# The instructions (valgrind's callgrind, which counts them exactly: no
# machine load moves them) that --colour --leaves add to an engine-ready GLB
# export (--lods 1), against those of the plant's growth (grow_dated,
# inclusive), for random genomes 1..N at configs/tree.json. With BASELINE
# (another build of morphogen), its added instructions too, beside.
# Usage: colour_leaves_ir.sh MORPHOGEN N [BASELINE]
set -euo pipefail
exe=$1 count=$2 base=${3:-}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Instructions of `grow` with build $1, seed $2 and the options after.
refs() {
  local exe=$1 seed=$2
  shift 2
  valgrind --tool=callgrind --callgrind-out-file="$out/cg" "$exe" grow --config configs/tree.json --random "$seed" \
    --lods 1 "$@" -o "$out/x.glb" 2>&1 >/dev/null | sed -n 's/.*I *refs: *//p' | tr -d ,
}
# Instructions the pass adds with build $1 for seed $2.
# The dressed run is the last: its profile, in $out/cg, holds the growth's count.
added() {
  local plain
  plain=$(refs "$1" "$2")
  echo $(($(refs "$1" "$2" --colour --leaves) - plain))
}
echo "seed,vertices,growth_Ir,colour_leaves_Ir,share${base:+,baseline_colour_leaves_Ir,baseline_share}"
for ((s = 1; s <= count; s++)); do
  vertices=$("$exe" grow --config configs/tree.json --random "$s" -o "$out/x.obj" | sed -n 's/.*: \([0-9]*\) vertices.*/\1/p')
  pass=$(added "$exe" "$s")
  growth=$(callgrind_annotate --inclusive=yes --threshold=100 "$out/cg" | grep 'GenomeGrower::grow_dated' | head -1 |
    awk '{print $1}' | tr -d ,)
  row="$s,$vertices,$growth,$pass,$(python3 -c "print(f'{$pass/$growth:.4f}')")"
  if [[ -n $base ]]; then
    base_pass=$(added "$base" "$s")
    row+=",$base_pass,$(python3 -c "print(f'{$base_pass/$growth:.4f}')")"
  fi
  echo "$row"
done
