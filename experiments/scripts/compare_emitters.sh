#!/usr/bin/env bash
# Every MAP-Elites emitter kind against the GA and random search on the canopy
# problem, on three descriptor grids, at an equal budget of births
# (experiments/2026-11-25-every-emitter-three-grids.md).
#
# usage: experiments/scripts/compare_emitters.sh [GENERATIONS] [POPULATION] [SEEDS...]
#   defaults: 200 100 1 2 3 -> B = POPULATION * (GENERATIONS + 1) = 20,100
#   births per run; results in out/compare_emitters/ (OUT=... to change)
#   GRIDS="hf fine shape"   which grids (default these three; also shipped,
#            small, wide, form, crown, posture, shape_fine, shape3d)
#   METHODS="ga random gaussian iso_line cma_me cma_mae mae_a01 mixed"   which methods
#   (runs go in the order of METHODS, every seed of a method before the next)
#   JOBS=2     runs side by side (default 1), THREADS=1 threads per run,
#   EXE=PATH   the executable (default build/morphogen)
#
# The grids:
#   shipped  configs/map_elites.json's grid
#   hf       height [10, 20] x footprint [0, 800], 20 x 20 (the grid shipped
#            before 2026-11-25)
#   fine     the same ranges in 40 x 40 cells
#   shape    spread [0, 4] x slenderness [0, 4], 20 x 20: two shape ratios the
#            canopy fitness does not bound
#   small    hf's ranges in 10 x 10 cells (for a small budget:
#            experiments/scripts/compare_emitters.sh 20 50 with GRIDS=small)
#   wide     height [10, 20] x footprint [0, 1600], 20 x 20
#   form     sphericity [0, 1] x lean [0, 8], 20 x 20: compact or thin,
#            upright or leaning
#   crown    spread [0, 4] x sphericity [0, 1], 20 x 20
#   posture  spread [0, 4] x lean [0, 8], 20 x 20: crown over base, and how
#            far the top half stands off the bottom half
#   shape_fine  shape's ranges in 40 x 40 cells
#   shape3d  spread [0, 4] x slenderness [0, 4] x lean [0, 8], 10 x 10 x 10
#            (a table only: heatmaps are drawn for grids of two descriptors)
#   low      height [0, 10] x footprint [0, 100], 10 x 10: small plants (with
#            STEPS=60 CANOPY_HEIGHT=2.5)
#   shape_small  shape's ranges in 10 x 10 cells
# STEPS=N and CANOPY_HEIGHT=H change the problem of every run (growth.steps,
# the canopy's height) from the shipped configs' 200 and 10.
# The methods (all with configs/map_elites.json's network, growth, fitness and
# evolution settings; only `emitters` differ between the MAP-Elites rows):
#   ga        configs/canopy.json with the `descriptors` of every grid (recorded
#             in lineage.csv; the search does not use them)
#   random    B random genomes: the same GA with population B and 0 generations
#   gaussian  [{"kind": "gaussian"}] (the default emitter)
#   iso_line  [{"kind": "iso_line", "selection": "fitness_proportional"}]
#   cma_me    4 x {"kind": "cma_me", "sigma0": 0.2}
#   cma_mae   4 x {"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.1}
#             (shipped until 2026-11-25)
#   mae_a01   the same with "learning_rate": 0.01 (the shipped emitters)
#   mae_a04   the same with "learning_rate": 0.04 (alpha for a 4 x finer grid
#             by the CMA-MAE paper's rule 1 - (1 - alpha)^(cells ratio))
#   mae_a025  the same with "learning_rate": 0.025 (that rule for 2.5 x the cells)
#   mixed     2 x that cma_mae emitter (alpha 0.1) and 2 x the iso_line one
#             (fitness-proportional); mixed3: 3 + 1; mixed_a01: 2 + 2 with alpha 0.01
#   cma_me2, cma_mae2   2 emitters instead of 4 (for small populations: at
#             population 50 each keeps the 25 births a generation it has at 100)
# A GA or random run records every grid's measures, so all grids share one
# such run per seed.
#
# A run whose history.csv is complete is not run again, one that was stopped is
# resumed (to the same bytes as an unbroken run), and one whose config changed
# is started again, so the script can be stopped and re-run. Then
# experiments/scripts/qd_bin.py bins every run's lineage.csv into each grid and prints one
# table per grid (coverage, QD-score, best canopy, ratios to the GA), and draws
# the methods' heatmaps for the first seed (GRID-heatmaps-seed-S.png).
set -euo pipefail
cd "$(dirname "$0")/../.."
generations=${1:-200}
population=${2:-100}
shift $(( $# > 2 ? 2 : $# ))
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2 3)
exe=${EXE:-build/morphogen}
out=${OUT:-out/compare_emitters}
threads=${THREADS:-1}
jobs=${JOBS:-1}
read -r -a grids <<< "${GRIDS:-hf fine shape}"
read -r -a methods <<< "${METHODS:-ga random gaussian iso_line cma_me cma_mae mae_a01 mixed}"
budget=$(( population * (generations + 1) ))
mkdir -p "$out"

# The configs, from the shipped ones: out/GRID.json (the grid), and for each
# grid and method the config of its runs; prints "GRID METHOD RUN_NAME" lines,
# RUN_NAME shared by the GA (random) runs of grids with the same measures.
plan=$(python3 - "$out" "$population" "$budget" "${grids[*]}" "${methods[*]}" <<'PY'
import json, os, sys
out, population, budget = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
grids, methods = sys.argv[4].split(), sys.argv[5].split()
ga_base = json.load(open("configs/canopy.json"))
me_base = json.load(open("configs/map_elites.json"))
for key in ("network", "growth", "fitness"):
    if ga_base.get(key) != me_base.get(key):
        sys.exit(f"compare_emitters: configs/canopy.json and configs/map_elites.json differ in {key!r}")
for c in (ga_base, me_base):
    c.pop("$schema", None)
    if os.environ.get("STEPS"):
        c["growth"]["steps"] = int(os.environ["STEPS"])
    if os.environ.get("CANOPY_HEIGHT"):
        c["fitness"]["height"] = float(os.environ["CANOPY_HEIGHT"])
hf = [{"measure": "height", "min": 10, "max": 20, "bins": 20},
      {"measure": "footprint", "min": 0, "max": 800, "bins": 20}]
all_grids = {
    "shipped": me_base["descriptors"],
    "hf": hf,
    "fine": [dict(d, bins=2 * d["bins"]) for d in hf],
    "shape": [{"measure": "spread", "min": 0, "max": 4, "bins": 20},
              {"measure": "slenderness", "min": 0, "max": 4, "bins": 20}],
    "small": [dict(d, bins=d["bins"] // 2) for d in hf],
    "wide": [hf[0], dict(hf[1], max=1600)],
    "form": [{"measure": "sphericity", "min": 0, "max": 1, "bins": 20},
             {"measure": "lean", "min": 0, "max": 8, "bins": 20}],
    "crown": [{"measure": "spread", "min": 0, "max": 4, "bins": 20},
              {"measure": "sphericity", "min": 0, "max": 1, "bins": 20}],
    "posture": [{"measure": "spread", "min": 0, "max": 4, "bins": 20},
                {"measure": "lean", "min": 0, "max": 8, "bins": 20}],
    "shape_fine": [{"measure": "spread", "min": 0, "max": 4, "bins": 40},
                   {"measure": "slenderness", "min": 0, "max": 4, "bins": 40}],
    "low": [{"measure": "height", "min": 0, "max": 10, "bins": 10},
            {"measure": "footprint", "min": 0, "max": 100, "bins": 10}],
    "shape_small": [{"measure": "spread", "min": 0, "max": 4, "bins": 10},
                    {"measure": "slenderness", "min": 0, "max": 4, "bins": 10}],
    "shape3d": [{"measure": "spread", "min": 0, "max": 4, "bins": 10},
                {"measure": "slenderness", "min": 0, "max": 4, "bins": 10},
                {"measure": "lean", "min": 0, "max": 8, "bins": 10}],
}
emitters = {
    "gaussian": [{"kind": "gaussian"}],
    "iso_line": [{"kind": "iso_line", "selection": "fitness_proportional"}],
    "cma_me": [{"kind": "cma_me", "sigma0": 0.2}] * 4,
    "cma_mae": [{"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.1}] * 4,
    "cma_me2": [{"kind": "cma_me", "sigma0": 0.2}] * 2,
    "cma_mae2": [{"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.1}] * 2,
    "mixed": [{"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.1}] * 2 +
             [{"kind": "iso_line", "selection": "fitness_proportional"}] * 2,
    "mae_a01": [{"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.01}] * 4,
    # alpha for 4 x the cells by the CMA-MAE paper's resolution rule, 1 - (1 - 0.01)^4
    "mae_a04": [{"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.04}] * 4,
    # the same rule for 2.5 x the cells (shape3d's 1,000): 1 - (1 - 0.01)^2.5
    "mae_a025": [{"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.025}] * 4,
    "mixed3": [{"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.1}] * 3 +
              [{"kind": "iso_line", "selection": "fitness_proportional"}],
    "mixed_a01": [{"kind": "cma_mae", "sigma0": 0.2, "learning_rate": 0.01}] * 2 +
                 [{"kind": "iso_line", "selection": "fitness_proportional"}] * 2,
}
for grid in grids:
    if grid not in all_grids:
        sys.exit(f"compare_emitters: unknown grid {grid!r} (one of {', '.join(all_grids)})")
# Every grid's measures, each once, for the GA and random runs to record.
recorded = {}
for name, g in all_grids.items():
    if name == "shipped":  # one of the named grids, which give the order
        continue
    for d in g:
        recorded.setdefault(d["measure"], d)
recorded = list(recorded.values())
for grid in grids:
    json.dump({"descriptors": all_grids[grid]}, open(f"{out}/{grid}.json", "w"), indent=2)
for method in methods:
    for grid in grids:
        if method in ("ga", "random"):
            c = json.loads(json.dumps(ga_base))
            c["evolution"]["population"] = budget if method == "random" else population
            c["descriptors"] = recorded
            name = method
        elif method in emitters:
            c = json.loads(json.dumps(me_base))
            c["evolution"]["population"] = population
            c["emitters"] = emitters[method]
            c["descriptors"] = all_grids[grid]
            name = f"{grid}-{method}"
        else:
            sys.exit(f"compare_emitters: unknown method {method!r} (ga, random or one of {', '.join(emitters)})")
        c["run"]["name"] = name
        json.dump(c, open(f"{out}/{name}.json", "w"), indent=2)
        print(grid, method, name)
PY
)

# Whether RUN's history.csv has its header and ROWS generations.
complete() { [ -f "$1/history.csv" ] && [ "$(wc -l < "$1/history.csv")" -eq $(( $2 + 1 )) ]; }

# One run: NAME SEED (evolve, resume, or nothing when it is complete).
run_one() {
  local name=$1 s=$2 dir="$out/$1-$2" gens=$generations same=false
  [[ $name == random ]] && gens=0
  cmp -s "$out/$name.json" "$dir.json" 2>/dev/null && same=true
  if $same && complete "$dir" $(( gens + 1 )); then return 0; fi
  if $same && [ -f "$dir/checkpoint.json" ]; then
    echo "$(date -u +%H:%M:%S) $name seed $s: resume" >&2
    "$exe" resume "$dir" --generations "$gens" --threads "$threads" >> "$dir.log" 2>&1
  else
    echo "$(date -u +%H:%M:%S) $name seed $s: evolve" >&2
    cp "$out/$name.json" "$dir.json"  # what this run was started from
    "$exe" evolve "$out/$name.json" --seed "$s" --generations "$gens" --threads "$threads" \
      --out "$dir" --force --no-report > "$dir.log" 2>&1
  fi
}
export -f run_one complete
export out exe generations threads

# Run names in plan order (a method's grids together), each once, then seeds.
awk '!seen[$3]++ {print $3}' <<< "$plan" | while read -r name; do
  for s in "${seeds[@]}"; do echo "$name $s"; done
done | xargs -P "$jobs" -L 1 bash -c 'run_one "$0" "$1"'

for grid in "${grids[@]}"; do
  runs=() first=()
  while read -r g method name; do
    [ "$g" = "$grid" ] || continue
    for s in "${seeds[@]}"; do runs+=("$method/$s=$out/$name-$s"); done
    first+=("$method=$out/$name-${seeds[0]}")
  done <<< "$plan"
  echo "## grid $grid"
  python3 experiments/scripts/qd_bin.py table --grid-from "$out/$grid.json" --budget "$budget" --reference ga "${runs[@]}"
  if [ "$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["descriptors"]))' "$out/$grid.json")" = 2 ]; then
    python3 experiments/scripts/qd_bin.py heatmap --grid-from "$out/$grid.json" --png "$out/$grid-heatmaps-seed-${seeds[0]}.png" "${first[@]}"
  fi
done
