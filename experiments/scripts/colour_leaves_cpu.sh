#!/usr/bin/env bash
# The CPU time (perf stat's task-clock, mean of R runs) that --colour --leaves
# add to an engine-ready GLB export (--lods 1, which already writes the plant's
# record), against the plant's growth (the fastest of R growths as grow times
# it, in the process), for random genomes 1..N at configs/tree.json. Run it on
# an idle machine: the growth is a wall time. With BASELINE (another build of
# morphogen), its cost is measured too, seed by seed beside MORPHOGEN's, so
# both see the same load.
# Usage: colour_leaves_cpu.sh MORPHOGEN N [R] [BASELINE]
set -euo pipefail
exe=$1 count=$2 runs=${3:-10} base=${4:-}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cpu_ms() { perf stat -r "$runs" -x, -e task-clock "$@" -o "$out/x.glb" 2>&1 >/dev/null | grep task-clock | cut -d, -f1; }
# The CPU time --colour --leaves add with build $1 for seed $2.
cost_ms() {
  local plain dressed
  plain=$(cpu_ms "$1" grow --config configs/tree.json --random "$2" --lods 1)
  dressed=$(cpu_ms "$1" grow --config configs/tree.json --random "$2" --lods 1 --colour --leaves)
  python3 -c "print(f'$plain,{$dressed-$plain:.2f}')"
}
echo "seed,vertices,growth_ms,export_ms,colour_leaves_ms,share${base:+,baseline_colour_leaves_ms,baseline_share}"
for ((s = 1; s <= count; s++)); do
  line=$("$exe" grow --config configs/tree.json --random "$s" -o "$out/x.obj")
  vertices=$(sed -n 's/.*: \([0-9]*\) vertices.*/\1/p' <<< "$line")
  growth=$(for ((r = 0; r < runs; r++)); do "$exe" grow --config configs/tree.json --random "$s" -o "$out/x.obj"; done |
    sed -n 's/.* in \([0-9.]*\) s$/\1/p' | sort -g | head -1)
  IFS=, read -r plain cost <<< "$(cost_ms "$exe" "$s")"
  row="$s,$vertices,$(python3 -c "print(f'{1000*$growth:.1f}')"),$plain,$cost,$(python3 -c "g=1000*$growth; print(f'{$cost/g:.3f}' if g>0 else '')")"
  if [[ -n $base ]]; then
    IFS=, read -r _ base_cost <<< "$(cost_ms "$base" "$s")"
    row+=",$base_cost,$(python3 -c "g=1000*$growth; print(f'{$base_cost/g:.3f}' if g>0 else '')")"
  fi
  echo "$row"
done
