#!/usr/bin/env bash
# MAP-Elites against the GA and random search on the canopy problem, at an
# equal budget of births, every run binned into the same descriptor grid
# (experiments/2026-11-23-map-elites-vs-ga.md).
#
# usage: experiments/scripts/compare_qd.sh [GENERATIONS] [POPULATION] [SEEDS...]
#   defaults: 50 100 1 2 3 -> budget B = POPULATION * (GENERATIONS + 1)
#   = 5,100 births per run; results in out/compare_qd/ (OUT=... to change)
#   ME_CONFIG=... replaces configs/map_elites.json (its descriptors are the grid)
#
# For each seed s:
#   ga-s      configs/canopy.json with map_elites.json's `descriptors` added
#             (a GA records them in lineage.csv; its search is unchanged)
#   me-s      configs/map_elites.json (or ME_CONFIG)
#   random-s  the same with population B and 0 generations:
#             generation 0 is B random genomes, nothing is bred
# all with `evolution.population` POPULATION (random: B), --seed s, 2 threads.
# A run whose history.csv is complete is not run again, and one that was
# stopped is resumed (to the same bytes as an unbroken run), so the script can
# be stopped and re-run, or re-run to redo the table (a run whose config
# changed is started again). Then experiments/scripts/qd_bin.py bins every lineage.csv
# into the grid of the MAP-Elites config (best fitness per cell) and prints the
# table: coverage, QD-score (sum of fitness - 0 over occupied cells) and best
# canopy per method and seed, with means; and draws the three methods'
# fitness heatmaps for the first seed side by side (heatmaps-seed-S.png).
set -euo pipefail
cd "$(dirname "$0")/../.."
generations=${1:-50}
population=${2:-100}
shift $(( $# > 2 ? 2 : $# ))
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2 3)
exe=build/morphogen
out=${OUT:-out/compare_qd}
threads=${THREADS:-2}
me_config=${ME_CONFIG:-configs/map_elites.json}
budget=$(( population * (generations + 1) ))
mkdir -p "$out"

# The three configs, from the shipped ones; they must agree on what is grown and scored.
python3 - "$out" "$population" "$budget" "$me_config" <<'PY'
import json, sys
out, population, budget, me_config = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
ga = json.load(open("configs/canopy.json"))
me = json.load(open(me_config))
for key in ("network", "growth", "fitness"):
    if ga.get(key) != me.get(key):
        sys.exit(f"compare_qd: configs/canopy.json and {me_config} differ in {key!r}")
for c in (ga, me):
    c.pop("$schema", None)
ga["descriptors"] = me["descriptors"]
ga["evolution"]["population"] = population
ga["run"]["name"] = "ga"
me["evolution"]["population"] = population
me["run"]["name"] = "me"
random = json.loads(json.dumps(me))
random["evolution"]["population"] = budget
random["run"]["name"] = "random"
for name, c in (("ga", ga), ("me", me), ("random", random)):
    json.dump(c, open(f"{out}/{name}.json", "w"), indent=2)
PY

# Whether RUN's history.csv has its header and ROWS generations.
complete() { [ -f "$1/history.csv" ] && [ "$(wc -l < "$1/history.csv")" -eq $(( $2 + 1 )) ]; }

for s in "${seeds[@]}"; do
  for method in ga me random; do
    dir="$out/$method-$s"
    gens=$generations
    [ "$method" = random ] && gens=0
    same=false  # the run was started from this very config
    cmp -s "$out/$method.json" "$dir.json" 2>/dev/null && same=true
    if $same && complete "$dir" $(( gens + 1 )); then continue; fi
    if $same && [ -f "$dir/checkpoint.json" ]; then
      echo "$(date -u +%H:%M:%S) $method seed $s: $exe resume $dir --generations $gens" >&2
      "$exe" resume "$dir" --generations "$gens" --threads "$threads" >> "$dir.log" 2>&1
    else
      echo "$(date -u +%H:%M:%S) $method seed $s: $exe evolve $out/$method.json --seed $s --generations $gens --out $dir" >&2
      cp "$out/$method.json" "$dir.json"  # what this run was started from
      "$exe" evolve "$out/$method.json" --seed "$s" --generations "$gens" --threads "$threads" --out "$dir" --force \
        > "$dir.log" 2>&1
    fi
  done
done

runs=()
for s in "${seeds[@]}"; do
  for method in ga me random; do runs+=("$method/$s=$out/$method-$s"); done
done
python3 experiments/scripts/qd_bin.py table --grid-from "$me_config" --budget "$budget" "${runs[@]}"
s=${seeds[0]}
python3 experiments/scripts/qd_bin.py heatmap --grid-from "$me_config" --png "$out/heatmaps-seed-$s.png" \
  "GA=$out/ga-$s" "MAP-Elites=$out/me-$s" "random=$out/random-$s"
