#!/usr/bin/env bash
# The CPU time (perf stat's task-clock, mean of R runs) that --colour --leaves
# add to an engine-ready GLB export (--lods 1, which already writes the plant's
# record), against the plant's growth (the fastest of R growths as grow times
# it, in the process), for random genomes 1..N at configs/tree.json. Run it on
# an idle machine: the growth is a wall time.
# Usage: colour_leaves_cpu.sh MORPHOGEN N [R]
set -euo pipefail
exe=$1 count=$2 runs=${3:-10}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cpu_ms() { perf stat -r "$runs" -x, -e task-clock "$exe" grow --config configs/tree.json "$@" -o "$out/x.glb" 2>&1 >/dev/null | grep task-clock | cut -d, -f1; }
echo "seed,vertices,growth_ms,export_ms,colour_leaves_ms,share"
for ((s = 1; s <= count; s++)); do
  line=$("$exe" grow --config configs/tree.json --random "$s" -o "$out/x.obj")
  vertices=$(sed -n 's/.*: \([0-9]*\) vertices.*/\1/p' <<< "$line")
  growth=$(for ((r = 0; r < runs; r++)); do "$exe" grow --config configs/tree.json --random "$s" -o "$out/x.obj"; done |
    sed -n 's/.* in \([0-9.]*\) s$/\1/p' | sort -g | head -1)
  plain=$(cpu_ms --random "$s" --lods 1)
  dressed=$(cpu_ms --random "$s" --lods 1 --colour --leaves)
  python3 -c "g=1000*$growth; d=$dressed-$plain; print(f'$s,$vertices,{g:.1f},$plain,{d:.1f},{d/g:.3f}' if g>0 else f'$s,$vertices,{g:.1f},$plain,{d:.1f},')"
done
