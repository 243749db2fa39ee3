#!/usr/bin/env bash
# The trees of experiments/2026-11-27-trees-with-limbs.md: configs/tree.json on
# several seeds, each best's architecture and verdict by the skeleton
# (experiments/scripts/trees/is_tree.py), the bests drawn side by side; the same
# without the signals of algorithm.md §5.9 (exposure, diffusion) on the first
# seed; then configs/tree_map.json (MAP-Elites over trunk_ratio x solidity)
# on the first seed, its map of elites drawn.
#
# usage: experiments/scripts/trees.sh [SEEDS...]     (default 1 2 3; results in out/trees/, OUT=... to change)
#   MAP=0 skips the MAP-Elites run, PLAIN=0 the run without signals;
#   THREADS (default 2) threads per run.
#
# A run whose history.csv is complete is not run again, and one that was
# stopped is resumed (to the same bytes as an unbroken run), so the script
# can be stopped and re-run; a run whose config changed is started again.
# Cost: tree.json's 3,100 births about 0.5 s of one core each (4,000 vertices,
# experiments/2026-11-29-tree-json-fine-growth.md); the map's 6,100 births 5-8
# minutes of one core; hours of wall time on a loaded machine.
set -euo pipefail
cd "$(dirname "$0")/../.."
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2 3)
exe=build/morphogen
out=${OUT:-out/trees}
threads=${THREADS:-2}
mkdir -p "$out"

# The map must score the same network's plants as the GA runs (it grows them
# at the smaller budget of 1,000 vertices and 150 steps, to stay cheap).
python3 - <<'PY'
import json, sys
tree, tree_map = json.load(open("configs/tree.json")), json.load(open("configs/tree_map.json"))
for key in ("network", "fitness"):
    if tree.get(key) != tree_map.get(key):
        sys.exit(f"trees.sh: configs/tree.json and configs/tree_map.json differ in {key!r}")
PY

# Whether RUN's history.csv has its header and ROWS generations.
complete() { [ -f "$1/history.csv" ] && [ "$(wc -l < "$1/history.csv")" -eq $(( $2 + 1 )) ]; }

# run CONFIG SEED DIR: evolve, resume, or nothing, as the directory says.
run() {
  local config=$1 seed=$2 dir=$3
  local generations
  generations=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["run"]["generations"])' "$config")
  if cmp -s "$config" "$dir.json" && complete "$dir" $(( generations + 1 )); then return; fi
  if cmp -s "$config" "$dir.json" && [ -f "$dir/checkpoint.json" ]; then
    echo "$(date -u +%H:%M:%S) $exe resume $dir" >&2
    "$exe" resume "$dir" --threads "$threads" --no-report >> "$dir.log" 2>&1
  else
    echo "$(date -u +%H:%M:%S) $exe evolve $config --seed $seed --out $dir" >&2
    cp "$config" "$dir.json"  # what this run was started from
    "$exe" evolve "$config" --seed "$seed" --out "$dir" --threads "$threads" --force --no-report > "$dir.log" 2>&1
  fi
}

bests=()
for s in "${seeds[@]}"; do
  run configs/tree.json "$s" "$out/tree-$s"
  last=$(ls "$out/tree-$s"/best/gen_*.obj | sort | tail -n 1)
  bests+=("$last")
done
python3 experiments/scripts/trees/is_tree.py configs/tree.json "${bests[@]}" | tee "$out/is_tree.csv"
"$exe" render "${bests[@]}" --columns "${#bests[@]}" -o "$out/trees.png"
echo "contact sheet: $out/trees.png" >&2

if [ "${PLAIN:-1}" != 0 ]; then
  # The same config without the signals: what they are worth to evolution.
  python3 - "$out/tree-plain.config.json" <<'PY'
import json, os, sys
config = json.load(open("configs/tree.json"))
for key in ("exposure", "signal_diffusion"):
    config["growth"].pop(key, None)
# run.from is read from the config's folder: keep it naming the same genomes.
config["run"]["from"] = [os.path.abspath(os.path.join("configs", f)) for f in config["run"].get("from", [])]
json.dump(config, open(sys.argv[1], "w"), indent=1)
PY
  s=${seeds[0]}
  run "$out/tree-plain.config.json" "$s" "$out/tree-plain-$s"
  plain=$(ls "$out/tree-plain-$s"/best/gen_*.obj | sort | tail -n 1)
  python3 experiments/scripts/trees/is_tree.py "$out/tree-plain.config.json" "$plain" | tee "$out/is_tree_plain.csv"
fi

if [ "${MAP:-1}" != 0 ]; then
  s=${seeds[0]}
  run configs/tree_map.json "$s" "$out/tree-map-$s"
  "$exe" archive "$out/tree-map-$s" --png "$out/tree-map-$s.png" > /dev/null
  echo "map of elites: $out/tree-map-$s.png" >&2
fi
