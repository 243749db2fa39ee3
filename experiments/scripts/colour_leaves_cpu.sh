#!/usr/bin/env bash
# The CPU time (perf stat's task-clock, mean of R runs) that --colour --leaves
# add to an engine-ready GLB export (--lods 1, which already writes the plant's
# record), against the plant's growth (grow to OBJ less grow --steps 0: the
# start-up, config and seed), for random genomes 1..N at configs/tree.json.
# CPU time, not wall time: the machine may be shared.
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
  grown=$(perf stat -r "$runs" -x, -e task-clock "$exe" grow --config configs/tree.json --random "$s" -o "$out/x.obj" 2>&1 >/dev/null | grep task-clock | cut -d, -f1)
  seed=$(perf stat -r "$runs" -x, -e task-clock "$exe" grow --config configs/tree.json --random "$s" --steps 0 -o "$out/x.obj" 2>&1 >/dev/null | grep task-clock | cut -d, -f1)
  plain=$(cpu_ms --random "$s" --lods 1)
  dressed=$(cpu_ms --random "$s" --lods 1 --colour --leaves)
  python3 -c "g=$grown-$seed; d=$dressed-$plain; print(f'$s,$vertices,{g:.1f},$plain,{d:.1f},{d/g:.3f}' if g>0 else f'$s,$vertices,{g:.1f},$plain,{d:.1f},')"
done
