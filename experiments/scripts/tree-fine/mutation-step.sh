#!/usr/bin/env bash
# configs/tree.json's GA at two mutation steps (evolution.mutation_sigma),
# the rest of the config as shipped: one run a (step, seed), one thread
# each, two at a time. Then each run's best (summarise.py: score --json,
# a picture) and the best of every generation (trajectory.py).
# Usage: mutation-step.sh MORPHOGEN OUT_DIR "SIGMAS" "SEEDS"   (from the repository's root)
#   e.g. mutation-step.sh build/morphogen /tmp/step "0.3 0.1" "1 2 3 6"
set -euo pipefail
exe=$1 out=$2 sigmas=$3 seeds=$4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"

for sigma in $sigmas; do
  # run.from made absolute, so the copy finds the bred tree from OUT_DIR.
  python3 - "$sigma" "$out/sigma$sigma.json" <<'PY'
import json, os, sys
c = json.load(open("configs/tree.json"))
c.pop("$schema", None)
c["run"]["from"] = [os.path.abspath(os.path.join("configs", p)) for p in c["run"]["from"]]
c["evolution"]["mutation_sigma"] = float(sys.argv[1])
json.dump(c, open(sys.argv[2], "w"), indent=1)
PY
  for seed in $seeds; do
    "$exe" evolve "$out/sigma$sigma.json" --seed "$seed" --threads 1 --no-report \
      --out "$out/sigma${sigma}_s$seed" > "$out/sigma${sigma}_s$seed.log" &
    # two runs at a time on a 2-core machine
    while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n; done
  done
done
wait

for sigma in $sigmas; do
  runs=()
  for seed in $seeds; do runs+=("$(cd "$out" && pwd)/sigma${sigma}_s$seed"); done
  echo "## mutation_sigma $sigma"
  python3 experiments/scripts/tree-strategies/summarise.py "$exe" "$out/sigma$sigma.json" "$out/sigma$sigma.png" "${runs[@]}"
  python3 "$here/trajectory.py" "$exe" "$out/sigma$sigma.json" "${runs[@]}"
done
